#pragma once

// Lesson files (JSON, see docs/lesson-format.md): steps through scenes, each
// a stage with a caption and perhaps a question the student answers before
// the answer shows. Every answer the scene determines is computed here, so a
// lesson cannot state a wrong one; an answer the lesson writes anyway must
// agree. Refusals are InputErrors naming the field ("steps[3].question.answer").

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <memory>
#include <set>

#include "viewpipe/evaluated_scene.hpp"
#include "viewpipe/scene.hpp"

namespace viewpipe {

enum class QuestionKind { Where, Inside, SignW, WhichStage, Order, Entry, Choice };
const char* questionKindName(QuestionKind kind); // "where", "sign_w", ...

struct Question {
    QuestionKind kind = QuestionKind::Choice;
    std::string prompt, explanation;
    Vec3<double> point = Vec3<double>::Zero(); // where, inside, sign_w
    std::array<std::string, 3> pointTyped;     // x, y, z as the file writes an exact expression ("1/3"), else empty
    int stage = 0;                             // where and sign_w: after it; which_stage, entry: its matrix
    int row = 0, column = 0;                   // entry, from 1
    double tolerance = 0.01;                   // where: relative to the answer's size
    int tries = 2;                             // answers checked before the answer is shown
    std::vector<std::string> choices;          // choice; which_stage and order: the scene's stage symbols
    // The answer, as the scene gives it (a choice's: as the lesson names it).
    Vec3<double> where = Vec3<double>::Zero();
    bool inside = false;
    int signW = 0;       // -1, 0 or 1
    int correct = 0;     // choice, which_stage: the index into `choices`
    double entry = 0;
    // where (x, y, z) and entry: the answer computed exactly (exactPipeline, the point as typed), which
    // decides a typed answer with no rounding; null where exact arithmetic refuses the scene. Include exact.hpp.
    std::shared_ptr<const std::vector<Exact>> exact;
};

// A question's point exactly: each coordinate's expression as typed, else the decimal written (0.1 is one
// tenth). Include exact.hpp.
Vec3<Exact> exactPoint(const Question& q);

// The world view as a user turns it (an orbit about the focal point, a zoom), within these: the pole is
// never crossed (the picture's up would flip) and the picture neither vanishes nor swallows the view.
// The lesson files, the app and the page hold to them.
struct ViewLimits {
    static constexpr double kYawDegrees = 180, kPitchDegrees = 89, kMinZoom = 0.1, kMaxZoom = 20;
};

struct LessonStep {
    Scene scene;
    int stage = 0;
    double yaw = 0, pitch = 0, zoom = 1;
    std::string caption;
    std::optional<Vec3<double>> trace;
    std::optional<Question> question;
    std::set<Element> hidden;           // not drawn at this step
    bool labelsHidden = false;          // no label drawn at this step
    bool legendHidden = false;          // no legend drawn at this step
    std::set<Element> highlighted;      // drawn with wider lines
    std::vector<std::array<int, 2>> entries; // the shown stage's matrix entries highlighted (row, column from 1)
    std::string panel;                  // the app's panel in front: stages, matrices, parameters, code, accuracy, depth
    bool storyboard = false;            // "layout": "storyboard": the app shows every stage at once (once answered)
};

// The elements a step can hide or highlight, by their names in the file
// ("objects", "world_axes", "window", ...).
const std::vector<std::pair<Element, const char*>>& lessonElementNames();

// What a step leaves out of its scene and draws wider, as its lesson file
// writes it ({"hide": [...], "highlight": {...}}), and a step that shows its
// scene so read back from that text (the web page places labels with it).
std::string stepShownJson(const LessonStep& step);
LessonStep stepShownFrom(const std::string& text);

// A scene as a step shows it: without the elements (labels, legends) it hides,
// its highlighted elements' lines wider; the scene itself where the step
// changes nothing. Every picture of the step draws this.
std::shared_ptr<const EvaluatedScene> shownAtStep(const std::shared_ptr<const EvaluatedScene>& scene, const LessonStep& step);

// What a reader may leave out of the pictures (export --hide, View > Leave Out, the page's toggles): the
// elements by the names a step's `hide` takes, "labels", "legend", "caption", "ticks" (the grey axes'
// ticks and numbers) and "notes" (the effects' note and the notice of labels left out for room), in
// the order the help lists them; and each one's name for people ("world axes", "PRP").
std::vector<std::string> hideNames();
std::string hideTitle(const std::string& name);
// The scene as the pictures show it, without the elements, labels, legend and effects' note `hidden`
// names (hideNames; the caption and ticks are left out where the picture is drawn).
std::shared_ptr<const EvaluatedScene> withoutHidden(const std::shared_ptr<const EvaluatedScene>& scene,
                                                    const std::set<std::string>& hidden);
// The scene without the effects' note (a storyboard's cells, which no cell repeats, and --hide notes).
std::shared_ptr<const EvaluatedScene> withoutEffectsNote(const std::shared_ptr<const EvaluatedScene>& scene);

struct Lesson {
    std::string title;
    std::vector<LessonStep> steps;
};

// The stage a step shows while its question is open: a question about stage K
// waits at the stage before K (its answer comes with K's transition), except
// an entry question, whose matrix is shown anyway.
int askingStage(const LessonStep& step);
// The stage a step shows once its question is answered, or all along without one.
int revealedStage(const LessonStep& step);
// What a step lets the app and the page show, one rule for both. While its
// question is open: no stage past the one it waits at (the stepper, the slider
// and the stage list hold there) and none of the stages' names, matrices and
// captions, nor the step's caption. Once answered, or without a question, any
// stage with its texts. In a lesson a traced point's rows are those up to the
// stage shown (a later row may be a later question's answer), and its verdict
// on the canonical volume shows only at the last stage.
struct StepShows {
    int lastStage = 0;       // the highest stage the step may show
    bool stageTexts = true;  // stage names, matrices, captions, the step's caption
};
StepShows stepShows(const LessonStep& step, bool answered, int stageCount);

// The point a step marks: the point its question asks about (where, inside,
// sign_w), otherwise the step's own trace. While an inside question is open
// its point is not marked: where it lies against the view volume is the answer.
std::optional<Vec3<double>> tracedAt(const LessonStep& step, bool answered);

// The order a question's choices are offered in, as indices: a choice
// question's as written, a scene's stage symbols (which_stage, order) sorted,
// so that their order gives nothing away.
std::vector<int> offeredChoices(const Question& question);

// A student's answer: the field its question's kind reads.
struct Answer {
    Vec3<double> where = Vec3<double>::Zero();
    bool inside = false;
    int signW = 0;          // -1, 0 or 1
    int choice = -1;        // which_stage and choice: an index into the question's choices
    std::vector<int> order; // order: indices into the choices, first to last
    double entry = 0;
    // where (x, y, z) and entry: the text as the student typed it ("-2/21"), kept beside its value
    std::vector<std::string> typed;
};
// Whether an answer is right, with the web page's tolerances: a point within
// the question's tolerance relative to its size (at least 1), an entry within
// 0.5 % (a fraction typed as a decimal to three places counts). Where the
// answer's `typed` texts and the question's `exact` answer are both exact, the
// comparison is decided exactly (sqrt(2)/2 is right for sqrt(2)/2, however
// near a boundary); otherwise in double, from `where` and `entry`.
bool isRight(const Question& question, const Answer& answer);
// A number a student types: any exact expression parseExact reads ("-2/21",
// "0.7071", "sqrt(2)/2", "√2/2", "1/√2", a typeset minus), as its nearest
// double. Throws InputError(field, reason) where the text is not one finite
// number (for 2 +* 3: unexpected "*" at character 4 of "2 +* 3").
double typedNumber(const std::string& text, const std::string& field);
// An answer as the results hold it: a point [x, y, z], true or false,
// "positive"/"zero"/"negative", a stage's symbol, the symbols in order, a
// number, a choice's index.
std::string answerToJson(const Question& question, const Answer& answer);

// A student's answers as the web page saves them ("Save my answers"):
// {"lesson": title, "answers": [{"step": 1, "kind": "where", "answer": ...,
// "correct": true}, ...]}, one entry a question answered; answers[k] is
// step k's. A question whose answer was shown before any was given
// (revealed[k]) has an entry too: "answer": null, "correct": false, "revealed": true.
// With `tries`, an answer is the last one checked and "tries" says how many were.
// An answer with its typed text has "typed" too: a string (entry) or three (where).
std::string resultsToJson(const Lesson& lesson, const std::vector<std::optional<Answer>>& answers,
                          const std::vector<bool>& revealed = {}, const std::vector<int>& tries = {});

// Scene paths are read relative to baseDir.
Lesson parseLesson(const std::string& text, const std::filesystem::path& baseDir);
// Throws InputError("$", ...) when the file cannot be read.
Lesson loadLesson(const std::filesystem::path& file);
// A lesson's steps evaluated: every scene once (its meshes read once), each
// step's as it shows it (shownAtStep), steps that show the same alike sharing
// one. The app's lesson and the CLI's check and export are made from it.
struct EvaluatedLesson {
    std::vector<std::shared_ptr<const EvaluatedScene>> shown;
    std::vector<int> stepShown; // shown[stepShown[k]] is step k's
    std::vector<std::shared_ptr<const EvaluatedScene>> stepScene; // step k's scene whole, as it opens in the app
};
// Throws InputError naming the step ("steps[3].scene.objects[0].path") whose
// scene the core refuses. With an evaluator, meshes come through its cache;
// with `before` (the lesson before an edit), its scenes are kept where a step's
// scene is unchanged.
EvaluatedLesson evaluateLesson(const Lesson& lesson, SceneEvaluator* evaluator = nullptr,
                               const EvaluatedLesson* before = nullptr);
// The lesson as its file holds it, to be read from `baseDir`: a scene loaded
// from a file as that file's path, any other inline with its meshes' paths;
// each path relative to baseDir where the two share a folder below the root,
// else absolute (pathFrom); answers the scenes give are left out.
std::string lessonToJson(const Lesson& lesson, const std::filesystem::path& baseDir);
// A lesson gathered with the files it uses, to travel as one folder: the
// lesson file as `lessonFileName`, each scene file its steps name as
// scenes/NAME.json, each mesh as meshes/NAME (a number added where two files
// share a name), every path relative to the file that names it. `folder` is
// where the caller writes `texts` and copies `copies`; nothing is written here.
struct LessonPack {
    std::vector<std::pair<std::filesystem::path, std::string>> texts;            // relative path, contents (the lesson first)
    std::vector<std::pair<std::filesystem::path, std::filesystem::path>> copies; // relative path, the file to copy there
};
LessonPack packLesson(const Lesson& lesson, const std::string& lessonFileName, const std::filesystem::path& folder);
// The scene and mesh files a lesson saved in `folder` uses from outside that
// folder: the lesson breaks where they do not travel with it (packLesson).
std::vector<std::filesystem::path> filesOutside(const Lesson& lesson, const std::filesystem::path& folder);
// Reads the question of a step from JSON, as a lesson file holds it (for
// editing one question), checked against the step's scene.
Question parseQuestion(const std::string& text, const Scene& scene);
// The question as its lesson file holds it.
std::string questionToJson(const Question& question);

} // namespace viewpipe
