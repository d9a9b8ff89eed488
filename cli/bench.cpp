// `viewpipe bench`: what each precision costs in time and buys in accuracy.

#include "command.hpp"
#include "text_commands.hpp"
#include "viewpipe/report/bench.hpp"
#include "viewpipe/evaluated_scene.hpp"

namespace viewpipe::commands {
namespace {

struct BenchCommandOptions {
    std::string scene;
    bool json = false;
    std::string plot, viewport;
    std::size_t vertices = 1000000;
    unsigned bits = 160;
};

int runBench(const BenchCommandOptions& options, const BenchPlotWriter& writePlot)
{
    return guarded(options.scene.empty() ? std::string("viewpipe bench") : options.scene, "viewpipe bench", [&] {
        const std::string file = options.scene.empty() ? defaultScene() : options.scene;
        const Scene scene = loadScene(file);
        BenchOptions o;
        o.vertices = options.vertices;
        o.mpfrBits = options.bits;
        if (!options.viewport.empty())
            std::tie(o.viewport.width, o.viewport.height) = parseSize(options.viewport, "--viewport");
        const BenchResult result = viewpipe::runBench(
            scene, evaluateScene(scene)->objectVertices(), o, [&](int done, int total, const std::string& tier) {
                if (!options.json && !tier.empty())
                    std::cerr << "[" << done + 1 << "/" << total << "] timing and measuring " << tier << "\n";
                return true;
            });
        if (options.json)
            std::cout << report::benchJson(result).dump() << "\n";
        else
            report::printBench(std::cout, result);
        if (!options.plot.empty()) {
            writePlot(result, options.plot);
            if (!options.json)
                std::cout << "\nPlot: " << options.plot << "\n";
        }
        return 0;
    });
}

} // namespace

void addBenchCommand(CLI::App& app, BenchPlotWriter writePlot)
{
    auto options = std::make_shared<BenchCommandOptions>();
    CLI::App* command = app.add_subcommand(
        "bench", "What each precision costs in time and buys in accuracy (default scene: the house from its front-right corner)");
    command->add_option("SCENE", options->scene, "Scene file (JSON)");
    command->add_flag("--json", options->json, "One JSON object on stdout");
    command->add_option("--plot", options->plot, "Draw error against time (log-log) to this PNG");
    command->add_option("--vertices", options->vertices, "Vertices timed per run")->capture_default_str();
    command->add_option("--bits", options->bits, "Significand bits of the mpfr tier")->capture_default_str();
    command->add_option("--viewport", options->viewport, "Viewport WxH for pixel errors (default 1920x1080)");
    setRun(command, [options, writePlot = std::move(writePlot)] { return runBench(*options, writePlot); });
}

} // namespace viewpipe::commands
