#include "web_data.hpp"

#include "viewpipe/format.hpp"
#include "viewpipe/math_text.hpp"
#include "viewpipe/report/latex.hpp"
#include "viewpipe/report/lesson_latex.hpp"
#include "viewpipe/report/stage_symbols.hpp"
#include "viewpipe/report/storyboard.hpp"
#include "viewpipe/report/world_view.hpp"

namespace viewpipe::report {
namespace {

using nlohmann::json;

constexpr int kWebFramesPerStep = 30; // the page's transitions: frames per step

// Geometry as little-endian binary (what typed arrays read), in base64.
std::string floats(const std::vector<Vec3<double>>& points)
{
    std::vector<float> packed;
    packed.reserve(points.size() * 3);
    for (const Vec3<double>& p : points)
        packed.insert(packed.end(), {float(p.x()), float(p.y()), float(p.z())});
    return base64(packed.data(), packed.size() * sizeof(float));
}

json matrix(const Mat4<double>& m) // row by row, as three.js's Matrix4.set takes it
{
    json rows = json::array();
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c)
            rows.push_back(m(r, c));
    return rows;
}

json vec(const Vec3<double>& v)
{
    return {v.x(), v.y(), v.z()};
}

json color(const Rgb& c)
{
    return {c.r, c.g, c.b};
}

json frameJson(const WebFrame& f)
{
    json out = {{"view", matrix(f.view)},
                {"projection", matrix(f.projection)},
                {"focal", vec(f.focalPoint)},
                {"shown", matrix(f.shown)},
                {"canonical", f.canonicalOpacity}};
    if (f.cut)
        out["cut"] = {f.cut->x(), f.cut->y(), f.cut->z(), f.cut->w()};
    return out;
}

json primitiveJson(const Primitive& p, Theme theme)
{
    const bool surface = p.kind == PrimitiveKind::Faces;
    json out = {{"surface", surface},
                {"color", color(styledColor(p.element, surface, theme))},
                {"opacity", p.opacity},
                {"lineWidth", lineWidthOf(p)},
                {"canonical", p.canonical},
                {"ghosted", StageShown::ghosted(p)},
                {"object", p.object}};
    if (!surface) {
        out["positions"] = floats(p.segments);
        return out;
    }
    std::vector<std::uint32_t> triangles; // each polygon as a fan
    for (const auto& face : p.faces->faces)
        for (std::size_t k = 1; k + 1 < face.size(); ++k)
            triangles.insert(triangles.end(), {std::uint32_t(face[0]), std::uint32_t(face[k]), std::uint32_t(face[k + 1])});
    out["positions"] = floats(p.faces->vertices);
    out["triangles"] = base64(triangles.data(), triangles.size() * sizeof(std::uint32_t));
    return out;
}

// Text with math as the core's runs, [text, italic, level] each: what the page draws on its canvas.
json runsJson(const std::string& text)
{
    json out = json::array();
    for (const MathRun& run : mathRuns(text))
        out.push_back({run.text, run.italic, run.level});
    return out;
}

json labelJson(const Label& l, Theme theme)
{
    return {{"text", l.text}, {"runs", runsJson(l.text)}, {"anchor", vec(l.anchor)}, {"fixed", l.fixed}, {"minor", l.minor},
            {"color", color(elementColor(l.element, theme))}};
}

json legendJson(const std::vector<LegendEntry>& entries, Theme theme)
{
    json out = json::array();
    for (const LegendEntry& e : entries) {
        if (e.swatch == LegendEntry::Swatch::Bands || e.swatch == LegendEntry::Swatch::Pixels)
            continue; // the page draws neither the depth bands nor the raster's pixels
        const bool surface = e.swatch == LegendEntry::Swatch::Face;
        const char* swatch = e.swatch == LegendEntry::Swatch::Line ? "line"
                             : e.swatch == LegendEntry::Swatch::Dot ? "dot"
                                                                    : "face";
        out.push_back({{"text", e.text}, {"swatch", swatch}, {"color", color(styledColor(e.element, surface, theme))},
                       {"opacity", e.opacity}, {"canonical", e.element == Element::Canonical}});
    }
    return out;
}

json boxJson(const Box2& box)
{
    return {box.min.x(), box.min.y(), box.max.x(), box.max.y()};
}

json placedLabelsJson(const std::vector<PlacedLabel>& placed, Theme theme)
{
    json labels = json::array();
    for (const PlacedLabel& l : placed)
        labels.push_back({{"text", l.text},
                          {"runs", runsJson(l.text)},
                          {"anchor", {l.anchor.x(), l.anchor.y()}},
                          {"box", boxJson(l.box)},
                          {"leader", l.leader},
                          {"minor", l.minor},
                          {"color", color(elementColor(l.element, theme))}});
    return labels;
}

// Whether the reader keeps `name` (hideNames) in the picture.
bool shows(const WebViewOptions& o, const char* name)
{
    return o.hidden.count(name) == 0;
}

// Stage k's caption, legend and note laid out as the PNG lays them out.
PictureLayout stageLayout(const EvaluatedScene& scene, int k, const WorldMoment& moment, const WebViewOptions& o,
                          const FontMeasure& measure)
{
    const std::string caption = shows(o, "caption") ? stageCaption(scene, std::size_t(k), StageText::Heading) : "";
    PictureText text = stagePictureText(stageShown(scene, moment), caption, o.fontSize, o.minFontSize,
                                        subjectOutline(WorldCamera{}, moment.framing), // from the exports' viewpoint
                                        subjectOutline(WorldCamera{}, moment.framing, true), o.legend);
    text.zoom = o.zoom; // the export's: the reader's zoom moves no text, as the app's wheel
    return layoutPicture(o.width, o.height, text, measure);
}

// Stage k's flat figure through `camera`, its labels placed around its text.
Figure stageFigure(const EvaluatedScene& scene, const WorldMoment& moment, const Mat4<double>& camera,
                   const PictureLayout& layout, const WebViewOptions& o, const FontMeasure& measure)
{
    FigureView view;
    view.camera = camera;
    view.width = o.width;
    view.height = o.height;
    view.frameExtent = frameExtent(moment.framing);
    view.fontSize = labelSizeIn(layout, o.fontSize); // the page sets each label to fit its box
    view.textSize = o.fontSize;
    view.minFontSize = o.minFontSize;
    view.lineScale = o.lineScale;
    view.ticks = shows(o, "ticks");
    view.notes = shows(o, "notes");
    return drawFigure(stageShown(scene, moment), view, labelMeasure(measure, view.fontSize), textBoxes(layout));
}

// The picture's text boxes and sizes (layoutPicture), for the page to set its caption, legend and note as the PNG does.
json layoutJson(const PictureLayout& layout, int height)
{
    json backdrops = json::array();
    for (const Box2& box : textBackdrops(layout, height))
        backdrops.push_back(boxJson(box));
    json out = {{"caption", {{"box", boxJson(layout.caption)}, {"size", layout.captionSize}, {"line", layout.captionLine},
                             {"lines", layout.captionLines}}},
                {"note", {{"box", boxJson(layout.note)}, {"size", layout.noteSize}, {"line", layout.noteLine},
                          {"lines", layout.noteLines}}},
                {"backdrops", backdrops}};
    if (!layout.legend.isEmpty()) {
        const LegendLayout& rows = layout.legendRows;
        out["legend"] = {{"box", boxJson(layout.legend)}, {"size", rows.textSize}, {"row", rows.rowHeight},
                         {"swatch", rows.swatchWidth}, {"padding", rows.padding}};
    }
    return out;
}

// A stage at rest as the page draws it: its frame, ghost, text and labels.
json stageViewJson(const WebStage& s, const WebViewOptions& o)
{
    json out = {{"rest", frameJson(s.rest)}, {"labels", placedLabelsJson(s.labels, o.theme)}, {"layout", layoutJson(s.layout, o.height)}};
    if (s.ghost)
        out["ghost"] = matrix(*s.ghost);
    return out;
}

} // namespace

