// The storyboard (storyboard.hpp): every stage at once in reading order, its
// text as large as asked when set 16 cm wide, arrows from each view to the
// next naming the stage's matrix, the traced point's coordinates in each
// stage's space (Foley's house: PRP (8, 6, 84), so T(-PRP) takes the corner
// (0, 0, 54) to (-8, -6, -30)).

#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <filesystem>

#include "build_paths.h"
#include "viewpipe/math_text.hpp"
#include "viewpipe/report/storyboard.hpp"
#include "viewpipe/report/style.hpp"
#include "viewpipe/report/tikz.hpp"
#include "viewpipe/report/web_page.hpp"

#include <nlohmann/json.hpp>

namespace viewpipe::report {
namespace {

namespace fs = std::filesystem;

std::shared_ptr<const EvaluatedScene> builtIn(const std::string& name)
{
    return evaluateScene(loadScene(fs::path(viewpipe::build::dataDir) / "scenes" / name));
}

std::vector<int> allStages(const EvaluatedScene& scene)
{
    std::vector<int> stages;
    for (int k = 0; k <= int(scene.pipeline.stages.size()); ++k)
        stages.push_back(k);
    return stages;
}

// Text as wide as the characters it shows at 0.6 of its size, as high as its size: enough to lay out by.
FontMeasure roughMeasure()
{
    return [](const std::string& text, double pixels, bool) {
        return Vec2<double>(0.6 * pixels * double(mathPlainText(text).size()), pixels);
    };
}

// 16 cm in points: what a pixel of the storyboard becomes when it is set that wide.
constexpr double kPointsAcross = 16 / 2.54 * 72.27;

TEST(Storyboard, ItsTextIsAtLeast8And6PointsSet16CmWide)
{
    for (const int width : {640, 800, 1280, 1920, 3840})
        for (const double textScale : {0.5, 1.0, 2.0}) {
            const double label = storyboardLabelSize(width, textScale), small = smallTextSize(label);
            const double pt = kPointsAcross / width;
            EXPECT_GE(label * pt, 8 * std::min(1.0, textScale)) << width << " at " << textScale;
            EXPECT_GE(small * pt, 6 * std::min(1.0, textScale)) << width << " at " << textScale;
        }
}

TEST(Storyboard, CellsFollowInReadingOrderAndApart)
{
    for (const auto& [width, height] : {std::pair(1280, 720), std::pair(800, 450), std::pair(1920, 400), std::pair(600, 1200)})
        for (const int pictures : {1, 5, 6, 7, 12}) {
            SCOPED_TRACE(std::to_string(width) + "x" + std::to_string(height) + ", " + std::to_string(pictures));
            std::vector<int> stages(static_cast<std::size_t>(pictures));
            for (int k = 0; k < pictures; ++k)
                stages[std::size_t(k)] = k;
            const StoryboardLayout layout = layoutStoryboard(stages, width, height, storyboardLabelSize(width, 1));
            ASSERT_EQ(int(layout.cells.size()), pictures);
            const Box2 page{{0, 0}, {double(width), double(height)}};
            std::vector<Box2> boxes;
            for (std::size_t k = 0; k < layout.cells.size(); ++k) {
                const StoryboardCell& cell = layout.cells[k];
                EXPECT_EQ(cell.stage, int(k));
                for (const Box2& box : {cell.header, cell.picture, cell.footer}) {
                    EXPECT_TRUE(page.contains(box));
                    EXPECT_FALSE(box.isEmpty());
                    boxes.push_back(box);
                }
                // The picture under its header, over its footer; all pictures one size.
                EXPECT_EQ(cell.header.max.y(), cell.picture.min.y());
                EXPECT_EQ(cell.picture.max.y(), cell.footer.min.y());
                EXPECT_TRUE((cell.picture.max - cell.picture.min).isApprox(layout.cells[0].picture.max - layout.cells[0].picture.min));
                if (k == 0)
                    continue;
                // Reading order: right of the one before in its row, else below it at the left.
                const StoryboardCell& before = layout.cells[k - 1];
                if (k % std::size_t(layout.columns) != 0) {
                    EXPECT_GT(cell.picture.min.x(), before.picture.max.x());
                    EXPECT_EQ(cell.picture.min.y(), before.picture.min.y());
                } else {
                    EXPECT_GT(cell.header.min.y(), before.footer.max.y() - 1e-9);
                    EXPECT_EQ(cell.picture.min.x(), layout.cells[0].picture.min.x());
                }
            }
            for (std::size_t a = 0; a < boxes.size(); ++a)
                for (std::size_t b = a + 1; b < boxes.size(); ++b)
                    EXPECT_FALSE(boxes[a].overlaps(boxes[b])) << a << " and " << b;
        }
    // The house's six pictures at 16:9: two rows of three.
    EXPECT_EQ(layoutStoryboard({0, 1, 2, 3, 4, 5}, 1280, 720, storyboardLabelSize(1280, 1)).columns, 3);
}

TEST(Storyboard, TheTracedPointIsGivenInEachStagesCoordinates)
{
    const auto house = builtIn("house.json");
    const Vec3<double> corner = storyboardTracedPoint(*house);
    EXPECT_EQ(corner, Vec3<double>(0, 0, 54));
    EXPECT_EQ(tracedCoordinates(*house, corner, 0), "(0, 0, 54)");
    EXPECT_EQ(tracedCoordinates(*house, corner, 3), "(\u22128, \u22126, \u221230)"); // T(-PRP): minus PRP (8, 6, 84)
    // gluPerspective leaves w = -z: the stage's coordinates are homogeneous.
    const auto opengl = builtIn("opengl-perspective.json");
    const int last = int(opengl->pipeline.stages.size());
    EXPECT_NE(tracedCoordinates(*opengl, storyboardTracedPoint(*opengl), last).find(", w = "), std::string::npos);
}

TEST(Storyboard, EachViewAfterTheFirstHasAnArrowNamingItsMatrix)
{
    const auto house = builtIn("house.json");
    const std::vector<int> stages = allStages(*house);
    const StoryboardLayout layout = layoutStoryboard(stages, 1280, 720, storyboardLabelSize(1280, 1));
    const Figure overlay = storyboardOverlay(*house, layout, storyboardTracedPoint(*house), roughMeasure(), 1);
    // A shaft and a head for each view after the world; a header and a footer for each.
    ASSERT_EQ(overlay.shapes.size(), 2 * (stages.size() - 1));
    ASSERT_EQ(overlay.labels.size(), 2 * stages.size());
    const char* headers[] = {"0. World", "1. $T(-\\mathit{VRP})$", "2. $R$", "3. $T(-\\mathit{PRP})$",
                             "4. $\\mathit{SH}_{\\mathrm{per}}$", "5. $S_{\\mathrm{per}}$"};
    for (std::size_t k = 0; k < stages.size(); ++k) {
        EXPECT_EQ(overlay.labels[2 * k].text, headers[k]);
        EXPECT_TRUE(layout.cells[k].header.contains(overlay.labels[2 * k].box)) << k;
        EXPECT_TRUE(layout.cells[k].footer.contains(overlay.labels[2 * k + 1].box)) << k;
        if (k == 0)
            continue;
        // The arrow's head ends in the view's header, before its text; in a row it starts in the gap from the one before.
        const FigureShape& head = overlay.shapes[2 * (k - 1) + 1];
        const FigureShape& shaft = overlay.shapes[2 * (k - 1)];
        EXPECT_TRUE(head.surface);
        EXPECT_LT(head.points[0].x(), overlay.labels[2 * k].box.min.x());
        EXPECT_GT(head.points[0].x(), layout.cells[k].header.min.x());
        if (k % std::size_t(layout.columns) != 0) {
            EXPECT_GT(shaft.points[0].x(), layout.cells[k - 1].picture.max.x());
            EXPECT_LT(shaft.points[0].x(), layout.cells[k].picture.min.x());
        }
    }
    EXPECT_EQ(labelOverlaps(overlay.labels), 0);
}

// A cell draws nothing outside its picture, in any format: lines and faces cut at its edges (a polyline
// leaving and coming back is two pieces), what lies wholly outside dropped.
TEST(Storyboard, ShapesAreCutToTheCell)
{
    using Points = std::vector<Vec2<double>>;
    Figure figure;
    figure.shapes.push_back({Element::Window, false, 1, 2, {{-50, 50}, {50, 50}, {150, 50}, {150, 80}, {50, 80}}, 0});
    figure.shapes.push_back({Element::Volume, true, 0.5, 0, {{-50, -50}, {50, -50}, {50, 50}, {-50, 50}}, 0});
    figure.shapes.push_back({Element::Dop, false, 1, 2, {{200, 200}, {300, 300}}, 0});
    cutShapesTo(figure, {{0, 0}, {100, 100}});
    ASSERT_EQ(figure.shapes.size(), 3u);
    EXPECT_EQ(figure.shapes[0].points, (Points{{0, 50}, {50, 50}, {100, 50}}));
    EXPECT_EQ(figure.shapes[1].points, (Points{{100, 80}, {50, 80}}));
    EXPECT_EQ(figure.shapes[1].element, Element::Window);
    EXPECT_EQ(figure.shapes[2].element, Element::Volume);
    ASSERT_EQ(figure.shapes[2].points.size(), 4u);
    for (const Vec2<double>& p : figure.shapes[2].points)
        EXPECT_TRUE(p.x() >= 0 && p.x() <= 50 && p.y() >= 0 && p.y() <= 50) << p.transpose();
}

// Text as wide as its characters (not its bytes: a minus sign is one) at 0.6 of its size.
FontMeasure glyphMeasure()
{
    return [](const std::string& text, double pixels, bool) {
        const std::string plain = mathPlainText(text);
        const auto glyphs = std::count_if(plain.begin(), plain.end(), [](char c) { return (c & 0xC0) != 0x80; });
        return Vec2<double>(0.6 * pixels * double(glyphs), pixels);
    };
}

// No header or footer is cut at a projector's text size (the house's S_per footer lost its z at 200 %
// in 1280x720): the text is set smaller where the cells are too narrow for it, never under its size at 100 %.
TEST(Storyboard, NoHeaderOrFooterIsCutAtLargeText)
{
    const auto house = builtIn("house.json");
    const std::vector<int> stages = allStages(*house);
    const Vec3<double> traced = storyboardTracedPoint(*house);
    const auto cut = [&](const StoryboardLayout& layout) {
        const Figure overlay = storyboardOverlay(*house, layout, traced, glyphMeasure(), 1);
        std::string cutTexts; // each text past its cell's right edge
        for (std::size_t k = 0; k < layout.cells.size(); ++k)
            for (const std::size_t text : {2 * k, 2 * k + 1})
                if (overlay.labels[text].box.max.x() > layout.cells[k].footer.max.x() + 0.5)
                    cutTexts += " \"" + overlay.labels[text].text + "\"";
        return cutTexts;
    };
    for (const auto& [width, height] : {std::pair{1280, 720}, std::pair{800, 450}, std::pair{1920, 1080}})
        for (const double textScale : {1.0, 2.0}) {
            const double label = storyboardLabelSize(width, textScale);
            const StoryboardLayout layout = layoutStoryboard(*house, stages, traced, width, height, label, glyphMeasure());
            ASSERT_EQ(layout.cells.size(), stages.size()) << width << "x" << height << " at " << textScale;
            EXPECT_LE(layout.labelSize, label);
            EXPECT_GE(layout.labelSize, storyboardLabelSize(width, 1));
            if (textScale == 1) { // where it fits as asked, as asked
                EXPECT_EQ(layout.labelSize, label);
            }
            EXPECT_EQ(cut(layout), "") << width << "x" << height << " at " << textScale << ": " << layout.columns << " columns";
        }
    // Laid out for the pictures alone, three columns cut the footers at 200 %.
    EXPECT_NE(cut(layoutStoryboard(stages, 1280, 720, storyboardLabelSize(1280, 2))), "");
}

// The page's storyboard (webStoryboard, which the page's core hands it) is this one: the same cells, headers and
// footers; each cell's labels placed inside its own picture, none over another; the point traced the page's.
TEST(Storyboard, ThePagesIsTheSameLayoutWithEachCellsLabelsPlacedInIt)
{
    const auto house = builtIn("house.json");
    WebViewOptions options;
    options.fontSize = options.minFontSize = exportLabelSize(options.width, 1); // text at 100 %
    const nlohmann::json page =
        nlohmann::json::parse(webStoryboard(*house, 1280, 720, std::nullopt, {}, options, roughMeasure()));
    const StoryboardLayout layout = layoutStoryboard(allStages(*house), 1280, 720, storyboardLabelSize(1280, 1));
    const Figure overlay = storyboardOverlay(*house, layout, storyboardTracedPoint(*house), roughMeasure(), 1);
    EXPECT_EQ(page["columns"], 3);
    EXPECT_EQ(page["labelSize"], layout.labelSize);
    EXPECT_EQ(page["traced"], nlohmann::json({0, 0, 54}));
    ASSERT_EQ(page["cells"].size(), layout.cells.size());
    ASSERT_EQ(page["texts"].size(), overlay.labels.size());
    EXPECT_EQ(page["arrows"].size(), overlay.shapes.size());
    const auto box = [](const Box2& b) { return nlohmann::json({b.min.x(), b.min.y(), b.max.x(), b.max.y()}); };
    for (std::size_t k = 0; k < layout.cells.size(); ++k) {
        const nlohmann::json& cell = page["cells"][k];
        EXPECT_EQ(cell["stage"], int(k));
        EXPECT_EQ(cell["picture"], box(layout.cells[k].picture));
        EXPECT_EQ(page["texts"][2 * k]["text"], overlay.labels[2 * k].text);
        EXPECT_EQ(page["texts"][2 * k + 1]["text"], overlay.labels[2 * k + 1].text);
        const double width = layout.cells[k].picture.max.x() - layout.cells[k].picture.min.x(),
                     height = layout.cells[k].picture.max.y() - layout.cells[k].picture.min.y();
        const nlohmann::json& labels = cell["labels"];
        EXPECT_FALSE(labels.empty()) << k;
        for (std::size_t a = 0; a < labels.size(); ++a) {
            const nlohmann::json& l = labels[a]["box"];
            EXPECT_TRUE(l[0] >= 0 && l[1] >= 0 && l[2] <= width && l[3] <= height) << k << ": " << labels[a]["text"];
            for (std::size_t b = a + 1; b < labels.size(); ++b) {
                const nlohmann::json& o = labels[b]["box"];
                EXPECT_FALSE(l[0] < o[2] && o[0] < l[2] && l[1] < o[3] && o[1] < l[3])
                    << k << ": " << labels[a]["text"] << " over " << labels[b]["text"];
            }
        }
    }
    EXPECT_EQ(page["texts"][7]["text"], "traced (\u22128, \u22126, \u221230)"); // T(-PRP), the footer of stage 3
    // A point the page traces instead: (8, 6, 84), the PRP, is the origin after T(-PRP).
    const nlohmann::json traced = nlohmann::json::parse(
        webStoryboard(*house, 1280, 720, Vec3<double>(8, 6, 84), {}, options, roughMeasure()));
    EXPECT_EQ(traced["texts"][7]["text"], "traced (0, 0, 0)");
    // gluPerspective leaves w = -z: the page's last footer gives w, as the native one (without "traced" where
    // the footer has no room for it).
    const auto opengl = builtIn("opengl-perspective.json");
    const nlohmann::json perspective =
        nlohmann::json::parse(webStoryboard(*opengl, 1280, 720, std::nullopt, {}, options, roughMeasure()));
    const std::string last = perspective["texts"].back()["text"];
    const std::string coordinates =
        tracedCoordinates(*opengl, storyboardTracedPoint(*opengl), int(opengl->pipeline.stages.size()));
    EXPECT_EQ(last.substr(last.size() - std::min(last.size(), coordinates.size())), coordinates);
    EXPECT_NE(last.find(", w = "), std::string::npos) << last;
}

// Where pictures are left out between two cells no arrow joins them: T(-PRP) does not lead from the world.
TEST(Storyboard, NoArrowJoinsPicturesOfStagesApart)
{
    const auto house = builtIn("house.json");
    const StoryboardLayout layout = layoutStoryboard({0, 3, 4}, 1280, 720, storyboardLabelSize(1280, 1));
    const Figure overlay = storyboardOverlay(*house, layout, {0, 0, 54}, roughMeasure(), 1);
    EXPECT_EQ(overlay.shapes.size(), 2u); // the one arrow, into stage 4: its shaft and head
    EXPECT_GT(overlay.shapes[1].points[0].x(), layout.cells[2].header.min.x());
}

// One document, each stage's figure in its box: pdflatex reads it as the single figures (tested there).
TEST(Storyboard, TikzDrawsEveryCellInItsBoxThenTheOverlay)
{
    const auto house = builtIn("house.json");
    Storyboard storyboard;
    storyboard.layout = layoutStoryboard(allStages(*house), 1280, 720, storyboardLabelSize(1280, 1));
    storyboard.overlay = storyboardOverlay(*house, storyboard.layout, {0, 0, 54}, roughMeasure(), 1);
    for (const StoryboardCell& cell : storyboard.layout.cells) {
        Figure figure;
        figure.width = int(cell.picture.max.x() - cell.picture.min.x());
        figure.height = int(cell.picture.max.y() - cell.picture.min.y());
        storyboard.cells.push_back(figure);
    }
    const std::string tex = tikzStoryboard(storyboard, Theme::Light);
    std::size_t at = 0;
    for (std::size_t k = 0; k < storyboard.cells.size(); ++k) {
        const std::string mark = k == 0 ? "% the world\n" : "% stage " + std::to_string(k) + "\n";
        at = tex.find(mark, at);
        ASSERT_NE(at, std::string::npos) << mark;
        // Moved to its picture's corner, in the picture's pixels (y down).
        const Vec2<double>& corner = storyboard.layout.cells[k].picture.min;
        char shift[64];
        std::snprintf(shift, sizeof shift, "\\begin{scope}[shift={(%.1f,%.1f)}]", corner.x(), corner.y());
        EXPECT_EQ(tex.compare(at + mark.size(), std::strlen(shift), shift), 0) << tex.substr(at, 120);
    }
    EXPECT_EQ(tex.find("\\begin{document}"), tex.rfind("\\begin{document}"));
    EXPECT_NE(tex.find("traced (\\textminus{}8, \\textminus{}6, \\textminus{}30)", at), std::string::npos);
}

} // namespace
} // namespace viewpipe::report
