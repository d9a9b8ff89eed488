// Lesson files: answers computed from the scene (checked here against the
// house's known numbers, Foley et al. ch. 6: PRP (8, 6, 84), SH_per's
// -DOPx/DOPz = -8/84 = -2/21), and refusals that name the field.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include "build_paths.h"
#include "evaluation_count.h"
#include "plain_math.h"
#include "support.hpp"
#include "viewpipe/exact.hpp"
#include "viewpipe/lesson.hpp"

namespace viewpipe {
namespace {

using test::expectRefused;

const std::string kScenes = std::string(viewpipe::build::dataDir) + "/scenes";

Lesson lessonWith(const std::string& step)
{
    return parseLesson(R"({"title": "t", "steps": [)" + step + "]}", kScenes);
}

std::string houseStep(const std::string& question)
{
    return R"({"scene": "house.json", "stage": 2, "caption": "c", "question": )" + question + "}";
}

TEST(Lesson, AnswersComeFromTheScene)
{
    const Lesson where = lessonWith(houseStep(R"({"kind": "where", "prompt": "p", "point": [8, 6, 84], "after": 3})"));
    ASSERT_TRUE(where.steps[0].question);
    EXPECT_LT(where.steps[0].question->where.norm(), 1e-12); // T(-PRP) takes the PRP to the origin

    const Lesson entry = lessonWith(houseStep(R"({"kind": "entry", "prompt": "p", "stage": 4, "row": 1, "column": 3})"));
    EXPECT_NEAR(entry.steps[0].question->entry, -2.0 / 21.0, 1e-15);

    const Lesson which = lessonWith(houseStep(R"({"kind": "which_stage", "prompt": "p", "stage": 4, "answer": "SH_per"})"));
    const Question& q = *which.steps[0].question;
    EXPECT_EQ(q.choices, (std::vector<std::string>{"T(-VRP)", "R", "T(-PRP)", "SH_per", "S_per"}));
    EXPECT_EQ(q.correct, 3);

    // Foley's stages keep w = 1 (the perspective comes after them, in M); the house's center lies inside, the PRP not.
    const Lesson sign = lessonWith(houseStep(R"({"kind": "sign_w", "prompt": "p", "point": [0, 0, 54], "after": 5})"));
    EXPECT_EQ(sign.steps[0].question->signW, 1);
    const Lesson inside = lessonWith(houseStep(R"({"kind": "inside", "prompt": "p", "point": [8, 8, 42]})"));
    EXPECT_TRUE(inside.steps[0].question->inside);
    const Lesson outside = lessonWith(houseStep(R"({"kind": "inside", "prompt": "p", "point": [8, 6, 84]})"));
    EXPECT_FALSE(outside.steps[0].question->inside);
}

TEST(Lesson, BadLessonsAreRefusedWithTheirFieldPaths)
{
    const auto refused = [](const std::string& step, const std::string& field, const std::string& reason) {
        expectRefused([&] { lessonWith(step); }, field, reason);
    };
    refused(houseStep(R"({"kind": "where", "prompt": "p", "point": [8, 6, 84], "after": 3, "answr": 1})"),
            "steps[0].question.answr", "unknown key");
    refused(houseStep(R"({"kind": "where", "prompt": "p", "point": [8, 6, 84], "after": 3, "answer": [0, 0, -1]})"),
            "steps[0].question.answer", "is (0, 0, -1) but the scene gives (0, 0, 0)");
    refused(houseStep(R"({"kind": "guess", "prompt": "p"})"), "steps[0].question.kind", "\"guess\"");
    refused(houseStep(R"({"kind": "where", "prompt": "p", "point": [8, 6, 84], "after": 6})"),
            "steps[0].question.after", "a whole number from 1 to 5 (got 6)");
    refused(houseStep(R"({"kind": "choice", "prompt": "p", "choices": ["a", "b"]})"), "steps[0].question.answer",
            "is missing");
    refused(houseStep(R"({"kind": "choice", "prompt": "p", "choices": ["a", "b"], "answer": 2})"),
            "steps[0].question.answer", "from 0 to 1");
    refused(houseStep(R"({"kind": "sign_w", "prompt": "p", "point": [0, 0, 0], "after": 1, "answer": "negative"})"),
            "steps[0].question.answer", "is negative but w is 1 (positive)");
    refused(R"({"scene": "house.json", "stage": 9, "caption": "c"})", "steps[0].stage", "from 0 to 5 (got 9)");
    refused(R"({"scene": "house.json", "stage": 18446744073709551615, "caption": "c"})", "steps[0].stage",
            "(got 18446744073709551615)");
    EXPECT_EQ(lessonWith(R"({"scene": "house.json", "stage": 2.0, "caption": "c"})").steps[0].stage, 2);
    refused(houseStep(R"({"kind": "inside", "prompt": "p", "point": [0, 0, 0], "tries": 0})"), "steps[0].question.tries",
            "a whole number from 1 to 10 (got 0)");
    refused(houseStep(R"({"kind": "inside", "prompt": "p", "point": [0, 0, 0], "tries": "2"})"), "steps[0].question.tries",
            "(got the text \"2\")");
    // A point whose image overflows has no answer: refused, not answered with NaN.
    refused(houseStep(R"({"kind": "where", "prompt": "p", "point": [1.7e308, 0, -1.7e308], "after": 4})"),
            "steps[0].question.point", "no finite image");
    refused(R"({"scene": "house.json", "caption": "costs $5"})", "steps[0].caption", "$");
    refused(R"({"scene": "nope.json", "caption": "c"})", "steps[0].scene", "nope.json: cannot read the scene file");
    refused(R"({"scene": {"view": {"projection": "perspective", "vrp": [0, 0, 0], "vpn": [0, 0, 1], "vup": [0, 0, 1],
                "prp": [8, 6, 84], "window": [-50, 50, -50, 50], "front": 60, "back": 25}}, "caption": "c"})",
            "steps[0].scene.view.vup", "parallel");
    refused(R"({"scene": "house.json", "caption": "c", "camera": {"pitch": 90}})", "steps[0].camera.pitch",
            "between -89 and 89");
    expectRefused([] { parseLesson(R"({"title": "t", "steps": []})", kScenes); }, "steps", "1 to 200");
    expectRefused([] { parseLesson(R"({"steps": [1]})", kScenes); }, "title", "is missing");
    // The divide is no matrix: it has no entries.
    expectRefused(
        [] {
            parseLesson(R"({"title": "t", "steps": [{"scene": "clipping-eye-plane.json", "caption": "c",
                            "question": {"kind": "entry", "prompt": "p", "stage": 5, "row": 1, "column": 1}}]})",
                        kScenes);
        },
        "steps[0].question.stage", "the divide");
}

