// The stage kinds' one table: complete, each name unique, and what every
// pipeline builds; a lesson's which_stage answer read as a kind.

#include <gtest/gtest.h>

#include <cctype>
#include <set>

#include "build_paths.h"
#include "support.hpp"
#include "viewpipe/effects.hpp"
#include "viewpipe/foley.hpp"
#include "viewpipe/gl.hpp"
#include "viewpipe/lesson.hpp"
#include "viewpipe/math_text.hpp"
#include "viewpipe/scene.hpp"
#include "viewpipe/stage_kind.hpp"

namespace viewpipe {
namespace {

TEST(StageKind, TheTableListsEveryKindOnceInOrder)
{
    const std::vector<StageKind> kinds = stageKinds();
    ASSERT_EQ(kinds.size(), std::size_t(StageKind::Divide) + 1);
    for (std::size_t k = 0; k < kinds.size(); ++k)
        EXPECT_EQ(kinds[k], StageKind(k)) << k;
}

TEST(StageKind, NamesAreUniqueAndRoundTrip)
{
    std::set<std::string> symbols, slugs, maths;
    for (const StageKind kind : stageKinds()) {
        const std::string symbol = stageSymbol(kind), slug = stageSlug(kind);
        EXPECT_TRUE(symbols.insert(symbol).second) << symbol;
        EXPECT_TRUE(slugs.insert(slug).second) << slug;
        EXPECT_TRUE(maths.insert(stageSymbolMath(kind)).second) << symbol;
        EXPECT_EQ(stageKindNamed(symbol), kind) << symbol;
        EXPECT_EQ(symbolMath(symbol), stageSymbolMath(kind)) << symbol;
        // A file name's part: the symbol in lower case, each run of other characters one hyphen, none at the ends.
        std::string expected;
        for (const char c : symbol)
            if (std::isalnum(static_cast<unsigned char>(c)))
                expected += char(std::tolower(static_cast<unsigned char>(c)));
            else if (!expected.empty() && expected.back() != '-')
                expected += '-';
        while (!expected.empty() && expected.back() == '-')
            expected.pop_back();
        EXPECT_EQ(slug, expected) << symbol;
    }
    EXPECT_EQ(stageKindNamed("S_PER"), std::nullopt);
    EXPECT_EQ(stageKindNamed(""), std::nullopt);
    EXPECT_EQ(symbolMath("Q_x"), "Q_x"); // no stage's: left as written
}

TEST(StageKind, OnlyTheDivideDivides)
{
    for (const StageKind kind : stageKinds())
        EXPECT_EQ(stageDivides(kind), kind == StageKind::Divide) << stageSymbol(kind);
}

TEST(StageKind, NamesAsTheBookAndTheReportsWriteThem)
{
    EXPECT_EQ(stageSymbol(StageKind::TranslateVrp), "T(-VRP)");
    EXPECT_EQ(stageSlug(StageKind::TranslateVrp), "t-vrp");
    EXPECT_EQ(stageSymbolMath(StageKind::TranslateVrp), "T(-\\mathit{VRP})");
    EXPECT_EQ(stageSymbolMath(StageKind::ScalePerspective), "S_{\\mathrm{per}}");
    EXPECT_EQ(stageSymbolMath(StageKind::NdcWebgpuReversed), "\\mathit{NDC}_{\\text{WebGPU, reversed}}");
    EXPECT_EQ(stageSymbol(StageKind::PerspectiveToParallel), "M");
    EXPECT_EQ(stageSymbol(StageKind::Divide), "divide");
}

// Every kind is one some pipeline builds: Foley's two views with the divide, and OpenGL's three projections in
// every API, handedness and depth.
TEST(StageKind, EveryKindIsBuiltBySomePipeline)
{
    std::set<StageKind> built;
    const auto add = [&](const Pipeline<double>& p) {
        for (const Stage<double>& stage : p.stages)
            built.insert(stage.kind);
    };
    const EffectList divide = withEffect({}, EffectKind::Divide, true);
    for (const char* name : {"house.json", "house-parallel-oblique.json"})
        add(buildPipeline(loadScene(std::string(build::dataDir) + "/scenes/" + name).camera, divide));
    const std::vector<gl::ProjectionSpec<double>> projections = {gl::Frustum<double>{-1, 1, -1, 1, 1, 10},
                                                                 gl::Ortho<double>{-1, 1, -1, 1, 1, 10},
                                                                 gl::Perspective<double>{60, 1, 1, 10}};
    for (const gl::ProjectionSpec<double>& projection : projections)
        for (const gl::Api api : gl::kApis)
            for (const gl::Handedness hand : {gl::Handedness::Right, gl::Handedness::Left})
                for (const gl::DepthMode depth : {gl::DepthMode::Standard, gl::DepthMode::Reversed}) {
                    gl::Camera<double> camera{{{0, 0, 5}, {0, 0, 0}, {0, 1, 0}}, projection};
                    camera.api = api;
                    camera.handedness = hand;
                    camera.depth = depth;
                    add(buildPipeline(CameraSpec<double>(camera), divide));
                }
    for (const StageKind kind : stageKinds())
        EXPECT_TRUE(built.count(kind)) << stageSymbol(kind) << " is built by no pipeline";
}

// A which_stage answer names a stage by its symbol: read as the kind of that stage, else refused.
TEST(StageKind, ALessonsWhichStageAnswerIsReadAsAKind)
{
    const auto lesson = [](const std::string& answer) {
        return parseLesson(R"({"title": "t", "steps": [{"scene": "house.json", "stage": 2, "caption": "c",
            "question": {"kind": "which_stage", "prompt": "p", "stage": 4, "answer": ")" + answer + R"("}}]})",
                           std::string(build::dataDir) + "/scenes");
    };
    EXPECT_EQ(lesson("SH_per").steps[0].question->correct, 3);
    test::expectRefused([&] { lesson("S_per"); }, "steps[0].question.answer", "is \"S_per\" but stage 4 is SH_per");
    test::expectRefused([&] { lesson("SH_PER"); }, "steps[0].question.answer", "is \"SH_PER\" but stage 4 is SH_per");
}

} // namespace
} // namespace viewpipe
