// `viewpipe trace`: one point through every stage and the divide.

#include "command.hpp"
#include "text_commands.hpp"
#include "viewpipe/report/report.hpp"

namespace viewpipe::commands {
namespace {

struct TraceOptions {
    std::string scene;
    std::vector<std::string> point; // numbers or exact expressions, as typed
    bool json = false;
    PrecisionOptions precision;
    std::string api; // "all" or an API's name: the point under each API's conventions
    bool apiGiven = false;
    std::string viewport = "640x480";
};

int runTrace(const TraceOptions& options)
{
    return guarded(options.scene, "viewpipe: internal error", [&] {
        const Scene scene = loadScene(options.scene);
        const report::PrecisionChoice precision = report::parsePrecision(options.precision.precision, options.precision.bits);
        Vec3<Exact> typed;
        for (int i = 0; i < 3; ++i) {
            try {
                typed[i] = parseExact(options.point[std::size_t(i)]);
            } catch (const std::exception& error) {
                throw InputError("--point", "must be three finite numbers or exact expressions (coordinate " +
                                                std::to_string(i + 1) + ": " + error.what() + ")");
            }
        }
        const Vec3<double> point = typed.unaryExpr([](const Exact& x) { return double(x); });
        if (!point.allFinite())
            throw InputError("--point", "must be three finite numbers");
        if (options.apiGiven) {
            if (precision.type != report::Precision::Double)
                throw InputError("--precision", "the --api table is computed in double precision");
            const auto [width, height] = parseSize(options.viewport, "--viewport");
            if (options.json)
                std::cout << report::apiTraceJson(scene, point, options.api, width, height).dump() << "\n";
            else
                report::printApiTrace(std::cout, scene, point, options.api, width, height);
            return 0;
        }
        if (options.json)
            std::cout << report::traceJson(scene, typed, precision).dump() << "\n";
        else
            report::printTrace(std::cout, scene, typed, precision);
        return 0;
    });
}

} // namespace

void addTraceCommand(CLI::App& app)
{
    auto options = std::make_shared<TraceOptions>();
    CLI::App* command = app.add_subcommand("trace", "Follow one point through every stage and the divide");
    command->add_option("SCENE", options->scene, "Scene file (JSON)")->required();
    command->add_option("--point", options->point, "World coordinates X Y Z: numbers or exact expressions (1/3, sqrt(2)/2)")->expected(3)->required();
    command->add_flag("--json", options->json, "One JSON object on stdout");
    CLI::Option* api = command->add_option(
        "--api", options->api,
        "all, or opengl, direct3d, vulkan, metal, webgpu: the point through the camera's numbers under each API's "
        "conventions (handedness, depth), to clip, NDC and window coordinates");
    command->add_option("--viewport", options->viewport, "With --api: the viewport's size WxH (default 640x480)")
        ->needs(api);
    addPrecision(command, options->precision);
    setRun(command, [options, api] {
        options->apiGiven = api->count() > 0;
        return runTrace(*options);
    });
}

} // namespace viewpipe::commands
