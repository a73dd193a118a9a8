// The explorer's layout at the sizes people open it (1280x720, 1920x1080): the first frame laid out
// as later ones, a buffer grid that fills its area with labels beside (not over) the images, lines
// that fit their panel, every preset listed with its description, '*' against the loaded preset,
// B's error beside A's in the split view; and the pure layout arithmetic behind it (ui_layout.h).
#include "gl_fixture.h"
#include "ui_driver.h"

#include "settings/preset_store.h"
#include "view/panels/ui_layout.h"

#include <chrono>
#include <functional>
#include <map>
#include <cmath>
#include <thread>

using namespace ssao;
using namespace ssaotest;

namespace {

const MeasureText kMono = [](const std::string& s) { return 7.0f * float(s.size()); };

bool overlaps(const ImVec4& a, const ImVec4& b) {
    return a.x < b.z && b.x < a.z && a.y < b.w && b.y < a.w;
}

// Every word of `text` is a word of exactly one line: nothing was cut inside a word or a number.
void expectWholeWords(const std::string& text, const std::vector<std::string>& lines) {
    std::string joined;
    for (const auto& l : lines)
        joined += (joined.empty() ? "" : " ") + l;
    EXPECT_EQ(joined, text);
}

} // namespace

// ---- Pure arithmetic ----

TEST(GridLayout, TenBuffersFillTheAreaAndNoRowIsMostlyEmpty) {
    // The view's area below the toolbar at 1280x720 and 1920x1080; the render has its aspect.
    for (const auto& [w, h] : {std::pair{852.0f, 436.0f}, std::pair{1492.0f, 796.0f}}) {
        const GridLayout g = gridLayout(10, w, h, w / h, 17.0f, 4.0f);
        ASSERT_EQ(g.slots.size(), 10u);
        EXPECT_GT(g.fill, 0.75f) << w << "x" << h << ": a uniform 4 x 3 grid shows 60%";
        size_t i = 0;
        for (int k : g.columns) {
            float used = 0;
            for (int c = 0; c < k; ++c)
                used += g.slots[i++].w;
            EXPECT_GT(used, 0.75f * w) << "a row of " << k << " is mostly empty";
        }
    }
}

TEST(GridLayout, SlotsStayInsideTheAreaApartAndNeverSmallerThanAUniformGrid) {
    for (int n = 1; n <= 12; ++n)
        for (float aspect : {1.0f, 1.78f, 2.4f})
            for (const auto& [w, h] : {std::pair{852.0f, 436.0f}, std::pair{600.0f, 900.0f}}) {
                const GridLayout g = gridLayout(n, w, h, aspect, 17.0f, 4.0f);
                ASSERT_EQ(int(g.slots.size()), n);
                float uniformBest = 0; // the largest images of a uniform grid of the same cells
                for (int cols = 1; cols <= n; ++cols) {
                    const int rows = (n + cols - 1) / cols;
                    const float cw = w / float(cols) - 4, ch = h / float(rows) - 4 - 17;
                    const float iw = std::min(cw, ch * aspect);
                    uniformBest = std::max(uniformBest, float(n) * iw * iw / aspect / (w * h));
                }
                EXPECT_GE(g.fill, uniformBest * 0.98f) << n << " at " << aspect;
                for (size_t a = 0; a < g.slots.size(); ++a) {
                    const GridSlot& s = g.slots[a];
                    EXPECT_NEAR(s.w / s.h, aspect, 1e-3);
                    EXPECT_GE(s.x, -1e-3f);
                    EXPECT_LE(s.x + s.w, w + 1e-3f);
                    EXPECT_GE(s.labelY, -1e-3f);
                    EXPECT_LE(s.y + s.h, h + 1e-3f);
                    EXPECT_LE(s.labelY + 17.0f, s.y + 1e-3f) << "the label line is above its image";
                    for (size_t b = a + 1; b < g.slots.size(); ++b) {
                        const GridSlot& o = g.slots[b];
                        EXPECT_FALSE(overlaps(ImVec4(s.x, s.labelY, s.x + s.w, s.y + s.h),
                                              ImVec4(o.x, o.labelY, o.x + o.w, o.y + o.h)))
                            << n << " slots " << a << " " << b;
                    }
                }
            }
}

