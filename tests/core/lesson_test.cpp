// Lesson files: answers computed from the scene (checked here against the
// house's known numbers, Foley et al. ch. 6: PRP (8, 6, 84), SH_per's
// -DOPx/DOPz = -8/84 = -2/21), and refusals that name the field.

#include <gtest/gtest.h>

#include <filesystem>

#include "support.hpp"
#include "viewpipe/lesson.hpp"

namespace viewpipe {
namespace {

using test::expectRefused;

const std::string kScenes = std::string(VIEWPIPE_DATA_DIR) + "/scenes";

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
    // A point whose image overflows has no answer: refused, not answered with NaN.
    refused(houseStep(R"({"kind": "where", "prompt": "p", "point": [1.7e308, 0, -1.7e308], "after": 4})"),
            "steps[0].question.point", "no finite image");
    refused(R"({"scene": "house.json", "caption": "costs $5"})", "steps[0].caption", "$");
    refused(R"({"scene": "nope.json", "caption": "c"})", "steps[0].scene", "nope.json: $: cannot read the scene file");
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
    for (const auto& entry : std::filesystem::directory_iterator(std::string(VIEWPIPE_DATA_DIR) + "/lessons")) {
        if (entry.path().extension() != ".json")
            continue;
        ++count;
        const Lesson lesson = loadLesson(entry.path());
        int questions = 0;
        for (const LessonStep& step : lesson.steps)
            questions += step.question.has_value();
        EXPECT_GE(questions, 3) << entry.path(); // each asks, not only shows
    }
    EXPECT_GE(count, 5);
}

} // namespace
} // namespace viewpipe
