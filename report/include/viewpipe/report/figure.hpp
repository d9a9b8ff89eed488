#pragma once

// A stage's picture as flat drawing, for the vector figures (SVG, PDF, TikZ):
// the evaluated scene's primitives through the stage's matrix and the world
// view's camera, cut where the VTK painter cuts them, faces and lines sorted
// back to front (painter's algorithm), and every label placed. The label
// placement step here is the only one: the app, the PNG export and the vector
// figures all call it. No VTK, no Qt.

#include <functional>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "viewpipe/evaluated_scene.hpp"
#include "viewpipe/math_text.hpp"
#include "viewpipe/report/style.hpp"

namespace viewpipe::report {

// A rectangle in picture coordinates: pixels, origin top-left, y down.
struct Box2 {
    Vec2<double> min = Vec2<double>::Zero(), max = Vec2<double>::Zero();
    bool overlaps(const Box2& other) const
    {
        return min.x() < other.max.x() && other.min.x() < max.x() && min.y() < other.max.y() && other.min.y() < max.y();
    }
    bool contains(const Box2& other) const
    {
        return min.x() <= other.min.x() && min.y() <= other.min.y() && other.max.x() <= max.x() &&
               other.max.y() <= max.y();
    }
    Box2 grown(double by) const { return {min - Vec2<double>::Constant(by), max + Vec2<double>::Constant(by)}; }
    bool isEmpty() const { return !(max.x() > min.x() && max.y() > min.y()); }
    // The box's point nearest `p`: where a leader line from p meets it.
    Vec2<double> nearest(const Vec2<double>& p) const { return p.cwiseMax(min).cwiseMin(max); }
};

// A stage as the pictures show it: every element through the stage's
// cumulative matrix (the canonical outline where it is, at its opacity), cut
// at the scene's near cut while the matrix divides.
struct StageShown {
    StageShown(const EvaluatedScene& scene, const Mat4<double>& cumulative, double canonicalOpacity);
    const EvaluatedScene* scene;
    Mat4<double> cumulative;
    double canonicalOpacity;
    std::optional<Vec4<double>> cut; // world coordinates, kept where cut . p >= 0
    // Where the objects' edges and the view volume's were a stage before, drawn faint (see ghostAt).
    std::optional<Mat4<double>> ghost;
    // A point marked as traced (world coordinates), as the app marks a vertex it traces.
    std::optional<Vec3<double>> traced;
    // The primitives a ghost repeats.
    static bool ghosted(const Primitive& primitive);
    // Whether a world point is drawn: it has an image and is not cut away.
    bool shows(const Vec3<double>& world) const;
    // Whether a primitive is drawn at all (the canonical outline only while it has an opacity).
    bool draws(const Primitive& primitive) const;
    const Mat4<double>& matrixOf(const Primitive& primitive) const;
};

// The dot and label that mark a traced point (world coordinates), wherever it is drawn.
Marker tracedMarker(const Vec3<double>& point);
Label tracedLabel(const Vec3<double>& point);

// Where a picture's legend goes (export --legend): wherever it costs the
// subject least; beside the stage: at the top right with the stage left of
// it, or under the caption with the stage right of both; at the bottom
// right with the stage above it; inside the stage's room in a corner the
// subject leaves free; or nowhere.
enum class LegendPlace { Best, Beside, Below, Inside, None };
// Every place, in the order the choices list them; the names --legend takes ("best", "beside", "below",
// "inside", "none"); and each place for people ("beside the stage").
const std::vector<LegendPlace>& legendPlaces();
const char* legendPlaceName(LegendPlace place);
const char* legendPlaceTitle(LegendPlace place);
std::optional<LegendPlace> legendPlaceNamed(const std::string& name);

// Where a picture is seen from and how it is drawn.
struct FigureView {
    Mat4<double> camera = Mat4<double>::Identity(); // stage coordinates -> the picture's clip coordinates
    int width = 1280, height = 720;                 // pixels
    Eigen::AlignedBox<double, 3> frameExtent; // where the fixed axes run along x, y and z (empty: none)
    bool ticks = true; // the fixed axes' ticks and their numbers drawn (export --hide ticks)
    bool notes = true; // the notice of labels left out for room said (export --hide notes)
    double fontSize = 20;   // pixels: the labels', no larger than the caption (labelSizeIn)
    // The size its text was laid out at (PictureText::fontSize), and where room runs out, the smallest the
    // caption and legend may shrink to.
    double textSize = 20, minFontSize = 20;
    // What its text was laid out for (PictureText): the subject's outline, and where the legend was asked to go.
    std::vector<Vec2<double>> subject, subjectShown;
    LegendPlace legendPlace = LegendPlace::Best;
    double zoom = 1; // the subject this many times larger than framed (export --zoom, a lesson step's; not the wheel's)
    double lineScale = 1;
    // Pixels a world point is drawn at, and its depth (smaller: nearer); nothing when it has no image.
    std::optional<Vec3<double>> pixel(const Vec3<double>& stagePoint) const;
};

// A text's size in pixels, as the writer that draws it measures it.
using TextMeasure = std::function<Vec2<double>(const std::string& text)>;
// A label's (minor ones are set smaller).
using LabelMeasure = std::function<Vec2<double>(const Label& label)>;

// Text broken into lines at spaces (and at its own line breaks) so that each
// line is at most `width` wide; a word wider stays whole on its line.
std::vector<std::string> wrapLines(const std::string& text, double width, const TextMeasure& measure);

// A text's size in pixels, set `pixels` high, bold or not, as the writer that
// draws it measures it (line breaks taken).
using FontMeasure = std::function<Vec2<double>(const std::string& text, double pixels, bool bold)>;
// One line of the core's math runs (math_text.hpp) measured as its writer sets it; and a FontMeasure made of
// that: text line by line, the lines 1.25 of the size apart, as the pictures set them.
using RunsMeasure = std::function<Vec2<double>(const std::vector<MathRun>& runs, double pixels, bool bold)>;
FontMeasure lineByLine(RunsMeasure measure);
// Labels as every picture sets them: names bold at `fontSize`, minor ones (tick numbers) plain and smaller.
LabelMeasure labelMeasure(const FontMeasure& measure, double fontSize);

// The legend's entries shown at a stage (the canonical volume's only while it is drawn).
std::vector<const LegendEntry*> legendShown(const std::vector<LegendEntry>& entries, bool canonicalShown);

// A legend's rows: a slot three text heights wide for the swatch (VTK's
// legend draws it half as wide, centred), then the entry's text, set at
// smallTextSize of the label size.
struct LegendLayout {
    double textSize = 0, rowHeight = 0, swatchWidth = 0, padding = 0;
    Vec2<double> size = Vec2<double>::Zero(); // the whole box; zero without entries
};
LegendLayout legendLayout(const std::vector<const LegendEntry*>& entries, double labelSize, const FontMeasure& measure);

// The convex hull of points (counter-clockwise where y runs up).
std::vector<Vec2<double>> convexHull(std::vector<Vec2<double>> points);

// What a picture says beside its stage.
struct PictureText {
    double fontSize = 20;    // the labels' and the caption's, as asked (text scale applied)
    double minFontSize = 20; // the smallest the caption and legend may take where room runs out (100 %)
    std::string caption, note;
    std::vector<const LegendEntry*> legend;
    // The subject's outline as the picture frames it, at any scale (subjectOutline): the legend goes where
    // the subject draws largest. Empty: not known, the larger room. `shown`: the part of it the picture
    // shows (stages framed together frame where the others go too), which a legend inside keeps clear of.
    std::vector<Vec2<double>> subject, shown;
    LegendPlace legendPlace = LegendPlace::Best;
    // How many times larger than framed the subject draws: zoomed in, it fills the corners a legend inside
    // would take.
    double zoom = 1;
};

// Where a picture's caption (top left), legend (top right) and effects note
// (bottom left) go, in pixels: the caption beside the legend where that leaves
// it half the width and two lines at most, above it otherwise; both texts
// wrapped to fit; each box as high as its lines measure together. The caption
// and legend take the asked size where the caption needs at most 30 % of the
// height and the legend fits above the note leaving the stage 40 % of the
// width and height, else the largest size down to minFontSize that does; a
// legend that fits at no size is left out.
// `scene` is where the stage is framed, between the caption and the note,
// where the legend leaves room (PictureText::legendPlace): left of it, above
// it, or all of it with the legend inside in a corner the subject leaves free
// (where none is, a legend asked inside goes where it fits best outside the stage's room). Beside, where the
// subject's outline is known and it draws larger so, the caption, the legend
// and the note stand in a column at the left (the note at the stage's foot where
// the column lacks room) and the stage right of them at the picture's whole
// height (the caption then needs no 30 %). Best takes the place where the subject
// draws largest (beside or below where its outline is not known: the larger
// room); a place asked for where the legend does not fit, the best of those where it does.
struct PictureLayout {
    std::vector<std::string> captionLines, noteLines;
    Box2 caption, legend, note, scene;
    double captionLine = 0, noteLine = 0; // from one line's baseline to the next
    double captionSize = 0, noteSize = 0;   // pixels
    LegendLayout legendRows;                // zero size: no legend
    LegendPlace legendAt = LegendPlace::None; // where the legend went (Beside, Below or Inside; None: left out)
};
PictureLayout layoutPicture(int width, int height, const PictureText& text, const FontMeasure& measure);
// The labels' size in a picture laid out as `layout`, asked `fontSize`: no
// larger than its caption, which a narrow or crowded picture sets smaller
// (labels twice the caption's height covered a narrow view's stage).
double labelSizeIn(const PictureLayout& layout, double fontSize);
// What the picture of a stage says: its caption, the scene's effects note and the legend of what it draws.
PictureText stagePictureText(const StageShown& stage, const std::string& caption, double fontSize, double minFontSize,
                             std::vector<Vec2<double>> subject = {}, std::vector<Vec2<double>> shown = {},
                             LegendPlace legendPlace = LegendPlace::Best);
// The boxes no label may take: the caption's, the note's and the legend's (where it is shown).
std::vector<Box2> textBoxes(const PictureLayout& layout);
// Where the picture's text stands on the background, hiding what runs behind it (axes, geometry cut
// at the eye): the caption's box from the picture's top left corner, the note's from its bottom left
// (the margins too) and the legend's box. Empty boxes: no such text.
std::vector<Box2> textBackdrops(const Box2& caption, const Box2& note, const Box2& legend, int height);
// The same for a picture's layout (its legend box is empty where no legend is shown).
std::vector<Box2> textBackdrops(const PictureLayout& layout, int height);

// The layout of the last picture asked for, made anew only when its size or
// text changes: the painters ask before every frame.
class PictureLayoutCache {
public:
    const PictureLayout& layout(int width, int height, const PictureText& text, const FontMeasure& measure);
    const PictureLayout& last() const { return layout_; }

private:
    std::optional<std::tuple<int, int, double, double, std::string, std::string, std::vector<std::string>,
                             std::vector<Vec2<double>>, std::vector<Vec2<double>>, LegendPlace, double>>
        key_;
    PictureLayout layout_;
};

// Where row k of a layout's legend draws its swatch and text, as VTK's legend
// draws them: the swatch half its slot wide, centred, a quarter of the text's
// height below the row's middle; the text after the slot, on the row's middle.
struct LegendRow {
    Box2 row;
    Vec2<double> swatchCenter = Vec2<double>::Zero();
    double textHeight = 0;   // a face's swatch is 1.5 by 0.4 of it, a line's 0.12 high, a dot 0.2 a radius
    double textLeft = 0;
};
LegendRow legendRow(const PictureLayout& layout, std::size_t k);

struct LabelRequest {
    Element element;
    std::string text;
    Vec2<double> anchor; // pixels
    Vec2<double> size;   // pixels
    bool minor = false;  // right beside the anchor or not at all
    // A tick number's axis as drawn (pixels): the number keeps off it (crossed by it, "100" reads "−100").
    std::optional<Segment2> axis = std::nullopt;
};

// What labels keep clear of: the lines drawn, each object's outline (a
// polygon), and boxes taken by captions and legends.
struct LabelObstacles {
    std::vector<Segment2> lines;
    std::vector<std::vector<Vec2<double>>> objects;
    std::vector<Box2> reserved;
};

struct PlacedLabel {
    Element element;
    std::string text;
    Vec2<double> anchor;
    Box2 box;            // where the text goes
    bool leader = false; // drawn away from its anchor: a line joins them
    bool minor = false;  // set smaller (tick numbers)
};

// Places each label near its anchor: inside the picture, on no other label,
// leader or reserved box, crossing as few lines and objects as it can, moved
// away with a leader line when nothing near is free (a leader crossing no
// label, reserved box or other leader). A label that finds no free place at
// all is left out (its index is missing from the result).
std::vector<std::optional<PlacedLabel>> placeLabels(const std::vector<LabelRequest>& requests,
                                                    const LabelObstacles& obstacles, int width, int height);

// Pairs of labels whose boxes overlap.
int labelOverlaps(const std::vector<PlacedLabel>& labels);


// Labels of a scene that show at a stage, placed clear of what the stage
// draws (its lines, objects and `markers`) and of the `reserved` boxes, by
// priority: the canonical volume's labels, the scene's names, the frame
// axes' names, tick numbers, so that where room runs out tick numbers are
// left out first. When any is left out, a notice in the bottom right
// corner says how many ("left out for room: 2 labels, 5 tick numbers"; in a
// view too narrow for that, "left out: 2 labels, 5 ticks"), set as a tick
// number. The canonical volume is named once it is drawn at least five of
// its labels' heights across (the step into S_per starts with it a dot).
struct SceneLabels {
    std::vector<std::optional<PlacedLabel>> placed; // each label's, in the order given; none where left out
    std::optional<PlacedLabel> leftOut;
};
SceneLabels placeSceneLabels(const StageShown& stage, const FigureView& view, const std::vector<const Label*>& labels,
                             const std::vector<Marker>& markers, const LabelMeasure& measure,
                             const std::vector<Box2>& reserved);

// The fixed axes of the coordinates a stage maps into, running through the
// origin across `extent`: the axes and their ticks (end points by pairs) and
// the labels naming them and numbering the ticks, all in the stage's
// coordinates. An axis the extent gives no length is left out; without
// `ticks`, the axes and their names alone.
struct FrameMarks {
    std::vector<Vec3<double>> lines;
    std::vector<Label> labels;
};
FrameMarks frameMarks(const Eigen::AlignedBox<double, 3>& extent, bool ticks = true);
// Where fixed axis `axis` (0: x, 1: y, 2: z) runs across `extent`: its two ends.
std::array<Vec3<double>, 2> frameAxis(const Eigen::AlignedBox<double, 3>& extent, int axis);

// One filled polygon or one line of the flat figure.
struct FigureShape {
    Element element;
    bool surface;       // a filled polygon; otherwise an open polyline
    double opacity;
    double lineWidth;   // pixels
    std::vector<Vec2<double>> points;
    double depth;       // for sorting: larger is farther
    std::optional<Rgb> color = std::nullopt; // its own where the element's is not: a face's depth band (bandColor)
};

// The markers that show at a stage, as filled polygons in pixels: a dot a
// 16-gon, an arrowhead a triangle along the image of its shaft.
std::vector<FigureShape> markerShapes(const StageShown& stage, const FigureView& view,
                                      const std::vector<Marker>& markers);

struct Figure {
    int width = 0, height = 0;
    double fontSize = 20, lineScale = 1; // as the view's
    std::vector<FigureShape> shapes; // back to front
    std::vector<PlacedLabel> labels;
    // Where the caption, legend and note go, and the legend's entries: for
    // writers that draw them (TikZ draws the legend and note, its document the caption).
    PictureLayout layout;
    std::vector<const LegendEntry*> legend;
};

// The flat figure of a stage with its labels where `labels` placed them
// (placeSceneLabels: the painter's, so that the PNG and the figure agree).
Figure drawFigure(const StageShown& stage, const FigureView& view, const SceneLabels& labels);
// The same, its labels placed here: the stage's, the fixed axes' and the
// traced point's, clear of `reserved` (boxes the writer keeps for its caption
// and legend); for pictures no painter draws (the page).
Figure drawFigure(const StageShown& stage, const FigureView& view, const LabelMeasure& measure,
                  const std::vector<Box2>& reserved);

// The line width the pictures draw an element's lines with, in pixels at lineScale 1.
double lineWidthOf(Element element, bool surface);
// A primitive's, wider where it is highlighted.
double lineWidthOf(const Primitive& primitive);
// How much of its color a ghost's line keeps.
constexpr double kGhostOpacity = 0.3;

} // namespace viewpipe::report