TEST(Lesson, TheBuiltInLessonsAreValid)
{
    int count = 0;
    for (const auto& entry : std::filesystem::directory_iterator(std::string(viewpipe::build::dataDir) + "/lessons")) {
        if (entry.path().extension() != ".json")
            continue;
        ++count;
        const Lesson lesson = loadLesson(entry.path());
        EXPECT_FALSE(plainTextMath(lesson.title)) << entry.path() << ": " << lesson.title; // set as plain text: no "N_per"
        int questions = 0;
        for (const LessonStep& step : lesson.steps) {
            questions += step.question.has_value();
            // Math set as math: no "SH_per", "-1" or "x = +-z" written as plain text.
            std::vector<std::string> texts = {step.caption};
            if (const auto& q = step.question) {
                texts.insert(texts.end(), {q->prompt, q->explanation});
                if (q->kind == QuestionKind::Choice) // which_stage's and order's choices are stage symbols
                    texts.insert(texts.end(), q->choices.begin(), q->choices.end());
            }
            for (const std::string& text : texts)
                EXPECT_FALSE(plainTextMath(text)) << entry.path() << ": " << text;
        }
        EXPECT_GE(questions, 3) << entry.path(); // each asks, not only shows
    }
    EXPECT_GE(count, 5);
}

// While a question is open its step shows no stage from the one it asks about on, nor the stages'
// texts; once answered, every stage (the app's stepper and the page follow this one rule).
TEST(Lesson, AnOpenQuestionHoldsTheStagesBeforeItsAnswer)
{
    int questions = 0;
    for (const auto& entry : std::filesystem::directory_iterator(std::string(viewpipe::build::dataDir) + "/lessons")) {
        const Lesson lesson = loadLesson(entry.path());
        for (const LessonStep& step : lesson.steps) {
            const int stages = int(buildPipeline(step.scene.camera, step.scene.effects).stages.size());
            const StepShows answered = stepShows(step, true, stages);
            EXPECT_EQ(answered.lastStage, stages);
            EXPECT_TRUE(answered.stageTexts);
            if (!step.question)
                continue;
            ++questions;
            const StepShows asking = stepShows(step, false, stages);
            EXPECT_FALSE(asking.stageTexts) << entry.path();
            EXPECT_EQ(asking.lastStage, askingStage(step));
            const Question& q = *step.question;
            if (q.kind == QuestionKind::Where || q.kind == QuestionKind::SignW || q.kind == QuestionKind::WhichStage) {
                EXPECT_LT(asking.lastStage, q.stage) << entry.path() << ": the stage asked about is held back";
            }
        }
    }
    EXPECT_GT(questions, 30);
}

// The point a step marks: an open inside question's point is not (its place against the volume is the
// answer); once answered it is, as a where question's is all along.
TEST(Lesson, AnOpenInsideQuestionMarksNoPoint)
{
    const Lesson lesson = loadLesson(std::string(viewpipe::build::dataDir) + "/lessons/foley-nper.json");
    const LessonStep& inside = lesson.steps[8]; // is (8, 16, 70) inside the view volume?
    ASSERT_EQ(inside.question->kind, QuestionKind::Inside);
    EXPECT_FALSE(tracedAt(inside, false));
    EXPECT_EQ(tracedAt(inside, true), inside.question->point);
    const LessonStep& where = lesson.steps[6]; // where is (16, 10, 30) after S_per?
    EXPECT_EQ(tracedAt(where, false), where.question->point);
    EXPECT_EQ(tracedAt(where, true), where.question->point);
}

// A pack holds each scene as its steps show it: two steps naming one file, one of them edited since (the
// app adds a step from the view of a scene saved over), get two scene files.
TEST(Lesson, APackKeepsEachStepsOwnScene)
{
    Lesson lesson = loadLesson(std::string(viewpipe::build::dataDir) + "/lessons/foley-nper.json");
    lesson.steps.resize(2);
    auto& view = std::get<foley::ViewSpec<double>>(lesson.steps[1].scene.camera);
    view.prp.z() = 90;
    const std::filesystem::path folder = std::filesystem::temp_directory_path() / "viewpipe-pack-core";
    const LessonPack pack = packLesson(lesson, "l.json", folder);
    ASSERT_EQ(pack.texts.size(), 3u); // the lesson, scenes/house.json and scenes/house-2.json
    EXPECT_EQ(pack.texts[1].first, std::filesystem::path("scenes/house.json"));
    EXPECT_EQ(pack.texts[2].first, std::filesystem::path("scenes/house-2.json"));
    EXPECT_NE(pack.texts[2].second.find("90"), std::string::npos);
    const nlohmann::json written = nlohmann::json::parse(pack.texts[0].second);
    EXPECT_EQ(written["steps"][0]["scene"], "scenes/house.json");
    EXPECT_EQ(written["steps"][1]["scene"], "scenes/house-2.json");
}

