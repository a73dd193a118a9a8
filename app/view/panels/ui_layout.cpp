#include "view/panels/ui_layout.h"

#include <algorithm>
#include <cmath>

namespace ssao {

namespace {

// Rows with these counts, row r's images 1/share[r] of the width, then all scaled alike to fit the
// height. Empty when nothing fits.
GridLayout rowsLayout(const std::vector<int>& counts, const std::vector<int>& share, float width, float height,
                      float aspect, float labelHeight, float gap) {
    GridLayout g;
    float imageHeights = 0;
    std::vector<float> widths;
    for (int k : share) {
        widths.push_back(std::max((width - gap * float(k)) / float(k), 0.0f));
        imageHeights += widths.back() / aspect;
    }
    const float spare = height - float(counts.size()) * (labelHeight + gap);
    if (spare <= 0 || imageHeights <= 0) return g;
    const float scale = std::min(1.0f, spare / imageHeights);
    g.columns = counts;
    float y = 0, area = 0;
    for (size_t r = 0; r < counts.size(); ++r) {
        const float w = widths[r] * scale, h = w / aspect;
        const float rowWidth = float(counts[r]) * (w + gap) - gap;
        for (int c = 0; c < counts[r]; ++c) {
            GridSlot s;
            s.x = (width - rowWidth) * 0.5f + float(c) * (w + gap);
            s.labelY = y;
            s.y = y + labelHeight;
            s.w = w;
            s.h = h;
            g.slots.push_back(s);
            area += w * h;
        }
        y += labelHeight + h + gap;
    }
    g.fill = area / (width * height);
    return g;
}

} // namespace

GridLayout gridLayout(int count, float width, float height, float aspect, float labelHeight, float gap) {
    GridLayout best;
    if (count <= 0 || !(width > 0) || !(height > 0) || !(aspect > 0)) return best;
    for (int rows = 1; rows <= count; ++rows) {
        // Uniform: every row as wide as a full one (the last may hold fewer).
        const int cols = (count + rows - 1) / rows;
        std::vector<int> uniform(size_t(rows), cols);
        uniform.back() = count - cols * (rows - 1);
        if (uniform.back() <= 0) continue;
        // Balanced: counts differ by one at most, the fuller rows (smaller images) first.
        std::vector<int> balanced(size_t(rows), count / rows);
        for (int r = 0; r < count % rows; ++r)
            ++balanced[size_t(r)];
        for (const auto& counts : {uniform, balanced}) {
            const std::vector<int> share = counts == uniform ? std::vector<int>(size_t(rows), cols) : counts;
            GridLayout g = rowsLayout(counts, share, width, height, aspect, labelHeight, gap);
            // Larger images win; within 1% the uniform grid (one size for every buffer) stays.
            if (!g.slots.empty() && g.fill > best.fill * (counts == uniform ? 1.0f : 1.01f)) best = std::move(g);
        }
    }
    return best;
}

std::vector<std::string> wrapWords(const std::string& text, float width, const MeasureText& measure) {
    std::vector<std::string> lines;
    for (size_t start = 0; start <= text.size();) {
        const size_t nl = std::min(text.find('\n', start), text.size());
        const std::string para = text.substr(start, nl - start);
        std::string line;
        size_t i = 0;
        while (i < para.size()) {
            const size_t end = std::min(para.find(' ', i), para.size());
            const std::string word = para.substr(i, end - i);
            const std::string joined = line.empty() ? word : line + " " + word;
            if (!line.empty() && measure(joined) > width) {
                lines.push_back(line);
                line = word;
            } else {
                line = joined;
            }
            i = end + 1;
        }
        lines.push_back(line);
        start = nl + 1;
    }
    return lines;
}

std::string fitLine(const std::string& text, float width, const MeasureText& measure, bool* cut,
                    const std::string& marker) {
    if (cut) *cut = false;
    if (measure(text) <= width) return text;
    if (cut) *cut = true;
    // A cut between "a" and ".." or ".." and "b" would leave half a range.
    auto inRange = [&](size_t at) {
        return (at >= 2 && text.compare(at - 2, 2, "..") == 0) || text.compare(at + 1, 2, "..") == 0;
    };
    // Whole groups first (a label's ranges are set apart by two spaces), then whole words outside
    // a range, then whole words (never ending on "..").
    for (int pass = 0; pass < 3; ++pass) {
        const std::string sep = pass == 0 ? "  " : " ";
        for (size_t at = text.rfind(sep); at != std::string::npos && at > 0; at = text.rfind(sep, at - 1)) {
            if ((pass == 1 && inRange(at)) || (pass == 2 && at >= 2 && text.compare(at - 2, 2, "..") == 0)) continue;
            std::string head = text.substr(0, at);
            while (!head.empty() && head.back() == ' ')
                head.pop_back();
            if (!head.empty() && measure(head + marker) <= width) return head + marker;
        }
    }
    for (size_t n = text.size(); n > 0; --n) // a single word too wide for the line
        if (measure(text.substr(0, n - 1) + marker) <= width) return text.substr(0, n - 1) + marker;
    return marker;
}

double clippedAxisTop(std::vector<double> values, double floor) {
    values.erase(std::remove_if(values.begin(), values.end(), [](double v) { return !std::isfinite(v); }),
                 values.end());
    if (values.empty()) return floor;
    std::sort(values.begin(), values.end());
    const double p90 = values[size_t(std::floor(0.9 * double(values.size() - 1)))];
    const double top = std::max(1.2 * p90, floor);
    return values.back() <= top ? std::max(values.back(), floor) : top;
}

} // namespace ssao
