// Mesh files: a cube in every format and encoding, and the hostile inputs
// that crash VTK 9.1's readers, each refused with its reason.

#include "build_paths.h"
#include "support.hpp"
#include "viewpipe/mesh_io.hpp"

#include <atomic>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <thread>

namespace viewpipe {
namespace {

using test::expectRefused;

const std::filesystem::path kData = viewpipe::build::dataDir;
const PolygonMesh kCube = boxMesh({0, 0, 0}, {1, 1, 1});

void refused(std::string_view bytes, MeshFormat format, const std::string& reason)
{
    expectRefused([&] { parseMesh(bytes, format, "mesh"); }, "mesh", reason);
}

void expectCube(const PolygonMesh& mesh)
{
    EXPECT_EQ(mesh.vertices, kCube.vertices);
    EXPECT_EQ(mesh.faces, kCube.faces);
}

std::string cubeObj()
{
    std::string text = "# a cube\nmtllib cube.mtl\no cube\n";
    for (const Vec3<double>& v : kCube.vertices)
        text += "v " + std::to_string(v.x()) + " " + std::to_string(v.y()) + " " + std::to_string(v.z()) + "\n";
    text += "vt 0 0\nvn 0 0 1\ng sides\nusemtl grey\ns off\n";
    const char* forms[] = {"%d", "%d/1", "%d//1", "%d/1/1"};
    int k = 0;
    for (const auto& face : kCube.faces) {
        text += "f";
        for (const int i : face) {
            char word[32];
            std::snprintf(word, sizeof word, forms[k++ % 4], i + 1);
            text += std::string(" ") + word;
        }
        text += "\n";
    }
    return text + "l 1 2\np 3\n";
}

bool hostIsLittleEndian()
{
    const std::uint16_t one = 1;
    unsigned char first = 0;
    std::memcpy(&first, &one, 1);
    return first == 1;
}

enum class Encoding { Ascii, Little, Big };

// PLY data in any encoding: values as words (ASCII) or bytes in the byte order.
class PlyWriter {
public:
    explicit PlyWriter(Encoding encoding) : encoding_(encoding) {}

    template <class T> PlyWriter& operator<<(T value)
    {
        if (encoding_ == Encoding::Ascii) {
            std::ostringstream word;
            word << +value << ' ';
            bytes_ += word.str();
            return *this;
        }
        char b[sizeof(T)];
        std::memcpy(b, &value, sizeof value);
        if ((encoding_ == Encoding::Little) != hostIsLittleEndian())
            std::reverse(b, b + sizeof(T));
        bytes_.append(b, sizeof b);
        return *this;
    }

    void endLine()
    {
        if (encoding_ == Encoding::Ascii)
            bytes_.back() = '\n';
    }

