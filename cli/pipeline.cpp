// `viewpipe pipeline`: every stage's matrix and the running product.

#include "command.hpp"
#include "text_commands.hpp"
#include "viewpipe/report/report.hpp"
#include "viewpipe/evaluated_scene.hpp"

namespace viewpipe::commands {
namespace {

struct PipelineOptions {
    std::string scene;
    bool json = false;
    PrecisionOptions precision;
};

int runPipeline(const PipelineOptions& options)
{
    return guarded(options.scene, "viewpipe: internal error", [&] {
        const Scene scene = loadScene(options.scene);
        const report::PrecisionChoice precision = report::parsePrecision(options.precision.precision, options.precision.bits);
        const EffectOutcomes outcomes = evaluateScene(scene)->outcomes;
        if (options.json)
            std::cout << report::pipelineJson(scene, precision, outcomes).dump() << "\n";
        else
            report::printPipeline(std::cout, scene, precision, outcomes);
        return 0;
    });
}

} // namespace

void addPipelineCommand(CLI::App& app)
{
    auto options = std::make_shared<PipelineOptions>();
    CLI::App* command = app.add_subcommand("pipeline", "Print every stage's matrix and the running product");
    command->add_option("SCENE", options->scene, "Scene file (JSON)")->required();
    command->add_flag("--json", options->json, "One JSON object on stdout");
    addPrecision(command, options->precision);
    setRun(command, [options] { return runPipeline(*options); });
}

} // namespace viewpipe::commands