// A lesson saved names the files it uses from outside its folder (it breaks where they do not go with
// it): foley-nper uses two scenes of data/scenes from outside data/lessons; packed, nothing.
TEST(Lesson, ItNamesTheFilesItUsesFromOutsideItsFolder)
{
    namespace fs = std::filesystem;
    const fs::path data = viewpipe::build::dataDir;
    const Lesson lesson = loadLesson(data / "lessons/foley-nper.json");
    const std::vector<fs::path> used{fs::weakly_canonical(data / "scenes/house-oblique-view.json"),
                                     fs::weakly_canonical(data / "scenes/house.json")};
    EXPECT_EQ(filesOutside(lesson, data / "lessons"), used);
    EXPECT_TRUE(filesOutside(lesson, data).empty());
    const fs::path folder = fs::temp_directory_path() / ("viewpipe-outside-" + std::to_string(::getpid()));
    const LessonPack pack = packLesson(lesson, "l.json", folder);
    fs::create_directories(folder / "scenes");
    for (const auto& [name, text] : pack.texts)
        std::ofstream(folder / name) << text;
    EXPECT_TRUE(filesOutside(loadLesson(folder / "l.json"), folder).empty());
    fs::remove_all(folder);
}

// Tries: two unless the lesson says; written back only when it says; the
// results hold the last answer checked and how many were.
TEST(Lesson, AQuestionsTriesAreTwoUnlessTheLessonSays)
{
    const Lesson twice = lessonWith(houseStep(R"({"kind": "inside", "prompt": "p", "point": [0, 0, 0]})"));
    EXPECT_EQ(twice.steps[0].question->tries, 2);
    EXPECT_EQ(questionToJson(*twice.steps[0].question).find("tries"), std::string::npos);
    const Lesson once = lessonWith(houseStep(R"({"kind": "inside", "prompt": "p", "point": [0, 0, 0], "tries": 1})"));
    EXPECT_EQ(once.steps[0].question->tries, 1);
    EXPECT_NE(questionToJson(*once.steps[0].question).find("\"tries\": 1"), std::string::npos);
    Answer answer;
    answer.inside = !once.steps[0].question->inside;
    const auto results = nlohmann::json::parse(resultsToJson(once, {answer}, {true}, {1}));
    EXPECT_EQ(results["answers"][0]["tries"], 1);
    EXPECT_EQ(results["answers"][0]["correct"], false);
    EXPECT_EQ(results["answers"][0]["answer"], answer.inside);
}

// The results keep what was typed beside the value read from it: an entry's text, a point's three;
// answers picked from a list, and answers shown unanswered, have none.
TEST(Lesson, ResultsKeepEachAnswerAsTyped)
{
    const std::string entryStep = houseStep(R"({"kind": "entry", "prompt": "p", "stage": 4, "row": 1, "column": 3})");
    const Lesson lesson = lessonWith(entryStep);
    const Lesson three = lessonWith(entryStep + "," + houseStep(R"({"kind": "where", "prompt": "p", "point": [8, 6, 84], "after": 3})") +
                                    "," + houseStep(R"({"kind": "inside", "prompt": "p", "point": [0, 0, 0]})"));
    Answer entry;
    entry.entry = typedNumber("-2/21", "entry");
    entry.typed = {"-2/21"};
    Answer where;
    where.where = {1.0 / 3, 0, -1};
    where.typed = {"1/3", "0", "-1"};
    Answer inside;
    inside.inside = true;
    const auto results = nlohmann::json::parse(resultsToJson(three, {entry, where, inside}, {true, true, true}, {1, 2, 1}));
    const auto& answers = results["answers"];
    ASSERT_EQ(answers.size(), 3u);
    EXPECT_EQ(answers[0]["answer"], -2.0 / 21);
    EXPECT_EQ(answers[0]["typed"], "-2/21");
    EXPECT_EQ(answers[0]["correct"], true); // SH_per's (1, 3) for the house is -2/21
    EXPECT_EQ(answers[1]["typed"], nlohmann::json({"1/3", "0", "-1"}));
    EXPECT_EQ(answers[1]["answer"][0], 1.0 / 3);
    EXPECT_FALSE(answers[2].contains("typed"));
    // Shown before any answer: no typed text, the entry as docs/lesson-format.md gives it.
    const auto shown = nlohmann::json::parse(resultsToJson(lesson, {std::nullopt}, {true}, {0}))["answers"][0];
    EXPECT_EQ(shown, nlohmann::json::parse(R"({"step": 1, "kind": "entry", "answer": null, "correct": false, "revealed": true})"));
}

