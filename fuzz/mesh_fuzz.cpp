// libFuzzer: parseMesh on arbitrary bytes. The first byte picks the format
// (its value mod 3: 0 OBJ, 1 PLY, 2 STL; the corpus files start with '0', '1'
// or '2'), the rest is the file. An InputError is the expected refusal; any
// other exception escaping, a crash, or an accepted mesh that breaks
// PolygonMesh's invariants is a bug.

#include "viewpipe/mesh_io.hpp"

#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    if (size == 0)
        return 0;
    const viewpipe::MeshFormat formats[] = {viewpipe::MeshFormat::Obj, viewpipe::MeshFormat::Ply,
                                            viewpipe::MeshFormat::Stl};
    const std::string_view bytes(reinterpret_cast<const char*>(data) + 1, size - 1);
    viewpipe::PolygonMesh mesh;
    try {
        mesh = viewpipe::parseMesh(bytes, formats[data[0] % 3], "mesh");
    } catch (const viewpipe::InputError&) {
        return 0;
    }
    if (mesh.faces.empty())
        __builtin_trap();
    for (const viewpipe::Vec3<double>& v : mesh.vertices)
        if (!viewpipe::allFinite(v))
            __builtin_trap();
    for (const auto& face : mesh.faces) {
        if (face.size() < 3)
            __builtin_trap();
        for (const int i : face)
            if (i < 0 || std::size_t(i) >= mesh.vertices.size())
                __builtin_trap();
    }
    return 0;
}