std::string base64(const void* data, std::size_t size)
{
    static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    const auto* bytes = static_cast<const unsigned char*>(data);
    std::string out;
    out.reserve((size + 2) / 3 * 4);
    for (std::size_t k = 0; k < size; k += 3) {
        const unsigned n = unsigned(bytes[k]) << 16 | (k + 1 < size ? unsigned(bytes[k + 1]) << 8 : 0u) |
                           (k + 2 < size ? unsigned(bytes[k + 2]) : 0u);
        out += digits[n >> 18 & 63];
        out += digits[n >> 12 & 63];
        out += k + 1 < size ? digits[n >> 6 & 63] : '=';
        out += k + 2 < size ? digits[n & 63] : '=';
    }
    return out;
}

// JSON inside <script>: every "<" written as \u003c, which JSON reads as "<"
// and after which no text of a lesson ("</script>", "<!--") can end or
// change the script element.
std::string scriptJson(const json& data)
{
    std::string out;
    for (char c : data.dump())
        out += c == '<' ? std::string("\\u003c") : std::string(1, c);
    return out;
}

json sceneData(const EvaluatedScene& scene, const WebPageViews& views)
{
    const WebViewOptions& options = views.options;
    const Theme theme = options.theme;
    const std::vector<Stage<double>>& stages = scene.pipeline.stages;
    const std::vector<StageLatex> latex = stagesLatex(scene.scene, 4);
    json stageList = json::array();
    for (std::size_t k = 0; k < views.stages.size(); ++k) {
        const WebStage& s = views.stages[k];
        const FrameMarks marks = frameMarks(s.frameExtent, shows(options, "ticks"));
        const std::string list = stageText(stages, k, StageText::ListEntry);
        const std::string claim = k < scene.stageClaims.size() ? scene.stageClaims[k] : "";
        json entry = {{"list", list},
                      {"listText", mathSpokenText(list)}, // for a screen reader
                      {"caption", stageCaption(scene, k, StageText::Caption)},
                      {"claim", claim},
                      {"claimText", mathSpokenText(claim)},
                      {"frame", floats(marks.lines)}};
        if (s.made) // else the page asks for it when it shows the stage (webStageView)
            entry.update(stageViewJson(s, options));
        if (k > 0) {
            const Stage<double>& stage = stages[k - 1];
            entry["symbol"] = stage.symbol();
            entry["symbolMath"] = stageSymbolMath(stage.kind);
            entry["matrix"] = matrix(stage.matrix);
            entry["divides"] = stage.divides();
            entry["latex"] = latex.at(k - 1).equation;
            entry["cumulativeLatex"] = latex.at(k - 1).cumulative;
            const SymbolicForm symbolic = symbolicMatrix(stage.kind);
            if (!symbolic.cells[0].empty())
                entry["symbolic"] = {{"latex", symbolicLatex(stage.kind)}, {"notes", symbolic.notes}};
        }
        stageList.push_back(entry);
    }
    json transitions = json::array();
    for (const std::vector<WebFrame>& frames : views.transitions) {
        if (frames.empty()) { // asked for when stepped (webTransition)
            transitions.push_back(nullptr);
            continue;
        }
        json list = json::array();
        for (const WebFrame& f : frames)
            list.push_back(frameJson(f));
        transitions.push_back(list);
    }
    json primitives = json::array();
    for (const Primitive& p : scene.primitives)
        primitives.push_back(primitiveJson(p, theme));
    json labels = json::array();
    for (const Label& l : scene.labels)
        labels.push_back(labelJson(l, theme));
    json markers = json::array();
    for (const Marker& m : scene.markers)
        markers.push_back({{"arrow", m.shape == Marker::Shape::ArrowHead},
                           {"point", vec(m.point)},
                           {"from", vec(m.from)},
                           {"size", m.size},
                           {"color", color(elementColor(m.element, theme))}});
    std::vector<Vec3<double>> vertices = scene.objectVertices();

    json projected = {{"clip", matrix(screenClipMatrix(scene.pipeline))},
                      {"aspect", pictureAspect(scene)},
                      {"window", floats(pictureWindowOutline(scene))},
                      {"windowColor", color(elementColor(Element::Window, theme))},
                      {"vanishingColor", color(elementColor(Element::Vanishing, theme))},
                      {"legend", legendJson(scene.projectedLegend, theme)}};
    json vanishing = json::array();
    for (const Segment2& s : scene.vanishingLines)
        vanishing.push_back({s[0].x(), s[0].y(), s[1].x(), s[1].y()});
    projected["vanishing"] = vanishing;
    json ring = json::array();
    for (const Segment2& s : scene.zFightingRing)
        ring.push_back({s[0].x(), s[0].y(), s[1].x(), s[1].y()});
    projected["zFighting"] = ring;
    projected["zFightingColor"] = color(elementColor(Element::ZFighting, theme));

    // What the reader may leave out and where the legend may go, as the CLI and the app offer them.
    json hideChoices = json::array(), legendChoices = json::array();
    for (const std::string& name : hideNames())
        hideChoices.push_back({{"name", name}, {"title", hideTitle(name)}});
    for (const LegendPlace place : legendPlaces())
        legendChoices.push_back({{"name", legendPlaceName(place)}, {"title", legendPlaceTitle(place)}});

    const json data = {{"title", scene.scene.name},
                       {"width", options.width},
                       {"height", options.height},
                       {"fontSize", options.fontSize},
                       {"minFontSize", options.minFontSize},
                       {"lineScale", options.lineScale},
                       {"framing", framingModeName(options.framing)},
                       {"stepMilliseconds", kStepMilliseconds},
                       {"drawnReach", kDrawnReach}, // the core's inFrontOfEye, the page's too
                       {"viewLimits", {{"pitch", ViewLimits::kPitchDegrees}, {"zoom", {ViewLimits::kMinZoom, ViewLimits::kMaxZoom}}}},
                       {"smallFontSize", smallTextSize(options.fontSize)},
                       {"scripts", {{"scale", kScriptScale}, {"drop", kSubscriptDrop}, {"rise", kSuperscriptRise}}},
                       {"background", color(backgroundColor(theme, false))},
                       {"labelBackdropOpacity", kLabelBackdropOpacity},
                       {"projectedBackground", color(backgroundColor(theme, true))},
                       {"ink", color(elementColor(Element::Objects, theme))},
                       {"dark", theme == Theme::Dark},
                       {"ghostOpacity", kGhostOpacity},
                       {"frameColor", color(elementColor(Element::Frame, theme))},
                       {"stages", stageList},
                       {"transitions", transitions},
                       {"primitives", primitives},
                       {"labels", labels},
                       {"markers", markers},
                       {"vertices", floats(vertices)},
                       {"legend", legendJson(scene.worldLegend, theme)},
                       {"projected", projected},
                       {"hideChoices", hideChoices},
                       // The choices the page was made with (export's --hide, --legend and --zoom): the reader's at first.
                       {"chosen", {{"hidden", options.hidden}, {"legend", legendPlaceName(options.legend)}, {"zoom", options.zoom}}},
                       {"legendChoices", legendChoices}};
    return data;
}

