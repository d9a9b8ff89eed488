#include "viewpipe/report/figure.hpp"

#include "viewpipe/format.hpp"
#include "viewpipe/math_text.hpp"
#include "viewpipe/report/style.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <sstream>
#include <tuple>

namespace viewpipe::report {
namespace {

using Vec2d = Vec2<double>;
using Vec3d = Vec3<double>;
using Vec4d = Vec4<double>;

// Objects with more vertices than this are outlined by their box's corners.
constexpr std::size_t kExactOutline = 20000;

// Keeps the part of a polygon (or, open, a polyline) where plane . p >= 0, in homogeneous coordinates.
std::vector<Vec4d> clipPolygon(const std::vector<Vec4d>& points, const Vec4d& plane, bool closed)
{
    std::vector<Vec4d> kept;
    const std::size_t n = points.size();
    const std::size_t edges = closed ? n : n - 1;
    if (n == 0)
        return kept;
    if (!closed && plane.dot(points[0]) >= 0)
        kept.push_back(points[0]);
    for (std::size_t k = 0; k < edges; ++k) {
        const Vec4d& a = points[k];
        const Vec4d& b = points[(k + 1) % n];
        const double da = plane.dot(a), db = plane.dot(b);
        if ((da >= 0) != (db >= 0))
            kept.push_back(a + (b - a) * (da / (da - db)));
        if (db >= 0)
            kept.push_back(b);
    }
    return kept;
}

} // namespace

// Andrew's monotone chain.
std::vector<Vec2d> convexHull(std::vector<Vec2d> points)
{
    std::sort(points.begin(), points.end(),
              [](const Vec2d& a, const Vec2d& b) { return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y()); });
    if (points.size() < 3)
        return points;
    auto cross = [](const Vec2d& o, const Vec2d& a, const Vec2d& b) {
        return (a - o).x() * (b - o).y() - (a - o).y() * (b - o).x();
    };
    std::vector<Vec2d> hull(2 * points.size());
    std::size_t k = 0;
    for (std::size_t i = 0; i < points.size(); ++i) {
        while (k >= 2 && cross(hull[k - 2], hull[k - 1], points[i]) <= 0)
            --k;
        hull[k++] = points[i];
    }
    for (std::size_t i = points.size() - 1, t = k + 1; i > 0; --i) {
        while (k >= t && cross(hull[k - 2], hull[k - 1], points[i - 1]) <= 0)
            --k;
        hull[k++] = points[i - 1];
    }
    hull.resize(k - 1);
    return hull;
}

namespace {

bool segmentCrossesBox(const Segment2& s, const Box2& box)
{
    // Liang-Barsky: the part of the segment inside the box is not empty.
    const Vec2d d = s[1] - s[0];
    double t0 = 0, t1 = 1;
    for (int axis = 0; axis < 2; ++axis) {
        for (const double side : {-1.0, 1.0}) {
            const double p = side * d[axis];
            const double q = side < 0 ? s[0][axis] - box.min[axis] : box.max[axis] - s[0][axis];
            if (p == 0) {
                if (q < 0)
                    return false;
            } else {
                const double t = q / p;
                if (p < 0)
                    t0 = std::max(t0, t);
                else
                    t1 = std::min(t1, t);
            }
        }
    }
    return t0 <= t1;
}

// Two segments cross at a point more than `margin` pixels from each one's ends
// (leaders from one anchor, or meeting end to end, do not cross).
bool segmentsCross(const Segment2& a, const Segment2& b, double margin)
{
    const Vec2d r = a[1] - a[0], s = b[1] - b[0], q = b[0] - a[0];
    const double d = r.x() * s.y() - r.y() * s.x();
    if (std::abs(d) < 1e-12 * r.norm() * s.norm())
        return false; // parallel
    const double t = (q.x() * s.y() - q.y() * s.x()) / d, u = (q.x() * r.y() - q.y() * r.x()) / d;
    const double ta = margin / r.norm(), ub = margin / s.norm();
    return t > ta && t < 1 - ta && u > ub && u < 1 - ub;
}

// Whether a point lies in a convex polygon (counter-clockwise where y runs up).
bool insideConvex(const Vec2d& p, const std::vector<Vec2d>& polygon)
{
    if (polygon.size() < 3)
        return false;
    for (std::size_t k = 0; k < polygon.size(); ++k) {
        const Vec2d a = polygon[k], b = polygon[(k + 1) % polygon.size()];
        if ((b - a).x() * (p - a).y() - (b - a).y() * (p - a).x() < 0)
            return false;
    }
    return true;
}

// The share of a box's area inside a convex polygon, sampled on a 5 x 5 grid.
double shareInside(const Box2& box, const std::vector<Vec2d>& polygon)
{
    int inside = 0;
    for (int i = 0; i < 5; ++i)
        for (int j = 0; j < 5; ++j)
            inside += insideConvex(Vec2d(box.min.x() + (i + 0.5) / 5 * (box.max.x() - box.min.x()),
                                         box.min.y() + (j + 0.5) / 5 * (box.max.y() - box.min.y())),
                                   polygon);
    return inside / 25.0;
}

// A polygon or segment through the stage and the camera, in pixels with a depth each (larger: farther).
// What the painter cuts away is cut (`cuttable`: all but the canonical outline and the fixed axes), and what
// lies behind the stage's eye or the camera's near plane has no image.
std::vector<Vec3d> throughView(const StageShown& stage, const FigureView& view, const Mat4<double>& matrix,
                               const std::vector<Vec3d>& points, bool closed, bool cuttable)
{
    std::vector<Vec4d> h;
    h.reserve(points.size());
    for (const Vec3d& p : points)
        h.push_back(p.homogeneous());
    if (cuttable && stage.cut)
        h = clipPolygon(h, *stage.cut, closed);
    if (isProjective(matrix)) { // w > 0, a little more so that the divide stays finite
        const Vec4d w = matrix.row(3).transpose();
        h = clipPolygon(h, w - 1e-9 * w.norm() * Vec4d::UnitW(), closed);
    }
    for (Vec4d& p : h) {
        const Vec4d q = matrix * p;
        p = Vec4d(q.x() / q.w(), q.y() / q.w(), q.z() / q.w(), 1);
    }
    h = clipPolygon(h, (view.camera.row(2) + view.camera.row(3)).transpose(), closed); // z >= -w
    std::vector<Vec3d> pixels;
    pixels.reserve(h.size());
    for (const Vec4d& p : h)
        if (const std::optional<Vec3d> px = view.pixel(p.head<3>()))
            pixels.push_back(*px);
    return pixels;
}

std::vector<Vec2d> flat(const std::vector<Vec3d>& pixels)
{
    std::vector<Vec2d> points;
    points.reserve(pixels.size());
    for (const Vec3d& p : pixels)
        points.push_back(p.head<2>());
    return points;
}

double meanDepth(const std::vector<Vec3d>& pixels)
{
    double sum = 0;
    for (const Vec3d& p : pixels)
        sum += p.z();
    return sum / double(pixels.size());
}


} // namespace

