// `viewpipe code`: the camera as code in a dialect.

#include <cmath>

#include <nlohmann/json.hpp>

#include "command.hpp"
#include "text_commands.hpp"
#include "viewpipe/report/code.hpp"
#include "viewpipe/scene.hpp"

namespace viewpipe::commands
{
namespace
{

using Json = nlohmann::json;

struct CodeOptions {
    std::string scene;
    std::string dialect = "glm";
    bool json = false;
};

// An infinite far as scene files write it.
Json numberJson(double value)
{
    return std::isinf(value) ? Json("infinity") : Json(value);
}

Json codeJson(report::Dialect dialect, const report::CameraCode& written)
{
    Json numbers = Json::array();
    for (const report::CodeNumber& number : written.numbers)
        numbers.push_back({{"offset", number.offset},
                           {"length", number.length},
                           {"field", number.field},
                           {"value", numberJson(number.value)},
                           {"tooltip", number.tooltip}});
    return {{"dialect", report::dialectName(dialect)}, {"code", written.text}, {"numbers", numbers}};
}

int runCode(const CodeOptions& options)
{
    return guarded(options.scene, "viewpipe: internal error", [&] {
        const report::Dialect dialect = report::dialectNamed(options.dialect, "--dialect");
        const Scene scene = loadScene(options.scene);
        const report::CameraCode written = report::cameraCode(lookAtCamera(scene, "the code dialects"), dialect);
        if (options.json)
            std::cout << codeJson(dialect, written).dump() << "\n";
        else
            std::cout << written.text;
        return 0;
    });
}

} // namespace

void addCodeCommand(CLI::App& app)
{
    auto options = std::make_shared<CodeOptions>();
    std::vector<std::string> dialects;
    for (const report::Dialect dialect : report::kDialects)
        dialects.push_back(report::dialectName(dialect));
    CLI::App* command = app.add_subcommand("code", "Print the code that gives a scene's camera in a library's calls");
    command->add_option("SCENE", options->scene, "Scene file (JSON) with a \"camera\"")->required();
    command->add_option("--dialect", options->dialect, "The library whose calls are written")
        ->check(CLI::IsMember(dialects))
        ->capture_default_str();
    command->add_flag("--json", options->json, "One JSON object on stdout: the code and where its numbers are");
    setRun(command, [options] { return runCode(*options); });
}

} // namespace viewpipe::commands