TEST(TextLayout, WrapsOnlyBetweenWordsNeverInsideANumber) {
    const std::string status =
        "loaded builtin:showcase with preset vbao-medium; AO radius follows the scene: 0.05 x diagonal 17.23 = "
        "0.8617 units";
    for (float width : {60.0f, 150.0f, 290.0f, 400.0f}) {
        const auto lines = wrapWords(status, width, kMono);
        expectWholeWords(status, lines);
        for (const auto& l : lines)
            if (l.find(' ') != std::string::npos) {
                EXPECT_LE(kMono(l), width) << l;
            }
    }
    EXPECT_EQ(wrapWords("a b\nc", 1000.0f, kMono), (std::vector<std::string>{"a b", "c"}));
}

TEST(TextLayout, FitLineCutsBetweenWordsAndSaysSo) {
    const std::string label = "gbuffer.position  x -6.37..7.1  y -1.76..2.78  z -12.1..-3.09 scene units (fitted)";
    bool cut = true;
    EXPECT_EQ(fitLine(label, 1000.0f, kMono, &cut), label);
    EXPECT_FALSE(cut);
    for (float width : {100.0f, 200.0f, 290.0f, 400.0f}) {
        const std::string s = fitLine(label, width, kMono, &cut);
        EXPECT_TRUE(cut);
        EXPECT_LE(kMono(s), width) << s;
        ASSERT_GE(s.size(), 3u);
        EXPECT_EQ(s.substr(s.size() - 3), "...");
        const std::string head = s.substr(0, s.size() - 3);
        EXPECT_EQ(label.compare(0, head.size(), head), 0) << s;
        if (width >= 200.0f) {
            EXPECT_EQ(label[head.size()], ' ') << "cut at a space: " << s;
        }
    }
}

TEST(TextLayout, FitLineKeepsGroupsAndRangesWhole) {
    bool cut = false;
    const std::string position = "x -6.37..7.1  y -1.76..2.78  z -12.1..-3.09 scene units (fitted)";
    EXPECT_EQ(fitLine(position, kMono("x -6.37..7.1  y -1.76..2.78  z -12"), kMono, &cut, ""),
              "x -6.37..7.1  y -1.76..2.78")
        << "a whole axis or none";
    EXPECT_TRUE(cut);
    const std::string depth = "3.091 .. 12.12 scene units (fitted)";
    EXPECT_EQ(fitLine(depth, kMono("3.091 .. 12.12 scene u"), kMono, &cut, ""), "3.091 .. 12.12 scene");
    EXPECT_EQ(fitLine(depth, kMono("3.091 .. 12"), kMono, &cut, ""), "3.091") << "never \"3.091 ..\" nor \"12\" cut";
}

TEST(TextLayout, ClippedAxisSpreadsTheBulkAndLeavesAnOutlierAtTheEdge) {
    std::vector<double> rmse;
    for (int i = 0; i < 29; ++i)
        rmse.push_back(0.05 + 0.002 * i); // 0.05 .. 0.106
    EXPECT_NEAR(clippedAxisTop(rmse, 0.0), 0.106, 1e-9) << "no outlier: every point on the axis";
    rmse.push_back(0.9);
    rmse.push_back(std::nan(""));
    const double top = clippedAxisTop(rmse, 0.0);
    EXPECT_LT(top, 0.2) << "one outlier does not flatten the rest";
    EXPECT_GT(top, 0.1);
    EXPECT_EQ(clippedAxisTop({}, 0.01), 0.01);
    EXPECT_EQ(clippedAxisTop({0.001}, 0.01), 0.01) << "the floor (the reference's noise band) stays visible";
}

// ---- The window at the sizes people open it ----