FontMeasure lineByLine(RunsMeasure measure)
{
    return [measure = std::move(measure)](const std::string& text, double pixels, bool bold) {
        Vec2<double> size = Vec2<double>::Zero();
        std::istringstream lines(text);
        std::string line;
        for (int k = 0; std::getline(lines, line); ++k) {
            const Vec2<double> measured = measure(mathRuns(line), pixels, bold);
            size.x() = std::max(size.x(), measured.x());
            size.y() = k == 0 ? measured.y() : size.y() + 1.25 * pixels;
        }
        return size;
    };
}

LabelMeasure labelMeasure(const FontMeasure& measure, double fontSize)
{
    return [measure, fontSize](const Label& label) {
        return label.minor ? measure(label.text, smallTextSize(fontSize), false) : measure(label.text, fontSize, true);
    };
}

std::vector<std::string> wrapLines(const std::string& text, double width, const TextMeasure& measure)
{
    std::vector<std::string> wrapped;
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);) {
        std::string current;
        for (const std::string& word : mathTextWords(line)) { // a formula stays on one line
            const std::string longer = current.empty() ? word : current + " " + word;
            if (current.empty() || measure(longer).x() <= width) {
                current = longer;
            } else {
                wrapped.push_back(current);
                current = word;
            }
        }
        wrapped.push_back(current);
    }
    return wrapped;
}

std::array<Vec3d, 2> frameAxis(const Eigen::AlignedBox<double, 3>& extent, int axis)
{
    const Vec3d along = Vec3d::Unit(axis);
    return {extent.min()[axis] * along, extent.max()[axis] * along};
}

FrameMarks frameMarks(const Eigen::AlignedBox<double, 3>& extent, bool ticks)
{
    FrameMarks marks;
    const double reach = extent.isEmpty() ? 0 : extent.sizes().maxCoeff();
    if (!(reach > 0))
        return marks;
    // Ticks at a round step (1, 2 or 5 times a power of ten), five or six along the longest axis.
    const double rough = reach / 6;
    const int exponent = int(std::floor(std::log10(rough)));
    const double power = std::pow(10.0, exponent);
    const int mantissa = rough >= 5 * power ? 5 : rough >= 2 * power ? 2 : 1;
    const double step = mantissa * power;
    // Tick j's number, j * mantissa over a power of ten where that is a fraction: the double nearest the
    // decimal (3 * 0.2 is 0.6000000000000001).
    auto tick = [&](int j) { return exponent >= 0 ? j * step : double(j * mantissa) / std::pow(10.0, -exponent); };
    const char* names[] = {"$x$", "$y$", "$z$"};
    for (int axis = 0; axis < 3; ++axis) {
        const Vec3d along = Vec3d::Unit(axis), across = Vec3d::Unit(axis == 0 ? 1 : 0);
        const auto [from, to] = frameAxis(extent, axis);
        if (from == to)
            continue;
        marks.lines.insert(marks.lines.end(), {from, to});
        marks.labels.push_back({Element::Frame, names[axis], to, true});
        const double low = extent.min()[axis], high = extent.max()[axis];
        for (int j = int(std::ceil(low / step * 0.999)); ticks && step * j <= 0.999 * high; ++j) {
            if (j == 0)
                continue;
            const Vec3d at = tick(j) * along;
            marks.lines.insert(marks.lines.end(), {at - 0.01 * reach * across, at + 0.01 * reach * across});
            marks.labels.push_back({Element::Frame, "$" + formatShortest(tick(j)) + "$", at, true, true}); // a real minus sign
        }
    }
    return marks;
}

std::vector<const LegendEntry*> legendShown(const std::vector<LegendEntry>& entries, bool canonicalShown)
{
    std::vector<const LegendEntry*> shown;
    for (const LegendEntry& entry : entries)
        if (entry.element != Element::Canonical || canonicalShown)
            shown.push_back(&entry);
    return shown;
}

LegendLayout legendLayout(const std::vector<const LegendEntry*>& entries, double labelSize, const FontMeasure& measure)
{
    LegendLayout rows;
    rows.textSize = smallTextSize(labelSize);
    double textWidth = 0, textHeight = 0;
    for (const LegendEntry* entry : entries) {
        const Vec2<double> size = measure(entry->text, rows.textSize, false);
        textWidth = std::max(textWidth, size.x());
        textHeight = std::max(textHeight, size.y());
    }
    rows.rowHeight = std::ceil(1.3 * textHeight);
    rows.swatchWidth = 3 * textHeight;
    rows.padding = std::max(3.0, std::floor(labelSize / 4));
    if (!entries.empty())
        rows.size = Vec2<double>(textWidth + rows.swatchWidth + 2 * rows.padding + 2,
                                 double(entries.size()) * rows.rowHeight + 2 * rows.padding);
    return rows;
}

PictureText stagePictureText(const StageShown& stage, const std::string& caption, double fontSize, double minFontSize,
                             std::vector<Vec2<double>> subject, std::vector<Vec2<double>> shown, LegendPlace legendPlace)
{
    PictureText text;
    text.subject = std::move(subject);
    text.shown = std::move(shown);
    text.legendPlace = legendPlace;
    text.fontSize = fontSize;
    text.minFontSize = minFontSize;
    text.caption = caption;
    text.note = stage.scene->effectsNote;
    text.legend = legendShown(stage.scene->worldLegend, stage.canonicalOpacity > 0);
    return text;
}

std::vector<Box2> textBoxes(const PictureLayout& layout)
{
    std::vector<Box2> boxes = {layout.caption, layout.note};
    if (!layout.legend.isEmpty())
        boxes.push_back(layout.legend);
    return boxes;
}

std::vector<Box2> textBackdrops(const Box2& caption, const Box2& note, const Box2& legend, int height)
{
    std::vector<Box2> backdrops;
    if (!caption.isEmpty())
        backdrops.push_back({Vec2d::Zero(), caption.max});
    if (!note.isEmpty())
        backdrops.push_back({Vec2d(0, note.min.y()), Vec2d(note.max.x(), height)});
    if (!legend.isEmpty())
        backdrops.push_back(legend);
    return backdrops;
}

std::vector<Box2> textBackdrops(const PictureLayout& layout, int height)
{
    return textBackdrops(layout.caption, layout.note, layout.legend, height);
}

namespace {

// Whether a box and a convex polygon share any point.
bool boxMeetsPolygon(const Box2& box, const std::vector<Vec2d>& polygon)
{
    if (polygon.empty())
        return false;
    for (const Vec2d& p : polygon)
        if (box.contains(Box2{p, p}))
            return true;
    for (std::size_t k = 0; k < polygon.size(); ++k)
        if (segmentCrossesBox({polygon[k], polygon[(k + 1) % polygon.size()]}, box))
            return true;
    return insideConvex(box.min, polygon); // the box within the polygon
}

} // namespace

const std::vector<LegendPlace>& legendPlaces()
{
    static const std::vector<LegendPlace> places = {LegendPlace::Best, LegendPlace::Beside, LegendPlace::Below,
                                                    LegendPlace::Inside, LegendPlace::None};
    return places;
}

const char* legendPlaceTitle(LegendPlace place)
{
    switch (place) {
    case LegendPlace::Best: return "where it costs the subject least";
    case LegendPlace::Beside: return "beside the stage";
    case LegendPlace::Below: return "below the stage";
    case LegendPlace::Inside: return "inside, in a corner the subject leaves free";
    case LegendPlace::None: return "none";
    }
    return "";
}

