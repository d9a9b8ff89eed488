#include "viewpipe/report/storyboard.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

#include "viewpipe/format.hpp"
#include "viewpipe/report/style.hpp"

namespace viewpipe::report {

double storyboardLabelSize(int widthPixels, double textScale)
{
    return exportLabelSize(widthPixels, textScale, kStoryboardLabelShare);
}

namespace {

// The room around and between the cells, in label sizes: the grid's margin, the gap an arrow
// crosses, the header's and the footer's height.
constexpr double kMargin = 0.5, kArrowGap = 1.2, kHeader = 1.6, kFooterLines = 1.5;

double footerHeight(double labelSize)
{
    return kFooterLines * smallTextSize(labelSize);
}

} // namespace

StoryboardLayout layoutStoryboard(const std::vector<int>& stages, int width, int height, double labelSize)
{
    const int pictures = int(stages.size());
    StoryboardLayout layout{width, height, 0, labelSize, {}};
    const double margin = kMargin * labelSize, gap = kArrowGap * labelSize, header = kHeader * labelSize,
                 footer = footerHeight(labelSize);
    double best = 0;
    int cellWidth = 0, pictureHeight = 0;
    for (int columns = 1; columns <= pictures; ++columns) {
        const int rows = (pictures + columns - 1) / columns;
        const int w = int((width - 2 * margin - gap * (columns - 1)) / columns);
        const int h = int((height - 2 * margin - margin * (rows - 1)) / rows - header - footer);
        if (w <= 0 || h <= 0)
            continue;
        // The largest 16:9 picture the cell holds: what a stage gets to show itself in.
        const double across = std::min(double(w), h * 16.0 / 9);
        if (across > best) {
            best = across;
            layout.columns = columns;
            cellWidth = w;
            pictureHeight = h;
        }
    }
    if (layout.columns == 0)
        return layout;
    for (int k = 0; k < pictures; ++k) {
        const int row = k / layout.columns, column = k % layout.columns;
        const double x = std::round(margin + column * (cellWidth + gap)),
                     y = std::round(margin + row * (header + pictureHeight + footer + margin));
        StoryboardCell cell;
        cell.stage = stages[std::size_t(k)];
        cell.header = {{x, y}, {x + cellWidth, std::round(y + header)}};
        cell.picture = {{x, cell.header.max.y()}, {x + cellWidth, cell.header.max.y() + pictureHeight}};
        cell.footer = {{x, cell.picture.max.y()}, {x + cellWidth, cell.picture.max.y() + footer}};
        layout.cells.push_back(cell);
    }
    return layout;
}

namespace {

// The header of a stage's cell: its number and matrix.
std::string headerText(const EvaluatedScene& scene, int stage)
{
    return stage == 0 ? "0. World"
                      : std::to_string(stage) + ". $" + stageSymbolMath(scene.pipeline.stages[std::size_t(stage - 1)].kind) + "$";
}

// An arrow's length before a header, and the room after it, in label sizes.
constexpr double kArrowLength = 1.6, kAfterArrow = 0.3;

// Sutherland–Hodgman: the part of a convex or concave polygon on the inner side of one edge of a box.
std::vector<Vec2<double>> clipPolygon(const std::vector<Vec2<double>>& polygon, int axis, double bound, bool below)
{
    std::vector<Vec2<double>> kept;
    const auto inside = [&](const Vec2<double>& p) { return below ? p[axis] <= bound : p[axis] >= bound; };
    for (std::size_t k = 0; k < polygon.size(); ++k) {
        const Vec2<double>& a = polygon[k];
        const Vec2<double>& b = polygon[(k + 1) % polygon.size()];
        if (inside(a))
            kept.push_back(a);
        if (inside(a) != inside(b))
            kept.push_back(a + (b - a) * ((bound - a[axis]) / (b[axis] - a[axis])));
    }
    return kept;
}

// Liang–Barsky: the part of segment ab inside the box, if any.
std::optional<std::pair<Vec2<double>, Vec2<double>>> clipSegment(const Vec2<double>& a, const Vec2<double>& b, const Box2& box)
{
    double enter = 0, leave = 1;
    const Vec2<double> d = b - a;
    for (int axis = 0; axis < 2; ++axis)
        for (const auto& [p, q] : {std::pair(-d[axis], a[axis] - box.min[axis]), std::pair(d[axis], box.max[axis] - a[axis])}) {
            if (p == 0) {
                if (q < 0)
                    return std::nullopt;
                continue;
            }
            const double t = q / p;
            if (p < 0)
                enter = std::max(enter, t);
            else
                leave = std::min(leave, t);
        }
    if (enter > leave)
        return std::nullopt;
    // The ends themselves where they are inside: a polyline's pieces join where its points are equal.
    return std::make_pair(enter == 0 ? a : Vec2<double>(a + enter * d), leave == 1 ? b : Vec2<double>(a + leave * d));
}

} // namespace

void cutShapesTo(Figure& figure, const Box2& box)
{
    std::vector<FigureShape> cut;
    for (FigureShape& shape : figure.shapes) {
        if (shape.surface) {
            for (int axis = 0; axis < 2 && !shape.points.empty(); ++axis) {
                shape.points = clipPolygon(shape.points, axis, box.min[axis], false);
                shape.points = clipPolygon(shape.points, axis, box.max[axis], true);
            }
            if (shape.points.size() >= 3)
                cut.push_back(std::move(shape));
            continue;
        }
        // A polyline in the pieces that stay inside, each a polyline of its own.
        FigureShape piece = shape;
        piece.points.clear();
        for (std::size_t k = 0; k + 1 < shape.points.size(); ++k) {
            const auto kept = clipSegment(shape.points[k], shape.points[k + 1], box);
            if (kept && !piece.points.empty() && piece.points.back() == kept->first) {
                piece.points.push_back(kept->second);
                continue;
            }
            if (piece.points.size() >= 2)
                cut.push_back(piece);
            piece.points.clear();
            if (kept)
                piece.points = {kept->first, kept->second};
        }
        if (piece.points.size() >= 2)
            cut.push_back(piece);
    }
    figure.shapes = std::move(cut);
}

Vec3<double> storyboardTracedPoint(const EvaluatedScene& scene)
{
    const std::vector<Vec3<double>> vertices = scene.objectVertices();
    if (!vertices.empty())
        return vertices.front();
    Vec3<double> center = Vec3<double>::Zero();
    for (const Vec3<double>& corner : scene.setup.volume)
        center += corner / double(scene.setup.volume.size());
    return center;
}

std::string tracedCoordinates(const EvaluatedScene& scene, const Vec3<double>& world, int k)
{
    const Vec4<double> p = k == 0 ? Vec4<double>(world.homogeneous())
                                  : tracePoint(scene.pipeline, world).afterStage[std::size_t(k - 1)];
    // What is zero but for the rounding of the stage's products reads 0.
    const double zero = 1e-12 * std::max(1.0, p.cwiseAbs().maxCoeff());
    const auto number = [&](double x) {
        const std::string text = formatSignificant(std::abs(x) <= zero ? 0 : x, 4);
        return text.front() == '-' ? "\u2212" + text.substr(1) : text;
    };
    std::string text = "(" + number(p.x()) + ", " + number(p.y()) + ", " + number(p.z());
    if (p.w() != 1)
        text += ", w = " + number(p.w());
    return text + ")";
}

StoryboardLayout layoutStoryboard(const EvaluatedScene& scene, const std::vector<int>& stages, const Vec3<double>& traced,
                                  int width, int height, double labelSize, const FontMeasure& measure)
{
    // The text smaller, never under its size at 100 %, until the widest header (with its arrow) and footer fit.
    const double floor = std::min(labelSize, storyboardLabelSize(width, 1));
    for (double size = labelSize;; size = std::max(floor, 0.95 * size)) {
        StoryboardLayout layout = layoutStoryboard(stages, width, height, size);
        double widest = 0;
        for (const int k : stages)
            widest = std::max({widest, (kArrowLength + kAfterArrow) * size + measure(headerText(scene, k), size, true).x(),
                               measure(tracedCoordinates(scene, traced, k), smallTextSize(size), false).x()});
        const bool fits = layout.cells.empty() || widest <= layout.cells.front().footer.max.x() - layout.cells.front().footer.min.x();
        if (fits || size == floor)
            return layout;
    }
}

Figure storyboardOverlay(const EvaluatedScene& scene, const StoryboardLayout& layout, const Vec3<double>& traced,
                         const FontMeasure& measure, double lineScale)
{
    Figure overlay;
    overlay.width = layout.width;
    overlay.height = layout.height;
    overlay.fontSize = layout.labelSize;
    overlay.lineScale = lineScale;
    const double size = layout.labelSize, small = smallTextSize(size), gap = kArrowGap * size;
    const auto label = [&](Element element, const std::string& text, const Vec2<double>& left, bool minor) {
        const Vec2<double> extent = measure(text, minor ? small : size, !minor);
        const Vec2<double> min(left.x(), left.y() - extent.y() / 2);
        overlay.labels.push_back({element, text, min, {min, min + extent}, false, minor});
    };
    for (std::size_t i = 0; i < layout.cells.size(); ++i) {
        const StoryboardCell& cell = layout.cells[i];
        const double middle = (cell.header.min.y() + cell.header.max.y()) / 2;
        double textLeft = cell.header.min.x();
        // An arrow from the picture before where that is the stage before: its matrix leads here.
        if (i > 0 && layout.cells[i - 1].stage == cell.stage - 1) {
            // Across the gap where the picture before is in the same row.
            const bool rowStart = i % std::size_t(layout.columns) == 0;
            const double from = rowStart ? cell.header.min.x() : cell.header.min.x() - 0.8 * gap,
                         tip = from + kArrowLength * size, head = 0.45 * size;
            const double width = lineWidthOf(Element::Frame, false) * overlay.lineScale; // as TikZ's style draws it
            overlay.shapes.push_back({Element::Frame, false, 1, width, {{from, middle}, {tip - head, middle}}, 0});
            overlay.shapes.push_back({Element::Frame, true, 1, 0,
                                      {{tip, middle}, {tip - head, middle - 0.45 * head}, {tip - head, middle + 0.45 * head}},
                                      0});
            textLeft = tip + kAfterArrow * size;
        }
        label(Element::Objects, headerText(scene, cell.stage), {textLeft, middle}, false);
        // Named where the footer has room for the name, the coordinates alone where it has not.
        const std::string coordinates = tracedCoordinates(scene, traced, cell.stage), named = "traced " + coordinates;
        const bool roomForName = measure(named, small, false).x() <= cell.footer.max.x() - cell.footer.min.x();
        label(Element::Traced, roomForName ? named : coordinates,
              {cell.footer.min.x(), (cell.footer.min.y() + cell.footer.max.y()) / 2}, true);
    }
    return overlay;
}

} // namespace viewpipe::report