json questionData(const Question& q)
{
    // Each text with math, and as plain text for a screen reader.
    json out = {{"kind", questionKindName(q.kind)},
                {"source", questionToJson(q)}, // for the page's core, which checks the answers
                {"tries", q.tries},
                {"prompt", q.prompt},
                {"promptPlain", mathSpokenText(q.prompt)},
                {"explanation", q.explanation},
                {"explanationPlain", mathSpokenText(q.explanation)}};
    switch (q.kind) {
    case QuestionKind::Where:
        out.update({{"point", vec(q.point)}, {"stage", q.stage}});
        break;
    case QuestionKind::Inside: out["point"] = vec(q.point); break;
    case QuestionKind::SignW: out.update({{"point", vec(q.point)}, {"stage", q.stage}}); break;
    case QuestionKind::WhichStage:
    case QuestionKind::Order: {
        json symbols = json::array(), spoken = json::array(); // the stage symbols, set as math, and in words
        for (const std::string& choice : q.choices) {
            symbols.push_back("$" + symbolMath(choice) + "$");
            spoken.push_back(mathSpokenText(symbols.back()));
        }
        out.update({{"choices", q.choices}, {"choicesMath", symbols}, {"choicesSpoken", spoken}});
        if (q.kind == QuestionKind::WhichStage)
            out["stage"] = q.stage;
        break;
    }
    case QuestionKind::Entry:
        out.update({{"stage", q.stage}, {"row", q.row}, {"column", q.column}});
        break;
    case QuestionKind::Choice: {
        json letters = json::array();
        for (std::size_t k = 0; k < q.choices.size(); ++k)
            letters.push_back(choiceLetter(k));
        out.update({{"choices", q.choices}, {"letters", letters}});
        break;
    }
    }
    return out;
}

