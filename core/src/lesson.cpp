#include "viewpipe/lesson.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <set>

#include "file_paths.hpp"
#include "json_fields.hpp"
#include "viewpipe/exact.hpp"
#include "viewpipe/format.hpp"
#include "viewpipe/math_text.hpp"

namespace viewpipe {
namespace {

using namespace fields;

constexpr std::size_t kMaxSteps = 200;

const std::pair<QuestionKind, const char*> kKindNames[] = {
    {QuestionKind::Where, "where"},          {QuestionKind::Inside, "inside"}, {QuestionKind::SignW, "sign_w"},
    {QuestionKind::WhichStage, "which_stage"}, {QuestionKind::Order, "order"}, {QuestionKind::Entry, "entry"},
    {QuestionKind::Choice, "choice"}};

double readIn(const Json& j, const std::string& path, double low, double high)
{
    const double x = readNumber(j, path);
    if (x < low || x > high)
        throw InputError(path, "must lie between " + formatShortest(low) + " and " + formatShortest(high) + " (got " +
                                   formatShortest(x) + ")");
    return x;
}

int readIndex(const Json& j, const std::string& path, int low, int high)
{
    const std::string range = "must be a whole number from " + std::to_string(low) + " to " + std::to_string(high);
    if (!j.is_number())
        throw InputError(path, range + " (got " + found(j) + ")");
    const double k = j.get<double>(); // 2.0 is 2; 2^64 is out of range, not -1
    if (!(k >= low && k <= high) || k != std::floor(k))
        throw InputError(path, range + " (got " + j.dump() + ")");
    return int(k);
}

// Text with inline math: the math within the subset every renderer sets (math_text.hpp).
std::string readCaption(const Json& j, const std::string& path, bool required)
{
    const std::string text = readString(j, path);
    if (required && text.find_first_not_of(" \t\n") == std::string::npos)
        throw InputError(path, "is empty");
    checkMathText(text, path);
    return text;
}

std::string vecText(const Vec3<double>& v)
{
    return "(" + formatShortest(v.x()) + ", " + formatShortest(v.y()) + ", " + formatShortest(v.z()) + ")";
}

Scene readStepScene(const Json& j, const std::string& path, const std::filesystem::path& baseDir)
{
    if (j.is_string()) {
        const std::filesystem::path file = baseDir / j.get<std::string>();
        try {
            return loadScene(file);
        } catch (const InputError& e) { // "$" is the file as a whole: its reason alone
            throw InputError(path, j.get<std::string>() + ": " + (e.field() == "$" ? e.reason() : e.what()));
        }
    }
    if (!j.is_object())
        throw InputError(path, "must be a scene file's path or a scene object (got " + found(j) + ")");
    try {
        Scene scene = parseScene(j.dump(), baseDir);
        if (scene.name.empty())
            scene.name = "inline scene";
        return scene;
    } catch (const InputError& e) {
        throw InputError(path + "." + e.field(), e.reason());
    }
}

// Whether values given (typed by a student, or written in the lesson) pass `rule` against the question's
// answer; `rule` is a generic lambda taking both as std::vector<Exact> or std::vector<double>. Exactly where
// both are exact, so that no rounding decides a verdict; else in double (gluPerspective at 50 degrees, whose
// cotangent is no root; a nested root typed).
template <class Rule>
bool judged(const std::optional<std::vector<Exact>>& given, const std::vector<double>& givenValues, const Question& q,
            const std::vector<double>& answerValues, Rule rule)
{
    const auto exact = [](const std::vector<Exact>& values) {
        return std::all_of(values.begin(), values.end(), [](const Exact& x) { return x.isExact(); });
    };
    if (given && q.exact && given->size() == q.exact->size() && exact(*given) && exact(*q.exact))
        return rule(*given, *q.exact);
    return rule(givenValues, answerValues);
}

template <class T> T squared(const T& x)
{
    return x * x;
}

// A tolerance the lesson writes, in the type compared: exactly, the decimal written.
template <class T> T toleranceOf(double x)
{
    if constexpr (isExactScalar<T>)
        return fromDecimal<Exact>(x);
    else
        return x;
}

// A point within `tolerance` times the answer's size (at least 1): compared squared, so that an exact
// distance needs no square root (a root of a sum of roots is no exact number).
template <class T> bool pointWithin(const std::vector<T>& given, const std::vector<T>& answer, double tolerance)
{
    T distance(0), size(0);
    for (std::size_t i = 0; i < answer.size(); ++i) {
        distance += squared(T(given[i] - answer[i]));
        size += squared(answer[i]);
    }
    return distance <= squared(toleranceOf<T>(tolerance)) * (size < T(1) ? T(1) : size); // false for a NaN
}

// Numbers the lesson writes, each a JSON number or an exact expression ("-13/36"), read as scene fields
// are: `values` gets each one's double; returned, each one's expression as written, empty for a number.
std::vector<std::string> readTyped(const Json& j, const std::string& path, std::size_t count, std::vector<double>& values)
{
    std::map<std::string, std::string> typed;
    const TypedExpressions scope(typed);
    values = count == 1 ? std::vector<double>{readNumber(j, path)} : readNumbers(j, path, count);
    std::vector<std::string> texts;
    for (std::size_t i = 0; i < values.size(); ++i) {
        const auto expression = typed.find(count == 1 ? path : element(path, i));
        texts.push_back(expression != typed.end() ? expression->second : "");
    }
    return texts;
}

// A number exactly: its expression as written, else the decimal written.
Exact exactly(const std::string& typed, double value)
{
    return typed.empty() ? fromDecimal<Exact>(value) : parseExact(typed);
}

// A number the lesson writes as an answer, exactly. `values` gets each one's double.
std::vector<Exact> readWritten(const Json& j, const std::string& path, std::size_t count, std::vector<double>& values)
{
    const std::vector<std::string> typed = readTyped(j, path, count, values);
    std::vector<Exact> exact;
    for (std::size_t i = 0; i < values.size(); ++i)
        exact.push_back(exactly(typed[i], values[i]));
    return exact;
}

// The question's answer as the scene gives it; an answer the file writes must agree with it. The verdicts
// (inside, the sign of w) and the exact answer a typed one is judged against come from the scene computed
// exactly (exactPipeline, the point as typed: exactPoint), as `viewpipe trace` decides them.
void solveQuestion(Question& q, const Json& j, const std::string& path, const Scene& scene, const Pipeline<double>& pipeline)
{
    const int n = int(pipeline.stages.size());
    const PointTrace<double> trace = tracePoint(pipeline, q.point);
    const std::string answerPath = child(path, "answer");
    const Json* answer = j.contains("answer") ? &j["answer"] : nullptr;
    std::optional<Pipeline<Exact>> exact;
    std::optional<PointTrace<Exact>> exactTrace;
    if (q.kind == QuestionKind::Where || q.kind == QuestionKind::Inside || q.kind == QuestionKind::SignW ||
        q.kind == QuestionKind::Entry) {
        try {
            exact = exactPipeline(scene);
        } catch (const std::exception&) { // refused exactly: the doubles answer alone
        }
        if (exact && q.kind != QuestionKind::Entry)
            exactTrace = tracePoint(*exact, exactPoint(q));
    }
    switch (q.kind) {
    case QuestionKind::Where: {
        const Vec4<double> p = trace.afterStage[std::size_t(q.stage - 1)];
        if (!p.allFinite())
            throw InputError(child(path, "point"), "has no finite image after stage " + std::to_string(q.stage));
        // An image in front of the eye or behind it (a false image, still an answer), as the pictures judge it.
        if (!inFrontOfEye(p) && !inFrontOfEye(-p))
            throw InputError(child(path, "point"), "has w = 0 (or too near it to be drawn) after stage " +
                                                       std::to_string(q.stage) + ": it lands nowhere (at infinity)");
        q.where = p.head<3>() / p.w();
        if (exactTrace) {
            const Vec4<Exact>& e = exactTrace->afterStage[std::size_t(q.stage - 1)];
            if (e.w().sign() != 0)
                q.exact = std::make_shared<const std::vector<Exact>>(std::vector<Exact>{e.x() / e.w(), e.y() / e.w(), e.z() / e.w()});
        }
        if (answer) {
            std::vector<double> values;
            const std::vector<Exact> written = readWritten(*answer, answerPath, 3, values);
            const auto within = [&](const auto& given, const auto& answer) { return pointWithin(given, answer, q.tolerance); };
            if (!judged(written, values, q, {q.where.x(), q.where.y(), q.where.z()}, within))
                throw InputError(answerPath, "is " + vecText({values[0], values[1], values[2]}) + " but the scene gives " +
                                                 vecText(q.where));
        }
        break;
    }
    case QuestionKind::Inside:
        if (!trace.clip.allFinite())
            throw InputError(child(path, "point"), "has no finite clip coordinates");
        q.inside = exactTrace ? clipVerdict(exactTrace->clip, exact->clipVolume).inside : trace.inside;
        if (answer) {
            if (!answer->is_boolean())
                throw InputError(answerPath, "must be true or false (got " + found(*answer) + ")");
            if (answer->get<bool>() != q.inside)
                throw InputError(answerPath, std::string("is ") + (answer->get<bool>() ? "true" : "false") +
                                                 " but the point is " + (q.inside ? "inside" : "outside"));
        }
        break;
    case QuestionKind::SignW: {
        const double w = trace.afterStage[std::size_t(q.stage - 1)].w();
        if (!std::isfinite(w))
            throw InputError(child(path, "point"), "has no finite w after stage " + std::to_string(q.stage));
        q.signW = exactTrace ? exactTrace->afterStage[std::size_t(q.stage - 1)].w().sign() : w > 0 ? 1 : w < 0 ? -1 : 0;
        if (answer) {
            const std::string written = readString(*answer, answerPath);
            const std::string sign = q.signW > 0 ? "positive" : q.signW < 0 ? "negative" : "zero";
            if (written != "positive" && written != "zero" && written != "negative")
                throw InputError(answerPath, "must be \"positive\", \"zero\" or \"negative\" (got \"" + written + "\")");
            if (written != sign)
                throw InputError(answerPath, "is " + written + " but w is " +
                                                 (exactTrace ? exactTrace->afterStage[std::size_t(q.stage - 1)].w().text()
                                                             : formatShortest(w)) + " (" + sign + ")");
        }
        break;
    }
    case QuestionKind::WhichStage:
        q.correct = q.stage - 1;
        if (answer && stageKindNamed(readString(*answer, answerPath)) != pipeline.stages[std::size_t(q.correct)].kind)
            throw InputError(answerPath, "is \"" + answer->get<std::string>() + "\" but stage " +
                                             std::to_string(q.stage) + " is " + q.choices[std::size_t(q.correct)]);
        break;
    case QuestionKind::Order:
        if (answer)
            throw InputError(answerPath, "is the scene's order of stages: leave it out");
        if (n < 2)
            throw InputError(path, "needs a scene with two stages or more");
        break;
    case QuestionKind::Entry: {
        q.row = readIndex(j["row"], child(path, "row"), 1, 4);
        q.column = readIndex(j["column"], child(path, "column"), 1, 4);
        const Stage<double>& stage = pipeline.stages[std::size_t(q.stage - 1)];
        if (stage.divides())
            throw InputError(child(path, "stage"), "is the divide, which has no matrix");
        q.entry = stage.matrix(q.row - 1, q.column - 1);
        if (exact)
            q.exact = std::make_shared<const std::vector<Exact>>(
                std::vector<Exact>{exact->stages[std::size_t(q.stage - 1)].matrix(q.row - 1, q.column - 1)});
        if (answer) {
            std::vector<double> values;
            const std::vector<Exact> written = readWritten(*answer, answerPath, 1, values);
            const auto agrees = [](const auto& given, const auto& answer) { // within 1e-9 times its size (at least 1)
                using T = std::decay_t<decltype(answer[0])>;
                using std::abs;
                const T size = abs(answer[0]);
                return abs(T(given[0] - answer[0])) <= T(1) / T(1000000000) * (size < T(1) ? T(1) : size);
            };
            if (!judged(written, values, q, {q.entry}, agrees))
                throw InputError(answerPath, "is " + (answer->is_string() ? answer->get<std::string>() : formatShortest(values[0])) +
                                                 " but the entry is " + formatShortest(q.entry) +
                                                 (q.exact && q.exact->front().readsExactly() ? " (" + q.exact->front().text() + ")" : ""));
        }
        break;
    }
    case QuestionKind::Choice: {
        const Json& choices = j["choices"];
        if (!choices.is_array() || choices.size() < 2 || choices.size() > 8)
            throw InputError(child(path, "choices"), "must be an array of 2 to 8 strings");
        for (std::size_t k = 0; k < choices.size(); ++k)
            q.choices.push_back(readCaption(choices[k], element(child(path, "choices"), k), true));
        q.correct = readIndex(*answer, answerPath, 0, int(choices.size()) - 1);
        break;
    }
    }
}

Question readQuestion(const Json& j, const std::string& path, const Scene& scene, const Pipeline<double>& pipeline)
{
    if (!j.is_object())
        throw InputError(path, "must be an object (got " + found(j) + ")");
    if (!j.contains("kind"))
        throw InputError(child(path, "kind"), "is missing");
    const std::string kindName = readString(j["kind"], child(path, "kind"));
    const auto named = std::find_if(std::begin(kKindNames), std::end(kKindNames),
                                    [&](const auto& entry) { return kindName == entry.second; });
    if (named == std::end(kKindNames))
        throw InputError(child(path, "kind"), "must be one of where, inside, sign_w, which_stage, order, entry, "
                                              "choice (got \"" + kindName + "\")");
    Question q;
    q.kind = named->first;
    const std::set<std::string> common = {"kind", "prompt", "explanation", "answer", "tries"};
    auto keys = [&](std::set<std::string> own, std::set<std::string> required) {
        own.insert(common.begin(), common.end());
        required.insert({"kind", "prompt"});
        requireObject(j, path, own, required);
    };
    const int n = int(pipeline.stages.size());
    switch (q.kind) {
    case QuestionKind::Where: keys({"point", "after", "tolerance"}, {"point", "after"}); break;
    case QuestionKind::Inside: keys({"point"}, {"point"}); break;
    case QuestionKind::SignW: keys({"point", "after"}, {"point", "after"}); break;
    case QuestionKind::WhichStage: keys({"stage"}, {"stage"}); break;
    case QuestionKind::Order: keys({}, {}); break;
    case QuestionKind::Entry: keys({"stage", "row", "column"}, {"stage", "row", "column"}); break;
    case QuestionKind::Choice: keys({"choices"}, {"choices", "answer"}); break;
    }
    q.prompt = readCaption(j["prompt"], child(path, "prompt"), true);
    if (j.contains("explanation"))
        q.explanation = readCaption(j["explanation"], child(path, "explanation"), false);
    if (j.contains("point")) {
        std::vector<double> point;
        const std::vector<std::string> typed = readTyped(j["point"], child(path, "point"), 3, point);
        q.point = {point[0], point[1], point[2]};
        std::copy(typed.begin(), typed.end(), q.pointTyped.begin());
    }
    if (j.contains("after"))
        q.stage = readIndex(j["after"], child(path, "after"), 1, n);
    if (j.contains("stage"))
        q.stage = readIndex(j["stage"], child(path, "stage"), 1, n);
    if (j.contains("tolerance"))
        q.tolerance = readIn(j["tolerance"], child(path, "tolerance"), 1e-9, 1);
    if (j.contains("tries"))
        q.tries = readIndex(j["tries"], child(path, "tries"), 1, 10);
    for (const Stage<double>& stage : pipeline.stages)
        if (q.kind == QuestionKind::WhichStage || q.kind == QuestionKind::Order)
            q.choices.push_back(stage.symbol());

    solveQuestion(q, j, path, scene, pipeline);
    return q;
}

// An array of element names; "labels" and "legend" too where `step` is given (whose labelsHidden and
// legendHidden say whether the array names them).
std::set<Element> readElements(const Json& j, const std::string& path, LessonStep* step)
{
    if (!j.is_array())
        throw InputError(path, "must be an array of element names (got " + found(j) + ")");
    std::set<Element> elements;
    for (std::size_t k = 0; k < j.size(); ++k) {
        const std::string name = readString(j[k], element(path, k));
        if (step && (name == "labels" || name == "legend")) {
            (name == "labels" ? step->labelsHidden : step->legendHidden) = true;
            continue;
        }
        const auto& names = lessonElementNames();
        const auto known = std::find_if(names.begin(), names.end(), [&](const auto& entry) { return name == entry.second; });
        if (known == names.end()) {
            std::string all;
            for (const auto& entry : names)
                all += std::string(all.empty() ? "" : ", ") + entry.second;
            throw InputError(element(path, k), "must be one of " + all + (step ? ", labels, legend" : "") + " (got \"" + name + "\")");
        }
        elements.insert(known->first);
    }
    return elements;
}

void readShown(const Json& j, const std::string& path, LessonStep& step, const Pipeline<double>& pipeline)
{
    static const std::vector<std::string> panels = {"stages", "matrices", "parameters", "code", "accuracy", "depth"};
    if (j.contains("hide"))
        step.hidden = readElements(j["hide"], child(path, "hide"), &step);
    if (j.contains("highlight")) {
        const std::string at = child(path, "highlight");
        requireObject(j["highlight"], at, {"elements", "entries"}, {});
        const Json& h = j["highlight"];
        if (h.contains("elements"))
            step.highlighted = readElements(h["elements"], child(at, "elements"), nullptr);
        if (h.contains("entries")) {
            const std::string list = child(at, "entries");
            const int stage = revealedStage(step);
            if (stage == 0)
                throw InputError(list, "the world (stage 0) has no matrix to highlight");
            if (pipeline.stages[std::size_t(stage - 1)].divides())
                throw InputError(list, "stage " + std::to_string(stage) + " is the divide, which has no matrix");
            if (!h["entries"].is_array())
                throw InputError(list, "must be an array of [row, column] pairs (got " + found(h["entries"]) + ")");
            for (std::size_t k = 0; k < h["entries"].size(); ++k) {
                const Json& entry = h["entries"][k];
                const std::string item = element(list, k);
                if (!entry.is_array() || entry.size() != 2)
                    throw InputError(item, "must be [row, column] (got " + entry.dump() + ")");
                step.entries.push_back({readIndex(entry[0], element(item, 0), 1, 4), readIndex(entry[1], element(item, 1), 1, 4)});
            }
        }
    }
    if (j.contains("layout")) {
        const std::string layout = readString(j["layout"], child(path, "layout"));
        if (layout != "stages" && layout != "storyboard")
            throw InputError(child(path, "layout"), "must be stages or storyboard (got \"" + layout + "\")");
        step.storyboard = layout == "storyboard";
    }
    if (j.contains("panel")) {
        step.panel = readString(j["panel"], child(path, "panel"));
        if (std::find(panels.begin(), panels.end(), step.panel) == panels.end())
            throw InputError(child(path, "panel"), "must be one of stages, matrices, parameters, code, accuracy, depth (got \"" +
                                                       step.panel + "\")");
    }
}

LessonStep readStep(const Json& j, const std::string& path, const std::filesystem::path& baseDir)
{
    requireObject(j, path, {"scene", "stage", "camera", "caption", "trace", "question", "hide", "highlight", "panel", "layout"},
                  {"scene", "caption"});
    LessonStep step;
    step.scene = readStepScene(j["scene"], child(path, "scene"), baseDir);
    const Pipeline<double> pipeline = buildPipeline(step.scene.camera, step.scene.effects);
    if (j.contains("stage"))
        step.stage = readIndex(j["stage"], child(path, "stage"), 0, int(pipeline.stages.size()));
    if (j.contains("camera")) {
        const std::string at = child(path, "camera");
        requireObject(j["camera"], at, {"yaw", "pitch", "zoom"}, {});
        const Json& c = j["camera"];
        using L = ViewLimits;
        step.yaw = c.contains("yaw") ? readIn(c["yaw"], child(at, "yaw"), -L::kYawDegrees, L::kYawDegrees) : 0;
        step.pitch = c.contains("pitch") ? readIn(c["pitch"], child(at, "pitch"), -L::kPitchDegrees, L::kPitchDegrees) : 0;
        step.zoom = c.contains("zoom") ? readIn(c["zoom"], child(at, "zoom"), L::kMinZoom, L::kMaxZoom) : 1;
    }
    step.caption = readCaption(j["caption"], child(path, "caption"), true);
    if (j.contains("trace"))
        step.trace = readVec3(j["trace"], child(path, "trace"));
    if (j.contains("question"))
        step.question = readQuestion(j["question"], child(path, "question"), step.scene, pipeline);
    readShown(j, path, step, pipeline); // after the question: entries are of the stage it reveals
    return step;
}

} // namespace

const char* questionKindName(QuestionKind kind)
{
    for (const auto& [k, name] : kKindNames)
        if (k == kind)
            return name;
    return "";
}

Lesson parseLesson(const std::string& text, const std::filesystem::path& baseDir)
{
    const Json root = parseJson(text);
    requireObject(root, "", {"title", "steps"}, {"title", "steps"});
    Lesson lesson;
    lesson.title = readString(root["title"], "title"); // plain text: a page's title and heading
    if (lesson.title.find_first_not_of(" \t\n") == std::string::npos)
        throw InputError("title", "is empty");
    checkTextCharacters(lesson.title, "title");
    const Json& steps = root["steps"];
    if (!steps.is_array() || steps.empty() || steps.size() > kMaxSteps)
        throw InputError("steps", "must be an array of 1 to " + std::to_string(kMaxSteps) + " steps");
    for (std::size_t k = 0; k < steps.size(); ++k)
        lesson.steps.push_back(readStep(steps[k], element("steps", k), baseDir));
    return lesson;
}

const std::vector<std::pair<Element, const char*>>& lessonElementNames()
{
    static const std::vector<std::pair<Element, const char*>> names = {
        {Element::Objects, "objects"},         {Element::WorldAxes, "world_axes"}, {Element::ViewAxes, "view_axes"},
        {Element::Prp, "prp"},                 {Element::Window, "window"},        {Element::Dop, "dop"},
        {Element::Volume, "volume"},           {Element::FrontPlane, "front_plane"}, {Element::BackPlane, "back_plane"},
        {Element::Projectors, "projectors"},   {Element::Canonical, "canonical"}};
    return names;
}

std::shared_ptr<const EvaluatedScene> shownAtStep(const std::shared_ptr<const EvaluatedScene>& scene, const LessonStep& step)
{
    if (step.hidden.empty() && !step.labelsHidden && !step.legendHidden && step.highlighted.empty())
        return scene;
    auto shown = std::make_shared<EvaluatedScene>(*scene);
    auto hidden = [&](Element e) { return step.hidden.count(e) > 0; };
    shown->primitives.clear();
    for (Primitive p : scene->primitives) {
        if (hidden(p.element))
            continue;
        if (step.highlighted.count(p.element))
            p.widthScale = 2.5;
        shown->primitives.push_back(std::move(p));
    }
    auto drop = [&](auto& list) {
        list.erase(std::remove_if(list.begin(), list.end(), [&](const auto& item) { return hidden(item.element); }), list.end());
    };
    drop(shown->markers);
    drop(shown->worldLegend);
    if (step.labelsHidden)
        shown->labels.clear();
    else
        drop(shown->labels);
    if (step.legendHidden) {
        shown->worldLegend.clear();
        shown->projectedLegend.clear();
    }
    return shown;
}

std::vector<std::string> hideNames()
{
    std::vector<std::string> names;
    for (const auto& [element, name] : lessonElementNames())
        names.emplace_back(name);
    names.insert(names.end(), {"labels", "legend", "caption", "ticks", "notes"});
    return names;
}

std::string hideTitle(const std::string& name)
{
    std::string title = name;
    std::replace(title.begin(), title.end(), '_', ' ');
    if (title.size() == 3) // PRP, DOP
        std::transform(title.begin(), title.end(), title.begin(), [](unsigned char c) { return char(std::toupper(c)); });
    return title;
}

std::shared_ptr<const EvaluatedScene> withoutHidden(const std::shared_ptr<const EvaluatedScene>& scene,
                                                    const std::set<std::string>& hidden)
{
    LessonStep shown;
    for (const auto& [element, name] : lessonElementNames())
        if (hidden.count(name))
            shown.hidden.insert(element);
    shown.labelsHidden = hidden.count("labels") > 0;
    shown.legendHidden = hidden.count("legend") > 0;
    std::shared_ptr<const EvaluatedScene> without = shownAtStep(scene, shown);
    return hidden.count("notes") ? withoutEffectsNote(without) : without;
}

std::shared_ptr<const EvaluatedScene> withoutEffectsNote(const std::shared_ptr<const EvaluatedScene>& scene)
{
    if (scene->effectsNote.empty())
        return scene;
    auto noteless = std::make_shared<EvaluatedScene>(*scene);
    noteless->effectsNote.clear();
    return noteless;
}

int askingStage(const LessonStep& step)
{
    const std::optional<Question>& q = step.question;
    return q && q->stage > 0 && q->kind != QuestionKind::Entry ? std::min(step.stage, q->stage - 1) : step.stage;
}

int revealedStage(const LessonStep& step)
{
    return step.question && step.question->stage > 0 ? std::max(step.stage, step.question->stage) : step.stage;
}

StepShows stepShows(const LessonStep& step, bool answered, int stageCount)
{
    if (!step.question || answered)
        return {stageCount, true};
    return {askingStage(step), false};
}

Vec3<Exact> exactPoint(const Question& q)
{
    return {exactly(q.pointTyped[0], q.point.x()), exactly(q.pointTyped[1], q.point.y()),
            exactly(q.pointTyped[2], q.point.z())};
}

std::optional<Vec3<double>> tracedAt(const LessonStep& step, bool answered)
{
    const std::optional<Question>& q = step.question;
    if (q && q->kind == QuestionKind::Inside && !answered)
        return step.trace == q->point ? std::nullopt : step.trace;
    if (q && (q->kind == QuestionKind::Where || q->kind == QuestionKind::Inside || q->kind == QuestionKind::SignW))
        return q->point;
    return step.trace;
}

EvaluatedLesson evaluateLesson(const Lesson& lesson, SceneEvaluator* evaluator, const EvaluatedLesson* before)
{
    EvaluatedLesson evaluated;
    // A scene evaluated already: by an earlier step, or before the edit (which changes one step at most).
    using Scenes = std::vector<std::shared_ptr<const EvaluatedScene>>;
    const Scenes none, &earlier = evaluated.stepScene, &edited = before ? before->stepScene : none;
    const auto evaluatedAlready = [&](const Scene& scene) -> std::shared_ptr<const EvaluatedScene> {
        for (const Scenes* list : {&earlier, &edited})
            for (const auto& evaluatedScene : *list)
                if (evaluatedScene->scene == scene)
                    return evaluatedScene;
        return nullptr;
    };
    const auto showAlike = [](const LessonStep& a, const LessonStep& b) {
        return a.scene == b.scene && a.hidden == b.hidden && a.highlighted == b.highlighted &&
               a.labelsHidden == b.labelsHidden && a.legendHidden == b.legendHidden;
    };
    for (std::size_t k = 0; k < lesson.steps.size(); ++k) {
        const LessonStep& step = lesson.steps[k];
        const auto first = lesson.steps.begin(), here = first + std::ptrdiff_t(k);
        if (const auto alike = std::find_if(first, here, [&](const LessonStep& s) { return showAlike(s, step); });
            alike != here) { // shown as an earlier step is
            evaluated.stepScene.push_back(evaluated.stepScene[std::size_t(alike - first)]);
            evaluated.stepShown.push_back(evaluated.stepShown[std::size_t(alike - first)]);
            continue;
        }
        std::shared_ptr<const EvaluatedScene> scene = evaluatedAlready(step.scene);
        try {
            if (!scene)
                scene = evaluator ? evaluator->evaluate(step.scene) : evaluateScene(step.scene);
        } catch (const InputError& e) {
            throw InputError("steps[" + std::to_string(k) + "].scene." + e.field(), e.reason());
        }
        evaluated.stepScene.push_back(scene);
        evaluated.shown.push_back(shownAtStep(scene, step));
        evaluated.stepShown.push_back(int(evaluated.shown.size()) - 1);
    }
    return evaluated;
}

Lesson loadLesson(const std::filesystem::path& file)
{
    return parseLesson(readInputFile(file, "lesson"), file.parent_path());
}

} // namespace viewpipe

