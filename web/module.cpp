// The module the web page calls: the core and the report library, as the CLI
// and the app call them, behind a few functions that take and give text.

#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <nlohmann/json.hpp>

#include <exception>
#include <filesystem>
#include <fstream>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>

#include "viewpipe/camera_choices.hpp"
#include "viewpipe/effects.hpp"
#include "viewpipe/error.hpp"
#include "viewpipe/evaluated_scene.hpp"
#include "viewpipe/lesson.hpp"
#include "viewpipe/math_text.hpp"
#include "viewpipe/report/code.hpp"
#include "viewpipe/report/report.hpp"
#include "viewpipe/report/trace_table.hpp"
#include "viewpipe/report/web_page.hpp"
#include "viewpipe/report/world_view.hpp"
#include "viewpipe/scene.hpp"

namespace viewpipe::web {
namespace {

// What a call gives the page: its text, or the reason it was refused.
struct Outcome {
    std::string text;
    std::string error; // "field.path: reason", as the CLI prints it after "FILE: "
};

// A scene evaluated for the page: what it draws (the web export's data for
// the scene) and its JSON view (pipelineJson's text), or why it is refused.
struct Evaluation {
    std::string page, pipeline;
    std::string error;
};

// The body's result, or the reason the core refused its input.
template <class Result = Outcome, class Body> Result guarded(Body&& body)
{
    Result refused;
    try {
        return body();
    } catch (const InputError& e) {
        refused.error = e.what();
    } catch (const std::exception& e) {
        refused.error = std::string("internal error: ") + e.what();
    }
    return refused;
}

// A matrix from the 16 numbers the page gives, row by row.
Mat4<double> matrixOfRows(const std::vector<double>& rows)
{
    Mat4<double> m;
    for (int k = 0; k < 16; ++k)
        m(k / 4, k % 4) = rows[std::size_t(k)];
    return m;
}

// Where a scene's files are, in the module's own file system: mesh paths
// resolve against it as they resolve against a scene file's folder.
const std::filesystem::path kSceneFolder = "/scene";

// A file a scene names (a mesh), at the path the scene writes.
Outcome putFile(const std::string& path, const std::string& bytes)
{
    return guarded([&] {
        const std::filesystem::path file = (kSceneFolder / path).lexically_normal();
        std::filesystem::create_directories(file.parent_path());
        std::filesystem::create_directories(kSceneFolder); // a path out of it (../meshes/f.obj) goes through it
        std::ofstream out(file, std::ios::binary | std::ios::trunc);
        if (!(out << bytes) || !out.flush())
            throw std::runtime_error("cannot keep " + path);
        return Outcome{file.string(), ""};
    });
}

// The mesh paths a scene's text names (meshPathsNamed), as a JSON list: where mesh files opened with it go.
std::string meshPaths(const std::string& sceneText)
{
    return nlohmann::json(meshPathsNamed(sceneText)).dump();
}

std::string pipelineText(const EvaluatedScene& evaluated)
{
    const report::PrecisionChoice precision; // double, as the CLI's default
    return report::pipelineJson(evaluated.scene, precision, evaluated.outcomes).dump();
}

// What `viewpipe pipeline SCENE --json` prints for a scene's JSON.
Outcome pipelineJson(const std::string& sceneText)
{
    return guarded([&] { return Outcome{pipelineText(*evaluateScene(parseScene(sceneText, kSceneFolder))), ""}; });
}

// The page's font, measured by the page: `measure(runs, pixels, bold)` gives
// [width, height] of one line of the core's math runs, [text, italic, level] each.
report::FontMeasure pageMeasure(const emscripten::val& measure)
{
    return report::lineByLine([measure](const std::vector<MathRun>& runs, double pixels, bool bold) {
        emscripten::val line = emscripten::val::array();
        for (const MathRun& run : runs) {
            emscripten::val entry = emscripten::val::array();
            entry.call<void>("push", run.text);
            entry.call<void>("push", run.italic);
            entry.call<void>("push", run.level);
            line.call<void>("push", entry);
        }
        const emscripten::val measured = measure(line, pixels, bold);
        return Vec2<double>(measured[0].as<double>(), measured[1].as<double>());
    });
}

// The page's own options: its data's width, height, fontSize, minFontSize, lineScale, framing and dark; and the
// reader's choices, where made: "hidden" (names of hideNames) and "legend" (a name of legendPlaceName); "zoom",
// the page's made-with zoom its text is laid out for.
report::WebViewOptions viewOptions(const std::string& options)
{
    const nlohmann::json given = nlohmann::json::parse(options);
    report::WebViewOptions view;
    view.width = given.at("width");
    view.height = given.at("height");
    view.fontSize = given.at("fontSize");
    view.minFontSize = given.at("minFontSize");
    view.lineScale = given.at("lineScale");
    view.framing = report::framingModeNamed(given.at("framing")).value_or(report::FramingMode::Together);
    view.theme = given.at("dark") ? report::Theme::Dark : report::Theme::Light;
    if (given.contains("hidden"))
        view.hidden = given["hidden"].get<std::set<std::string>>();
    if (given.contains("legend"))
        view.legend = report::legendPlaceNamed(given["legend"]).value_or(report::LegendPlace::Best);
    if (given.contains("zoom"))
        view.zoom = given["zoom"];
    return view;
}

// A scene's text evaluated and drawn without what the reader leaves out (withoutHidden, as export --hide),
// kept for the calls that follow with the same text and choices (turning the view asks for labels many
// times a second); `fresh`: evaluated anew all the same (its meshes may have changed).
std::shared_ptr<const EvaluatedScene> evaluatedOnce(const std::string& sceneText, const std::set<std::string>& hidden,
                                                    bool fresh)
{
    static std::string text;
    static std::set<std::string> leftOut;
    static std::shared_ptr<const EvaluatedScene> evaluated, shown;
    if (fresh || !evaluated || text != sceneText) {
        evaluated = shown = nullptr; // a refused scene keeps none
        evaluated = evaluateScene(parseScene(sceneText, kSceneFolder));
        text = sceneText;
    }
    if (!shown || leftOut != hidden) {
        shown = withoutHidden(evaluated, hidden);
        leftOut = hidden;
    }
    return shown;
}

// A scene's JSON as the page shows it, with the page's `options` (viewOptions): `stage` made at rest, the
// others and the steps' frames left for the page to ask for when it shows them (stageView, transition).
Evaluation evaluate(const std::string& sceneText, const std::string& options, const emscripten::val& measure, int stage)
{
    return guarded<Evaluation>([&] {
        const report::WebViewOptions view = viewOptions(options);
        const auto evaluated = evaluatedOnce(sceneText, view.hidden, true);
        const report::WebPageViews views = webPageViews(*evaluated, view, pageMeasure(measure), {}, stage);
        return Evaluation{webPageData(*evaluated, views), pipelineText(*evaluated), ""};
    });
}

// Stage k at rest (its frame, ghost, layout and labels), as evaluate would have made it.
Outcome stageView(const std::string& sceneText, const std::string& options, int stage, const emscripten::val& measure)
{
    return guarded([&] {
        const report::WebViewOptions view = viewOptions(options);
        const auto evaluated = evaluatedOnce(sceneText, view.hidden, false);
        if (stage < 0 || stage > int(evaluated->pipeline.stages.size()))
            throw std::invalid_argument("stageView: no stage " + std::to_string(stage));
        return Outcome{webStageView(*evaluated, stage, view, pageMeasure(measure)), ""};
    });
}

// The step from stage `from` to the next, frame by frame, as evaluate would have made it.
Outcome transition(const std::string& sceneText, const std::string& options, int from, const emscripten::val& measure)
{
    return guarded([&] {
        const report::WebViewOptions view = viewOptions(options);
        const auto evaluated = evaluatedOnce(sceneText, view.hidden, false);
        if (from < 0 || from >= int(evaluated->pipeline.stages.size()))
            throw std::invalid_argument("transition: no step from stage " + std::to_string(from));
        return Outcome{webTransition(*evaluated, from, view, pageMeasure(measure)), ""};
    });
}

// The scene as a lesson's step shows it (shownAtStep), from the step's
// "shown" in the page's data (stepShownJson); the scene itself for "null".
std::shared_ptr<const EvaluatedScene> shownAs(const std::shared_ptr<const EvaluatedScene>& scene, const std::string& shown)
{
    return shown == "null" ? scene : shownAtStep(scene, stepShownFrom(shown));
}

// Stage k seen through `camera` (16 numbers, row by row: stage coordinates
// -> clip coordinates of the picture `options` sizes), as `draw` makes it
// (webStageLabels, webStageFigure); `shown`: as a lesson's step shows the scene (shownAs).
template <class Draw>
Outcome stageThrough(const char* what, const std::string& sceneText, const std::string& options, int stage,
                     const std::string& camera, const emscripten::val& measure, const std::string& shown, Draw draw)
{
    return guarded([&] {
        const report::WebViewOptions view = viewOptions(options);
        const auto evaluated = shownAs(evaluatedOnce(sceneText, view.hidden, false), shown);
        const std::vector<double> rows = nlohmann::json::parse(camera);
        if (rows.size() != 16 || stage < 0 || stage > int(evaluated->pipeline.stages.size()))
            throw std::invalid_argument(std::string(what) + ": a stage and 16 numbers");
        return Outcome{draw(*evaluated, stage, matrixOfRows(rows), view, pageMeasure(measure)), ""};
    });
}

// The labels placed by the core as at rest: the page's labels while the view is turned.
Outcome placeLabels(const std::string& sceneText, const std::string& options, int stage, const std::string& camera,
                    const emscripten::val& measure, const std::string& shown)
{
    return stageThrough("placeLabels", sceneText, options, stage, camera, measure, shown, report::webStageLabels);
}

// The whole flat figure, as the SVG export draws it: the page's SVG of the view shown.
Outcome stageFigure(const std::string& sceneText, const std::string& options, int stage, const std::string& camera,
                    const emscripten::val& measure, const std::string& shown)
{
    return stageThrough("stageFigure", sceneText, options, stage, camera, measure, shown, report::webStageFigure);
}

// Every stage at once in the page's room (webStoryboard): `room` is {"width", "height"}, `traced` [x, y, z]
// or null, `cameras` null (each cell at rest) or one camera a stage (16 numbers, row by row, as stageThrough's);
// `shapes`: each cell's lines and faces too (the storyboard saved as SVG).
Outcome storyboard(const std::string& sceneText, const std::string& options, const std::string& room,
                   const std::string& traced, const std::string& cameras, const emscripten::val& measure, bool shapes)
{
    return guarded([&] {
        const report::WebViewOptions view = viewOptions(options);
        const auto evaluated = evaluatedOnce(sceneText, view.hidden, false);
        const nlohmann::json size = nlohmann::json::parse(room), point = nlohmann::json::parse(traced),
                             turned = nlohmann::json::parse(cameras);
        std::optional<Vec3<double>> tracedPoint;
        if (!point.is_null())
            tracedPoint = Vec3<double>(point.at(0), point.at(1), point.at(2));
        std::vector<Mat4<double>> clips;
        for (const nlohmann::json& rows : turned.is_null() ? nlohmann::json::array() : turned) {
            if (rows.size() != 16)
                throw std::invalid_argument("storyboard: 16 numbers a camera");
            clips.push_back(matrixOfRows(rows.get<std::vector<double>>()));
        }
        return Outcome{webStoryboard(*evaluated, size.at("width"), size.at("height"), tracedPoint, clips, view,
                                     pageMeasure(measure), shapes),
                       ""};
    });
}

// The vertex a click at `at` picks (pickVertex, as the app picks): `vertices` the page's (x, y, z each, a
// typed array), `drawn` 16 numbers row by row (world -> clip coordinates), `size` and `window` [width,
// height] and `at` [x, y] in pixels, `cut` 4 numbers or null. [x, y, z] or null.
Outcome pickVertexAt(const emscripten::val& vertices, const std::string& drawn, const std::string& size,
                     const std::string& at, const std::string& window, const std::string& cut)
{
    return guarded([&] {
        const std::vector<double> flat = emscripten::convertJSArrayToNumberVector<double>(vertices);
        std::vector<Vec3<double>> points;
        for (std::size_t k = 0; k + 2 < flat.size(); k += 3)
            points.emplace_back(flat[k], flat[k + 1], flat[k + 2]);
        const std::vector<double> rows = nlohmann::json::parse(drawn);
        const nlohmann::json view = nlohmann::json::parse(size), click = nlohmann::json::parse(at),
                             whole = nlohmann::json::parse(window), plane = nlohmann::json::parse(cut);
        if (rows.size() != 16)
            throw std::invalid_argument("pickVertex: 16 numbers");
        const Mat4<double> clip = matrixOfRows(rows);
        std::optional<Vec4<double>> kept;
        if (!plane.is_null())
            kept = Vec4<double>(plane.at(0), plane.at(1), plane.at(2), plane.at(3));
        const std::optional<Vec3<double>> picked =
            report::pickVertex(points, clip, Vec2<double>(view.at(0), view.at(1)), Vec2<double>(click.at(0), click.at(1)),
                       Vec2<double>(whole.at(0), whole.at(1)), kept);
        return Outcome{picked ? nlohmann::json{picked->x(), picked->y(), picked->z()}.dump() : "null", ""};
    });
}

// The world view as the reader turned it (report::turnedCamera): `view` and `projection` 16 numbers each, row by
// row, `focal` [x, y, z]; the turned view's rows then the projection's, 32 numbers (null for other sizes). Asked
// for each frame drawn: numbers in and out, no text.
emscripten::val turnedCameraOf(const emscripten::val& view, const emscripten::val& projection, const emscripten::val& focal,
                               double yawDegrees, double pitchDegrees, double zoom)
{
    const std::vector<double> viewRows = emscripten::convertJSArrayToNumberVector<double>(view),
                              projectionRows = emscripten::convertJSArrayToNumberVector<double>(projection),
                              point = emscripten::convertJSArrayToNumberVector<double>(focal);
    if (viewRows.size() != 16 || projectionRows.size() != 16 || point.size() != 3)
        return emscripten::val::null();
    const report::TurnedCamera turned = report::turnedCamera(matrixOfRows(viewRows), matrixOfRows(projectionRows),
                                                             Vec3<double>(point[0], point[1], point[2]), yawDegrees,
                                                             pitchDegrees, zoom);
    std::vector<double> rows;
    for (const Mat4<double>* m : {&turned.view, &turned.projection})
        for (int k = 0; k < 16; ++k)
            rows.push_back((*m)(k / 4, k % 4));
    return emscripten::val::array(rows);
}

// A scene's text read without its objects, for what its camera and effects decide: the meshes may not be
// in the module's files (a page may leave them out).
Scene cameraScene(const std::string& sceneText)
{
    nlohmann::json scene = nlohmann::json::parse(sceneText);
    scene.erase("objects");
    return parseScene(scene.dump(), kSceneFolder);
}

// A lesson's question (`question` as the lesson file holds it) about `sceneText`.
Question questionAbout(const std::string& sceneText, const std::string& question)
{
    return parseQuestion(question, cameraScene(sceneText));
}

// A vertex traced through the stages, as the app's Matrices panel shows it (report::traceTable, the
// pipeline computed exactly too): `point` [x, y, z], rows up to stage `lastRow`. {"rows": [{"stage",
// "cells"}], "verdict"}, texts with math between dollars, and "spoken": the point as a screen reader says it.
Outcome traceTable(const std::string& sceneText, const std::string& point, int lastRow)
{
    return guarded([&] {
        static std::string text; // the pipelines of the scene last traced: a click or a step traces again
        static std::optional<std::pair<Pipeline<double>, Pipeline<Exact>>> pipelines;
        if (!pipelines || text != sceneText) {
            pipelines.reset();
            const Scene scene = cameraScene(sceneText);
            pipelines.emplace(buildPipeline(scene.camera, scene.effects), exactPipeline(scene));
            text = sceneText;
        }
        const nlohmann::json at = nlohmann::json::parse(point);
        const report::TraceTable table =
            report::traceTable(pipelines->first, &pipelines->second, Vec3<double>(at.at(0), at.at(1), at.at(2)), lastRow);
        nlohmann::json rows = nlohmann::json::array();
        for (const report::TraceTable::Row& row : table.rows)
            rows.push_back({{"stage", row.stage}, {"cells", row.cells}});
        const std::array<std::string, 4>& world = table.rows.front().cells;
        const std::string spoken = mathSpokenText("(" + world[0] + ", " + world[1] + ", " + world[2] + ")");
        return Outcome{nlohmann::json{{"rows", rows}, {"verdict", table.verdict}, {"spoken", spoken}}.dump(), ""};
    });
}

// A student's answer to `q` as the page gives it: the kind's field, {"where":
// [x, y, z]} or {"entry": n} as typed text (kept as typed), {"choice": k},
// {"inside": b}, {"signW": s} or {"order": [k, ...]}. A text typed that is no
// number is refused as the app refuses it, naming its field: "x: is empty: ...",
// "entry: unexpected "*" at character 4 of "2 +* 3"".
Answer readAnswer(const Question& q, const nlohmann::json& given)
{
    Answer answer;
    auto number = [&answer](const nlohmann::json& text, const char* field) {
        if (!text.is_string())
            throw InputError(std::string("answer.") + field, "must be the text typed");
        answer.typed.push_back(text.get<std::string>());
        return typedNumber(answer.typed.back(), field);
    };
    // A whole number in [low, high], as the page's controls give it.
    auto index = [](const nlohmann::json& k, int low, int high, const char* what) {
        if (!k.is_number_integer() || k.get<int>() < low || k.get<int>() > high)
            throw InputError(std::string("answer.") + what, "must be a whole number from " + std::to_string(low) +
                                                               " to " + std::to_string(high));
        return k.get<int>();
    };
    const int choices = int(q.choices.size());
    if (given.contains("where")) {
        if (!given["where"].is_array() || given["where"].size() != 3)
            throw InputError("answer.where", "must be three typed numbers");
        const double x = number(given["where"][0], "x"), y = number(given["where"][1], "y"), z = number(given["where"][2], "z");
        answer.where = {x, y, z};
    }
    if (given.contains("entry"))
        answer.entry = number(given["entry"], "entry");
    if (given.contains("choice"))
        answer.choice = index(given["choice"], 0, choices - 1, "choice");
    if (given.contains("inside")) {
        if (!given["inside"].is_boolean())
            throw InputError("answer.inside", "must be true or false");
        answer.inside = given["inside"].get<bool>();
    }
    if (given.contains("signW"))
        answer.signW = index(given["signW"], -1, 1, "signW");
    if (given.contains("order")) {
        if (!given["order"].is_array() || int(given["order"].size()) != choices)
            throw InputError("answer.order", "must list each of the " + std::to_string(choices) + " stages once");
        std::vector<bool> seen(std::size_t(choices), false);
        for (const nlohmann::json& k : given["order"]) {
            const int c = index(k, 0, choices - 1, "order");
            if (seen[std::size_t(c)])
                throw InputError("answer.order", "must list each of the " + std::to_string(choices) + " stages once");
            seen[std::size_t(c)] = true;
            answer.order.push_back(c);
        }
    }
    return answer;
}

// A student's answer (readAnswer's `typed`) to a lesson's question about
// `sceneText`, checked as the app checks it: {"right": b, "answer": a} (a as
// the results hold it), or the error refusing it ("entry: ...", readAnswer).
Outcome checkAnswer(const std::string& sceneText, const std::string& question, const std::string& typed)
{
    return guarded([&] {
        const Question q = questionAbout(sceneText, question);
        const Answer answer = readAnswer(q, nlohmann::json::parse(typed));
        const nlohmann::json checked = {{"right", isRight(q, answer)}, {"answer", nlohmann::json::parse(answerToJson(q, answer))}};
        return Outcome{checked.dump(), ""};
    });
}

// A student's answers as the results file holds them (resultsToJson, as the
// app saves them). `steps`: one entry a lesson step, null without a question,
// else {"scene", "question" (as checkAnswer takes them), "given" (the last
// answer checked, as checkAnswer takes it, or null), "tries", "closed" (its
// answer shown: answered, or revealed without an answer)}.
Outcome lessonResults(const std::string& title, const std::string& steps)
{
    return guarded([&] {
        Lesson lesson;
        lesson.title = title;
        std::vector<std::optional<Answer>> answers;
        std::vector<bool> closed;
        std::vector<int> tries;
        for (const nlohmann::json& step : nlohmann::json::parse(steps)) {
            LessonStep& shown = lesson.steps.emplace_back();
            answers.emplace_back();
            closed.push_back(!step.is_null() && step.at("closed").get<bool>());
            tries.push_back(step.is_null() ? 0 : step.at("tries").get<int>());
            if (step.is_null())
                continue;
            shown.question = questionAbout(step.at("scene"), step.at("question"));
            if (!step.at("given").is_null())
                answers.back() = readAnswer(*shown.question, step["given"]);
        }
        return Outcome{resultsToJson(lesson, answers, closed, tries), ""};
    });
}

// UTF-16 code units before byte `offset` of UTF-8 `text`: where JavaScript's strings count it.
std::size_t utf16Offset(const std::string& text, std::size_t offset)
{
    std::size_t units = 0;
    for (std::size_t k = 0; k < offset && k < text.size(); ++k) {
        const auto byte = static_cast<unsigned char>(text[k]);
        if ((byte & 0xC0) != 0x80) // a character's first byte; four-byte ones take two units
            units += byte >= 0xF0 ? 2 : 1;
    }
    return units;
}

// A look-at scene's camera as code in a dialect ("opengl", ... as --dialect
// names them), as the app's Code panel shows it: {"text", "numbers": [{"start",
// "end", "field", "value", "tooltip"}]}, start and end as JavaScript counts.
// A Foley view is refused: no API writes it as code.
Outcome cameraCode(const std::string& sceneText, const std::string& dialect)
{
    return guarded([&] {
        const Scene scene = parseScene(sceneText, kSceneFolder);
        const report::CameraCode written =
            report::cameraCode(lookAtCamera(scene, "the code dialects"), report::dialectNamed(dialect, "dialect"));
        nlohmann::json numbers = nlohmann::json::array();
        for (const report::CodeNumber& n : written.numbers)
            numbers.push_back({{"start", utf16Offset(written.text, n.offset)},
                               {"end", utf16Offset(written.text, n.offset + n.length)},
                               {"field", n.field},
                               {"value", n.value},
                               {"tooltip", n.tooltip}});
        return Outcome{nlohmann::json{{"text", written.text}, {"numbers", numbers}}.dump(), ""};
    });
}

// The dialects, [{"name", "title"}], in the app's order.
std::string codeDialects()
{
    nlohmann::json dialects = nlohmann::json::array();
    for (const report::Dialect d : report::kDialects)
        dialects.push_back({{"name", report::dialectName(d)}, {"title", report::dialectTitle(d)}});
    return dialects.dump();
}

// The scene with one of its code's numbers set (report::withField) or with
// pasted code applied (report::applyCode): its JSON anew, or why not.
Outcome withCodeNumber(const std::string& sceneText, const std::string& field, double value)
{
    return guarded([&] {
        Scene scene = parseScene(sceneText, kSceneFolder);
        scene.camera = report::withField(lookAtCamera(scene, "the code dialects"), field, value);
        return Outcome{sceneToJson(scene, kSceneFolder), ""};
    });
}

Outcome withPastedCode(const std::string& sceneText, const std::string& pasted)
{
    return guarded([&] {
        Scene scene = parseScene(sceneText, kSceneFolder);
        scene.camera = report::applyCode(lookAtCamera(scene, "the code dialects"), pasted);
        return Outcome{sceneToJson(scene, kSceneFolder), ""};
    });
}

// The scene with a field of the page's Scene panel set to the text typed (withTypedField: a decimal in a
// number's field is that number, other text stays text for parseScene to read): its JSON anew, or why not.
Outcome withTypedFieldOf(const std::string& sceneText, const std::string& path, const std::string& typed, bool number)
{
    return guarded([&] { return Outcome{withTypedField(sceneText, path, typed, number), ""}; });
}

// The scene camera's settings picked from a list, as the app's Parameters
// list them (cameraChoices): [{"field", "title", "options", "chosen"}].
Outcome cameraChoicesOf(const std::string& sceneText)
{
    return guarded([&] {
        nlohmann::json choices = nlohmann::json::array();
        for (const CameraChoice& c : cameraChoices(parseScene(sceneText, kSceneFolder).camera))
            choices.push_back({{"field", c.field}, {"title", c.title}, {"options", c.options}, {"chosen", c.chosen}});
        return Outcome{choices.dump(), ""};
    });
}

// The scene with option `index` of its camera's choice `field` taken
// (withChoice): its JSON anew, or why not.
Outcome withCameraChoice(const std::string& sceneText, const std::string& field, int index)
{
    return guarded([&] {
        Scene scene = parseScene(sceneText, kSceneFolder);
        scene.camera = withChoice(scene.camera, field, index);
        return Outcome{sceneToJson(scene, kSceneFolder), ""};
    });
}

// The scene camera's numbers typed as exact expressions, {"view.prp[2]": "20*sqrt(2)"}
// (Scene::typedExpressions): the fields whose JSON holds text for a number.
Outcome typedExpressionsOf(const std::string& sceneText)
{
    return guarded([&] { return Outcome{nlohmann::json(cameraScene(sceneText).typedExpressions).dump(), ""}; });
}

} // namespace
} // namespace viewpipe::web

