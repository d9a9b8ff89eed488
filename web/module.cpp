// The module the web page calls: the core and the report library, as the CLI
// and the app call them, behind a few functions that take and give text.

#include <emscripten/bind.h>

#include <exception>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include "viewpipe/error.hpp"
#include "viewpipe/evaluated_scene.hpp"
#include "viewpipe/report/report.hpp"
#include "viewpipe/scene.hpp"

namespace viewpipe::web {
namespace {

// What a call gives the page: its text, or the reason it was refused.
struct Outcome {
    std::string text;
    std::string error; // "field.path: reason", as the CLI prints it after "FILE: "
};

template <class Body> Outcome guarded(Body&& body)
{
    try {
        return {body(), ""};
    } catch (const InputError& e) {
        return {"", e.what()};
    } catch (const std::exception& e) {
        return {"", std::string("internal error: ") + e.what()};
    }
}

// Where a scene's files are, in the module's own file system: mesh paths
// resolve against it as they resolve against a scene file's folder.
const std::filesystem::path kSceneFolder = "/scene";

// A file a scene names (a mesh), at the path the scene writes.
Outcome putFile(const std::string& path, const std::string& bytes)
{
    return guarded([&] {
        const std::filesystem::path file = (kSceneFolder / path).lexically_normal();
        std::filesystem::create_directories(file.parent_path());
        std::ofstream out(file, std::ios::binary | std::ios::trunc);
        if (!(out << bytes) || !out.flush())
            throw std::runtime_error("cannot keep " + path);
        return file.string();
    });
}

// What `viewpipe pipeline SCENE --json` prints for a scene's JSON.
Outcome pipelineJson(const std::string& sceneText)
{
    return guarded([&] {
        const Scene scene = parseScene(sceneText, kSceneFolder);
        const cli::PrecisionChoice precision; // double, as the CLI's default
        return cli::pipelineJson(scene, precision, evaluateScene(scene)->outcomes).dump();
    });
}

} // namespace
} // namespace viewpipe::web

EMSCRIPTEN_BINDINGS(viewpipe)
{
    using namespace viewpipe::web;
    emscripten::value_object<Outcome>("Outcome").field("text", &Outcome::text).field("error", &Outcome::error);
    emscripten::function("putFile", &putFile);
    emscripten::function("pipelineJson", &pipelineJson);
}
