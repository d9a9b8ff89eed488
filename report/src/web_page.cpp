#include "viewpipe/report/web_page.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <map>
#include <fstream>
#include <regex>
#include <sstream>
#include <stdexcept>

#include "viewpipe/format.hpp"
#include "viewpipe/math_text.hpp"
#include "viewpipe/report/latex.hpp"
#include "viewpipe/report/lesson_latex.hpp"
#include "web_data.hpp"
#include "web_template.hpp" // generated from report/web: kPageHtml, kPageCss, kPageJs

namespace viewpipe::report {
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

WebAssets loadWebAssets(const std::filesystem::path& javascript, const std::filesystem::path& core,
                        const std::filesystem::path& presets)
{
    WebAssets assets;
    if (!presets.empty())
        for (const Preset& preset : presetScenes(presets)) {
            const bool meshes = std::any_of(preset.scene.objects.begin(), preset.scene.objects.end(),
                                            [](const SceneObject& o) { return o.type == ObjectType::Mesh; });
            if (!meshes)
                assets.presets.push_back({preset.group, preset.scene.name, sceneToJson(preset.scene)});
        }
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

// A scene's data with its source: the scene as the core reads it and the
// files it names (each once), which the page's core evaluates anew on every
// edit. Large meshes stay out, unread (the page draws them from its own
// arrays), and the page says so.
json sceneWithSource(const EvaluatedScene& scene, const WebPageViews& views)
{
    json data = sceneData(scene, views);
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
    data["scene"] = sceneToJson(scene.scene);
    data["files"] = files;
    data["filesLeftOut"] = filesLeftOut;
    return data;
}

// A lesson's data sealed: its answers, explanations, captions and the stage names that answer its questions
// are no text in the page's source for a student to read or search. A seal, not a secret: the page opens it
// with the key beside it (begin.js).
json sealed(const json& data)
{
    const std::string key = "ViewPipe lesson";
    std::string bytes = data.dump();
    for (std::size_t k = 0; k < bytes.size(); ++k)
        bytes[k] = char(bytes[k] ^ key[k % key.size()]);
    return {{"seal", key}, {"sealed", base64(bytes.data(), bytes.size())}};
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

std::string webPage(const EvaluatedScene& scene, const WebPageViews& views, const WebAssets& assets)
{
    json presets = json::array();
    for (const WebPreset& preset : assets.presets)
        presets.push_back({{"group", preset.group}, {"name", preset.name}, {"scene", preset.scene}});
    return page(scene.scene.name, {{"scenes", {sceneWithSource(scene, views)}}, {"presets", presets}}, assets);
}

std::string lessonPage(const Lesson& lesson, const std::vector<int>& stepScenes, const std::vector<LessonScene>& scenes,
                       const WebAssets& assets)
{
    json steps = json::array();
    for (std::size_t k = 0; k < lesson.steps.size(); ++k) {
        const LessonStep& step = lesson.steps[k];
        json entry = {{"scene", stepScenes.at(k)}, {"stage", step.stage}, {"yaw", step.yaw},
                      {"pitch", step.pitch},       {"zoom", step.zoom},   {"caption", step.caption},
                      {"captionPlain", mathSpokenText(step.caption)},
                      // The stages it shows while its question is open and once answered: the app's rule (stepShows).
                      {"askingStage", askingStage(step)}, {"revealedStage", revealedStage(step)}};
        // The point it marks while its question is open and once answered (tracedAt), or null.
        const auto point = [](const std::optional<Vec3<double>>& p) { return p ? json{p->x(), p->y(), p->z()} : json(nullptr); };
        entry["tracedAsking"] = point(tracedAt(step, false));
        entry["tracedAnswered"] = point(tracedAt(step, true));
        // What the step leaves out of its scene and draws wider, for the core to place labels as it shows them.
        entry["shown"] = json::parse(stepShownJson(step));
        if (!step.entries.empty()) { // the stage's equation with those entries marked, as the page's own shows it
            entry["latexStage"] = revealedStage(step);
            entry["latex"] = stageLatex(step.scene, revealedStage(step), 4, step.entries);
        }
        if (step.question) {
            entry["question"] = questionData(*step.question);
            entry["question"]["answerText"] = answerText(step);
            entry["question"]["answerPlain"] = mathSpokenText(answerText(step));
            entry["question"]["offered"] = offeredChoices(*step.question);
            if (step.question->kind == QuestionKind::WhichStage) // its matrix without its name, as the handout shows it
                entry["question"]["matrixLatex"] = stageMatrixLatex(step.scene, step.question->stage, 4);
        }
        steps.push_back(entry);
    }
    json sceneList = json::array();
    for (const LessonScene& s : scenes)
        sceneList.push_back(sceneWithSource(*s.scene, s.views));
    return page(lesson.title, sealed({{"lesson", {{"title", lesson.title}, {"steps", steps}}}, {"scenes", sceneList}}), assets);
}

} // namespace viewpipe::report
