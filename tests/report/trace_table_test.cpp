// The trace table the app's Matrices panel and the web page show (report::traceTable): one text for both.

#include <gtest/gtest.h>

#include <filesystem>

#include "build_paths.h"
#include "viewpipe/effects.hpp"
#include "viewpipe/report/trace_table.hpp"
#include "viewpipe/scene.hpp"

namespace viewpipe::report {
namespace {

const std::filesystem::path kScenes = std::filesystem::path(viewpipe::build::dataDir) / "scenes";

TEST(TableCell, FiveDigitsWithMinusSignsOrTheExactValue)
{
    EXPECT_EQ(tableCell(-24.0 / 59), "\u22120.40678");
    EXPECT_EQ(tableCell(-1.5e-7), "\u22121.5e\u221207");
    EXPECT_EQ(tableCell(-0.0), "0");
    const Exact third = Exact(1) / Exact(3);
    EXPECT_EQ(tableCell(1.0 / 3, &third), "$\\frac{1}{3}$");
    const Exact wide = Exact("0.5773502691896258"); // a scene's decimal taken exactly does not read so
    EXPECT_EQ(tableCell(0.5773502691896258, &wide), "0.57735");
}

// Foley's house (PRP (8, 6, 84), VRC = world): its front's corner (0, 0, 54) after T(-PRP) is (-8, -6, -30);
// after every stage it is inside the canonical volume.
TEST(TraceTable, TheHousesCornerByHand)
{
    const Scene house = loadScene(kScenes / "house.json");
    const Pipeline<double> pipeline = buildPipeline(house.camera, house.effects);
    const Pipeline<Exact> exact = exactPipeline(house);
    const int stages = int(pipeline.stages.size());
    const TraceTable all = traceTable(pipeline, &exact, {0, 0, 54}, stages);
    ASSERT_EQ(int(all.rows.size()), stages + 1);
    EXPECT_EQ(all.rows[0].stage, "world");
    EXPECT_EQ(all.rows[0].cells, (std::array<std::string, 4>{"$0$", "$0$", "$54$", "$1$"}));
    EXPECT_EQ(all.rows[3].stage, "$T(-\\mathit{PRP})$");
    EXPECT_EQ(all.rows[3].cells, (std::array<std::string, 4>{"$-8$", "$-6$", "$-30$", "$1$"}));
    EXPECT_EQ(all.verdict.substr(0, 19), "After the divide: (");
    EXPECT_NE(all.verdict.find("; inside the canonical volume."), std::string::npos) << all.verdict;

    // Without the exact pipeline: numbers in the one format; rows up to the stage asked, no verdict.
    const TraceTable two = traceTable(pipeline, nullptr, {0, 0, 54}, 3);
    ASSERT_EQ(two.rows.size(), 4u);
    EXPECT_EQ(two.rows[3].cells, (std::array<std::string, 4>{"\u22128", "\u22126", "\u221230", "1"}));
    EXPECT_EQ(two.verdict, "");
}

} // namespace
} // namespace viewpipe::report