const char* legendPlaceName(LegendPlace place)
{
    switch (place) {
    case LegendPlace::Best: return "best";
    case LegendPlace::Beside: return "beside";
    case LegendPlace::Below: return "below";
    case LegendPlace::Inside: return "inside";
    case LegendPlace::None: return "none";
    }
    return "";
}

std::optional<LegendPlace> legendPlaceNamed(const std::string& name)
{
    for (const LegendPlace place : legendPlaces())
        if (name == legendPlaceName(place))
            return place;
    return std::nullopt;
}

PictureLayout layoutPicture(int width, int height, const PictureText& text, const FontMeasure& measure)
{
    PictureLayout layout;
    const double left = 0.02 * width, margin = std::max(4.0, text.fontSize / 2);
    auto place = [&](const std::string& t, double size, bool bold, double x, double room, double& line, bool fromBottom) {
        const TextMeasure at = [&](const std::string& s) { return measure(s, size, bold); };
        std::vector<std::string> lines = t.empty() ? std::vector<std::string>{} : wrapLines(t, room, at);
        std::string joined;
        for (const std::string& l : lines)
            joined += (joined.empty() ? "" : "\n") + l;
        const Vec2<double> extent = lines.empty() ? Vec2<double>::Zero() : at(joined); // as drawn, all lines
        line = lines.size() > 1 ? (extent.y() - at("Ag").y()) / double(lines.size() - 1) : 0;
        const double top = fromBottom ? 0.98 * height - extent.y() : 0.04 * height;
        return std::pair{lines, Box2{Vec2<double>(x, top), Vec2<double>(x + extent.x(), top + extent.y())}};
    };
    auto roomy = [&](const Box2& scene) {
        return scene.max.x() - scene.min.x() >= 0.4 * width && scene.max.y() - scene.min.y() >= 0.4 * height;
    };
    // The subject's outline and the box about it, as the text's layout sees it.
    Eigen::AlignedBox<double, 2> outline;
    for (const Vec2d& p : text.subject)
        outline.extend(p);
    const bool subjectKnown = !outline.isEmpty() && (outline.sizes().array() > 0).all();
    // How large the subject draws in a room (its scale), or, not knowing it, how large the room is.
    auto scaleIn = [&](const Box2& room) {
        if (room.isEmpty())
            return 0.0;
        const Vec2d size = room.max - room.min;
        return subjectKnown ? size.cwiseQuotient(outline.sizes()).minCoeff() : size.prod();
    };
    // What the picture shows of the subject as the camera fits the subject in a room (centred, 0.95 of the
    // way to the nearer edges), grown by a little for the camera's perspective, which the outline (seen
    // from afar) leaves out.
    auto subjectIn = [&](const Box2& room) {
        const double scale = 0.95 * text.zoom * scaleIn(room), grow = 0.04 * (room.max - room.min).minCoeff();
        const Vec2d center = (room.min + room.max) / 2;
        std::vector<Vec2d> drawn;
        for (const Vec2d& p : text.shown.empty() ? text.subject : text.shown) {
            const Vec2d offset = scale * (p - outline.center());
            drawn.push_back(center + offset + grow * offset.normalized());
        }
        return drawn;
    };

    std::vector<double> sizes; // largest first
    for (double size = text.fontSize; size > text.minFontSize && size >= 1 && sizes.size() < 30; size = std::floor(0.9 * size))
        sizes.push_back(size);
    sizes.push_back(std::max(1.0, std::min(text.fontSize, text.minFontSize)));
    // The legend beside the stage (top right), below it (bottom right), or inside the stage's room in a
    // corner the subject leaves free: where asked, else where the subject draws largest.
    const std::vector<LegendPlace> anywhere =
        subjectKnown ? std::vector<LegendPlace>{LegendPlace::Beside, LegendPlace::Below, LegendPlace::Inside}
                     : std::vector<LegendPlace>{LegendPlace::Beside, LegendPlace::Below};
    std::vector<LegendPlace> places = text.legendPlace == LegendPlace::Best ? anywhere : std::vector<LegendPlace>{text.legendPlace};
    // Beside, the legend may stand in a column with the caption, the note at the column's foot or at the stage's.
    enum class Column { None, NoteInColumn, NoteUnderStage };
    // At one size, the legend put at `where` (beside: in a column with the caption, where `column` says): the
    // layout, or none where it does not fit.
    auto arrange = [&](double size, LegendPlace where, Column column, const LegendLayout& rows, double bottom) -> std::optional<PictureLayout> {
        PictureLayout l = layout;
        l.legendRows = rows;
        l.legend = {};
        l.legendAt = where;
        const Vec2d legendSize = rows.size;
        const double legendLeft = width - margin - legendSize.x();
        if (where == LegendPlace::Beside && column != Column::None) {
            // The caption, the legend under it and the note at their foot in a column at the left as wide
            // as the legend, the stage right of them at the picture's whole height: where the subject is
            // tall, it draws larger there. Where the caption is long, the note may stand at the stage's foot
            // instead, leaving the column its height.
            const double room = std::max(legendSize.x(), 0.3 * width), stageLeft = left + room + margin;
            const bool noteUnderStage = column == Column::NoteUnderStage;
            std::tie(l.captionLines, l.caption) = place(text.caption, size, true, left, room, l.captionLine, false);
            std::tie(l.noteLines, l.note) = noteUnderStage
                                                ? place(text.note, l.noteSize, false, stageLeft, 0.98 * width - stageLeft, l.noteLine, true)
                                                : place(text.note, l.noteSize, false, left, room, l.noteLine, true);
            const double noteTop = l.noteLines.empty() ? height : l.note.min.y();
            const Vec2d top(left, l.caption.max.y() + 0.6 * size);
            l.legend = {top, top + legendSize};
            l.scene = {Vec2d(stageLeft, margin), Vec2d(width, (noteUnderStage ? noteTop : height) - margin)};
            const double foot = (noteUnderStage ? height : noteTop) - margin;
            return l.legend.max.y() <= foot && roomy(l.scene) ? std::optional<PictureLayout>(l) : std::nullopt;
        }
        // The caption beside a legend at the top right where that leaves it half the width and two lines at most.
        bool captionBeside = where == LegendPlace::Beside && legendLeft - margin - left >= 0.5 * width;
        std::tie(l.captionLines, l.caption) =
            place(text.caption, size, true, left, captionBeside ? legendLeft - margin - left : 0.96 * width, l.captionLine, false);
        if (captionBeside && l.captionLines.size() > 2) {
            std::tie(l.captionLines, l.caption) = place(text.caption, size, true, left, 0.96 * width, l.captionLine, false);
            captionBeside = false;
        }
        const Box2 full{Vec2d(0, l.caption.max.y() + margin), Vec2d(width, bottom)};
        switch (where) {
        case LegendPlace::Best:
        case LegendPlace::None:
            l.scene = full;
            return l;
        case LegendPlace::Beside: {
            const double top = captionBeside ? 0.04 * height + 1.6 * size : l.caption.max.y() + 0.6 * size;
            l.legend = {Vec2d(legendLeft, top), Vec2d(width - margin, top + legendSize.y())};
            l.scene = {full.min, Vec2d(legendLeft - margin, bottom)};
            break;
        }
        case LegendPlace::Below:
            l.legend = {Vec2d(legendLeft, bottom - legendSize.y()), Vec2d(width - margin, bottom)};
            l.scene = {full.min, Vec2d(width, l.legend.min.y() - margin)};
            break;
        case LegendPlace::Inside: {
            l.scene = full;
            const std::vector<Vec2d> subject = subjectIn(full);
            const Box2 inner = full.grown(-margin);
            l.legend = {};
            for (const Vec2d& corner : {Vec2d(1, 0), Vec2d(1, 1), Vec2d(0, 1), Vec2d(0, 0)}) { // top right first
                const Vec2d at = inner.min + corner.cwiseProduct(inner.max - inner.min - legendSize);
                const Box2 box{at, at + legendSize};
                if (!boxMeetsPolygon(box.grown(margin), subject)) {
                    l.legend = box;
                    break;
                }
            }
            if (l.legend.isEmpty())
                return std::nullopt; // no corner free: not inside, even where asked (it covered the subject)
            break;
        }
        }
        const bool fits = l.legend.min.x() >= left && l.legend.min.y() >= 0 && l.legend.max.y() <= bottom + 1e-9 &&
                          roomy(l.scene);
        return fits ? std::optional<PictureLayout>(l) : std::nullopt;
    };
    // The largest size at which the caption takes at most 30 % of the height and the legend fits with room
    // left for the stage; at the smallest, the caption as it falls. Where the legend fits at no size, none.
    auto attempt = [&](bool withLegend) {
        for (std::size_t k = 0; k < sizes.size(); ++k) {
            const double size = sizes[k];
            layout.captionSize = size;
            layout.noteSize = smallTextSize(size); // the note no larger than the caption's lines
            std::tie(layout.noteLines, layout.note) = place(text.note, layout.noteSize, false, left, 0.96 * width, layout.noteLine, true);
            const double bottom = (layout.noteLines.empty() ? height : layout.note.min.y()) - margin;
            const LegendLayout rows = legendLayout(withLegend ? text.legend : std::vector<const LegendEntry*>{}, size, measure);
            std::optional<PictureLayout> best;
            for (const LegendPlace where : withLegend ? places : std::vector<LegendPlace>{LegendPlace::None})
                for (const Column column : {Column::None, Column::NoteInColumn, Column::NoteUnderStage})
                    if (column == Column::None || (subjectKnown && where == LegendPlace::Beside))
                        if (std::optional<PictureLayout> l = arrange(size, where, column, rows, bottom);
                            l && (!best || scaleIn(l->scene) > scaleIn(best->scene)))
                            best = std::move(l);
            if (!best)
                continue;
            // Beside the stage, the caption takes none of its height.
            const bool captionFits = best->caption.max.y() - best->caption.min.y() <= 0.3 * height || best->scene.min.x() > best->caption.max.x();
            if (captionFits || k + 1 == sizes.size()) {
                layout = std::move(*best);
                return true;
            }
        }
        return false;
    };
    // A legend that fits nowhere at any size is left out; one that does not fit where asked goes where it fits.
    const bool placed = !text.legend.empty() && text.legendPlace != LegendPlace::None &&
                        (attempt(true) || (places != anywhere && (places = anywhere, attempt(true))));
    if (!placed)
        attempt(false);
    if (!(layout.scene.max.x() - layout.scene.min.x() > 0.2 * width && layout.scene.max.y() - layout.scene.min.y() > 0.2 * height))
        layout.scene = {Vec2<double>::Zero(), Vec2<double>(width, height)}; // no room apart: the whole picture
    return layout;
}

