// `viewpipe sheet`: the CAD layout of a scene's objects on one PNG.

#include "command.hpp"
#include "drawing_commands.hpp"
#include "export/Exporter.h"
#include "export/VirtualDisplay.h"

namespace viewpipe::commands {
namespace {

struct SheetOptions {
    std::string scene, out, size = "1600x1200", theme = "light";
};

int runSheet(const SheetOptions& options)
{
    return guarded(options.scene, "viewpipe sheet", [&] {
        const Scene scene = loadScene(options.scene);
        const auto [width, height] = parseSize(options.size, "--size");
        const gui::VirtualDisplay display;
        gui::exportSheet(*evaluateScene(scene), options.out, width, height,
                         options.theme == "dark" ? report::Theme::Dark : report::Theme::Light);
        return 0;
    });
}

} // namespace

void addSheetCommand(CLI::App& app)
{
    auto options = std::make_shared<SheetOptions>();
    CLI::App* command = app.add_subcommand(
        "sheet", "The CAD layout of a scene's objects: top, front, side and isometric views on one PNG");
    command->add_option("SCENE", options->scene, "Scene file (JSON)")->required();
    command->add_option("--out", options->out, "The PNG to write")->required();
    command->add_option("--size", options->size, "Sheet size WxH")->capture_default_str();
    command->add_option("--theme", options->theme, "light or dark")
        ->check(CLI::IsMember({"light", "dark"}))
        ->capture_default_str();
    setRun(command, [options] { return runSheet(*options); });
}

} // namespace viewpipe::commands
