#include "viewpipe/report/web_page.hpp"

#include <nlohmann/json.hpp>

#include <map>
#include <fstream>
#include <regex>
#include <sstream>
#include <stdexcept>

#include "viewpipe/format.hpp"
#include "viewpipe/math_text.hpp"
#include "viewpipe/report/latex.hpp"
#include "viewpipe/report/lesson_latex.hpp"
#include "viewpipe/report/stage_symbols.hpp"
#include "web_template.hpp" // generated from report/web: kPageHtml, kPageCss, kPageJs

namespace viewpipe {
namespace {

using nlohmann::json;

// Mesh files up to this size in all go into the page, for its core to read.
constexpr std::size_t kMaxCarriedMeshBytes = 1'000'000;

// `source` says where the file comes from, for the message when it cannot be read.
std::string readFile(const std::filesystem::path& file, const std::string& source)
{
    std::ifstream in(file, std::ios::binary);
    if (!in)
        throw std::runtime_error("cannot read " + file.string() + " (" + source + ")");
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

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

std::string escapeForScript(std::string text)
{
    // Inside <script>, "</" could end the element: JSON and JavaScript both read "<\/" as "</".
    std::string out;
    out.reserve(text.size());
    for (std::size_t k = 0; k < text.size(); ++k) {
        out += text[k];
        if (text[k] == '<' && k + 1 < text.size() && text[k + 1] == '/')
            out += '\\';
    }
    return out;
}

// The template with each "{{name}}" replaced by its value; the values are not searched.
std::string fill(const std::string& text, const std::map<std::string, std::string>& values)
{
    std::string out;
    std::size_t at = 0;
    while (true) {
        const std::size_t open = text.find("{{", at);
        if (open == std::string::npos)
            return out + text.substr(at);
        const std::size_t close = text.find("}}", open);
        const auto value = values.find(text.substr(open + 2, close - open - 2));
        if (close == std::string::npos || value == values.end())
            throw std::logic_error("the web page template names an unknown value at " + std::to_string(open));
        out += text.substr(at, open - at) + value->second;
        at = close + 2;
    }
}

} // namespace

WebAssets loadWebAssets(const std::filesystem::path& javascript, const std::filesystem::path& core)
{
    WebAssets assets;
    assets.core = readFile(core.empty() ? VIEWPIPE_WEB_CORE : core, "the core compiled to WebAssembly, built with the app");
    assets.three = readFile(javascript / "three" / "build" / "three.min.js", "Debian package libjs-three");
    assets.katex = readFile(javascript / "katex" / "katex.min.js", "Debian package libjs-katex");
    std::string css = readFile(javascript / "katex" / "katex.min.css", "Debian package libjs-katex");
    // Each @font-face keeps its woff2 source, inlined; browsers all read woff2.
    const std::regex source(R"(src:url\((fonts/[A-Za-z0-9_-]+)\.woff2\) format\(['"]woff2['"]\)[^;}]*)");
    std::string inlined;
    std::size_t last = 0;
    for (auto it = std::sregex_iterator(css.begin(), css.end(), source); it != std::sregex_iterator(); ++it) {
        const std::string font = readFile(javascript / "katex" / ((*it)[1].str() + ".woff2"), "Debian package fonts-katex");
        inlined += css.substr(last, std::size_t(it->position()) - last) + "src:url(data:font/woff2;base64," +
                   base64(font.data(), font.size()) + ") format(\"woff2\")";
        last = std::size_t(it->position() + it->length());
    }
    assets.katexCss = inlined + css.substr(last);
    if (assets.katexCss.find("url(fonts/") != std::string::npos)
        throw std::runtime_error("KaTeX's style sheet names a font file that could not be inlined");
    return assets;
}

namespace {

json boxJson(const Box2& box)
{
    return {box.min.x(), box.min.y(), box.max.x(), box.max.y()};
}

// The picture's text boxes and sizes (layoutPicture), for the page to set its caption, legend and note as the PNG does.
json layoutJson(const PictureLayout& layout)
{
    json out = {{"caption", {{"box", boxJson(layout.caption)}, {"size", layout.captionSize}, {"line", layout.captionLine},
                             {"lines", layout.captionLines}}},
                {"note", {{"box", boxJson(layout.note)}, {"size", layout.noteSize}, {"line", layout.noteLine},
                          {"lines", layout.noteLines}}}};
    if (!layout.legend.isEmpty()) {
        const LegendLayout& rows = layout.legendRows;
        out["legend"] = {{"box", boxJson(layout.legend)}, {"size", rows.textSize}, {"row", rows.rowHeight},
                         {"swatch", rows.swatchWidth}, {"padding", rows.padding}};
    }
    return out;
}

json sceneData(const EvaluatedScene& scene, const WebPageViews& views)
{
    const Theme theme = views.theme;
    const std::vector<Stage<double>>& stages = scene.pipeline.stages;
    const std::vector<cli::StageLatex> latex = cli::stagesLatex(scene.scene, 4);
    json stageList = json::array();
    for (std::size_t k = 0; k < views.stages.size(); ++k) {
        const WebStage& s = views.stages[k];
        json labels = json::array();
        for (const PlacedLabel& l : s.labels)
            labels.push_back({{"text", l.text},
                              {"runs", runsJson(l.text)},
                              {"anchor", {l.anchor.x(), l.anchor.y()}},
                              {"box", boxJson(l.box)},
                              {"leader", l.leader},
                              {"minor", l.minor},
                              {"color", color(elementColor(l.element, theme))}});
        const FrameMarks marks = frameMarks(s.frameReach);
        const std::string list = stageText(stages, k, StageText::ListEntry);
        const std::string claim = k < scene.stageClaims.size() ? scene.stageClaims[k] : "";
        json entry = {{"list", list},
                      {"listText", mathPlainText(list)}, // for a screen reader
                      {"caption", stageCaption(scene, k, StageText::Caption)},
                      {"claim", claim},
                      {"claimText", mathPlainText(claim)},
                      {"rest", frameJson(s.rest)},
                      {"labels", labels},
                      {"frame", floats(marks.lines)}};
        if (s.ghost)
            entry["ghost"] = matrix(*s.ghost);
        entry["layout"] = layoutJson(s.layout);
        if (k > 0) {
            const Stage<double>& stage = stages[k - 1];
            entry["symbol"] = stage.symbol;
            entry["symbolMath"] = symbolMath(stage.symbol);
            entry["matrix"] = matrix(stage.matrix);
            entry["divides"] = stage.divides;
            entry["latex"] = latex.at(k - 1).equation;
            entry["cumulativeLatex"] = latex.at(k - 1).cumulative;
            const SymbolicForm symbolic = symbolicMatrix(stage.symbol);
            if (!symbolic.cells[0].empty())
                entry["symbolic"] = {{"latex", symbolicLatex(stage.symbol)}, {"notes", symbolic.notes}};
        }
        stageList.push_back(entry);
    }
    json transitions = json::array();
    for (const std::vector<WebFrame>& frames : views.transitions) {
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

    // The scene as the core reads it, with the files it names (each once): what the page's core evaluates.
    // Large meshes stay out, unread (the page draws them from its own arrays), and the page says so.
    std::map<std::string, std::filesystem::path> meshFiles;
    std::uintmax_t fileBytes = 0;
    for (const SceneObject& object : scene.scene.objects)
        if (object.type == ObjectType::Mesh && meshFiles.emplace(object.path, object.resolvedPath).second)
            fileBytes += std::filesystem::file_size(object.resolvedPath);
    json files = json::object();
    std::string filesLeftOut;
    if (fileBytes > kMaxCarriedMeshBytes)
        filesLeftOut = "The scene's meshes (" + formatSignificant(double(fileBytes) / 1e6, 2) +
                       " MB) are left out of this page to keep it small: viewpipe pipeline SCENE --json prints "
                       "these numbers.";
    else
        for (const auto& [path, file] : meshFiles) {
            const std::string bytes = readFile(file, "a mesh of the scene");
            files[path] = base64(bytes.data(), bytes.size());
        }

    const json data = {{"title", scene.scene.name},
                       {"scene", sceneToJson(scene.scene)},
                       {"files", files},
                       {"filesLeftOut", filesLeftOut},
                       {"width", views.width},
                       {"height", views.height},
                       {"fontSize", views.fontSize},
                       {"smallFontSize", smallTextSize(views.fontSize)},
                       {"scripts", {{"scale", kScriptScale}, {"drop", kSubscriptDrop}, {"rise", kSuperscriptRise}}},
                       {"background", color(backgroundColor(theme, false))},
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
                       {"note", scene.effectsNote},
                       {"projected", projected}};
    return data;
}

json questionData(const Question& q)
{
    // Each text with math, and as plain text for a screen reader.
    json out = {{"kind", questionKindName(q.kind)},
                {"prompt", q.prompt},
                {"promptPlain", mathPlainText(q.prompt)},
                {"explanation", q.explanation},
                {"explanationPlain", mathPlainText(q.explanation)}};
    switch (q.kind) {
    case QuestionKind::Where:
        out.update({{"point", vec(q.point)}, {"stage", q.stage}, {"tolerance", q.tolerance}, {"answer", vec(q.where)}});
        break;
    case QuestionKind::Inside: out.update({{"point", vec(q.point)}, {"answer", q.inside}}); break;
    case QuestionKind::SignW: out.update({{"point", vec(q.point)}, {"stage", q.stage}, {"answer", q.signW}}); break;
    case QuestionKind::WhichStage:
    case QuestionKind::Order: {
        json symbols = json::array(); // the stage symbols, set as math
        for (const std::string& choice : q.choices)
            symbols.push_back("$" + symbolMath(choice) + "$");
        out.update({{"choices", q.choices}, {"choicesMath", symbols}});
        if (q.kind == QuestionKind::WhichStage)
            out.update({{"stage", q.stage}, {"answer", q.correct}});
        break;
    }
    case QuestionKind::Entry:
        out.update({{"stage", q.stage}, {"row", q.row}, {"column", q.column}, {"answer", q.entry}});
        break;
    case QuestionKind::Choice: out.update({{"choices", q.choices}, {"answer", q.correct}}); break;
    }
    return out;
}

std::string page(const std::string& title, const json& data, const WebAssets& assets)
{
    std::string escaped;
    for (char c : title)
        escaped += c == '<' ? "&lt;" : c == '>' ? "&gt;" : c == '&' ? "&amp;" : std::string(1, c);
    return fill(web::kPageHtml, {{"title", escaped},
                                 {"katex-css", assets.katexCss},
                                 {"page-css", web::kPageCss},
                                 {"data", scriptJson(data)},
                                 {"three", escapeForScript(assets.three)},
                                 {"katex", escapeForScript(assets.katex)},
                                 {"core", escapeForScript(assets.core)},
                                 {"page-js", escapeForScript(web::kPageJs)}});
}

} // namespace

std::string webPageData(const EvaluatedScene& scene, const WebPageViews& views)
{
    return scriptJson({{"scenes", {sceneData(scene, views)}}});
}

std::string webPage(const EvaluatedScene& scene, const WebPageViews& views, const WebAssets& assets)
{
    return page(scene.scene.name, {{"scenes", {sceneData(scene, views)}}}, assets);
}

std::string lessonPage(const Lesson& lesson, const std::vector<int>& stepScenes, const std::vector<LessonScene>& scenes,
                       const WebAssets& assets)
{
    json steps = json::array();
    for (std::size_t k = 0; k < lesson.steps.size(); ++k) {
        const LessonStep& step = lesson.steps[k];
        json entry = {{"scene", stepScenes.at(k)}, {"stage", step.stage}, {"yaw", step.yaw},
                      {"pitch", step.pitch},       {"zoom", step.zoom},   {"caption", step.caption},
                      {"captionPlain", mathPlainText(step.caption)}};
        if (step.trace)
            entry["trace"] = vec(*step.trace);
        if (!step.entries.empty()) { // the stage's equation with those entries marked, as the page's own shows it
            entry["latexStage"] = revealedStage(step);
            entry["latex"] = cli::stageLatex(step.scene, revealedStage(step), 4, step.entries);
        }
        if (step.question) {
            entry["question"] = questionData(*step.question);
            entry["question"]["answerText"] = answerText(step);
            entry["question"]["answerPlain"] = mathPlainText(answerText(step));
            entry["question"]["offered"] = offeredChoices(*step.question);
        }
        steps.push_back(entry);
    }
    json sceneList = json::array();
    for (const LessonScene& s : scenes)
        sceneList.push_back(sceneData(*s.scene, s.views));
    return page(lesson.title, {{"lesson", {{"title", lesson.title}, {"steps", steps}}}, {"scenes", sceneList}}, assets);
}

} // namespace viewpipe