double labelSizeIn(const PictureLayout& layout, double fontSize)
{
    return layout.captionSize > 0 ? std::min(fontSize, layout.captionSize) : fontSize;
}

const PictureLayout& PictureLayoutCache::layout(int width, int height, const PictureText& text, const FontMeasure& measure)
{
    std::vector<std::string> legend; // the entries' texts: a new scene's entries may reuse an old one's addresses
    for (const LegendEntry* entry : text.legend)
        legend.push_back(entry->text);
    auto key = std::make_tuple(width, height, text.fontSize, text.minFontSize, text.caption, text.note, std::move(legend),
                               text.subject, text.shown, text.legendPlace, text.zoom);
    if (key_ != key) {
        layout_ = layoutPicture(width, height, text, measure);
        key_ = std::move(key);
    }
    return layout_;
}

LegendRow legendRow(const PictureLayout& layout, std::size_t k)
{
    const LegendLayout& rows = layout.legendRows;
    LegendRow row;
    const double top = layout.legend.min.y() + rows.padding + double(k) * rows.rowHeight;
    row.row = {Vec2<double>(layout.legend.min.x(), top), Vec2<double>(layout.legend.max.x(), top + rows.rowHeight)};
    row.textHeight = rows.swatchWidth / 3;
    row.swatchCenter = Vec2<double>(layout.legend.min.x() + rows.padding + rows.swatchWidth / 2,
                                    top + rows.rowHeight / 2 + 0.25 * row.textHeight);
    row.textLeft = layout.legend.min.x() + rows.padding + rows.swatchWidth;
    return row;
}

StageShown::StageShown(const EvaluatedScene& evaluated, const Mat4<double>& matrix, double opacity)
    : scene(&evaluated), cumulative(matrix), canonicalOpacity(opacity)
{
    if (evaluated.nearCut && isProjective(matrix))
        cut = evaluated.nearCut;
}

bool StageShown::shows(const Vec3<double>& world) const
{
    return !(cut && cut->dot(world.homogeneous()) < 0) && projectPoint(cumulative, world).has_value();
}

bool StageShown::ghosted(const Primitive& primitive)
{
    return primitive.kind == PrimitiveKind::Lines && !primitive.canonical &&
           (primitive.element == Element::Objects || primitive.element == Element::Volume);
}

bool StageShown::draws(const Primitive& primitive) const
{
    return !primitive.canonical || canonicalOpacity > 0;
}

const Mat4<double>& StageShown::matrixOf(const Primitive& primitive) const
{
    static const Mat4<double> identity = Mat4<double>::Identity();
    return primitive.canonical ? identity : cumulative;
}

std::optional<Vec3<double>> FigureView::pixel(const Vec3<double>& stagePoint) const
{
    const Vec4d c = camera * stagePoint.homogeneous();
    if (!inFrontOfEye(c))
        return std::nullopt;
    const Vec3d ndc = c.head<3>() / c.w();
    return Vec3d((ndc.x() + 1) / 2 * width, (1 - ndc.y()) / 2 * height, ndc.z());
}

double lineWidthOf(Element element, bool surface)
{
    if (surface)
        return 1;
    const bool emphasised = element == Element::WorldAxes || element == Element::ViewAxes ||
                            element == Element::Canonical || element == Element::Dop ||
                            element == Element::ZFighting;
    return emphasised ? 3.5 : 2.0;
}