namespace {

// The page's views of one scene, each part made when first asked: each
// stage's moment at rest and text laid out (a step's camera moves from the
// scene area the last stage's text leaves to the one the next stage's
// leaves, so that its last frame is the stage at rest).
class PageViewMaker {
public:
    PageViewMaker(const EvaluatedScene& scene, const WebViewOptions& o, const FontMeasure& measure)
        : scene_(scene), o_(o), measure_(measure), framings_(stageFramings(scene, o.framing)),
          moments_(scene.pipeline.stages.size() + 1), layouts_(moments_.size())
    {
    }

    const WorldMoment& moment(int k)
    {
        std::optional<WorldMoment>& m = moments_.at(std::size_t(k));
        if (!m)
            m = stageAtRest(scene_, k, framings_);
        return *m;
    }
    const PictureLayout& layout(int k)
    {
        std::optional<PictureLayout>& l = layouts_.at(std::size_t(k));
        if (!l)
            l = stageLayout(scene_, k, moment(k), o_, measure_);
        return *l;
    }

    // Stage k at rest; where not `made`, its frame extent only (the page asks for the rest: webStageView).
    WebStage stage(int k, bool made)
    {
        const WorldMoment& m = moment(k);
        if (!made)
            return {{}, {}, frameExtent(m.framing), {}, {}, false};
        const WebFrame rest = frameOf(m, layout(k).scene);
        WebStage out{rest, m.ghost, frameExtent(m.framing), {}, layout(k), true};
        out.labels = stageFigure(scene_, m, rest.projection * rest.view, out.layout, o_, measure_).labels;
        return out;
    }

