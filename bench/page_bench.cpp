// What the web page asks of the core on every edit, natively: the house read,
// evaluated, its JSON view (pipeline --json) and its page data made (each
// stage's framing and text, the labels of the stage shown: the first). bench/page_bench.mjs runs the
// same in WebAssembly and in Chromium and prints the ratios; run it rather
// than this alone:
//   xvfb-run -a node --experimental-websocket bench/page_bench.mjs build

#include <benchmark/benchmark.h>

#include <fstream>
#include <sstream>

#include "build_paths.h"
#include "viewpipe/evaluated_scene.hpp"
#include "viewpipe/report/report.hpp"
#include "viewpipe/report/web_page.hpp"
#include "viewpipe/scene.hpp"

namespace viewpipe {
namespace {

// Each line's runs as wide as 0.6 of the size a byte, one size high: page_bench.mjs measures so too.
const report::FontMeasure fixedWidth = report::lineByLine([](const std::vector<MathRun>& runs, double pixels, bool) {
    std::size_t bytes = 0;
    for (const MathRun& run : runs)
        bytes += run.text.size();
    return Vec2<double>(0.6 * pixels * double(bytes), pixels);
});

std::string houseText()
{
    std::ifstream in(std::string(viewpipe::build::dataDir) + "/scenes/house.json");
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

void nativeEvaluate(benchmark::State& state)
{
    const std::string text = houseText();
    const report::WebViewOptions options; // the page's: 1280 x 720, 20-pixel labels
    for (auto _ : state) {
        const auto evaluated = evaluateScene(parseScene(text, std::string(viewpipe::build::dataDir) + "/scenes"));
        const std::string pipeline = report::pipelineJson(evaluated->scene, report::PrecisionChoice{}, evaluated->outcomes).dump();
        const std::string page = report::webPageData(*evaluated, report::webPageViews(*evaluated, options, fixedWidth, {}, 0));
        benchmark::DoNotOptimize(pipeline.size() + page.size());
    }
}
BENCHMARK(nativeEvaluate)->Name("PageEvaluate/native/house")->Unit(benchmark::kMillisecond);

// Its parts: the scene read and evaluated alone (what every view needs), and the page's views of every stage
// with their labels and steps (what the export writes).
void nativeSceneOnly(benchmark::State& state)
{
    const std::string text = houseText();
    for (auto _ : state)
        benchmark::DoNotOptimize(evaluateScene(parseScene(text, std::string(viewpipe::build::dataDir) + "/scenes")));
}
BENCHMARK(nativeSceneOnly)->Name("PageEvaluate/native/house_scene")->Unit(benchmark::kMillisecond);

void nativeViewsOnly(benchmark::State& state)
{
    const auto evaluated = evaluateScene(parseScene(houseText(), std::string(viewpipe::build::dataDir) + "/scenes"));
    const report::WebViewOptions options;
    for (auto _ : state)
        benchmark::DoNotOptimize(report::webPageViews(*evaluated, options, fixedWidth));
}
BENCHMARK(nativeViewsOnly)->Name("PageEvaluate/native/house_views")->Unit(benchmark::kMillisecond);

} // namespace
} // namespace viewpipe

BENCHMARK_MAIN();