// What the app saves reads back as the same lesson, from another folder too:
// scene files as relative paths, every question with the same answer.
TEST(Lesson, ALessonSavedReadsBackTheSame)
{
    namespace fs = std::filesystem;
    const fs::path elsewhere = fs::temp_directory_path() / ("viewpipe-lesson-elsewhere-" + std::to_string(::getpid()));
    fs::create_directories(elsewhere);
    for (const auto& entry : fs::directory_iterator(std::string(viewpipe::build::dataDir) + "/lessons")) {
        const Lesson lesson = loadLesson(entry.path());
        for (const fs::path& folder : {entry.path().parent_path(), elsewhere}) {
            // A scene file is named relative to the lesson only where that does not climb to the root
            // (found: "../../work/..."), else absolutely; beside the lesson, in data/, relatively.
            const nlohmann::json saved = nlohmann::json::parse(lessonToJson(lesson, folder));
            for (const auto& step : saved["steps"])
                if (step["scene"].is_string()) {
                    const fs::path named = step["scene"].get<std::string>();
                    std::size_t up = 0, depth = 0;
                    for (const fs::path& part : named)
                        up += part == "..";
                    for (const fs::path& part : fs::weakly_canonical(folder).relative_path())
                        depth += !part.empty();
                    EXPECT_TRUE(named.is_absolute() || up < depth) << named << " from " << folder;
                    if (folder == entry.path().parent_path()) {
                        EXPECT_TRUE(named.is_relative()) << named;
                    }
                }
            const Lesson again = parseLesson(lessonToJson(lesson, folder), folder);
            ASSERT_EQ(again.steps.size(), lesson.steps.size());
            EXPECT_EQ(again.title, lesson.title);
            for (std::size_t k = 0; k < lesson.steps.size(); ++k) {
                const LessonStep &a = lesson.steps[k], &b = again.steps[k];
                EXPECT_EQ(sceneToJson(a.scene), sceneToJson(b.scene)) << entry.path() << " step " << k;
                EXPECT_EQ(fs::weakly_canonical(a.scene.file), fs::weakly_canonical(b.scene.file));
                EXPECT_EQ(std::tie(a.stage, a.yaw, a.pitch, a.zoom, a.caption), std::tie(b.stage, b.yaw, b.pitch, b.zoom, b.caption));
                EXPECT_EQ(a.trace.has_value(), b.trace.has_value());
                EXPECT_EQ(std::tie(a.hidden, a.labelsHidden, a.legendHidden, a.highlighted, a.entries, a.panel, a.storyboard),
                          std::tie(b.hidden, b.labelsHidden, b.legendHidden, b.highlighted, b.entries, b.panel, b.storyboard));
                ASSERT_EQ(a.question.has_value(), b.question.has_value());
                if (!a.question)
                    continue;
                EXPECT_EQ(questionToJson(*a.question), questionToJson(*b.question));
                EXPECT_EQ(a.question->correct, b.question->correct);
                EXPECT_EQ(a.question->where, b.question->where);
            }
        }
    }
    // A scene made in memory goes inline, its mesh's path made relative to the lesson's folder.
    const fs::path meshes = fs::temp_directory_path() / ("viewpipe-lesson-meshes-" + std::to_string(::getpid()));
    fs::create_directories(meshes);
    writeFileAtomically(meshes / "tri.obj", "v 0 0 -1\nv 1 0 -1\nv 0 1 -1\nf 1 2 3\n");
    Lesson made = lessonWith(R"({"scene": "house.json", "caption": "c"})");
    Scene& scene = made.steps[0].scene;
    nlohmann::json withMesh = nlohmann::json::parse(sceneToJson(scene));
    withMesh["objects"] = nlohmann::json::parse(R"([{"type": "mesh", "path": "tri.obj"}])");
    scene = parseScene(withMesh.dump(), meshes);
    ASSERT_TRUE(scene.file.empty());
    const Lesson inlined = parseLesson(lessonToJson(made, elsewhere), elsewhere);
    ASSERT_EQ(inlined.steps[0].scene.objects.size(), 1u);
    EXPECT_EQ(fs::weakly_canonical(inlined.steps[0].scene.objects[0].resolvedPath), fs::weakly_canonical(meshes / "tri.obj"));
    fs::remove_all(meshes);
    fs::remove_all(elsewhere);
}

TEST(Lesson, AnswersAreCheckedAsThePageChecksThem)
{
    const Lesson where = lessonWith(houseStep(R"({"kind": "where", "prompt": "p", "point": [16, 10, 30], "after": 3})"));
    const Question& q = *where.steps[0].question;
    Answer a;
    a.where = q.where;
    EXPECT_TRUE(isRight(q, a));
    a.where.x() += 0.009 * std::max(1.0, q.where.norm()); // inside the 1 % tolerance
    EXPECT_TRUE(isRight(q, a));
    a.where.x() += 0.01 * q.where.norm();
    EXPECT_FALSE(isRight(q, a));
    a.where.x() = std::nan("");
    EXPECT_FALSE(isRight(q, a));

    const Lesson entry = lessonWith(houseStep(R"({"kind": "entry", "prompt": "p", "stage": 4, "row": 1, "column": 3})"));
    Answer typed;
    typed.entry = typedNumber("\u22122/21", "entry"); // the typeset minus, as the page prints it
    EXPECT_TRUE(isRight(*entry.steps[0].question, typed));
    typed.entry = typedNumber("-0.095", "entry");
    EXPECT_TRUE(isRight(*entry.steps[0].question, typed));
    typed.entry = typedNumber("-0.09", "entry");
    EXPECT_FALSE(isRight(*entry.steps[0].question, typed));
    for (const char* bad : {"", " ", "x", "1/0", "nan", "inf", "1e400", "2/", "/3", "1.5.2", "1 2", "0,5", "sqrt(-2)"})
        EXPECT_THROW(typedNumber(bad, "entry"), InputError) << bad;
    EXPECT_DOUBLE_EQ(typedNumber(" 3 / 4 ", "entry"), 0.75);

    const Lesson order = lessonWith(houseStep(R"({"kind": "order", "prompt": "p"})"));
    Answer ordered;
    ordered.order = {0, 1, 2, 3, 4};
    EXPECT_TRUE(isRight(*order.steps[0].question, ordered));
    ordered.order = {1, 0, 2, 3, 4};
    EXPECT_FALSE(isRight(*order.steps[0].question, ordered));
}

