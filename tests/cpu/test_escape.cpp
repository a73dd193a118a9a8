// The escapers every report writer uses: names from input stay text in HTML, one cell in a
// Markdown table, one cell (and no formula) in a CSV file.
#include "output/escape.h"
#include "util/error.h"

#include <gtest/gtest.h>

using namespace ssao;

TEST(Escape, HtmlTextEscapesEveryCharacterThatOpensMarkupOrEndsAQuote) {
    EXPECT_EQ(htmlText("<img src=x onerror=alert(1)>"), "&lt;img src=x onerror=alert(1)&gt;");
    EXPECT_EQ(htmlText("a & b"), "a &amp; b");
    EXPECT_EQ(htmlText("\" onload=\"x"), "&quot; onload=&quot;x");
    EXPECT_EQ(htmlText("it's"), "it&#39;s");
    EXPECT_EQ(htmlText("&amp;"), "&amp;amp;"); // escaped once more: shown as typed
    EXPECT_EQ(htmlText("plain text, 1.5 | ok"), "plain text, 1.5 | ok");
    EXPECT_EQ(htmlText(""), "");
}

TEST(Escape, HtmlAttrLeavesNoQuoteToCloseTheAttribute) {
    for (const std::string s : {"\" onload=\"alert(1)", "' onload='alert(1)", "x\" y='z' <w>"}) {
        const std::string e = htmlAttr(s);
        EXPECT_EQ(e.find_first_of("\"'<>"), std::string::npos) << e;
    }
    EXPECT_EQ(htmlAttr("a&b"), "a&amp;b");
}

TEST(Escape, MarkdownCellKeepsOneCellOnOneLineWithoutMarkup) {
    EXPECT_EQ(markdownCell("a|b"), "a\\|b");
    EXPECT_EQ(markdownCell("one\ntwo\r\nthree\rfour"), "one two three four");
    EXPECT_EQ(markdownCell("<img src=x onerror=alert(1)>"), "&lt;img src=x onerror=alert(1)&gt;");
    EXPECT_EQ(markdownCell("a & b"), "a &amp; b");
    EXPECT_EQ(markdownCell("`code|x`"), "\\`code\\|x\\`"); // no code span hides a pipe
    EXPECT_EQ(markdownCell("[x](javascript:alert(1))"), "\\[x\\](javascript:alert(1))");
    EXPECT_EQ(markdownCell("**b** _i_ \\|"), "\\*\\*b\\*\\* \\_i\\_ \\\\\\|");
    EXPECT_EQ(markdownCell("learnopengl (baseline)"), "learnopengl (baseline)");
    EXPECT_EQ(markdownCell("2/2"), "2/2");
}

TEST(Escape, MarkdownCellHasNoUnescapedPipeWhateverTheInput) {
    const std::string nasty = "|\\|\\\\|`|`\r|\n|";
    const std::string e = markdownCell(nasty);
    EXPECT_EQ(e.find_first_of("\r\n"), std::string::npos);
    for (size_t i = 0; i < e.size(); ++i) {
        if (e[i] == '\\') {
            ++i; // the escaped character
            continue;
        }
        EXPECT_NE(e[i], '|') << e << " at " << i;
    }
}

TEST(Escape, CsvFieldQuotesPerRfc4180) {
    EXPECT_EQ(csvField("plain"), "plain");
    EXPECT_EQ(csvField("a,b"), "\"a,b\"");
    EXPECT_EQ(csvField("say \"hi\""), "\"say \"\"hi\"\"\"");
    EXPECT_EQ(csvField("one\ntwo"), "\"one\ntwo\"");
    EXPECT_EQ(csvField("one\rtwo"), "\"one\rtwo\""); // a bare CR splits a row in most readers
    EXPECT_EQ(csvField(""), "");
    EXPECT_EQ(csvField("{\"ao.power\":2}"), "\"{\"\"ao.power\"\":2}\"");
}

