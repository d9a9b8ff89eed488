// `viewpipe classify`: the classical projection a scene's view realizes.

#include "command.hpp"
#include "text_commands.hpp"
#include "viewpipe/report/report.hpp"

namespace viewpipe::commands {
namespace {

struct ClassifyOptions {
    std::string scene;
    bool json = false;
};

int runClassify(const ClassifyOptions& options)
{
    return guarded(options.scene, "viewpipe: internal error", [&] {
        const Scene scene = loadScene(options.scene);
        if (options.json)
            std::cout << report::classifyJson(scene).dump() << "\n";
        else
            report::printClassification(std::cout, scene);
        return 0;
    });
}

} // namespace

void addClassifyCommand(CLI::App& app)
{
    auto options = std::make_shared<ClassifyOptions>();
    CLI::App* command = app.add_subcommand("classify", "Name the classical projection a scene's view realizes");
    command->add_option("SCENE", options->scene, "Scene file (JSON)")->required();
    command->add_flag("--json", options->json, "One JSON object on stdout");
    setRun(command, [options] { return runClassify(*options); });
}

} // namespace viewpipe::commands