// A small scene with VPN (1, 0, 1) and VRP at the origin: R's third row is n = (sqrt(2)/2, 0, sqrt(2)/2), so
// R's entry (3, 1) is sqrt(2)/2 and R takes (1, 0, 0) to its first column, (sqrt(2)/2, 0, sqrt(2)/2).
std::string diagonalStep(const std::string& question)
{
    return R"({"scene": {"view": {"projection": "perspective", "vrp": [0, 0, 0], "vpn": [1, 0, 1], "vup": [0, 1, 0],
               "prp": [0, 0, 10], "window": [-1, 1, -1, 1], "front": 5, "back": -5}},
               "caption": "c", "question": )" + question + "}";
}

// A student's answer as the app and the page read it: the typed texts, and their doubles.
Answer typedAnswer(const std::vector<std::string>& texts)
{
    Answer answer;
    answer.typed = texts;
    const auto value = [&](std::size_t k) { return typedNumber(texts[k], "x"); };
    if (texts.size() == 1)
        answer.entry = value(0);
    else
        answer.where = {value(0), value(1), value(2)};
    return answer;
}

TEST(Lesson, ExactAnswersAreDecidedExactly)
{
    const Lesson r = lessonWith(diagonalStep(R"({"kind": "entry", "prompt": "p", "stage": 2, "row": 3, "column": 1})"));
    const Question& entry = *r.steps[0].question;
    ASSERT_EQ(r.steps[0].scene.name, "inline scene");
    EXPECT_DOUBLE_EQ(entry.entry, std::sqrt(0.5));
    for (const char* right : {"sqrt(2)/2", "\u221a2/2", "1/\u221a2", "1/sqrt(2)", "sqrt(1/2)", "0.7071", "0.707"})
        EXPECT_TRUE(isRight(entry, typedAnswer({right}))) << right; // 0.7071 and 0.707 within 0.5 %, as before
    for (const char* wrong : {"sqrt(3)/2", "-sqrt(2)/2", "0.7", "\u221a2"})
        EXPECT_FALSE(isRight(entry, typedAnswer({wrong}))) << wrong;

    // Foley's house from its corner: SH_per's shy = -13/36 (entry (2, 3) of stage 4).
    const Lesson corner = lessonWith(R"({"scene": "house-corner.json", "caption": "c", "question":
        {"kind": "entry", "prompt": "p", "stage": 4, "row": 2, "column": 3}})");
    const Question& shy = *corner.steps[0].question;
    EXPECT_TRUE(isRight(shy, typedAnswer({"-13/36"})));
    EXPECT_TRUE(isRight(shy, typedAnswer({"\u221213/36"})));
    EXPECT_TRUE(isRight(shy, typedAnswer({"-0.3611"})));
    EXPECT_FALSE(isRight(shy, typedAnswer({"-13/35"}))); // 2.8 % off
    // Decided exactly at the tolerance's edge (0.5 % of 13/36 and 1e-9): on it is right, 1e-30 beyond it is
    // not, a difference no double holds (the doubles of both are the same number).
    const std::string edge = "-13/36 - 13/7200 - 1/1000000000";
    EXPECT_TRUE(isRight(shy, typedAnswer({edge})));
    EXPECT_FALSE(isRight(shy, typedAnswer({edge + " - 1e-30"})));
    EXPECT_EQ(typedNumber(edge, "x"), typedNumber(edge + " - 1e-30", "x"));

    // A point: (1, 0, 0) after R, within the 1 % tolerance as before.
    const Lesson where = lessonWith(diagonalStep(R"({"kind": "where", "prompt": "p", "point": [1, 0, 0], "after": 2})"));
    const Question& point = *where.steps[0].question;
    EXPECT_TRUE(isRight(point, typedAnswer({"\u221a2/2", "0", "1/\u221a2"})));
    EXPECT_TRUE(isRight(point, typedAnswer({"0.7071", "0", "0.7071"})));
    EXPECT_FALSE(isRight(point, typedAnswer({"\u221a2/2", "0", "-1/\u221a2"})));

    // The answers kept as typed, beside their values.
    const auto results = nlohmann::json::parse(
        resultsToJson(lessonWith(diagonalStep(R"({"kind": "entry", "prompt": "p", "stage": 2, "row": 3, "column": 1})")),
                      {typedAnswer({"1/\u221a2"})}, {true}, {1}))["answers"][0];
    EXPECT_EQ(results["typed"], "1/\u221a2");
    EXPECT_EQ(results["answer"], std::sqrt(0.5));
    EXPECT_EQ(results["correct"], true);
    EXPECT_EQ(nlohmann::json::parse(answerToJson(entry, typedAnswer({"1/\u221a2"}))), std::sqrt(0.5));
}

