// The explorer's layout arithmetic, free of ImGui so it is tested on the CPU: the buffer grid,
// text that wraps or shortens only between words (never inside a number), and the Front plot's
// error axis that one outlier cannot flatten.
#pragma once
#include <functional>
#include <string>
#include <vector>

namespace ssao {

// Where one buffer goes in the grid: its label line and, under it, its image (area coordinates).
struct GridSlot {
    float x = 0, y = 0, w = 0, h = 0; // the image
    float labelY = 0;                 // the label line's top (the line is labelHeight tall, image-wide)
};

struct GridLayout {
    std::vector<int> columns; // buffers per row, top row first
    std::vector<GridSlot> slots; // one per buffer, in order
    float fill = 0;              // image area / grid area
    int rows() const { return int(columns.size()); }
};

// `count` images of `aspect` (width / height) in a `width x height` area, each under a label line
// `labelHeight` tall, `gap` apart. Rows hold their own count of images (the counts differ by one
// at most, fuller rows first) and each row's images are as wide as the row allows, all scaled
// down alike when the rows do not fit the height: 10 buffers in a wide area take rows of 4, 3 and 3
// (80-90% of it) instead of a uniform 4 x 3 whose last row is half empty (60%). A uniform grid is
// kept when it shows the images larger.
GridLayout gridLayout(int count, float width, float height, float aspect, float labelHeight, float gap);

// Width of a string in pixels (ImGui::CalcTextSize in the app, a fixed advance in the tests).
using MeasureText = std::function<float(const std::string&)>;

// Lines of at most `width` broken at spaces only; a word wider than the width gets a line of its
// own (and overflows: the caller clips it and gives the full text in a tooltip). ImGui's own wrap
// also breaks after '.', splitting "0.8617" into "0." and "8617".
std::vector<std::string> wrapWords(const std::string& text, float width, const MeasureText& measure);

// `text` when it fits `width`, else its longest prefix that ends before a group (two spaces: a
// label's "x a..b  y c..d") or else before a word, never inside "a .. b", with `marker` appended;
// a first word that alone is too wide is cut where it must. `cut` (when given) says whether
// anything was left off.
std::string fitLine(const std::string& text, float width, const MeasureText& measure, bool* cut = nullptr,
                    const std::string& marker = "...");

// The top of an error axis for `values` (non-finite ones ignored) that keeps the bulk spread out:
// 1.2 x the 90th percentile (at least `floor`); all of them when the largest is within that.
// Points above it are drawn as markers at the plot's edge.
double clippedAxisTop(std::vector<double> values, double floor);

} // namespace ssao