double lineWidthOf(const Primitive& primitive)
{
    const bool surface = primitive.kind == PrimitiveKind::Faces;
    return lineWidthOf(primitive.element, surface) * (surface ? 1 : primitive.widthScale);
}

std::vector<std::optional<PlacedLabel>> placeLabels(const std::vector<LabelRequest>& requests,
                                                    const LabelObstacles& obstacles, int width, int height)
{
    constexpr double kPadding = 5; // between labels, and from the picture's edge
    // Beside other text, at least this share of a label's height: a space for names; for tick numbers
    // two (numbers have no letters' shapes to part them: "200" and "150" a space apart read "200150").
    constexpr double kWordSpace = 0.3, kNumberSpace = 0.6;
    constexpr double kAxisClearance = 2; // pixels between a tick number and its axis, drawn 2 wide
    const Box2 picture{Vec2d::Constant(kPadding), Vec2d(width - kPadding, height - kPadding)};
    // Directions to try, the customary up-right first.
    const std::array<Vec2d, 8> directions = {{{1, -1}, {1, 0}, {1, 1}, {0, -1}, {-1, -1}, {-1, 0}, {-1, 1}, {0, 1}}};
    const std::array<double, 6> distances = {4, 24, 48, 80, 130, 200}; // pixels; from the second on, with a leader
    const double farthest = 0.3 * std::hypot(width, height); // a leader longer than this would pile labels up
    std::vector<std::optional<PlacedLabel>> placed(requests.size());

    auto cost = [&](const Box2& box) {
        double c = 0;
        const Box2 clear = box.grown(1);
        for (const Segment2& line : obstacles.lines)
            c += segmentCrossesBox(line, clear) ? 2 : 0;
        for (const std::vector<Vec2d>& object : obstacles.objects)
            c += 6 * shareInside(box, object);
        return c;
    };
    std::vector<Segment2> leaders; // of the labels placed so far
    // The boxes taken (the reserved ones first, then each label's), grown by the padding (no label within) and by a pixel (no leader through);
    // grown as each is taken (made again only when a label placed before moves), as the crowded search asks of every box for thousands of places.
    std::vector<Box2> padded, cleared;
    auto take = [&](const Box2& box) {
        padded.push_back(box.grown(kPadding));
        cleared.push_back(box.grown(1));
    };
    auto takeLabel = [&](const PlacedLabel& label) {
        take(label.box);
        if (label.leader)
            leaders.push_back({label.anchor, label.box.nearest(label.anchor)});
    };
    auto retake = [&] { // after a label placed before is moved
        padded.clear();
        cleared.clear();
        leaders.clear();
        for (const Box2& box : obstacles.reserved)
            take(box);
        for (const std::optional<PlacedLabel>& p : placed)
            if (p)
                takeLabel(*p);
    };
    retake();
    // Free: inside the picture, off every box taken and every leader drawn;
    // with a leader to `anchor`, that leader crosses no box taken and no
    // leader drawn either; a tick number off its own axis.
    auto free = [&](const Box2& box, const std::optional<Vec2d>& anchor, bool number, const std::optional<Segment2>& ownAxis) {
        if (!picture.contains(box))
            return false;
        const Vec2d space(std::max(0.0, (number ? kNumberSpace : kWordSpace) * (box.max.y() - box.min.y()) - kPadding), 0);
        const Box2 spaced{box.min - space, box.max + space};
        for (const Box2& other : padded)
            if (spaced.overlaps(other))
                return false;
        if (anchor) {
            const Segment2 leader = {*anchor, box.nearest(*anchor)};
            if ((leader[1] - leader[0]).norm() > farthest)
                return false;
            for (const Box2& other : cleared)
                if (segmentCrossesBox(leader, other))
                    return false;
            for (const Segment2& other : leaders)
                if (segmentsCross(leader, other, 1))
                    return false;
        }
        const Box2 clear = box.grown(1);
        for (const Segment2& line : leaders)
            if (segmentCrossesBox(line, clear))
                return false;
        return !ownAxis || !segmentCrossesBox(*ownAxis, box.grown(kAxisClearance));
    };

    // Leaders pointing away from the labels' middle fan out and seldom cross one another.
    Vec2d middle = Vec2d::Zero();
    double names = 0;
    for (const LabelRequest& r : requests)
        if (!r.minor) {
            middle += r.anchor;
            ++names;
        }
    middle /= std::max(names, 1.0);

    // The best free place for a label given those taken: near its anchor, else (`anywhere`) the
    // nearest free place in the picture, with a leader.
    auto search = [&](std::size_t k, bool anywhere) -> std::optional<PlacedLabel> {
        const LabelRequest& r = requests[k];
        const Vec2d outward = (r.anchor - middle).norm() > 1 ? Vec2d((r.anchor - middle).normalized()) : Vec2d::Zero();
        std::optional<Box2> best;
        double bestCost = 0;
        bool bestLeader = false;
        // A place nearer the anchor often costs the same as one further out, a crossing as much as two rings
        // (the direction's turn the same): the first found keeps it, whatever the last bits of the pixels, so
        // that two pictures through cameras a rounding apart (the PNG's and the page's) place alike.
        constexpr double kTie = 1e-9;
        auto consider = [&](const Box2& box, double penalty, bool leader) {
            if (best && penalty >= bestCost - kTie)
                return; // its cost is never below its penalty: it cannot do better
            if (!free(box, leader ? std::optional<Vec2d>(r.anchor) : std::nullopt, r.minor, r.axis))
                return;
            const double c = cost(box) + penalty;
            if (!best || c < bestCost - kTie) {
                best = box;
                bestCost = c;
                bestLeader = leader;
            }
        };
        for (std::size_t d = 0; d < (r.minor ? 1 : distances.size()); ++d) {
            for (std::size_t j = 0; j < directions.size(); ++j) {
                const Vec2d dir = directions[j];
                // The box's corner or edge middle nearest the anchor sits `distance` away along dir.
                const Vec2d offset = distances[d] * dir.normalized();
                const Vec2d min(dir.x() > 0 ? 0 : dir.x() < 0 ? -r.size.x() : -r.size.x() / 2,
                                dir.y() > 0 ? 0 : dir.y() < 0 ? -r.size.y() : -r.size.y() / 2);
                const Box2 box{r.anchor + offset + min, r.anchor + offset + min + r.size};
                // Nearer is better: a crossing line costs as much as going one ring further out. Beside
                // the anchor, the customary direction; with a leader, outward (less than a ring's worth).
                const double turn = d > 0 ? 0.45 * (1 - outward.dot(dir.normalized())) : 0;
                consider(box, double(d) * 1.0 + turn + 0.01 * double(j), d > 0);
            }
            if (best && bestCost < double(d) + 1)
                break; // nothing further out can do better
        }
        if (!best && anywhere && !r.minor)
            for (double y = picture.min.y(); y + r.size.y() <= picture.max.y(); y += 8)
                for (double x = picture.min.x(); x + r.size.x() <= picture.max.x(); x += 8) {
                    const Box2 box{Vec2d(x, y), Vec2d(x, y) + r.size};
                    consider(box, 0.02 * (box.min + r.size / 2 - r.anchor).norm(), true);
                }
        if (!best)
            return std::nullopt;
        return PlacedLabel{r.element, r.text, r.anchor, *best, bestLeader, r.minor};
    };

    for (std::size_t k = 0; k < requests.size(); ++k) {
        if ((placed[k] = search(k, true))) {
            takeLabel(*placed[k]);
            continue;
        }
        // Crowded out, often by a leader placed before: moving that label may leave room for both
        // (near their anchors: the search anywhere is too slow to try for each).
        for (std::size_t j = 0; j < k && !placed[k] && !requests[k].minor; ++j) {
            if (!placed[j] || !placed[j]->leader)
                continue;
            const std::optional<PlacedLabel> before = std::move(placed[j]);
            placed[j].reset();
            retake();
            if ((placed[k] = search(k, false))) {
                retake();
                if (!(placed[j] = search(j, false)))
                    placed[k].reset();
            }
            if (!placed[j])
                placed[j] = before;
        }
        if (!requests[k].minor)
            retake();
    }
    return placed;
}