EMSCRIPTEN_BINDINGS(viewpipe)
{
    using namespace viewpipe::web;
    emscripten::value_object<Outcome>("Outcome").field("text", &Outcome::text).field("error", &Outcome::error);
    emscripten::value_object<Evaluation>("Evaluation")
        .field("page", &Evaluation::page)
        .field("pipeline", &Evaluation::pipeline)
        .field("error", &Evaluation::error);
    emscripten::function("putFile", &putFile);
    emscripten::function("meshPaths", &meshPaths);
    emscripten::function("pipelineJson", &pipelineJson);
    emscripten::function("evaluate", &evaluate);
    emscripten::function("stageView", &stageView);
    emscripten::function("transition", &transition);
    emscripten::function("placeLabels", &placeLabels);
    emscripten::function("stageFigure", &stageFigure);
    emscripten::function("pickVertex", &pickVertexAt);
    emscripten::function("turnedCamera", &turnedCameraOf);
    emscripten::function("traceTable", &traceTable);
    emscripten::function("storyboard", &storyboard);
    emscripten::function("checkAnswer", &checkAnswer);
    emscripten::function("lessonResults", &lessonResults);
    emscripten::function("codeDialects", &codeDialects);
    emscripten::function("cameraCode", &cameraCode);
    emscripten::function("withCodeNumber", &withCodeNumber);
    emscripten::function("withPastedCode", &withPastedCode);
    emscripten::function("withTypedField", &withTypedFieldOf);
    emscripten::function("steppedValue", &viewpipe::report::steppedValue);
    emscripten::function("cameraChoices", &cameraChoicesOf);
    emscripten::function("withCameraChoice", &withCameraChoice);
    emscripten::function("typedExpressions", &typedExpressionsOf);
}
