// `viewpipe convert`: the scene with a camera for another API that draws the same picture.

#include "command.hpp"
#include "text_commands.hpp"
#include "viewpipe/api.hpp"
#include "viewpipe/scene.hpp"

namespace viewpipe::commands {
namespace {

struct ConvertOptions {
    std::string scene;
    std::string api;
    std::string handedness; // empty: the API's usual one
    std::string depth;      // empty: the scene's
};

int runConvert(const ConvertOptions& options)
{
    return guarded(options.scene, "viewpipe: internal error", [&] {
        const gl::Api api = gl::apiNamed(options.api, "--api");
        Scene scene = loadScene(options.scene);
        const gl::Camera<double>& camera = lookAtCamera(scene, "API conversions");
        gl::Handedness handedness = gl::defaultHandedness(api);
        if (!options.handedness.empty()) {
            if (options.handedness != "right" && options.handedness != "left")
                throw InputError("--handedness", "must be right or left (got \"" + options.handedness + "\")");
            handedness = options.handedness == "left" ? gl::Handedness::Left : gl::Handedness::Right;
        }
        gl::DepthMode depth = camera.depth;
        if (!options.depth.empty()) {
            if (options.depth != "standard" && options.depth != "reversed")
                throw InputError("--depth", "must be standard or reversed (got \"" + options.depth + "\")");
            depth = options.depth == "reversed" ? gl::DepthMode::Reversed : gl::DepthMode::Standard;
        }
        scene.camera = gl::convertCamera(camera, api, handedness, depth);
        // One suffix, however often converted: an earlier one of ours is replaced.
        const std::size_t earlier = scene.name.rfind(" (as ");
        if (earlier != std::string::npos && scene.name.size() > 7 &&
            scene.name.compare(scene.name.size() - 7, 7, " depth)") == 0 &&
            scene.name.find("-handed, ", earlier) != std::string::npos)
            scene.name.erase(earlier);
        scene.name += " (as " + gl::apiTitle(api) + ", " + gl::handednessName(handedness) + "-handed, " +
                      gl::depthModeName(depth) + " depth)";
        std::cout << sceneToJson(scene);
        return 0;
    });
}

} // namespace

void addConvertCommand(CLI::App& app)
{
    auto options = std::make_shared<ConvertOptions>();
    CLI::App* command = app.add_subcommand(
        "convert", "Print the scene with a camera for another graphics API that draws the same picture");
    command->add_option("SCENE", options->scene, "Scene file (JSON) with a \"camera\"")->required();
    command->add_option("--api", options->api, "opengl, direct3d, vulkan, metal or webgpu")->required();
    command->add_option("--handedness", options->handedness,
                        "right or left (default: the API's usual one, left for direct3d)");
    command->add_option("--depth", options->depth, "standard or reversed (default: the scene's)");
    setRun(command, [options] { return runConvert(*options); });
}

} // namespace viewpipe::commands
