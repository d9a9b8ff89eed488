#pragma once

// Every stage at once: the storyboard. Small multiples in reading order, a
// row or a grid, each cell a stage's own picture (the same display list as
// its picture alone, labels placed for the cell's size), under a header whose
// arrow comes from the view before and names the stage's matrix, over a
// footer giving one traced point's coordinates in that stage's space. Set
// 16 cm wide, its labels and headers are 8 pt, the rest 6 pt. The writers (SVG, PDF, PNG, TikZ) draw each cell's figure moved
// into its cell, then the overlay. No VTK, no Qt.

#include <string>
#include <vector>

#include "viewpipe/report/figure.hpp"

namespace viewpipe::report {

// Labels and headers take this share of the storyboard's width (8 pt of 16 cm),
// tick numbers, legends and footers smallTextSize of it (6 pt).
constexpr double kStoryboardLabelShare = 0.018;
double storyboardLabelSize(int widthPixels, double textScale);

struct StoryboardCell {
    int stage = 0;
    Box2 header, picture, footer; // pixels of the whole storyboard
};

// Where the pictures of `stages` go: the columns that give the pictures the
// most area near the single pictures' shape (16:9), each row's cells left to
// right. No cells where the size holds none.
struct StoryboardLayout {
    int width = 0, height = 0, columns = 0;
    double labelSize = 0; // pixels
    std::vector<StoryboardCell> cells;
};
StoryboardLayout layoutStoryboard(const std::vector<int>& stages, int width, int height, double labelSize);
// The same for a scene's `stages` tracing `traced`, its text (layout.labelSize) smaller than `labelSize`
// where a cell would cut its widest header (with its arrow) or footer (the traced point's coordinates),
// never under the size at 100 % (storyboardLabelSize(width, 1)); text measured by `measure`.
StoryboardLayout layoutStoryboard(const EvaluatedScene& scene, const std::vector<int>& stages, const Vec3<double>& traced,
                                  int width, int height, double labelSize, const FontMeasure& measure);

// A figure's lines and faces cut to a box (its picture): a storyboard's cell draws nothing on its
// neighbours in any format, SVG too, where Qt writes no clip region.
void cutShapesTo(Figure& figure, const Box2& box);

// The point a storyboard traces: the objects' first vertex, else the view volume's center.
Vec3<double> storyboardTracedPoint(const EvaluatedScene& scene);
// The traced point after stage k in that stage's coordinates, four significant digits:
// "(8, 16, 30)", with w where the stage leaves it other than 1 ("(1, 2, 3, w = 4)").
std::string tracedCoordinates(const EvaluatedScene& scene, const Vec3<double>& world, int k);

// The headers (the stage's number and matrix, after an arrow from the picture before where that
// is the stage before)
// and footers (the traced point's coordinates) as a flat figure over the whole storyboard,
// its lines `lineScale` as wide as a picture's at scale 1.
Figure storyboardOverlay(const EvaluatedScene& scene, const StoryboardLayout& layout, const Vec3<double>& traced,
                         const FontMeasure& measure, double lineScale);

// A storyboard to write: each cell's figure drawn in its picture box, then the overlay.
struct Storyboard {
    StoryboardLayout layout;
    std::vector<Figure> cells; // in layout.cells' order, each its picture box's size
    Figure overlay;
    std::string title; // the document's (accessible) name
};

} // namespace viewpipe::report
