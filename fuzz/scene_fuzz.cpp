// libFuzzer: parseScene on arbitrary text. An InputError is the expected
// refusal; any other exception escaping, or a crash, is a bug. A scene that is
// accepted must also accept its own serialization, unchanged.

#include "viewpipe/scene.hpp"

#include <cstdint>
#include <fstream>
#include <string>
#include <unistd.h>

namespace {

// Mesh paths resolve in a folder of this process holding cube.obj, removed at exit.
struct TempFolder {
    TempFolder() : path(std::filesystem::temp_directory_path() / ("viewpipe-scene-fuzz-" + std::to_string(::getpid())))
    {
        std::filesystem::create_directories(path);
        std::ofstream(path / "cube.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
    }
    ~TempFolder()
    {
        std::error_code ignored;
        std::filesystem::remove_all(path, ignored);
    }
    std::filesystem::path path;
};

const std::filesystem::path& baseDir()
{
    static const TempFolder folder;
    return folder.path;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    viewpipe::Scene scene;
    try {
        scene = viewpipe::parseScene(std::string(reinterpret_cast<const char*>(data), size), baseDir());
    } catch (const viewpipe::InputError&) {
        return 0;
    }
    const std::string json = viewpipe::sceneToJson(scene);
    if (viewpipe::sceneToJson(viewpipe::parseScene(json, baseDir())) != json)
        __builtin_trap();
    return 0;
}