int labelOverlaps(const std::vector<PlacedLabel>& labels)
{
    int count = 0;
    for (std::size_t i = 0; i < labels.size(); ++i)
        for (std::size_t j = i + 1; j < labels.size(); ++j)
            count += labels[i].box.overlaps(labels[j].box);
    return count;
}

std::vector<FigureShape> markerShapes(const StageShown& stage, const FigureView& view,
                                      const std::vector<Marker>& markers)
{
    std::vector<FigureShape> shapes;
    auto pixel = [&](const Vec3d& world) -> std::optional<Vec2d> {
        if (!stage.shows(world))
            return std::nullopt;
        const std::optional<Vec3d> px = view.pixel(*projectPoint(stage.cumulative, world));
        return px ? std::optional<Vec2d>(px->head<2>()) : std::nullopt;
    };
    for (const Marker& m : markers) {
        const std::optional<Vec2d> at = pixel(m.point);
        if (!at)
            continue;
        const double size = m.size * view.lineScale;
        std::vector<Vec2d> corners;
        if (m.shape == Marker::Shape::Dot) {
            for (int k = 0; k < 16; ++k)
                corners.push_back(*at + size * Vec2d(std::cos(k * M_PI / 8), std::sin(k * M_PI / 8)));
        } else {
            const std::optional<Vec2d> from = pixel(m.from);
            if (!from || (*at - *from).norm() < 1e-9)
                continue; // seen head on: no direction to point in
            const Vec2d along = (*at - *from).normalized(), across(-along.y(), along.x());
            corners = {*at, *at - 3 * size * along + 1.1 * size * across, *at - 3 * size * along - 1.1 * size * across};
        }
        shapes.push_back({m.element, true, 1, 0, std::move(corners), -std::numeric_limits<double>::infinity()});
    }
    return shapes;
}

namespace {

LabelObstacles labelObstacles(const StageShown& stage, const FigureView& view, const std::vector<Marker>& markers)
{
    LabelObstacles obstacles;
    for (FigureShape& marker : markerShapes(stage, view, markers))
        obstacles.objects.push_back(std::move(marker.points));
    for (const Primitive& p : stage.scene->primitives) {
        if (!stage.draws(p))
            continue;
        const Mat4<double>& m = stage.matrixOf(p);
        if (p.kind == PrimitiveKind::Lines) {
            for (std::size_t k = 0; k + 1 < p.segments.size(); k += 2) {
                const std::vector<Vec3d> line = throughView(stage, view, m, {p.segments[k], p.segments[k + 1]}, false, !p.canonical);
                if (line.size() == 2)
                    obstacles.lines.push_back({line[0].head<2>(), line[1].head<2>()});
            }
        } else if (p.element == Element::Objects && p.object >= 0) {
            std::vector<Vec2d> outline;
            auto add = [&](const Vec3d& world) {
                if (stage.shows(world))
                    if (const auto q = projectPoint(m, world))
                        if (const auto px = view.pixel(*q))
                            outline.push_back(px->head<2>());
            };
            if (p.faces->vertices.size() > kExactOutline) {
                for (int c = 0; c < 8; ++c)
                    add(p.bounds.corner(Eigen::AlignedBox<double, 3>::CornerType(c)));
            } else {
                for (const Vec3d& v : p.faces->vertices)
                    add(v);
            }
            obstacles.objects.push_back(convexHull(std::move(outline)));
        }
    }
    const std::vector<Vec3d> axes = frameMarks(view.frameExtent, view.ticks).lines;
    for (std::size_t k = 0; k + 1 < axes.size(); k += 2) {
        const auto a = view.pixel(axes[k]), b = view.pixel(axes[k + 1]);
        if (a && b)
            obstacles.lines.push_back({a->head<2>(), b->head<2>()});
    }
    return obstacles;
}

} // namespace