    const std::string& bytes() const { return bytes_; }

private:
    Encoding encoding_;
    std::string bytes_;
};

std::string formatLine(Encoding encoding)
{
    return std::string("format ") +
           (encoding == Encoding::Ascii    ? "ascii"
            : encoding == Encoding::Little ? "binary_little_endian"
                                           : "binary_big_endian") +
           " 1.0\n";
}

// The cube as PLY; with extras, properties and an element ViewPipe skips.
std::string cubePly(Encoding encoding, bool extras)
{
    std::string header = "ply\n" + formatLine(encoding) + "comment written by mesh_io_test\nelement vertex 8\n";
    header += extras ? "property double x\nproperty float nx\nproperty float y\nproperty float nz\nproperty short z\n"
                       "property uchar red\nproperty uint8 green\nproperty uchar blue\n"
                     : "property float x\nproperty float y\nproperty float z\n";
    header += extras ? "element face 6\nproperty uchar flags\nproperty list ushort uint vertex_index\n"
                       "property list uchar float texcoord\n"
                       "element edge 2\nproperty int vertex1\nproperty int32 vertex2\nproperty list int char tag\n"
                     : "element face 6\nproperty list uchar int vertex_indices\n";
    header += "end_header\n";
    PlyWriter data(encoding);
    for (const Vec3<double>& v : kCube.vertices) {
        if (extras)
            data << v.x() << 0.5f << float(v.y()) << -0.5f << std::int16_t(v.z()) << std::uint8_t(200)
                 << std::uint8_t(10) << std::uint8_t(255);
        else
            data << float(v.x()) << float(v.y()) << float(v.z());
        data.endLine();
    }
    for (const auto& face : kCube.faces) {
        if (extras) {
            data << std::uint8_t(7) << std::uint16_t(face.size());
            for (const int i : face)
                data << std::uint32_t(i);
            data << std::uint8_t(2) << 0.25f << 0.75f;
        } else {
            data << std::uint8_t(face.size());
            for (const int i : face)
                data << std::int32_t(i);
        }
        data.endLine();
    }
    if (extras)
        for (int e = 0; e < 2; ++e) {
            data << std::int32_t(e) << std::int32_t(e + 1) << std::int32_t(3) << std::int8_t(-1) << std::int8_t(0)
                 << std::int8_t(1);
            data.endLine();
        }
    return header + data.bytes();
}

// A binary PLY with one triangle whose last index is `index` (3 vertices).
std::string triangleBinaryPly(std::int32_t index, std::uint8_t listLength = 3, std::size_t indicesWritten = 3)
{
    PlyWriter data(Encoding::Little);
    for (int v = 0; v < 3; ++v)
        data << float(v) << float(v * v) << 0.0f;
    data << listLength << std::int32_t(0) << std::int32_t(1);
    if (indicesWritten == 3)
        data << index;
    return "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
           "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n" +
           data.bytes();
}

struct Triangle {
    Vec3<double> a, b, c;
};

std::vector<Triangle> cubeTriangles()
{
    std::vector<Triangle> triangles;
    for (const auto& f : kCube.faces) {
        const auto& v = kCube.vertices;
        triangles.push_back({v[std::size_t(f[0])], v[std::size_t(f[1])], v[std::size_t(f[2])]});
        triangles.push_back({v[std::size_t(f[0])], v[std::size_t(f[2])], v[std::size_t(f[3])]});
    }
    return triangles;
}

std::string binaryStl(const std::vector<Triangle>& triangles, const std::string& header = "binary STL")
{
    PlyWriter data(Encoding::Little);
    for (const Triangle& t : triangles) {
        data << 0.0f << 0.0f << 1.0f;
        for (const Vec3<double>* p : {&t.a, &t.b, &t.c})
            data << float(p->x()) << float(p->y()) << float(p->z());
        data << std::uint16_t(0);
    }
    std::string bytes = header;
    bytes.resize(80, ' ');
    PlyWriter count(Encoding::Little);
    count << std::uint32_t(triangles.size());
    return bytes + count.bytes() + data.bytes();
}

std::string asciiStl(const std::vector<Triangle>& triangles)
{
    std::ostringstream text;
    text << "solid cube\n";
    for (const Triangle& t : triangles) {
        text << "  facet normal 0 0 1\n    outer loop\n";
        for (const Vec3<double>* p : {&t.a, &t.b, &t.c})
            text << "      vertex " << p->x() << ' ' << p->y() << ' ' << p->z() << '\n';
        text << "    endloop\n  endfacet\n";
    }
    text << "endsolid cube\n";
    return text.str();
}

// The faces as corner positions: equal whatever the vertex numbering.
std::vector<std::vector<Vec3<double>>> corners(const PolygonMesh& mesh)
{
    std::vector<std::vector<Vec3<double>>> out;
    for (const auto& face : mesh.faces) {
        out.emplace_back();
        for (const int i : face)
            out.back().push_back(mesh.vertices[std::size_t(i)]);
    }
    return out;
}

void expectCubeTriangles(const PolygonMesh& mesh)
{
    EXPECT_EQ(mesh.vertices.size(), 8u) << "equal vertices are merged";
    std::vector<std::vector<Vec3<double>>> expected;
    for (const Triangle& t : cubeTriangles())
        expected.push_back({t.a, t.b, t.c});
    EXPECT_EQ(corners(mesh), expected);
}

TEST(MeshIo, FormatFromExtension)
{
    EXPECT_EQ(meshFormatOf("a/b.obj", "f"), MeshFormat::Obj);
    EXPECT_EQ(meshFormatOf("B.PLY", "f"), MeshFormat::Ply);
    EXPECT_EQ(meshFormatOf("c.Stl", "f"), MeshFormat::Stl);
    expectRefused([] { meshFormatOf("mesh.off", "objects[0].path"); }, "objects[0].path", ".obj, .ply or .stl");
    expectRefused([] { meshFormatOf("obj", "f"); }, "f", ".obj, .ply or .stl");
}

TEST(MeshIo, ObjCube)
{
    expectCube(parseMesh(cubeObj(), MeshFormat::Obj, "mesh"));
}

TEST(MeshIo, ObjRelativeIndices)
{
    // -1 is the last vertex defined so far, wherever the face is.
    const PolygonMesh mesh = parseMesh("v 0 0 0\nv 1 0 0\nv 1 1 0\nf -3 -2 -1\nv 0 1 0\nf -4 -2/5 -1//2\n"
                                       "f 1 -2 4\n",
                                       MeshFormat::Obj, "mesh");
    EXPECT_EQ(mesh.faces, (FaceList{{0, 1, 2}, {0, 2, 3}, {0, 2, 3}}));
}

TEST(MeshIo, ObjNumbers)
{
    // Windows line ends, a w, a leading +, underflow to zero; a face may refer to a vertex defined after it.
    const PolygonMesh mesh =
        parseMesh("f 1 2 3\r\nv +1.5 2e-400 -3 1\r\nv 0 0 0 0.5 0.5 0.5\r\nv 1e2 .5 5.\r\n", MeshFormat::Obj, "m");
    EXPECT_EQ(mesh.vertices, (std::vector<Vec3<double>>{{1.5, 0, -3}, {0, 0, 0}, {100, 0.5, 5}}));
}

TEST(MeshIo, ObjRefusals)
{
    const std::string square = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";
    refused(square + "f 1 2 9\n", MeshFormat::Obj, "line 5: face index 9 is out of range (the file has 4 vertices)");
    refused(square + "f 0 1 2\n", MeshFormat::Obj, "line 5: face index 0 is not allowed");
    refused(square + "f -1 -2 -5\n", MeshFormat::Obj,
            "line 5: face index -5 is out of range (4 vertices are defined before it)");
    refused("v 0 0 0\nf -1 -2 1\nv 1 0 0\n", MeshFormat::Obj, "line 2: face index -2 is out of range");
    refused(square + "f 1 2 -99999999999999999999999\n", MeshFormat::Obj, "out of range");
    refused(square + "f 1 2 99999999999999999999999\n", MeshFormat::Obj, "out of range");
    refused(square + "f 1 2\n", MeshFormat::Obj, "line 5: a face needs at least 3 vertices (this one has 2)");
    refused(square + "f 1 2 x\n", MeshFormat::Obj, "line 5: 'x' is not a vertex reference");
    refused("v 0 0 0\nv 1 0 0\nv 0 1 nan\nf 1 2 3\n", MeshFormat::Obj, "line 3: vertex 3 is not finite");
    refused("v 0 0 0\nv 1e999 0 0\nv 0 1 0\nf 1 2 3\n", MeshFormat::Obj, "line 2: vertex 2 is not finite");
    refused("v 0 0 0\nv 1 0\n", MeshFormat::Obj, "line 2: a vertex needs x, y and z");
    refused("v 0 0 0\nv 1 0 zero\n", MeshFormat::Obj, "line 2: 'zero' is not a number");
    refused(square, MeshFormat::Obj, "holds no faces");
    refused("", MeshFormat::Obj, "holds no faces");
}

TEST(MeshIo, PlyCubeInEveryEncoding)
{
    for (const Encoding encoding : {Encoding::Ascii, Encoding::Little, Encoding::Big})
        for (const bool extras : {false, true}) {
            SCOPED_TRACE(testing::Message() << "encoding " << int(encoding) << ", extras " << extras);
            expectCube(parseMesh(cubePly(encoding, extras), MeshFormat::Ply, "mesh"));
        }
}

TEST(MeshIo, PlyRefusals)
{
    const std::string vertices = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                                 "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                                 "end_header\n0 0 0\n1 0 0\n0 1 0\n";
    refused(vertices + "3 0 1 3\n", MeshFormat::Ply,
            "line 13: face 0: vertex index 3 is out of range (the file has 3 vertices)");
    refused(vertices + "3 0 1 -1\n", MeshFormat::Ply, "face 0: vertex index -1 is out of range");
    refused(vertices + "3 0 1 1.5\n", MeshFormat::Ply, "face 0: vertex index 1.5 is not a whole number");
    refused(vertices + "2 0 1\n", MeshFormat::Ply, "face 0 has 2 vertices; a face needs at least 3");
    refused(vertices + "5 0 1 2\n", MeshFormat::Ply, "the PLY header says 1 face but the data ends after 0");
    refused(vertices + "200 0 1 2\n", MeshFormat::Ply, "the PLY header says 1 face but the data ends after 0");
    refused(vertices + "3 0 1 x\n", MeshFormat::Ply, "line 13: 'x' is not a number");
    refused(vertices.substr(0, vertices.size() - 6), MeshFormat::Ply,
            "the PLY header says 3 vertices but the data ends after 2");

    refused(triangleBinaryPly(3), MeshFormat::Ply, "face 0: vertex index 3 is out of range (the file has 3 vertices)");
    refused(triangleBinaryPly(-1), MeshFormat::Ply, "face 0: vertex index -1 is out of range");
    refused(triangleBinaryPly(2, 200), MeshFormat::Ply, "the PLY header says 1 face but the data ends after 0");
    refused(triangleBinaryPly(2, 2, 2), MeshFormat::Ply, "face 0 has 2 vertices");
    refused(triangleBinaryPly(2, 3, 2), MeshFormat::Ply, "the PLY header says 1 face but the data ends after 0");
    EXPECT_EQ(parseMesh(triangleBinaryPly(2), MeshFormat::Ply, "mesh").faces.size(), 1u);

    const std::string header = "ply\nformat binary_little_endian 1.0\n";
    const std::string xyz = "property float x\nproperty float y\nproperty float z\n";
    const std::string faces = "element face 1\nproperty list uchar int vertex_indices\n";
    refused(header + "element vertex -5\n" + xyz + faces + "end_header\n", MeshFormat::Ply,
            "line 3: element 'vertex' has a negative count ('-5')");
    refused(header + "element vertex 4000000000\n" + xyz + faces + "end_header\n", MeshFormat::Ply,
            "ViewPipe reads at most 50000000");
    refused(header + "element vertex 40000000\n" + xyz + faces + "end_header\n" + std::string(100, '\0'),
            MeshFormat::Ply, "the PLY header says 40000000 vertices but the file is too short to hold them");
    refused(header + "element vertex 3\n" + xyz + "element face 4000000000\nproperty list uchar int vertex_indices\n"
                                                  "end_header\n",
            MeshFormat::Ply, "ViewPipe reads at most 50000000");
    refused(header + "element junk 18446744073709551615\nproperty uchar a\nelement vertex 3\n" + xyz + faces +
                "end_header\n",
            MeshFormat::Ply, "the PLY header says 18446744073709551615 'junk' elements but the file is too short");
    refused(header + "element vertex 99999999999999999999999\n" + xyz + faces + "end_header\n", MeshFormat::Ply,
            "count too large");
    refused(header + "element vertex 3\n" + xyz + faces, MeshFormat::Ply, "no end_header line");
    refused(header + "element vertex 3\n" + xyz + faces + "element e\x1b 1\nproperty list int int a\nend_header\n" +
                std::string(36, '\0') + std::string(1, '\3') + std::string(12, '\0') + "\xff\xff\xff\xff",
            MeshFormat::Ply, "element 'e?' 0: list length -1 is not a count");
    refused(header + "element vertex 3\nproperty float x\nproperty float y\n" + faces + "end_header\n",
            MeshFormat::Ply, "no number property 'z'");
    refused(header + "element vertex 3\n" + xyz + "element face 1\nproperty list uchar int indices\nend_header\n",
            MeshFormat::Ply, "no list property 'vertex_indices'");
    refused(header + "element vertex 3\n" + xyz + "end_header\n", MeshFormat::Ply, "holds no faces");
    refused(header + "element vertex 3\nproperty int64 x\n", MeshFormat::Ply, "line 4: unknown PLY type 'int64'");
    refused("ply\nformat ascii 2.0\nend_header\n", MeshFormat::Ply, "unsupported PLY version '2.0'");
    refused("solid\n", MeshFormat::Ply, "not a PLY file");

    PlyWriter nan(Encoding::Big);
    nan << 0.0f << 0.0f << 0.0f << 1.0f << std::numeric_limits<float>::quiet_NaN() << 0.0f << 0.0f << 1.0f << 0.0f
        << std::uint8_t(3) << 0 << 1 << 2;
    refused("ply\nformat binary_big_endian 1.0\nelement vertex 3\n" + xyz + faces + "end_header\n" + nan.bytes(),
            MeshFormat::Ply, "vertex 1 is not finite");
}

// Every prefix of a PLY with skipped properties, lists and elements parses or
// is refused, never a crash; a binary one is always refused (ASCII can lose its
// last line end and still be whole).
TEST(MeshIo, PlyEveryTruncation)
{
    for (const Encoding encoding : {Encoding::Little, Encoding::Big, Encoding::Ascii}) {
        const std::string file = cubePly(encoding, true);
        std::size_t parsed = 0;
        for (std::size_t n = 0; n < file.size(); ++n)
            try {
                parseMesh(std::string_view(file).substr(0, n), MeshFormat::Ply, "mesh");
                ++parsed;
            } catch (const InputError&) {
            }
        EXPECT_EQ(parsed, encoding == Encoding::Ascii ? 1u : 0u);
        expectCube(parseMesh(file, MeshFormat::Ply, "mesh"));
    }
}

TEST(MeshIo, StlCube)
{
    expectCubeTriangles(parseMesh(binaryStl(cubeTriangles()), MeshFormat::Stl, "mesh"));
    // Binary files whose header starts with "solid" are told apart by their size.
    expectCubeTriangles(parseMesh(binaryStl(cubeTriangles(), "solid cube"), MeshFormat::Stl, "mesh"));
    expectCubeTriangles(parseMesh(asciiStl(cubeTriangles()), MeshFormat::Stl, "mesh"));
}

TEST(MeshIo, StlRefusals)
{
    const std::string cube = binaryStl(cubeTriangles());
    refused(cube.substr(0, cube.size() - 1), MeshFormat::Stl,
            "a binary STL of 12 triangles takes 684 bytes, but the file has 683");
    refused(cube + "x", MeshFormat::Stl, "takes 684 bytes, but the file has 685");
    refused(cube.substr(0, 50), MeshFormat::Stl, "too short for a binary STL");
    refused(binaryStl({}), MeshFormat::Stl, "holds no faces");
    const double nan = std::numeric_limits<double>::quiet_NaN();
    refused(binaryStl({{{0, 0, 0}, {nan, 0, 0}, {0, 1, 0}}}), MeshFormat::Stl, "triangle 1: vertex 2 is not finite");

    const std::string text = asciiStl(cubeTriangles());
    refused(text.substr(0, text.size() - 14), MeshFormat::Stl,
            "expected 'facet' or 'endsolid' (got the end of the file)");
    refused(text.substr(0, 100), MeshFormat::Stl, "expected a number (got the end of the file)");
    refused("solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nendloop\nendfacet\nendsolid x\n",
            MeshFormat::Stl, "line 6: a facet needs at least 3 vertices (this one has 2)");
    refused("solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertx 0 1 0\n", MeshFormat::Stl,
            "line 6: expected 'vertex' or 'endloop' (got 'vertx')");
    refused("solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 inf\nvertex 0 1 0\n", MeshFormat::Stl,
            "line 5: the vertex is not finite");
    refused("solid x\nendsolid x\n", MeshFormat::Stl, "holds no faces");
}

TEST(MeshIo, ReadsFiles)
{
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "viewpipe-mesh-io-test";
    std::filesystem::create_directories(dir);
    std::ofstream(dir / "cube.OBJ", std::ios::binary) << cubeObj();
    expectCube(readMeshFile(dir / "cube.OBJ", "objects[0].path"));
    expectRefused([&] { readMeshFile(dir / "missing.ply", "objects[0].path"); }, "objects[0].path",
                  "No such file or directory");
    std::filesystem::create_directories(dir / "folder.stl");
    expectRefused([&] { readMeshFile(dir / "folder.stl", "p"); }, "p", "cannot read");
    std::filesystem::remove_all(dir);

    // The meshes that ship with ViewPipe, if any.
    if (std::filesystem::is_directory(kData / "meshes"))
        for (const auto& entry : std::filesystem::directory_iterator(kData / "meshes")) {
            EXPECT_FALSE(readMeshFile(entry.path(), "mesh").faces.empty()) << entry.path();
        }
}

// A read on a thread asked to stop (a wait the user cancels) ends with its reason, in every reader and
// from a file; the stop is that thread's alone, and ends with its guard.
TEST(MeshIo, ReadingStopsWhenAsked)
{
    const std::filesystem::path file = kData / "meshes" / "letter-f.obj";
    std::atomic<bool> stop = true;
    {
        const MeshReadingStop stoppable(stop);
        expectRefused([&] { readMeshFile(file, "objects[0].path"); }, "objects[0].path", "reading was stopped");
        for (const auto& [bytes, format] : {std::pair{cubeObj(), MeshFormat::Obj},
                                            std::pair{cubePly(Encoding::Ascii, false), MeshFormat::Ply},
                                            std::pair{cubePly(Encoding::Little, false), MeshFormat::Ply},
                                            std::pair{binaryStl(cubeTriangles()), MeshFormat::Stl},
                                            std::pair{asciiStl(cubeTriangles()), MeshFormat::Stl}})
            expectRefused([&] { parseMesh(bytes, format, "mesh"); }, "mesh", "reading was stopped");
        std::thread other([&] { EXPECT_FALSE(readMeshFile(file, "mesh").faces.empty()) << "another thread reads on"; });
        other.join();
        stop = false;
        EXPECT_FALSE(readMeshFile(file, "mesh").faces.empty()) << "not (yet) asked to stop";
    }
    stop = true;
    EXPECT_FALSE(readMeshFile(file, "mesh").faces.empty()) << "the guard gone";
}

} // namespace
} // namespace viewpipe
