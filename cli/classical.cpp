// `viewpipe classical`: a scene that realizes a classical projection, printed or saved.

#include <array>
#include <sstream>

#include "command.hpp"
#include "text_commands.hpp"
#include "viewpipe/classical.hpp"
#include "viewpipe/evaluated_scene.hpp"

namespace viewpipe::commands {
namespace {

struct ClassicalOptions {
    std::string kind, object = "house", out, ratios;
    ClassicalParameters parameters;
    double azimuth = 0, elevation = 0;
    CLI::Option* azimuthOption = nullptr;
    CLI::Option* elevationOption = nullptr;
};

int runClassical(ClassicalOptions& options)
{
    return guarded("viewpipe classical", "viewpipe classical", [&] {
        const auto kind = classicalKindNamed(options.kind);
        if (!kind)
            throw InputError("KIND", "unknown classical projection \"" + options.kind + "\"");
        if (*options.azimuthOption)
            options.parameters.azimuthDegrees = options.azimuth;
        if (*options.elevationOption)
            options.parameters.elevationDegrees = options.elevation;
        if (!options.ratios.empty()) {
            std::array<double, 3> f{};
            char comma1 = 0, comma2 = 0;
            std::istringstream in(options.ratios);
            if (!(in >> f[0] >> comma1 >> f[1] >> comma2 >> f[2]) || comma1 != ',' || comma2 != ',')
                throw InputError("--foreshortening", "must be three numbers fx,fy,fz");
            options.parameters.foreshortening = f;
        }
        Scene scene;
        scene.name = options.object + ", " + classicalName(*kind);
        SceneObject object;
        if (options.object == "cube") {
            object.type = ObjectType::Box;
            object.min = Vec3<double>(-5, -5, -5);
            object.max = Vec3<double>(5, 5, 5);
        }
        scene.objects.push_back(object);
        const Eigen::AlignedBox<double, 3> box = boundsOf(objectMeshes(scene));
        scene.camera = classicalView(*kind, box.min(), box.max(), options.parameters);
        if (options.out.empty())
            std::cout << sceneToJson(scene);
        else
            saveScene(scene, options.out);
        return 0;
    });
}

} // namespace

void addClassicalCommand(CLI::App& app)
{
    auto options = std::make_shared<ClassicalOptions>();
    CLI::App* command = app.add_subcommand(
        "classical", "Print a scene that realizes a classical projection (front, top, side, isometric, dimetric, "
                     "trimetric, cavalier, cabinet, oblique, one-point, two-point, three-point)");
    command->add_option("KIND", options->kind, "The projection")->required();
    command->add_option("--object", options->object, "house or cube")
        ->check(CLI::IsMember({"house", "cube"}))
        ->capture_default_str();
    options->azimuthOption = command->add_option("--azimuth", options->azimuth, "Axonometric: degrees about y");
    options->elevationOption = command->add_option("--elevation", options->elevation, "Axonometric: degrees about x");
    command->add_option("--foreshortening", options->ratios, "Axonometric: ratios fx,fy,fz (squares sum to 2)");
    command->add_option("--receding", options->parameters.receding, "Oblique: receding-axis factor")
        ->capture_default_str();
    command->add_option("--angle", options->parameters.angleDegrees, "Oblique: receding axis angle, degrees")
        ->capture_default_str();
    command->add_option("--out", options->out, "Write the scene here (atomically) instead of stdout");
    setRun(command, [options] { return runClassical(*options); });
}

} // namespace viewpipe::commands