SceneLabels placeSceneLabels(const StageShown& stage, const FigureView& view, const std::vector<const Label*>& labels,
                             const std::vector<Marker>& markers, const LabelMeasure& measure,
                             const std::vector<Box2>& reserved)
{
    constexpr double kNamedAcross = 5; // the canonical volume is named once drawn this many label heights across
    std::vector<LabelRequest> requests;
    std::vector<std::size_t> from; // each request's label
    const Box2 picture{Vec2d::Zero(), Vec2d(view.width, view.height)};
    // By priority: the canonical volume's labels (the point of the stage that shows it), the scene's
    // names, the frame axes' names, tick numbers: where room runs out the last are left out first.
    auto rank = [](const Label& label) {
        return label.minor ? 3 : label.element == Element::Canonical ? 0 : label.element == Element::Frame ? 2 : 1;
    };
    // How wide the canonical volume is drawn: the step into S_per starts with it a few pixels across,
    // where its labels would crowd a dot.
    const double canonicalAcross = [&] {
        Eigen::AlignedBox<double, 2> drawn;
        for (const Primitive& p : stage.scene->primitives)
            if (p.canonical && stage.draws(p))
                for (int k = 0; k < 8; ++k)
                    if (const auto px = view.pixel(p.bounds.corner(Eigen::AlignedBox<double, 3>::CornerType(k))))
                        drawn.extend(px->head<2>());
        return drawn.isEmpty() ? 0.0 : drawn.sizes().maxCoeff();
    }();
    for (int priority = 0; priority <= 3; ++priority)
        for (std::size_t k = 0; k < labels.size(); ++k) {
            const Label& label = *labels[k];
            if (rank(label) != priority)
                continue;
            const bool shown = label.fixed ? label.element != Element::Canonical || stage.canonicalOpacity > 0
                                           : stage.shows(label.anchor);
            if (!shown)
                continue;
            if (label.element == Element::Canonical && canonicalAcross < kNamedAcross * measure(label).y())
                continue;

            auto q = label.fixed ? std::optional<Vec3d>(label.anchor) : projectPoint(stage.cumulative, label.anchor);
            if (label.element == Element::Frame && !label.minor && stage.cumulative.isIdentity(0))
                continue; // the world's own axes name them
            if (label.element == Element::Frame && !label.minor) // an axis's name: at the end of it the picture shows
                for (double t = 1; t > 0.05; t -= 0.025)
                    if (const auto end = view.pixel(t * label.anchor); end && picture.grown(-0.05 * view.height).contains(Box2{end->head<2>(), end->head<2>()})) {
                        q = t * label.anchor;
                        break;
                    }
            const auto px = q ? view.pixel(*q) : std::nullopt;
            if (!px || !picture.contains(Box2{px->head<2>(), px->head<2>()}))
                continue;
            std::optional<Segment2> axis;
            if (label.element == Element::Frame && label.minor) { // a tick number, on its axis as frameMarks draws it
                int along = 0;
                label.anchor.cwiseAbs().maxCoeff(&along);
                const auto [start, end] = frameAxis(view.frameExtent, along);
                const auto from = view.pixel(start), to = view.pixel(end);
                if (from && to)
                    axis = Segment2{from->head<2>(), to->head<2>()};
            }
            requests.push_back({label.element, label.text, px->head<2>(), measure(label), label.minor, axis});
            from.push_back(k);
        }
    LabelObstacles obstacles = labelObstacles(stage, view, markers);
    obstacles.reserved.insert(obstacles.reserved.end(), reserved.begin(), reserved.end());
    // Where the whole sentence finds no room (a narrow view), a brief one: "left out: 3 labels, 6 ticks".
    auto notice = [&](const std::vector<std::optional<PlacedLabel>>& placed, bool brief) {
        int names = 0, ticks = 0;
        for (std::size_t k = 0; k < placed.size(); ++k)
            if (!placed[k])
                ++(requests[k].minor ? ticks : names);
        auto count = [](int n, const char* one, const char* many) { return std::to_string(n) + " " + (n == 1 ? one : many); };
        return names + ticks == 0 ? std::string()
                                  : (brief ? "left out: " : "left out for room: ") + (names ? count(names, "label", "labels") : "") +
                                        (names && ticks ? ", " : "") +
                                        (ticks ? brief ? count(ticks, "tick", "ticks") : count(ticks, "tick number", "tick numbers") : "");
    };
    std::vector<std::optional<PlacedLabel>> placed = placeLabels(requests, obstacles, view.width, view.height);
    SceneLabels result;
    if (const std::string first = view.notes ? notice(placed, false) : ""; !first.empty()) {
        // In the bottom right corner; else right above what is reserved at the bottom (the effects'
        // note), at the right or the left; else below the caption. Nowhere free: not said.
        constexpr double kEdge = 5;
        const Box2 inside{Vec2d::Constant(kEdge), Vec2d(view.width, view.height) - Vec2d::Constant(kEdge)};
        auto sizeOf = [&](const std::string& text) { return measure(Label{Element::Frame, text, Vec3d::Zero(), true, true}); };
        auto corner = [&](const Vec2d& size) -> std::optional<Box2> {
            double below = inside.min.y();
            for (const Box2& other : reserved)
                if (other.min.y() <= 0.1 * view.height)
                    below = std::max(below, other.max.y() + kEdge);
            // Right above what is reserved at the bottom between x0 and x1 (a legend in a column at the left
            // reaches the bottom too, but not under a notice at the right).
            auto bottomBetween = [&](double x0, double x1) {
                double bottom = inside.max.y();
                for (const Box2& other : reserved)
                    if (other.max.y() >= 0.9 * view.height && other.max.x() > x0 && other.min.x() < x1)
                        bottom = std::min(bottom, other.min.y() - kEdge);
                return bottom;
            };
            const double right = bottomBetween(inside.max.x() - size.x(), inside.max.x()),
                         left = bottomBetween(inside.min.x(), inside.min.x() + size.x());
            for (const Box2& at : {Box2{inside.max - size, inside.max},
                                   Box2{Vec2d(inside.max.x() - size.x(), right - size.y()), Vec2d(inside.max.x(), right)},
                                   Box2{Vec2d(inside.min.x(), left - size.y()), Vec2d(inside.min.x() + size.x(), left)},
                                   Box2{Vec2d(inside.min.x(), below), Vec2d(inside.min.x(), below) + size}})
                if (inside.contains(at) &&
                    std::none_of(reserved.begin(), reserved.end(), [&](const Box2& other) { return at.overlaps(other.grown(kEdge)); }))
                    return at;
            return std::nullopt;
        };
        // Room for the notice, the labels placed again around it; until the notice of what that
        // pass left out fits the room (it grows by a few characters at most).
        const std::size_t reservedBefore = obstacles.reserved.size();
        std::string text = first;
        bool brief = false;
        for (int tries = 0; tries < 6 && !text.empty(); ++tries) {
            const std::optional<Box2> room = corner(sizeOf(text + "8"));
            if (!room) {
                if (brief)
                    break;
                brief = true;
                text = notice(placed, brief);
                continue;
            }
            obstacles.reserved.resize(reservedBefore);
            obstacles.reserved.push_back(*room);
            placed = placeLabels(requests, obstacles, view.width, view.height);
            text = notice(placed, brief);
            const Vec2d size = sizeOf(text);
            if (text.empty() || size.x() > room->max.x() - room->min.x())
                continue;
            const bool right = room->max.x() >= inside.max.x() - 0.5;
            const Vec2d min(right ? room->max.x() - size.x() : room->min.x(), room->max.y() - size.y());
            result.leftOut = PlacedLabel{Element::Frame, text, min, Box2{min, min + size}, false, true};
            break;
        }
    }
    result.placed.resize(labels.size());
    for (std::size_t k = 0; k < placed.size(); ++k)
        result.placed[from[k]] = std::move(placed[k]);
    return result;
}

Marker tracedMarker(const Vec3<double>& point)
{
    return Marker{Element::Traced, Marker::Shape::Dot, point, point, 8};
}

Label tracedLabel(const Vec3<double>& point)
{
    return Label{Element::Traced, "traced", point};
}