TEST(Lesson, ATypedNumberThatIsNoneIsRefusedWithItsReason)
{
    const auto reason = [](const std::string& text) {
        try {
            typedNumber(text, "entry");
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string("read");
    };
    EXPECT_EQ(reason("2 +* 3"), "entry: expected a number, sqrt(...) or ( at character 4 of \"2 +* 3\"");
    EXPECT_EQ(reason("1/0"), "entry: division by zero at character 3 of \"1/0\"");
    EXPECT_EQ(reason("\u221a(-2)"), "entry: the square root of -2, a negative number, at character 1 of \"\u221a(-2)\"");
    EXPECT_EQ(reason("1e400"), "entry: must be a finite number (1e400 is too large for a double)");
    EXPECT_EQ(reason(""), "entry: is empty: type a number (a decimal, a fraction p/q, a root with sqrt(\u2026) or \u221a)");
}

// The verdicts are the scene's as typed, decided exactly as `viewpipe trace` decides them: glFrustum(-2, 2,
// -1.5, 1.5, 2, 10)'s near center (0, 0, -2) and corner (2, 1.5, -2) lie on the canonical volume's near face,
// so inside (in double -3/2 comes out -1.4999999999999998 and the near center outside: exact_test.cpp).
TEST(Lesson, InsideAndTheSignOfWAreDecidedExactly)
{
    const auto frustum = [](const std::string& question) {
        return lessonWith(R"({"scene": {"camera": {"look_at": {"eye": [0, 0, 0], "center": [0, 0, -1], "up": [0, 1, 0]},
            "projection": {"type": "frustum", "left": -2, "right": 2, "bottom": -1.5, "top": 1.5, "near": 2, "far": 10}}},
            "caption": "c", "question": )" + question + "}");
    };
    for (const char* point : {"[0, 0, -2]", "[2, 1.5, -2]", "[0, 0, -10]"})
        EXPECT_TRUE(frustum(std::string(R"({"kind": "inside", "prompt": "p", "point": )") + point + "}").steps[0].question->inside)
            << point;
    EXPECT_FALSE(frustum(R"({"kind": "inside", "prompt": "p", "point": [2.001, 0, -2]})").steps[0].question->inside);
    EXPECT_NO_THROW(frustum(R"({"kind": "inside", "prompt": "p", "point": [0, 0, -2], "answer": true})"));
    // Looking at (1, 2, 3), the point (5, -1, -1) lies in the eye's plane (5 - 2 - 3 = 0): w is 0 after the
    // projection (double arithmetic gives -1.1e-16, "negative").
    const Lesson onEyePlane = lessonWith(R"({"scene": {"camera": {"look_at": {"eye": [0, 0, 0], "center": [1, 2, 3], "up": [0, 1, 0]},
        "projection": {"type": "frustum", "left": -2, "right": 2, "bottom": -1.5, "top": 1.5, "near": 2, "far": 10}}},
        "caption": "c", "question": {"kind": "sign_w", "prompt": "p", "point": [5, -1, -1], "after": 5, "answer": "zero"}})");
    EXPECT_EQ(onEyePlane.steps[0].question->signW, 0);
}

// A lesson's written answer may be an exact expression, checked exactly against the scene's.
TEST(Lesson, AWrittenAnswerMayBeAnExactExpression)
{
    const auto entry = [](const std::string& answer) {
        return lessonWith(R"({"scene": "house-corner.json", "caption": "c", "question": {"kind": "entry", "prompt": "p",
            "stage": 4, "row": 2, "column": 3, "answer": )" + answer + "}}");
    };
    EXPECT_NO_THROW(entry("\"-13/36\""));
    EXPECT_NO_THROW(entry("-0.3611111111111111")); // a number as before, within 1e-9
    expectRefused([&] { entry("\"-13/35\""); }, "steps[0].question.answer",
                  "is -13/35 but the entry is -0.3611111111111111 (-13/36)");
    expectRefused([&] { entry("\"2 +* 3\""); }, "steps[0].question.answer", "expected a number, sqrt(...) or ( at character 4 of \"2 +* 3\"");
    EXPECT_NO_THROW(lessonWith(diagonalStep(
        R"({"kind": "where", "prompt": "p", "point": [1, 0, 0], "after": 2, "answer": ["sqrt(2)/2", 0, "1/√2"]})")));
}

// A question's point takes exact expressions as a scene's fields do (parseExact, the field's path in a
// refusal), is saved as typed and traced exactly. gluPerspective(60, 1, 1, 10)'s right face is x = -z/sqrt(3),
// so (3 sqrt(3), 0, -9) lies on it: inside, and x/w = 1 after the projection. Its nearest double,
// 5.196152422706632, is a decimal just past the face: outside.
TEST(Lesson, AQuestionsPointMayBeExactExpressions)
{
    const auto ask = [](const std::string& question) {
        return lessonWith(R"({"scene": {"camera": {"look_at": {"eye": [0, 0, 0], "center": [0, 0, -1], "up": [0, 1, 0]},
            "projection": {"type": "perspective", "fovy_deg": 60, "aspect": 1, "near": 1, "far": 10}}},
            "caption": "c", "question": )" + question + "}");
    };
    const Lesson inside = ask(R"j({"kind": "inside", "prompt": "p", "point": ["3*sqrt(3)", 0, "-9"]})j");
    const Question& q = *inside.steps[0].question;
    EXPECT_TRUE(q.inside);
    EXPECT_EQ(q.point, Vec3<double>(5.196152422706632, 0, -9));
    EXPECT_FALSE(ask(R"({"kind": "inside", "prompt": "p", "point": [5.196152422706632, 0, -9]})").steps[0].question->inside);
    EXPECT_EQ(nlohmann::json::parse(questionToJson(q))["point"], nlohmann::json::parse(R"j(["3*sqrt(3)", 0.0, "-9"])j"));
    EXPECT_TRUE(parseQuestion(questionToJson(q), inside.steps[0].scene).inside); // read back as typed

    const Question where = *ask(R"j({"kind": "where", "prompt": "p", "point": ["3*sqrt(3)", "√3", -9], "after": 4,
        "answer": [1, "1/3", "79/81"]})j").steps[0].question;
    ASSERT_TRUE(where.exact);
    EXPECT_EQ((*where.exact)[0], Exact(1));
    EXPECT_EQ((*where.exact)[1], Exact(1) / Exact(3));

    expectRefused([&] { ask(R"({"kind": "inside", "prompt": "p", "point": [0, 0, "1/0"]})"); }, "steps[0].question.point[2]",
                  "division by zero at character 3 of \"1/0\"");
    expectRefused([&] { ask(R"({"kind": "inside", "prompt": "p", "point": [0, true, -2]})"); }, "steps[0].question.point[1]",
                  "must be a number or an exact expression such as \"20*sqrt(2)\" (got true)");
}