    // The app's transition from stage k to k + 1, frame by frame.
    std::vector<WebFrame> transition(int k)
    {
        const StageMotion motion(scene_, k, k + 1, framings_);
        const Box2 before = layout(k).scene, after = layout(k + 1).scene;
        std::vector<WebFrame> frames;
        for (int f = 1; f <= kWebFramesPerStep; ++f) {
            const double s = double(f) / kWebFramesPerStep, u = smoothStep(s);
            frames.push_back(frameOf(motion.at(s), {before.min + u * (after.min - before.min), before.max + u * (after.max - before.max)}));
        }
        return frames;
    }

private:
    // A moment framed in `sceneArea` from the default viewpoint, as every export is seen.
    WebFrame frameOf(const WorldMoment& moment, const Box2& sceneArea) const
    {
        WorldCamera camera;
        frameOn(camera, moment.framing, ViewFit{o_.width, o_.height, sceneArea, 1, Vec3<double>::Zero()});
        WebFrame frame;
        frame.view = camera.view();
        frame.projection = camera.projection(double(o_.width) / o_.height);
        frame.focalPoint = camera.focalPoint;
        frame.shown = moment.drawn;
        frame.canonicalOpacity = moment.canonicalOpacity;
        frame.cut = stageShown(scene_, moment).cut;
        return frame;
    }

