#pragma once

// Mesh files (OBJ, PLY, STL) read into a PolygonMesh. The readers trust
// nothing in the file: every count is checked against the bytes that remain
// before anything is allocated, every index against the vertices, every
// coordinate for finiteness, so hostile input ends in an InputError, never in
// a crash (VTK 9.1's readers crash on out-of-range indices and truncated PLY).

#include <atomic>
#include <filesystem>
#include <string>
#include <string_view>

#include "viewpipe/error.hpp"
#include "viewpipe/geometry.hpp"

namespace viewpipe {

enum class MeshFormat { Obj, Ply, Stl };

// The format from the file's extension (.obj, .ply or .stl, any case);
// throws InputError(field, ...) for any other.
MeshFormat meshFormatOf(const std::filesystem::path& file, const std::string& field);

// Parses a whole file's bytes. Every problem is an InputError(field, reason)
// whose reason says what and where ("line 12: face index 9 is out of range
// (the file has 8 vertices)"). Vertex and face counts are capped at 50 million.
PolygonMesh parseMesh(std::string_view bytes, MeshFormat format, const std::string& field);

// Reads and parses a file; its format from its extension.
PolygonMesh readMeshFile(const std::filesystem::path& file, const std::string& field);

// While one lives on a thread, reading or parsing a mesh on that thread
// stops soon after `stop` is set (a wait the user cancels): InputError(field,
// "reading was stopped"). The flag outlives it.
class MeshReadingStop {
public:
    explicit MeshReadingStop(const std::atomic<bool>& stop);
    ~MeshReadingStop();
    MeshReadingStop(const MeshReadingStop&) = delete;
    MeshReadingStop& operator=(const MeshReadingStop&) = delete;

private:
    const std::atomic<bool>* previous_;
};

} // namespace viewpipe
