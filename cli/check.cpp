// `viewpipe check`: a scene file and its meshes, read and evaluated as every other command does
// (what the pictures cannot draw is refused here too).

#include "command.hpp"
#include "text_commands.hpp"
#include "viewpipe/evaluated_scene.hpp"

namespace viewpipe::commands {

void addCheckCommand(CLI::App& app)
{
    auto scene = std::make_shared<std::string>();
    CLI::App* command =
        app.add_subcommand("check", "Validate a scene file; print nothing and exit 0 if it is valid");
    command->add_option("SCENE", *scene, "Scene file (JSON)")->required();
    setRun(command, [scene] {
        return guarded(*scene, "viewpipe: internal error", [&] {
            evaluateScene(loadScene(*scene));
            return 0;
        });
    });
}

} // namespace viewpipe::commands