    const EvaluatedScene& scene_;
    const WebViewOptions& o_;
    const FontMeasure& measure_;
    const StageFramings framings_;
    std::vector<std::optional<WorldMoment>> moments_;
    std::vector<std::optional<PictureLayout>> layouts_;
};

} // namespace

WebPageViews webPageViews(const EvaluatedScene& scene, const WebViewOptions& o, const FontMeasure& measure,
                          const std::function<void(int)>& onStage, std::optional<int> shown)
{
    const int n = int(scene.pipeline.stages.size());
    PageViewMaker maker(scene, o, measure);
    WebPageViews views;
    views.options = o;
    for (int k = 0; k <= n; ++k) {
        if (onStage)
            onStage(k);
        if (k > 0)
            views.transitions.push_back(shown ? std::vector<WebFrame>{} : maker.transition(k - 1));
        views.stages.push_back(maker.stage(k, !shown || *shown == k));
    }
    return views;
}

std::string webStageView(const EvaluatedScene& scene, int stage, const WebViewOptions& o, const FontMeasure& measure)
{
    return stageViewJson(PageViewMaker(scene, o, measure).stage(stage, true), o).dump();
}

std::string webTransition(const EvaluatedScene& scene, int from, const WebViewOptions& o, const FontMeasure& measure)
{
    json frames = json::array();
    for (const WebFrame& f : PageViewMaker(scene, o, measure).transition(from))
        frames.push_back(frameJson(f));
    return frames.dump();
}

std::string webStageLabels(const EvaluatedScene& scene, int stage, const Mat4<double>& camera, const WebViewOptions& o,
                           const FontMeasure& measure)
{
    const WorldMoment moment = stageAtRest(scene, stage, stageFramings(scene, o.framing));
    return placedLabelsJson(
               stageFigure(scene, moment, camera, stageLayout(scene, stage, moment, o, measure), o, measure).labels,
               o.theme)
        .dump();
}

namespace {

// A figure's line or face as the page draws it: its points in pixels, its style.
json shapeJson(const FigureShape& s, Theme theme)
{
    json points = json::array();
    for (const Vec2<double>& p : s.points)
        points.push_back({p.x(), p.y()});
    return {{"surface", s.surface}, {"color", color(styledColor(s.element, s.surface, theme))},
            {"opacity", s.opacity}, {"lineWidth", s.lineWidth}, {"points", points}};
}

} // namespace

std::string webStageFigure(const EvaluatedScene& scene, int stage, const Mat4<double>& camera, const WebViewOptions& o,
                           const FontMeasure& measure)
{
    const WorldMoment moment = stageAtRest(scene, stage, stageFramings(scene, o.framing));
    const Figure figure = stageFigure(scene, moment, camera, stageLayout(scene, stage, moment, o, measure), o, measure);
    json shapes = json::array();
    for (const FigureShape& s : figure.shapes)
        shapes.push_back(shapeJson(s, o.theme));
    return json{{"width", figure.width}, {"height", figure.height}, {"shapes", shapes},
                {"labels", placedLabelsJson(figure.labels, o.theme)}}
        .dump();
}

