// The module the web page calls: the core and the report library, as the CLI
// and the app call them, behind a few functions that take and give text.

#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <nlohmann/json.hpp>

#include <exception>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include "viewpipe/error.hpp"
#include "viewpipe/evaluated_scene.hpp"
#include "viewpipe/lesson.hpp"
#include "viewpipe/math_text.hpp"
#include "viewpipe/report/report.hpp"
#include "viewpipe/report/web_page.hpp"
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

// Where a scene's files are, in the module's own file system: mesh paths
// resolve against it as they resolve against a scene file's folder.
const std::filesystem::path kSceneFolder = "/scene";

// A file a scene names (a mesh), at the path the scene writes.
Outcome putFile(const std::string& path, const std::string& bytes)
{
    return guarded([&] {
        const std::filesystem::path file = (kSceneFolder / path).lexically_normal();
        std::filesystem::create_directories(file.parent_path());
        std::ofstream out(file, std::ios::binary | std::ios::trunc);
        if (!(out << bytes) || !out.flush())
            throw std::runtime_error("cannot keep " + path);
        return Outcome{file.string(), ""};
    });
}

std::string pipelineText(const EvaluatedScene& evaluated)
{
    const cli::PrecisionChoice precision; // double, as the CLI's default
    return cli::pipelineJson(evaluated.scene, precision, evaluated.outcomes).dump();
}

// What `viewpipe pipeline SCENE --json` prints for a scene's JSON.
Outcome pipelineJson(const std::string& sceneText)
{
    return guarded([&] { return Outcome{pipelineText(*evaluateScene(parseScene(sceneText, kSceneFolder))), ""}; });
}

// The page's font, measured by the page: `measure(runs, pixels, bold)` gives
// [width, height] of one line of the core's math runs, [text, italic, level] each.
FontMeasure pageMeasure(const emscripten::val& measure)
{
    return lineByLine([measure](const std::vector<MathRun>& runs, double pixels, bool bold) {
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

// A scene's JSON as the page shows it. `options` are the page's own: its
// data's width, height, fontSize, minFontSize, lineScale, fixedFraming and dark.
Evaluation evaluate(const std::string& sceneText, const std::string& options, const emscripten::val& measure)
{
    return guarded<Evaluation>([&] {
        const auto evaluated = evaluateScene(parseScene(sceneText, kSceneFolder));
        const nlohmann::json given = nlohmann::json::parse(options);
        WebViewOptions view;
        view.width = given.at("width");
        view.height = given.at("height");
        view.fontSize = given.at("fontSize");
        view.minFontSize = given.at("minFontSize");
        view.lineScale = given.at("lineScale");
        view.fixedFraming = given.at("fixedFraming");
        view.theme = given.at("dark") ? Theme::Dark : Theme::Light;
        const WebPageViews views = webPageViews(*evaluated, view, pageMeasure(measure));
        return Evaluation{webPageData(*evaluated, views), pipelineText(*evaluated), ""};
    });
}

// A student's answer to a lesson's question (`question` as the lesson file
// holds it, about `sceneText`), checked as the app checks it. `typed`: the
// kind's field, {"where": [x, y, z]} or {"entry": n} as typed text, {"choice":
// k}, {"inside": b}, {"signW": s} or {"order": [k, ...]}. Gives {"right": b,
// "answer": a} (a as the results hold it), or the error "unreadable" when the
// text typed is not a number.
Outcome checkAnswer(const std::string& sceneText, const std::string& question, const std::string& typed)
{
    return guarded([&] {
        const Question q = parseQuestion(question, parseScene(sceneText, kSceneFolder));
        const nlohmann::json given = nlohmann::json::parse(typed);
        Answer answer;
        auto number = [](const nlohmann::json& text) {
            const std::optional<double> x = text.is_string() ? parseTypedNumber(text.get<std::string>()) : std::nullopt;
            if (!x)
                throw InputError("answer", "unreadable");
            return *x;
        };
        if (given.contains("where"))
            answer.where = {number(given["where"].at(0)), number(given["where"].at(1)), number(given["where"].at(2))};
        if (given.contains("entry"))
            answer.entry = number(given["entry"]);
        answer.choice = given.value("choice", -1);
        answer.inside = given.value("inside", false);
        answer.signW = given.value("signW", 0);
        answer.order = given.value("order", std::vector<int>{});
        const nlohmann::json checked = {{"right", isRight(q, answer)}, {"answer", nlohmann::json::parse(answerToJson(q, answer))}};
        return Outcome{checked.dump(), ""};
    });
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
    emscripten::function("pipelineJson", &pipelineJson);
    emscripten::function("evaluate", &evaluate);
    emscripten::function("checkAnswer", &checkAnswer);
}