namespace viewpipe {
namespace {

using namespace fields;

Json vecJson(const Vec3<double>& v)
{
    return Json::array({v.x(), v.y(), v.z()});
}

// A question's point as the file wrote it: an expression kept as typed.
Json pointJson(const Question& q)
{
    Json j = vecJson(q.point);
    for (std::size_t i = 0; i < 3; ++i)
        if (!q.pointTyped[i].empty())
            j[i] = q.pointTyped[i];
    return j;
}

Json questionJson(const Question& q)
{
    Json j = {{"kind", questionKindName(q.kind)}, {"prompt", q.prompt}};
    switch (q.kind) {
    case QuestionKind::Where:
        j.update({{"point", pointJson(q)}, {"after", q.stage}, {"tolerance", q.tolerance}});
        break;
    case QuestionKind::Inside: j["point"] = pointJson(q); break;
    case QuestionKind::SignW: j.update({{"point", pointJson(q)}, {"after", q.stage}}); break;
    case QuestionKind::WhichStage: j["stage"] = q.stage; break;
    case QuestionKind::Order: break;
    case QuestionKind::Entry: j.update({{"stage", q.stage}, {"row", q.row}, {"column", q.column}}); break;
    case QuestionKind::Choice: j.update({{"choices", q.choices}, {"answer", q.correct}}); break;
    }
    if (!q.explanation.empty())
        j["explanation"] = q.explanation;
    if (q.tries != Question().tries)
        j["tries"] = q.tries;
    return j;
}

Json givenJson(const Question& q, const Answer& a)
{
    switch (q.kind) {
    case QuestionKind::Where: return vecJson(a.where);
    case QuestionKind::Inside: return a.inside;
    case QuestionKind::SignW: return a.signW > 0 ? "positive" : a.signW < 0 ? "negative" : "zero";
    case QuestionKind::WhichStage:
        return a.choice >= 0 && a.choice < int(q.choices.size()) ? Json(q.choices[std::size_t(a.choice)]) : Json();
    case QuestionKind::Order: {
        Json given = Json::array();
        for (int c : a.order)
            given.push_back(q.choices.at(std::size_t(c)));
        return given;
    }
    case QuestionKind::Entry: return a.entry;
    case QuestionKind::Choice: return a.choice;
    }
    return Json();
}

// A step's "hide" and "highlight", as its lesson file holds them.
void writeShown(const LessonStep& step, Json& entry)
{
    auto name = [](Element e) {
        for (const auto& [element, known] : lessonElementNames())
            if (element == e)
                return std::string(known);
        return std::string();
    };
    Json hide = Json::array();
    for (Element e : step.hidden)
        hide.push_back(name(e));
    if (step.labelsHidden)
        hide.push_back("labels");
    if (step.legendHidden)
        hide.push_back("legend");
    if (!hide.empty())
        entry["hide"] = hide;
    if (!step.highlighted.empty() || !step.entries.empty()) {
        Json highlight = Json::object();
        for (Element e : step.highlighted)
            highlight["elements"].push_back(name(e));
        for (const auto& [row, column] : step.entries)
            highlight["entries"].push_back({row, column});
        entry["highlight"] = highlight;
    }
}

} // namespace

std::vector<int> offeredChoices(const Question& q)
{
    std::vector<int> order(q.choices.size());
    for (std::size_t k = 0; k < order.size(); ++k)
        order[k] = int(k);
    if (q.kind == QuestionKind::WhichStage || q.kind == QuestionKind::Order)
        std::sort(order.begin(), order.end(),
                  [&](int a, int b) { return q.choices[std::size_t(a)] < q.choices[std::size_t(b)]; });
    return order;
}

bool isRight(const Question& q, const Answer& a)
{
    // What the student typed, read exactly (nothing for an answer made without its text).
    const auto typed = [&a](std::size_t count) -> std::optional<std::vector<Exact>> {
        if (a.typed.size() != count)
            return std::nullopt;
        std::vector<Exact> values;
        try {
            for (const std::string& text : a.typed)
                values.push_back(parseExact(text));
        } catch (const std::exception&) {
            return std::nullopt;
        }
        return values;
    };
    switch (q.kind) {
    case QuestionKind::Where: {
        const auto within = [&q](const auto& given, const auto& answer) { return pointWithin(given, answer, q.tolerance); };
        return judged(typed(3), {a.where.x(), a.where.y(), a.where.z()}, q, {q.where.x(), q.where.y(), q.where.z()}, within);
    }
    case QuestionKind::Inside: return a.inside == q.inside;
    case QuestionKind::SignW: return a.signW == q.signW;
    case QuestionKind::WhichStage:
    case QuestionKind::Choice: return a.choice == q.correct;
    case QuestionKind::Order: {
        std::vector<int> inOrder(q.choices.size());
        for (std::size_t k = 0; k < inOrder.size(); ++k)
            inOrder[k] = int(k);
        return a.order == inOrder;
    }
    case QuestionKind::Entry: {
        // Within 0.5 % (1e-9 of 0): -0.0952 and -0.095 count for -2/21, -0.0962 does not.
        const auto within = [](const auto& given, const auto& answer) {
            using T = std::decay_t<decltype(answer[0])>;
            using std::abs;
            return abs(T(given[0] - answer[0])) <= T(5) / T(1000) * abs(answer[0]) + T(1) / T(1000000000); // false for a NaN
        };
        return judged(typed(1), {a.entry}, q, {q.entry}, within);
    }
    }
    return false;
}

double typedNumber(const std::string& text, const std::string& field)
{
    if (text.find_first_not_of(' ') == std::string::npos) // parseExact's reason gives examples, which could be the answer
        throw InputError(field, "is empty: type a number (a decimal, a fraction p/q, a root with sqrt(…) or √)");
    return readExpression(text, field);
}

std::string answerToJson(const Question& question, const Answer& answer)
{
    return givenJson(question, answer).dump();
}

std::string resultsToJson(const Lesson& lesson, const std::vector<std::optional<Answer>>& answers,
                          const std::vector<bool>& revealed, const std::vector<int>& tries)
{
    Json entries = Json::array();
    for (std::size_t k = 0; k < lesson.steps.size() && k < answers.size(); ++k) {
        const std::optional<Question>& q = lesson.steps[k].question;
        const std::optional<Answer>& a = answers[k];
        if (q && !a && k < revealed.size() && revealed[k])
            entries.push_back({{"step", k + 1}, {"kind", questionKindName(q->kind)}, {"answer", nullptr},
                               {"correct", false}, {"revealed", true}});
        if (!q || !a)
            continue;
        Json entry = {{"step", k + 1}, {"kind", questionKindName(q->kind)}, {"answer", givenJson(*q, *a)}, {"correct", isRight(*q, *a)}};
        if (!a->typed.empty())
            entry["typed"] = q->kind == QuestionKind::Entry ? Json(a->typed.front()) : Json(a->typed);
        if (k < tries.size())
            entry["tries"] = tries[k];
        entries.push_back(entry);
    }
    return Json{{"lesson", lesson.title}, {"answers", entries}}.dump(2) + "\n";
}

std::string lessonToJson(const Lesson& lesson, const std::filesystem::path& baseDir)
{
    Json steps = Json::array();
    for (const LessonStep& step : lesson.steps) {
        Json entry;
        if (!step.scene.file.empty()) {
            entry["scene"] = pathFrom(baseDir, step.scene.file).generic_string();
        } else {
            entry["scene"] = Json::parse(sceneToJson(step.scene, baseDir));
        }
        entry["stage"] = step.stage;
        if (step.yaw != 0 || step.pitch != 0 || step.zoom != 1)
            entry["camera"] = {{"yaw", step.yaw}, {"pitch", step.pitch}, {"zoom", step.zoom}};
        entry["caption"] = step.caption;
        if (step.trace)
            entry["trace"] = vecJson(*step.trace);
        if (step.question)
            entry["question"] = questionJson(*step.question);
        writeShown(step, entry);
        if (!step.panel.empty())
            entry["panel"] = step.panel;
        if (step.storyboard)
            entry["layout"] = "storyboard";
        steps.push_back(entry);
    }
    return Json{{"title", lesson.title}, {"steps", steps}}.dump(2) + "\n";
}

LessonPack packLesson(const Lesson& lesson, const std::string& lessonFileName, const std::filesystem::path& folder)
{
    namespace fs = std::filesystem;
    LessonPack pack;
    // A file read, with what it holds as written (a scene edited since another step named it is another
    // scene), and where it goes, relative to the folder.
    std::map<std::pair<fs::path, std::string>, fs::path> placed;
    std::set<fs::path> taken;
    // Where `source` holding `text` goes in `subfolder`, and whether it is placed there for the first time.
    const auto place = [&](const fs::path& source, const std::string& text,
                           const std::string& subfolder) -> std::pair<fs::path, bool> {
        const auto key = std::make_pair(fs::weakly_canonical(fs::absolute(source)), text);
        if (const auto found = placed.find(key); found != placed.end())
            return {found->second, false};
        fs::path name = fs::path(subfolder) / source.filename();
        for (int k = 2; taken.count(name); ++k)
            name = fs::path(subfolder) / (source.stem().string() + "-" + std::to_string(k) + source.extension().string());
        taken.insert(name);
        return {placed[key] = name, true};
    };
    const fs::path root = fs::absolute(folder);
    Lesson packed = lesson;
    for (LessonStep& step : packed.steps) {
        Scene& scene = step.scene;
        for (SceneObject& object : scene.objects) {
            if (object.type != ObjectType::Mesh)
                continue;
            const auto [name, first] = place(object.resolvedPath, {}, "meshes");
            if (first)
                pack.copies.emplace_back(name, object.resolvedPath);
            object.resolvedPath = root / name;
        }
        if (scene.file.empty())
            continue; // written inline, its meshes named from the lesson
        const auto [name, first] = place(scene.file, sceneToJson(scene), "scenes");
        scene.file = root / name;
        if (first)
            pack.texts.emplace_back(name, sceneToJson(scene, scene.file.parent_path()));
    }
    pack.texts.insert(pack.texts.begin(), {fs::path(lessonFileName), lessonToJson(packed, root)});
    return pack;
}

std::vector<std::filesystem::path> filesOutside(const Lesson& lesson, const std::filesystem::path& folder)
{
    namespace fs = std::filesystem;
    std::error_code ignored; // a folder that cannot be read is compared as named
    const fs::path inside = fs::weakly_canonical(fs::absolute(folder), ignored);
    std::set<fs::path> outside;
    const auto check = [&](const fs::path& file) {
        const fs::path canonical = fs::weakly_canonical(fs::absolute(file), ignored);
        const fs::path up = canonical.lexically_relative(inside);
        if (up.empty() || *up.begin() == "..")
            outside.insert(canonical);
    };
    for (const LessonStep& step : lesson.steps) {
        if (!step.scene.file.empty())
            check(step.scene.file);
        for (const SceneObject& object : step.scene.objects)
            if (object.type == ObjectType::Mesh)
                check(object.resolvedPath);
    }
    return {outside.begin(), outside.end()};
}

Question parseQuestion(const std::string& text, const Scene& scene)
{
    return readQuestion(parseJson(text), "question", scene, buildPipeline(scene.camera, scene.effects));
}

std::string questionToJson(const Question& question)
{
    return questionJson(question).dump(2);
}

std::string stepShownJson(const LessonStep& step)
{
    Json entry = Json::object();
    writeShown(step, entry);
    return entry.dump();
}

LessonStep stepShownFrom(const std::string& text)
{
    const Json j = parseJson(text);
    LessonStep step;
    if (j.contains("hide"))
        step.hidden = readElements(j["hide"], "hide", &step);
    if (j.contains("highlight") && j["highlight"].contains("elements"))
        step.highlighted = readElements(j["highlight"]["elements"], "highlight.elements", nullptr);
    return step;
}

} // namespace viewpipe