// One question edited as JSON is read as the lesson reads it, with its field paths.
TEST(Lesson, AQuestionIsEditedAsTheFileHoldsIt)
{
    const Scene house = loadScene(kScenes + "/house.json");
    const Question q = parseQuestion(R"({"kind": "sign_w", "prompt": "p", "point": [8, 6, 84], "after": 5})", house);
    EXPECT_EQ(q.signW, 1); // N_per's five stages are affine: w stays 1
    expectRefused([&] { parseQuestion(R"({"kind": "entry", "prompt": "p", "stage": 9, "row": 1, "column": 1})", house); },
                  "question.stage", "must be a whole number from 1 to 5");
}

// What a step hides is not in the scene its pictures draw; what it highlights is wider there.
TEST(Lesson, AStepHidesAndHighlightsElementsAndEntries)
{
    const Lesson lesson = lessonWith(R"({"scene": "house.json", "stage": 4, "caption": "c", "hide": ["projectors", "labels", "legend"],
        "highlight": {"elements": ["window"], "entries": [[1, 3], [2, 3]]}, "panel": "matrices"})");
    const LessonStep& step = lesson.steps[0];
    EXPECT_EQ(step.hidden, std::set<Element>{Element::Projectors});
    EXPECT_TRUE(step.labelsHidden);
    EXPECT_EQ(step.entries, (std::vector<std::array<int, 2>>{{1, 3}, {2, 3}}));
    const std::shared_ptr<const EvaluatedScene> full = evaluateScene(step.scene), shown = shownAtStep(full, step);
    auto count = [](const EvaluatedScene& scene, Element e) {
        return std::count_if(scene.primitives.begin(), scene.primitives.end(), [&](const Primitive& p) { return p.element == e; });
    };
    ASSERT_GT(count(*full, Element::Projectors), 0);
    EXPECT_EQ(count(*shown, Element::Projectors), 0);
    EXPECT_EQ(count(*shown, Element::Window), count(*full, Element::Window));
    for (const Primitive& p : shown->primitives)
        EXPECT_EQ(p.widthScale, p.element == Element::Window ? 2.5 : 1.0);
    EXPECT_TRUE(shown->labels.empty());
    EXPECT_FALSE(full->labels.empty());
    EXPECT_TRUE(step.legendHidden);
    EXPECT_TRUE(shown->worldLegend.empty() && shown->projectedLegend.empty());
    EXPECT_FALSE(full->worldLegend.empty());
    // A step that changes nothing draws the scene itself.
    EXPECT_EQ(shownAtStep(full, lessonWith(R"({"scene": "house.json", "caption": "c"})").steps[0]), full);

    expectRefused([] { lessonWith(R"({"scene": "house.json", "caption": "half $\\frac{1}{2$"})"); }, "steps[0].caption",
                  "has math whose braces do not pair up: $\\frac{1}{2$");
    expectRefused([] { lessonWith(R"({"scene": "house.json", "caption": "$x}{$"})"); }, "steps[0].caption",
                  "braces do not pair up");
    EXPECT_NO_THROW(lessonWith(R"({"scene": "house.json", "caption": "a set $\\{x\\}$ and \\$5 {plain}"})"));
    expectRefused([] { lessonWith(R"({"scene": "house.json", "caption": "c", "question": {"kind": "choice", "prompt": "p",
                   "choices": ["$x$", "$\\mathcal{X}$"], "answer": 1}})"); }, "steps[0].question.choices[1]", "\\mathcal");
    expectRefused([] { lessonWith(R"({"scene": "house.json", "caption": "c", "hide": ["walls"]})"); }, "steps[0].hide[0]",
                  "must be one of objects, world_axes");
    expectRefused([] { lessonWith(R"({"scene": "house.json", "caption": "c", "highlight": {"entries": [[1, 3]]}})"); },
                  "steps[0].highlight.entries", "the world (stage 0) has no matrix");
    expectRefused([] { lessonWith(R"({"scene": "house.json", "stage": 2, "caption": "c", "highlight": {"entries": [[1, 5]]}})"); },
                  "steps[0].highlight.entries[0][1]", "must be a whole number from 1 to 4");
    expectRefused([] { lessonWith(R"({"scene": "house.json", "caption": "c", "highlight": {"elements": ["labels"]}})"); },
                  "steps[0].highlight.elements[0]", "must be one of");
    expectRefused([] { lessonWith(R"({"scene": "house.json", "caption": "c", "panel": "tikz"})"); }, "steps[0].panel",
                  "must be one of stages, matrices");
}