namespace {

struct WindowSize {
    int w, h;
};

class AppLayout : public GlTest, public ::testing::WithParamInterface<WindowSize> {
  protected:
    void SetUp() override {
        GlTest::SetUp();
        AppOptions o;
        o.userPresetDir = std::string(SSAOLAB_TEST_TMP) + "/layout_presets";
        o.preset = kStartPreset; // as `ssaolab view` starts
        o.renderScale = 0.3f;
        o.reference = false;
        ui_ = std::make_unique<UiDriver>(o, GetParam().w, GetParam().h); // draws the first frame
    }
    void TearDown() override {
        ui_.reset();
        GlTest::TearDown();
    }
    AppCore& app() { return ui_->app(); }
    // One frame recording only what it drew.
    void freshFrame() {
        app().view().widgetRects.clear();
        ui_->frame();
    }
    // Frames (sleeping a little between) until `done`, at most `tries`.
    bool until(const std::function<bool()>& done, int tries = 1500) {
        for (int i = 0; i < tries; ++i) {
            freshFrame();
            if (done()) return true;
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
        }
        return false;
    }
    std::string tag() const { return std::to_string(GetParam().w) + "x" + std::to_string(GetParam().h); }
    std::unique_ptr<UiDriver> ui_;
};

std::string sizeName(const ::testing::TestParamInfo<WindowSize>& i) {
    return std::to_string(i.param.w) + "x" + std::to_string(i.param.h);
}

} // namespace

INSTANTIATE_TEST_SUITE_P(Sizes, AppLayout, ::testing::Values(WindowSize{1280, 720}, WindowSize{1920, 1080}),
                         sizeName);

TEST_P(AppLayout, TheFirstFrameHasTheTabsAndSaneTimingColumns) {
    // No frame drawn but the constructor's first one.
    for (const char* t : {"Parameters", "Scene & camera", "Presets", "Front"}) {
        const ImVec4 r = ui_->rect(std::string("tab#") + t);
        EXPECT_GT(r.z - r.x, ImGui::CalcTextSize(t).x) << t << " on the first frame";
        EXPECT_GT(r.w - r.y, ImGui::GetTextLineHeight() * 0.9f) << t;
    }
    const FrameDriver::Timing& full = app().frames().timing(false);
    char h1[48];
    std::snprintf(h1, sizeof h1, "full %dx%d", full.width, full.height);
    const std::string headers[3] = {"all passes", h1, "moving 0x0"};
    for (int c = 0; c < 3; ++c) {
        const ImVec4 r = ui_->rect("timing#col" + std::to_string(c));
        EXPECT_GT(r.z - r.x, ImGui::CalcTextSize(headers[c].c_str()).x) << "column " << c << " on the first frame";
    }
    ui_->save(std::string(SSAOLAB_TEST_TMP) + "/layout_first_" + tag() + ".png");
}

TEST_P(AppLayout, TheGridFillsItsAreaAndLabelsStayOffTheImages) {
    app().frames().referenceRays = 8;
    app().frames().referenceOn = true; // 10 buffers, as a new user sees them
    ui_->settle();
    freshFrame();
    const auto buffers = app().renderer().buffers();
    ASSERT_EQ(buffers.size(), 10u);
    const ImVec4 area = ui_->rect("view#grid");
    double imageArea = 0;
    std::map<float, float> rowWidth; // image widths by row (top y)
    for (const Resource* res : buffers) {
        const std::string& name = res->desc.name;
        const ImVec4 img = ui_->rect("view#" + name), label = ui_->rect("label#" + name);
        EXPECT_FALSE(overlaps(img, label)) << name << "'s label covers its image";
        EXPECT_GE(label.x, img.x - 0.5f) << name;
        EXPECT_LE(label.z, img.z + 0.5f) << name << "'s label runs past its cell";
        EXPECT_GE(img.x, area.x - 0.5f);
        EXPECT_LE(img.z, area.z + 0.5f);
        EXPECT_LE(img.w, area.w + 0.5f);
        imageArea += double(img.z - img.x) * double(img.w - img.y);
        rowWidth[std::round(img.y)] += img.z - img.x;
    }
    const double fill = imageArea / (double(area.z - area.x) * double(area.w - area.y));
    EXPECT_GT(fill, 0.62) << "images cover " << fill << " of the grid";
    for (const auto& [y, width] : rowWidth)
        EXPECT_GT(width, 0.75f * (area.z - area.x)) << "the row at y " << y << " is mostly empty";
    ui_->save(std::string(SSAOLAB_TEST_TMP) + "/layout_grid_" + tag() + ".png");
}