std::string webStoryboard(const EvaluatedScene& scene, int width, int height, const std::optional<Vec3<double>>& traced,
                          const std::vector<Mat4<double>>& cameras, const WebViewOptions& o, const FontMeasure& measure,
                          bool shapes)
{
    std::vector<int> stages;
    for (int k = 0; k <= int(scene.pipeline.stages.size()); ++k)
        stages.push_back(k);
    const double textScale = o.fontSize / exportLabelSize(o.width, 1);
    const Vec3<double> point = traced ? *traced : storyboardTracedPoint(scene);
    const StoryboardLayout layout =
        layoutStoryboard(scene, stages, point, width, height, storyboardLabelSize(width, textScale), measure);
    const StageFramings framings = stageFramings(scene, o.framing);
    json cells = json::array();
    for (const StoryboardCell& cell : layout.cells) {
        const Vec2<double> size = cell.picture.max - cell.picture.min;
        const int w = int(size.x()), h = int(size.y());
        // Framed in the whole picture, as the native storyboard's cells: no caption or legend in it.
        WorldCamera camera;
        const WorldMoment moment = stageAtRest(scene, cell.stage, framings);
        frameOn(camera, moment.framing, ViewFit{w, h, Box2{{0, 0}, {double(w), double(h)}}, 1, Vec3<double>::Zero()});
        WebFrame rest;
        rest.view = camera.view();
        rest.projection = camera.projection(double(w) / h);
        rest.focalPoint = camera.focalPoint;
        rest.shown = moment.drawn;
        rest.canonicalOpacity = moment.canonicalOpacity;
        StageShown shown = stageShown(scene, moment);
        rest.cut = shown.cut;
        shown.traced = point;
        FigureView view;
        view.camera = std::size_t(cell.stage) < cameras.size() ? cameras[std::size_t(cell.stage)] : rest.projection * rest.view;
        view.width = w;
        view.height = h;
        view.frameExtent = frameExtent(moment.framing);
        view.fontSize = view.textSize = view.minFontSize = layout.labelSize;
        view.lineScale = o.lineScale;
        view.ticks = shows(o, "ticks");
        Figure figure = drawFigure(shown, view, labelMeasure(measure, layout.labelSize), {});
        json entry = {{"stage", cell.stage},         {"header", boxJson(cell.header)},
                      {"picture", boxJson(cell.picture)}, {"footer", boxJson(cell.footer)},
                      {"rest", frameJson(rest)},     {"labels", placedLabelsJson(figure.labels, o.theme)}};
        if (shapes) { // drawn on nothing of its neighbours', as the exported storyboard's cells
            cutShapesTo(figure, {{0, 0}, {double(w), double(h)}});
            json drawn = json::array();
            for (const FigureShape& s : figure.shapes)
                drawn.push_back(shapeJson(s, o.theme));
            entry["shapes"] = drawn;
        }
        if (moment.ghost)
            entry["ghost"] = matrix(*moment.ghost);
        cells.push_back(entry);
    }
    const Figure overlay = storyboardOverlay(scene, layout, point, measure, o.lineScale);
    json arrows = json::array();
    for (const FigureShape& s : overlay.shapes)
        arrows.push_back(shapeJson(s, o.theme));
    json texts = json::array(); // each cell's header, then its footer
    for (const PlacedLabel& l : overlay.labels)
        texts.push_back({{"text", l.text}, {"runs", runsJson(l.text)}, {"spoken", mathSpokenText(l.text)}, {"box", boxJson(l.box)}, {"minor", l.minor},
                         {"color", color(elementColor(l.element, o.theme))}});
    return json{{"columns", layout.columns},
                {"labelSize", layout.labelSize},
                {"smallSize", smallTextSize(layout.labelSize)},
                {"traced", vec(point)},
                {"cells", cells},
                {"arrows", arrows},
                {"texts", texts}}
        .dump();
}

std::string webPageData(const EvaluatedScene& scene, const WebPageViews& views)
{
    return sceneData(scene, views).dump();
}

} // namespace viewpipe::report