// A step may show every stage at once; the file keeps it, and only the layouts there are.
TEST(Lesson, AStepMayShowTheStoryboard)
{
    const Lesson lesson = lessonWith(R"({"scene": "house.json", "caption": "c", "layout": "storyboard"})");
    EXPECT_TRUE(lesson.steps[0].storyboard);
    EXPECT_FALSE(lessonWith(R"({"scene": "house.json", "caption": "c", "layout": "stages"})").steps[0].storyboard);
    EXPECT_FALSE(lessonWith(R"({"scene": "house.json", "caption": "c"})").steps[0].storyboard);
    const std::string written = lessonToJson(lesson, kScenes);
    EXPECT_NE(written.find(R"("layout": "storyboard")"), std::string::npos) << written;
    EXPECT_TRUE(parseLesson(written, kScenes).steps[0].storyboard);
    expectRefused([] { lessonWith(R"({"scene": "house.json", "caption": "c", "layout": "grid"})"); }, "steps[0].layout",
                  "must be stages or storyboard (got \"grid\")");
    expectRefused([] { lessonWith(R"({"scene": "house.json", "caption": "c", "layout": 2})"); }, "steps[0].layout", "");
}

// One evaluation a scene, however many steps show it; one shown scene for the steps that show it alike; a scene the
// core refuses named by its step.
TEST(Lesson, ItsStepsAreEvaluatedOnceAndRefusedByStep)
{
    const Lesson lesson = parseLesson(R"({"title": "t", "steps": [
        {"scene": "house.json", "stage": 1, "caption": "a"},
        {"scene": "house.json", "stage": 3, "caption": "b"},
        {"scene": "house.json", "caption": "c", "hide": ["projectors"]},
        {"scene": "opengl-perspective.json", "caption": "d"},
        {"scene": "house.json", "caption": "e", "hide": ["projectors"]}]})", kScenes);
    SceneEvaluator evaluator;
    test::EvaluationCount count;
    const ListeningToEvaluations listening(count);
    const EvaluatedLesson evaluated = evaluateLesson(lesson, &evaluator);
    EXPECT_EQ(count.evaluations, 2) << "the house once, the OpenGL scene once";
    EXPECT_EQ(evaluated.stepShown, (std::vector<int>{0, 0, 1, 2, 1}));
    ASSERT_EQ(evaluated.shown.size(), 3u);
    ASSERT_EQ(evaluated.stepScene.size(), 5u);
    EXPECT_EQ(evaluated.stepScene[0], evaluated.stepScene[2]);
    EXPECT_EQ(evaluated.stepScene[0], evaluated.stepScene[4]);
    EXPECT_EQ(evaluated.shown[0], evaluated.stepScene[0]) << "a step that hides nothing shows the scene itself";
    EXPECT_NE(evaluated.shown[1], evaluated.stepScene[2]);
    EXPECT_EQ(evaluated.stepScene[3]->scene, lesson.steps[3].scene);
    for (const Primitive& p : evaluated.shown[1]->primitives)
        EXPECT_NE(p.element, Element::Projectors);
    // Evaluated again after an edit of a caption: the scenes evaluated before are kept.
    Lesson edited = lesson;
    edited.steps[1].caption = "b, edited";
    const EvaluatedLesson again = evaluateLesson(edited, &evaluator, &evaluated);
    EXPECT_EQ(count.evaluations, 2);
    EXPECT_EQ(again.stepScene, evaluated.stepScene);

    // A mesh that parses as a file name but not as a mesh: refused when the step's scene is evaluated.
    namespace fs = std::filesystem;
    const fs::path folder = fs::temp_directory_path() / ("viewpipe-lesson-refused-" + std::to_string(::getpid()));
    fs::create_directories(folder);
    writeFileAtomically(folder / "cut.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                                            "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                                            "end_header\n0 0 0\n1 0");
    writeFileAtomically(folder / "mesh.json", R"({"view": )" + nlohmann::json::parse(sceneToJson(loadScene(kScenes + "/house.json")))["view"].dump() +
                                              R"(, "objects": [{"type": "mesh", "path": "cut.ply"}]})");
    writeFileAtomically(folder / "house.json", sceneToJson(loadScene(kScenes + "/house.json")));
    const Lesson refused = parseLesson(R"({"title": "t", "steps": [{"scene": "house.json", "caption": "a"},
        {"scene": "mesh.json", "caption": "b"}]})", folder);
    expectRefused([&] { evaluateLesson(refused); }, "steps[1].scene.objects[0].path", "");
    fs::remove_all(folder);
}

// Scenes are the same by their contents: name, camera, objects and effects, not the file they were read from.
TEST(Lesson, ScenesCompareByWhatTheyHold)
{
    const Scene house = loadScene(kScenes + "/house.json");
    Scene copy = parseScene(sceneToJson(house), kScenes);
    copy.name = house.name;
    EXPECT_TRUE(copy == house);
    Scene moved = copy;
    std::get<foley::ViewSpec<double>>(moved.camera).prp.x() += 1e-12;
    EXPECT_TRUE(moved != house);
    Scene parallel = copy;
    std::get<foley::ViewSpec<double>>(parallel.camera).projection = foley::Projection::Parallel;
    EXPECT_TRUE(parallel != house);
    Scene clipped = copy;
    clipped.effects = withEffect(clipped.effects, EffectKind::Clip, true);
    EXPECT_TRUE(clipped != house);
    Scene boxed = copy;
    SceneObject box;
    box.type = ObjectType::Box;
    box.max = Vec3<double>(1, 1, 1);
    boxed.objects.push_back(box);
    EXPECT_TRUE(boxed != house);
    const Scene gl = loadScene(kScenes + "/opengl-perspective.json");
    EXPECT_TRUE(gl != house);
    Scene vulkan = gl;
    std::get<gl::Camera<double>>(vulkan.camera).api = gl::Api::Vulkan;
    EXPECT_TRUE(vulkan != gl);
}

} // namespace
} // namespace viewpipe