TEST_P(AppLayout, StatusAndStripLinesFitTheirPanels) {
    ui_->settle();
    freshFrame();
    const ImVec4 panel = ui_->rect("panel");
    const ImVec4 status = ui_->rect("status");
    EXPECT_LE(status.z, panel.z + 0.5f) << "the status line runs past the panel";
    const ImVec4 timing = ui_->rect("timing"), ran = ui_->rect("timing#ran");
    EXPECT_LE(ran.z, timing.z + 0.5f) << "'last change re-ran' runs past its column";
    EXPECT_GT(ran.w - ran.y, 0.0f);
}

TEST_P(AppLayout, PresetsTabListsEveryPresetWithItsDescription) {
    ui_->click("tab#Presets");
    freshFrame();
    ui_->save(std::string(SSAOLAB_TEST_TMP) + "/layout_presets_" + tag() + ".png");
    const ImVec4 panel = ui_->rect("panel"), list = ui_->rect("preset#list");
    EXPECT_GT(list.w - list.y, 0.5f * (panel.w - panel.y)) << "the list fills the tab";
    EXPECT_GE(app().presets().entries().size(), 30u);
    for (const PresetEntry& e : app().presets().entries()) {
        EXPECT_TRUE(ui_->has("preset#" + e.name)) << e.name;
        EXPECT_TRUE(ui_->has("preset#" + e.name + "#description")) << e.name;
        if (e.builtin) {
            EXPECT_FALSE(app().presetDescription(e).empty()) << e.name;
            EXPECT_EQ(app().presetDescription(e), app().presets().load(e.name).description) << e.name;
        }
    }
}

TEST_P(AppLayout, StarsCompareWithTheLoadedPresetAndResetGoesBackToIt) {
    ui_->frames(2);
    freshFrame();
    for (const auto& [key, r] : app().view().widgetRects)
        EXPECT_NE(key.rfind("changed#", 0), 0u) << key << " starred right after loading " << kStartPreset;
    const int slices = app().loadedPreset().settings.vbao.slices;
    app().settings().vbao.slices = slices + 1;
    freshFrame();
    ASSERT_TRUE(ui_->has("changed#vbao.slices"));
    ui_->click("vbao.slices#reset");
    EXPECT_EQ(app().settings().vbao.slices, slices) << "R goes back to the preset's value";
    EXPECT_FALSE(app().unsavedChanges());
}

TEST_P(AppLayout, SplitViewShowsBsErrorBesideAs) {
    app().frames().referenceRays = 8;
    app().frames().referenceOn = true;
    app().view().mode = ViewMode::Split;
    app().view().splitKind = SplitKind::Preset;
    app().view().splitPresetB = "gtao-low"; // another technique: its own AO, its own error
    app().frames().keepAwake();
    const bool shown = until([&] { return ui_->has("reference#rmse_b"); });
    ui_->save(std::string(SSAOLAB_TEST_TMP) + "/layout_split_" + tag() + ".png");
    ASSERT_TRUE(shown) << "no B column of errors";
    const auto& a = app().frames().reference().metrics();
    const auto& b = app().frames().reference().metricsB();
    ASSERT_TRUE(a && b);
    EXPECT_TRUE(std::isfinite(b->rmse) && b->rmse > 0);
    EXPECT_NE(a->rmse, b->rmse) << "B is judged on its own AO";
    const ImVec4 ra = ui_->rect("reference#rmse_a"), rb = ui_->rect("reference#rmse_b");
    EXPECT_NEAR(ra.y, rb.y, 0.5f) << "side by side";
    EXPECT_GT(rb.x, ra.x);
}