namespace {

// Where the level the depth buffer stores passes from one of the scene's bands
// to the next: planes in world coordinates, as the level changes with the
// window depth alone (an affine function of z / w in clip coordinates).
std::vector<Vec4d> bandBoundaries(const EvaluatedScene& scene)
{
    const DepthBands& bands = *scene.bands;
    const DepthOptions& options = *scene.scene.effects.depth;
    const ClipVolume volume = scene.pipeline.clipVolume;
    const double at0 = windowDepth(Vec4d(0, 0, 0, 1), volume), slope = windowDepth(Vec4d(0, 0, 1, 1), volume) - at0;
    const Mat4<double> clipT = scene.pipeline.clipMatrix().transpose();
    std::vector<Vec4d> planes;
    for (int k = 1; k < bands.count; ++k) {
        const double level = bands.first + k * bands.levelsPerBand;
        // The window depth where the stored level reaches band k's first: levels run one way along the depth.
        const bool reachedAtNear = depthLevel(0, options) >= level;
        double low = 0, high = 1;
        for (int step = 0; step < 60; ++step) {
            const double middle = (low + high) / 2;
            ((depthLevel(middle, options) >= level) != reachedAtNear ? high : low) = middle;
        }
        planes.push_back(clipT * Vec4d(0, 0, 1, -(high - at0) / slope));
    }
    return planes;
}

// A face cut along the band boundaries it crosses: each piece lies in one band.
std::vector<std::vector<Vec3d>> bandPieces(const std::vector<Vec3d>& face, const std::vector<Vec4d>& boundaries)
{
    std::vector<std::vector<Vec4d>> pieces(1);
    for (const Vec3d& p : face)
        pieces[0].push_back(p.homogeneous());
    for (const Vec4d& plane : boundaries) {
        std::vector<std::vector<Vec4d>> cut;
        for (const std::vector<Vec4d>& piece : pieces) {
            const auto [low, high] = std::minmax_element(piece.begin(), piece.end(), [&](const Vec4d& a, const Vec4d& b) {
                return plane.dot(a) < plane.dot(b);
            });
            if (plane.dot(*low) >= 0 || plane.dot(*high) <= 0) {
                cut.push_back(piece);
                continue;
            }
            for (const Vec4d& side : {plane, Vec4d(-plane)})
                if (std::vector<Vec4d> part = clipPolygon(piece, side, true); part.size() >= 3)
                    cut.push_back(std::move(part));
        }
        pieces = std::move(cut);
    }
    std::vector<std::vector<Vec3d>> result;
    for (const std::vector<Vec4d>& piece : pieces) {
        result.emplace_back();
        for (const Vec4d& p : piece)
            result.back().push_back(p.head<3>() / p.w());
    }
    return result;
}

// A piece of a depth-colored face in its band's color (the level stored at its center), grey and faint where the
// buffer stores nothing, as the painter colors each pixel.
void colorByBand(FigureShape& shape, const EvaluatedScene& scene, const std::vector<Vec3d>& piece)
{
    const Vec3d center = std::accumulate(piece.begin(), piece.end(), Vec3d(Vec3d::Zero())) / double(piece.size());
    if (const std::optional<double> level =
            depthLevelAt(scene.pipeline.clipMatrix(), scene.pipeline.clipVolume, center, *scene.scene.effects.depth)) {
        shape.color = bandColor(*scene.bands, bandOf(*scene.bands, *level));
    } else {
        shape.color = kNoBandColor;
        shape.opacity *= kNoBandOpacity;
    }
}

// The points a stage marks: the scene's and the traced one.
std::vector<Marker> stageMarkers(const StageShown& stage)
{
    std::vector<Marker> markers = stage.scene->markers;
    if (stage.traced)
        markers.push_back(tracedMarker(*stage.traced));
    return markers;
}

} // namespace

Figure drawFigure(const StageShown& stage, const FigureView& view, const SceneLabels& labels)
{
    Figure figure;
    figure.width = view.width;
    figure.height = view.height;
    figure.fontSize = view.fontSize;
    figure.lineScale = view.lineScale;
    auto add = [&](Element element, bool surface, double opacity, const std::vector<Vec3d>& pixels,
                   double widthScale = 1) {
        if (pixels.size() < (surface ? 3u : 2u))
            return;
        // The viewing axes over the world axes where they coincide (after R), as the app draws them.
        const double bias = element == Element::ViewAxes ? 1e-7 : 0;
        figure.shapes.push_back({element, surface, opacity, view.lineScale * lineWidthOf(element, surface) * widthScale,
                                 flat(pixels), meanDepth(pixels) - bias});
    };
    const std::vector<Vec4d> bandBounds = stage.scene->bands ? bandBoundaries(*stage.scene) : std::vector<Vec4d>();
    for (const Primitive& p : stage.scene->primitives) {
        if (!stage.draws(p))
            continue;
        const Mat4<double>& m = stage.matrixOf(p);
        const double opacity = p.canonical ? stage.canonicalOpacity : p.opacity;
        if (p.kind == PrimitiveKind::Lines) {
            for (std::size_t k = 0; k + 1 < p.segments.size(); k += 2)
                add(p.element, false, opacity, throughView(stage, view, m, {p.segments[k], p.segments[k + 1]}, false, !p.canonical),
                    p.widthScale);
            continue;
        }
        const bool banded = p.depthColored && stage.scene->bands;
        std::vector<Vec3d> corners;
        for (const auto& face : p.faces->faces) {
            corners.clear();
            for (int v : face)
                corners.push_back(p.faces->vertices[std::size_t(v)]);
            if (!banded) {
                add(p.element, true, opacity, throughView(stage, view, m, corners, true, !p.canonical));
                continue;
            }
            for (const std::vector<Vec3d>& piece : bandPieces(corners, bandBounds)) {
                const std::size_t before = figure.shapes.size();
                add(p.element, true, opacity, throughView(stage, view, m, piece, true, !p.canonical));
                if (figure.shapes.size() > before)
                    colorByBand(figure.shapes.back(), *stage.scene, piece);
            }
        }
    }
    const FrameMarks frame = frameMarks(view.frameExtent, view.ticks);
    {
        const std::vector<Vec3d>& axes = frame.lines;
        static const Mat4<double> identity = Mat4<double>::Identity();
        for (std::size_t k = 0; k + 1 < axes.size(); k += 2) {
            add(Element::Frame, false, 1, throughView(stage, view, identity, {axes[k], axes[k + 1]}, false, false));
            if (!figure.shapes.empty() && figure.shapes.back().element == Element::Frame)
                figure.shapes.back().depth = std::numeric_limits<double>::infinity(); // behind all: the world axes lie on them at first
        }
    }
    if (stage.ghost) // behind everything, faint
        for (const Primitive& p : stage.scene->primitives)
            if (StageShown::ghosted(p))
                for (std::size_t k = 0; k + 1 < p.segments.size(); k += 2) {
                    const std::size_t before = figure.shapes.size();
                    add(p.element, false, kGhostOpacity,
                        throughView(stage, view, *stage.ghost, {p.segments[k], p.segments[k + 1]}, false, false));
                    if (figure.shapes.size() > before)
                        figure.shapes.back().depth = std::numeric_limits<double>::infinity();
                }
    // Back to front; at equal depth lines over faces.
    std::stable_sort(figure.shapes.begin(), figure.shapes.end(), [](const FigureShape& a, const FigureShape& b) {
        return a.depth > b.depth || (a.depth == b.depth && a.surface && !b.surface);
    });
    const std::vector<FigureShape> markerFaces = markerShapes(stage, view, stageMarkers(stage));
    figure.shapes.insert(figure.shapes.end(), markerFaces.begin(), markerFaces.end()); // over everything
    for (const std::optional<PlacedLabel>& label : labels.placed)
        if (label)
            figure.labels.push_back(*label);
    if (labels.leftOut)
        figure.labels.push_back(*labels.leftOut);
    return figure;
}

Figure drawFigure(const StageShown& stage, const FigureView& view, const LabelMeasure& measure,
                  const std::vector<Box2>& reserved)
{
    std::vector<const Label*> labels;
    for (const Label& label : stage.scene->labels)
        labels.push_back(&label);
    const FrameMarks frame = frameMarks(view.frameExtent, view.ticks);
    for (const Label& label : frame.labels)
        labels.push_back(&label);
    const std::optional<Label> traced = stage.traced ? std::optional<Label>(tracedLabel(*stage.traced)) : std::nullopt;
    if (traced)
        labels.push_back(&*traced);
    return drawFigure(stage, view, placeSceneLabels(stage, view, labels, stageMarkers(stage), measure, reserved));
}

} // namespace viewpipe::report