TEST(Escape, CsvFieldNeutralisesALeadingFormulaCharacter) {
    EXPECT_EQ(csvField("=HYPERLINK(\"http://x\")"), "\"'=HYPERLINK(\"\"http://x\"\")\"");
    EXPECT_EQ(csvField("@SUM(A1)"), "'@SUM(A1)");
    EXPECT_EQ(csvField("+1"), "'+1");
    EXPECT_EQ(csvField("-1"), "'-1");
    EXPECT_EQ(csvField("\tx"), "'\tx");
    EXPECT_EQ(csvField("\rx"), "\"'\rx\"");
    EXPECT_EQ(csvField("a=1"), "a=1"); // only the first character starts a formula
    EXPECT_EQ(csvField("orbit-25"), "orbit-25");
}

TEST(Escape, AnErrorLineHoldsNoControlBytes) {
    // The terminal is a sink too: an escape sequence in a file name must not recolour or move it.
    EXPECT_EQ(ssao::oneLine("scene \x1b[31mred\x1b[0m.gltf: no such file\n"), "scene ?[31mred?[0m.gltf: no such file");
    EXPECT_EQ(ssao::oneLine("a\r\nb\x07\x7f"), "a;;b??");
    EXPECT_EQ(ssao::oneLine("caf\xc3\xa9 \t ok"), "caf\xc3\xa9 \t ok"); // UTF-8 and tabs stay
}

TEST(Escape, AnErrorLineIsBoundedAndKeepsWhatWasExpected) {
    // A preset's 100 000-character enum value echoed back: the line keeps its start and the end
    // that names the choices, never a UTF-8 sequence cut in two.
    const std::string value(100000, 'x');
    const std::string line = ssao::oneLine("preset p.json: gbuffer.second_layer_build: '\xc3\xa9" + value +
                                           "\xc3\xa9' is not one of peel|previous");
    EXPECT_LE(line.size(), 640u);
    EXPECT_EQ(line.rfind("preset p.json: gbuffer.second_layer_build: '", 0), 0u);
    EXPECT_NE(line.find("bytes left out"), std::string::npos);
    const std::string end = "' is not one of peel|previous";
    EXPECT_EQ(line.substr(line.size() - end.size()), end);
    for (size_t i = 0; i + 1 < line.size(); ++i)
        if (static_cast<unsigned char>(line[i]) == 0xc3) EXPECT_EQ(static_cast<unsigned char>(line[i + 1]), 0xa9);
    EXPECT_EQ(ssao::oneLine(std::string(600, 'a')), std::string(600, 'a')); // a line that fits is whole
}

TEST(Escape, JsStringIsPrintableAsciiThatNothingEnds) {
    EXPECT_EQ(ssao::jsString("plain name.gltf"), "\"plain name.gltf\"");
    EXPECT_EQ(ssao::jsString("a\"b\\c"), "\"a\\\"b\\\\c\"");
    EXPECT_EQ(ssao::jsString("x\xe2\x80\xa8y\xe2\x80\xa9z"), "\"x\\u2028y\\u2029z\""); // line ends in JavaScript
    EXPECT_EQ(ssao::jsString("</script><!--"), "\"\\u003C/script\\u003E\\u003C!--\"");
    EXPECT_EQ(ssao::jsString("\n\r\t\x7f"), "\"\\u000A\\u000D\\u0009\\u007F\"");
    EXPECT_EQ(ssao::jsString("\xf0\x9f\x98\x80"), "\"\\uD83D\\uDE00\""); // a surrogate pair
    EXPECT_EQ(ssao::jsString("\xe9"), "\"\\uFFFD\"");                        // a lone Latin-1 byte
    EXPECT_EQ(ssao::jsString("\xc0\xaf"), "\"\\uFFFD\\uFFFD\"");              // an overlong '/'
    EXPECT_EQ(ssao::jsString("\xed\xa0\x80"), "\"\\uFFFD\\uFFFD\\uFFFD\"");   // an encoded surrogate
    for (int c = 0; c < 256; ++c)
        for (unsigned char b : ssao::jsString(std::string(1, char(c)) + "\xe2\x80")) EXPECT_TRUE(b >= 0x20 && b < 0x7f) << c;
}

TEST(Escape, JsCommentTextKeepsOnlyPrintableAscii) {
    EXPECT_EQ(ssao::jsCommentText("R = 0.5 (640x360)"), "R = 0.5 (640x360)");
    EXPECT_EQ(ssao::jsCommentText("a\xe2\x80\xa8" "b\nc\rd"), "a???b?c?d");
}
