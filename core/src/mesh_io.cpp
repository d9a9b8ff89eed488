#include "viewpipe/mesh_io.hpp"

#include "parse_number.hpp"

#include <fast_float/fast_float.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <new>
#include <cstring>
#include <fstream>
#include <limits>
#include <optional>
#include <sstream>
#include <unordered_map>

namespace viewpipe {
namespace {

// The stop asked for on this thread (MeshReadingStop), if any: looked at every kStopLook lines,
// elements or facets parsed and every 64 kB read, which keeps the looking out of the readers' time.
thread_local const std::atomic<bool>* askedToStop = nullptr;
constexpr std::uint64_t kStopLook = 1 << 14;

struct Stopped {};

bool stopAsked()
{
    return askedToStop && askedToStop->load(std::memory_order_relaxed);
}

void stopIfAsked(std::uint64_t count)
{
    if (count % kStopLook == 0 && stopAsked())
        throw Stopped{};
}

// Caps that keep a hostile or absurd file from exhausting memory.
constexpr std::size_t kMaxVertices = 50'000'000;
constexpr std::size_t kMaxFaces = 50'000'000;
constexpr std::size_t kMaxCorners = 200'000'000; // face indices in all: 800 MB of int

std::string tooMany(std::size_t count, const std::string& what, std::size_t cap)
{
    return "the file has " + std::to_string(count) + " " + what + "; ViewPipe reads at most " + std::to_string(cap);
}

// A word of the file for a message: quoted, shortened, non-printable bytes as '?'.
std::string quotedWord(std::string_view word)
{
    if (word.empty())
        return "the end of the file";
    std::string out = "'";
    for (const char c : word.substr(0, 40))
        out += c >= 32 && c < 127 ? c : '?';
    return out + (word.size() > 40 ? "...'" : "'");
}

// A value read from a file, for a message: whole numbers without an exponent.
std::string formatValue(double v)
{
    if (v == std::floor(v) && std::abs(v) < 1e18)
        return std::to_string(static_cast<long long>(v));
    std::ostringstream out;
    out.precision(17);
    out << v;
    return out.str();
}

bool isSpace(char c)
{
    return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v';
}

bool equalsIgnoringCase(std::string_view a, std::string_view b)
{
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
               return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
           });
}

} // namespace

// Locale-independent (Qt sets the locale from the environment): fast_float,
// the parser libstdc++'s from_chars is built on, here and in the browser's
// build. An overflow gives an infinity (refused later as not finite), an
// underflow zero, as strtod would.
std::optional<double> parseDouble(std::string_view token)
{
    if (token.size() > 1 && token[0] == '+' && token[1] != '-')
        token.remove_prefix(1);
    if (token.empty())
        return std::nullopt;
    double value = 0;
    const auto [end, error] = fast_float::from_chars(token.data(), token.data() + token.size(), value);
    if (end != token.data() + token.size() || error != std::errc())
        return std::nullopt;
    return value;
}

namespace {

// A whole number; one beyond long long saturates (the caller then finds it out of range).
bool parseInteger(std::string_view token, long long& value)
{
    if (token.size() > 1 && token[0] == '+' && token[1] != '-')
        token.remove_prefix(1);
    const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
    if (token.empty() || end != token.data() + token.size())
        return false;
    if (error == std::errc::result_out_of_range)
        value = token[0] == '-' ? std::numeric_limits<long long>::min() : std::numeric_limits<long long>::max();
    else if (error != std::errc())
        return false;
    return true;
}

// The whitespace-separated words of one line.
class Words {
public:
    explicit Words(std::string_view line) : rest_(line) {}

    // The next word; empty at the end of the line.
    std::string_view next()
    {
        std::size_t start = 0;
        while (start < rest_.size() && isSpace(rest_[start]))
            ++start;
        std::size_t end = start;
        while (end < rest_.size() && !isSpace(rest_[end]))
            ++end;
        const std::string_view word = rest_.substr(start, end - start);
        rest_.remove_prefix(end);
        return word;
    }

private:
    std::string_view rest_;
};

// The words of a text across lines, with the line each word is on.
class TextScanner {
public:
    TextScanner(std::string_view text, std::size_t firstLine) : text_(text), line_(firstLine) {}

    // The next word; empty at the end of the text.
    std::string_view next()
    {
        while (pos_ < text_.size() && isSpace(text_[pos_]))
            line_ += text_[pos_++] == '\n' ? 1 : 0;
        const std::size_t start = pos_;
        while (pos_ < text_.size() && !isSpace(text_[pos_]))
            ++pos_;
        return text_.substr(start, pos_ - start);
    }

    void skipLine()
    {
        while (pos_ < text_.size() && text_[pos_] != '\n')
            ++pos_;
    }

    std::size_t line() const { return line_; }
    std::size_t remaining() const { return text_.size() - pos_; }

private:
    std::string_view text_;
    std::size_t pos_ = 0;
    std::size_t line_;
};

// Calls visit(line, number) for each line, comments ('#' on) removed.
template <class Visit> void forEachLine(std::string_view text, Visit&& visit)
{
    for (std::size_t number = 1; !text.empty(); ++number) {
        stopIfAsked(number - 1);
        const std::size_t end = text.find('\n');
        const std::string_view line = text.substr(0, end);
        visit(line.substr(0, line.find('#')), number);
        text.remove_prefix(end == std::string_view::npos ? text.size() : end + 1);
    }
}

// ---- OBJ ----

PolygonMesh parseObj(std::string_view bytes, const std::string& field)
{
    // Positive indices may refer to vertices defined further down: count them all first.
    std::size_t total = 0;
    forEachLine(bytes, [&](std::string_view line, std::size_t) { total += Words(line).next() == "v" ? 1 : 0; });
    if (total > kMaxVertices)
        throw InputError(field, tooMany(total, "vertices", kMaxVertices));

    PolygonMesh mesh;
    mesh.vertices.reserve(total);
    std::size_t corners = 0;
    forEachLine(bytes, [&](std::string_view line, std::size_t number) {
        auto fail = [&](const std::string& reason) {
            throw InputError(field, "line " + std::to_string(number) + ": " + reason);
        };
        Words words(line);
        const std::string_view keyword = words.next();
        if (keyword == "v") {
            std::array<double, 3> xyz{};
            for (double& x : xyz) {
                const std::string_view word = words.next();
                if (word.empty())
                    fail("a vertex needs x, y and z");
                const std::optional<double> value = parseDouble(word);
                if (!value)
                    fail(quotedWord(word) + " is not a number");
                x = *value;
            }
            // A w, or the r g b some exporters append, does not move the vertex.
            const Vec3<double> p(xyz[0], xyz[1], xyz[2]);
            if (!allFinite(p))
                fail("vertex " + std::to_string(mesh.vertices.size() + 1) + " is not finite");
            mesh.vertices.push_back(p);
        } else if (keyword == "f") {
            const long long defined = static_cast<long long>(mesh.vertices.size());
            std::vector<int> face;
            for (std::string_view word = words.next(); !word.empty(); word = words.next()) {
                // i, i/t, i//n or i/t/n: only i places the corner.
                const std::string_view text = word.substr(0, word.find('/'));
                long long index = 0;
                if (!parseInteger(text, index))
                    fail(quotedWord(word) + " is not a vertex reference");
                if (index == 0)
                    fail("face index 0 is not allowed (OBJ counts vertices from 1)");
                if (index > static_cast<long long>(total))
                    fail("face index " + std::string(text) + " is out of range (the file has " +
                         std::to_string(total) + " vertices)");
                if (index < -defined)
                    fail("face index " + std::string(text) + " is out of range (" + std::to_string(defined) +
                         " vertices are defined before it)");
                face.push_back(static_cast<int>(index > 0 ? index - 1 : defined + index));
            }
            if (face.size() < 3)
                fail("a face needs at least 3 vertices (this one has " + std::to_string(face.size()) + ")");
            corners += face.size();
            if (mesh.faces.size() == kMaxFaces || corners > kMaxCorners)
                fail(mesh.faces.size() == kMaxFaces ? tooMany(kMaxFaces + 1, "faces or more", kMaxFaces)
                                                    : tooMany(corners, "face corners or more", kMaxCorners));
            mesh.faces.push_back(face);
        }
        // Other statements (vn, vt, o, g, s, usemtl, mtllib, l, p, ...) add no polygons.
    });
    return mesh;
}

// ---- Binary numbers (PLY and STL) ----

enum class ScalarType { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

std::optional<ScalarType> scalarType(std::string_view name)
{
    static const std::array<std::pair<std::string_view, ScalarType>, 16> names = {{
        {"char", ScalarType::Int8},     {"int8", ScalarType::Int8},       {"uchar", ScalarType::UInt8},
        {"uint8", ScalarType::UInt8},   {"short", ScalarType::Int16},     {"int16", ScalarType::Int16},
        {"ushort", ScalarType::UInt16}, {"uint16", ScalarType::UInt16},   {"int", ScalarType::Int32},
        {"int32", ScalarType::Int32},   {"uint", ScalarType::UInt32},     {"uint32", ScalarType::UInt32},
        {"float", ScalarType::Float32}, {"float32", ScalarType::Float32}, {"double", ScalarType::Float64},
        {"float64", ScalarType::Float64},
    }};
    for (const auto& [text, type] : names)
        if (text == name)
            return type;
    return std::nullopt;
}

std::size_t sizeOf(ScalarType type)
{
    constexpr std::array<std::size_t, 8> sizes = {1, 1, 2, 2, 4, 4, 4, 8}; // in ScalarType's order
    return sizes[static_cast<std::size_t>(type)];
}

bool hostIsLittleEndian()
{
    const std::uint16_t one = 1;
    unsigned char first = 0;
    std::memcpy(&first, &one, 1);
    return first == 1;
}

// Thrown by the sources when the data ends; the element loop says where.
struct Truncated {};

// Binary numbers of either byte order, read with memcpy (no unaligned access).
class BinarySource {
public:
    BinarySource(std::string_view data, bool littleEndian) : data_(data), swap_(littleEndian != hostIsLittleEndian()) {}

    std::size_t remaining() const { return data_.size() - pos_; }

    // Every number type converts exactly to double.
    double number(ScalarType type)
    {
        switch (type) {
        case ScalarType::Int8: return load<std::int8_t>();
        case ScalarType::UInt8: return load<std::uint8_t>();
        case ScalarType::Int16: return load<std::int16_t>();
        case ScalarType::UInt16: return load<std::uint16_t>();
        case ScalarType::Int32: return load<std::int32_t>();
        case ScalarType::UInt32: return load<std::uint32_t>();
        case ScalarType::Float32: return load<float>();
        case ScalarType::Float64: break;
        }
        return load<double>();
    }

    void skip(ScalarType type) { skipBytes(sizeOf(type)); }

    void skipList(std::size_t length, ScalarType type)
    {
        if (length > remaining() / sizeOf(type))
            throw Truncated{};
        pos_ += length * sizeOf(type);
    }

    void skipBytes(std::size_t n)
    {
        if (n > remaining())
            throw Truncated{};
        pos_ += n;
    }

    std::string where() const { return ""; }

private:
    template <class T> double load()
    {
        static_assert(sizeof(T) <= 8);
        if (remaining() < sizeof(T))
            throw Truncated{};
        unsigned char bytes[sizeof(T)];
        std::memcpy(bytes, data_.data() + pos_, sizeof(T));
        if (swap_)
            std::reverse(bytes, bytes + sizeof(T));
        T value;
        std::memcpy(&value, bytes, sizeof(T));
        pos_ += sizeof(T);
        return static_cast<double>(value);
    }

    std::string_view data_;
    std::size_t pos_ = 0;
    bool swap_;
};

// ---- PLY ----

enum class PlyRole { Skip, X, Y, Z, FaceIndices };

struct PlyProperty {
    std::string name;
    ScalarType type = ScalarType::Float32;
    bool list = false;
    ScalarType countType = ScalarType::UInt8;
    PlyRole role = PlyRole::Skip;
};

struct PlyElement {
    std::string name;
    std::uint64_t count = 0;
    std::vector<PlyProperty> properties;
};

struct PlyHeader {
    bool ascii = true;
    bool littleEndian = true;
    std::vector<PlyElement> elements;
    std::size_t dataStart = 0;     // the byte after end_header's line
    std::size_t lines = 0;         // the header's lines: ASCII data lines count on from them
    std::uint64_t vertexCount = 0; // the bound of every face index, wherever the faces come
};

// "8 vertices", "3 faces", "2 'edge' elements".
std::string counted(std::uint64_t n, const std::string& element)
{
    const std::string count = std::to_string(n);
    if (element == "vertex")
        return count + (n == 1 ? " vertex" : " vertices");
    if (element == "face")
        return count + (n == 1 ? " face" : " faces");
    return count + " " + quotedWord(element) + " element" + (n == 1 ? "" : "s");
}

// Finds the roles of the properties ViewPipe reads and refuses a header without them.
void assignPlyRoles(PlyHeader& header, const std::string& field)
{
    bool vertexSeen = false, faceSeen = false;
    for (PlyElement& element : header.elements) {
        const bool vertex = element.name == "vertex", face = element.name == "face";
        if ((vertex && vertexSeen) || (face && faceSeen))
            throw InputError(field, "the PLY header has two '" + element.name + "' elements");
        if (vertex) {
            vertexSeen = true;
            header.vertexCount = element.count;
            if (element.count > kMaxVertices)
                throw InputError(field, tooMany(element.count, "vertices", kMaxVertices));
            const std::array<std::pair<std::string, PlyRole>, 3> coordinates = {
                {{"x", PlyRole::X}, {"y", PlyRole::Y}, {"z", PlyRole::Z}}};
            for (const auto& coordinate : coordinates) {
                const auto p = std::find_if(element.properties.begin(), element.properties.end(),
                                            [&](const PlyProperty& q) { return q.name == coordinate.first; });
                if (p == element.properties.end() || p->list)
                    throw InputError(field,
                                     "the PLY element 'vertex' has no number property '" + coordinate.first + "'");
                p->role = coordinate.second;
            }
        }
        if (face) {
            faceSeen = true;
            if (element.count > kMaxFaces)
                throw InputError(field, tooMany(element.count, "faces", kMaxFaces));
            const auto p = std::find_if(element.properties.begin(), element.properties.end(), [](const PlyProperty& q) {
                return q.name == "vertex_indices" || q.name == "vertex_index";
            });
            if (p == element.properties.end() || !p->list)
                throw InputError(field, "the PLY element 'face' has no list property 'vertex_indices'");
            p->role = PlyRole::FaceIndices;
        }
    }
    if (!vertexSeen)
        throw InputError(field, "the PLY header has no 'vertex' element");
    if (!faceSeen)
        throw InputError(field, "the file holds no faces (the PLY header has no 'face' element)");
}

PlyHeader parsePlyHeader(std::string_view bytes, const std::string& field)
{
    PlyHeader header;
    bool formatSeen = false;
    std::size_t pos = 0;
    for (std::size_t number = 1;; ++number) {
        if (pos >= bytes.size())
            throw InputError(field, "the PLY header has no end_header line");
        const std::size_t end = bytes.find('\n', pos);
        Words words(bytes.substr(pos, end == std::string_view::npos ? std::string_view::npos : end - pos));
        pos = end == std::string_view::npos ? bytes.size() : end + 1;
        auto fail = [&](const std::string& reason) {
            throw InputError(field, "line " + std::to_string(number) + ": " + reason);
        };
        const std::string_view keyword = words.next();
        if (number == 1) {
            if (keyword != "ply" || !words.next().empty())
                throw InputError(field, "not a PLY file (the first line is not \"ply\")");
            continue;
        }
        if (keyword == "end_header") {
            header.dataStart = pos;
            header.lines = number;
            break;
        }
        if (keyword == "format") {
            const std::string_view encoding = words.next(), version = words.next();
            if (encoding == "binary_little_endian" || encoding == "binary_big_endian") {
                header.ascii = false;
                header.littleEndian = encoding == "binary_little_endian";
            } else if (encoding != "ascii") {
                fail("unknown PLY format " + quotedWord(encoding));
            }
            if (version != "1.0")
                fail("unsupported PLY version " + quotedWord(version) + " (1.0 is read)");
            formatSeen = true;
        } else if (keyword == "element") {
            PlyElement element;
            element.name = words.next();
            const std::string_view count = words.next();
            if (!count.empty() && count[0] == '-')
                fail("element " + quotedWord(element.name) + " has a negative count (" + quotedWord(count) + ")");
            const auto [countEnd, error] = std::from_chars(count.data(), count.data() + count.size(), element.count);
            if (element.name.empty() || count.empty() || countEnd != count.data() + count.size())
                fail("expected \"element NAME COUNT\"");
            if (error != std::errc())
                fail("element " + quotedWord(element.name) + " has a count too large to read (" + quotedWord(count) + ")");
            header.elements.push_back(std::move(element));
        } else if (keyword == "property") {
            if (header.elements.empty())
                fail("a property before any element");
            PlyProperty property;
            std::string_view type = words.next();
            if (type == "list") {
                property.list = true;
                const std::string_view countType = words.next();
                const std::optional<ScalarType> t = scalarType(countType);
                if (!t)
                    fail("unknown PLY type " + quotedWord(countType));
                property.countType = *t;
                type = words.next();
            }
            const std::optional<ScalarType> t = scalarType(type);
            if (!t)
                fail("unknown PLY type " + quotedWord(type));
            property.type = *t;
            property.name = words.next();
            if (property.name.empty())
                fail("the property has no name");
            header.elements.back().properties.push_back(std::move(property));
        } else if (keyword != "comment" && keyword != "obj_info" && !keyword.empty()) {
            fail("unexpected " + quotedWord(keyword) + " in the PLY header");
        }
    }
    if (!formatSeen)
        throw InputError(field, "the PLY header has no format line");
    assignPlyRoles(header, field);
    return header;
}

// ASCII PLY values: one word each, whatever the declared type.
class AsciiSource {
public:
    AsciiSource(std::string_view data, std::size_t firstLine, const std::string& field)
        : scanner_(data, firstLine), field_(field)
    {
    }

    std::size_t remaining() const { return scanner_.remaining(); }

    double number(ScalarType)
    {
        const std::string_view word = next();
        const std::optional<double> value = parseDouble(word);
        if (!value)
            throw InputError(field_, where() + quotedWord(word) + " is not a number");
        return *value;
    }

    void skip(ScalarType) { next(); }

    // Each word takes a byte at least, so a list longer than the rest of the data ends it.
    void skipList(std::size_t length, ScalarType)
    {
        for (std::size_t k = 0; k < length; ++k)
            next();
    }

    std::string where() const { return "line " + std::to_string(scanner_.line()) + ": "; }

private:
    std::string_view next()
    {
        const std::string_view word = scanner_.next();
        if (word.empty())
            throw Truncated{};
        return word;
    }

    TextScanner scanner_;
    const std::string& field_;
};

// The least bytes an element takes: a word per property (ASCII) or the scalars and list counts (binary).
std::size_t leastBytes(const PlyElement& element, const AsciiSource&)
{
    return element.properties.size();
}

std::size_t leastBytes(const PlyElement& element, const BinarySource&)
{
    std::size_t n = 0;
    for (const PlyProperty& p : element.properties)
        n += sizeOf(p.list ? p.countType : p.type);
    return n;
}

template <class Source> PolygonMesh readPlyData(Source& source, const PlyHeader& header, const std::string& field)
{
    PolygonMesh mesh;
    std::size_t corners = 0;
    for (const PlyElement& element : header.elements) {
        if (element.properties.empty())
            continue; // takes no data
        if (element.count > source.remaining() / leastBytes(element, source))
            throw InputError(field, "the PLY header says " + counted(element.count, element.name) +
                                        " but the file is too short to hold them");
        if (element.name == "vertex")
            mesh.vertices.reserve(element.count);
        else if (element.name == "face")
            mesh.faces.reserve(element.count, 3 * element.count); // triangles, mostly
        std::uint64_t i = 0;
        std::vector<int> face; // the face being read (one buffer for all)
        try {
            for (; i < element.count; ++i) {
                stopIfAsked(i);
                auto fail = [&](const std::string& reason) {
                    const bool known = element.name == "vertex" || element.name == "face";
                    throw InputError(field, source.where() + (known ? element.name : "element " + quotedWord(element.name)) +
                                                " " + std::to_string(i) + reason);
                };
                Vec3<double> p = Vec3<double>::Zero();
                face.clear();
                for (const PlyProperty& property : element.properties) {
                    if (!property.list) {
                        switch (property.role) {
                        case PlyRole::X: p.x() = source.number(property.type); break;
                        case PlyRole::Y: p.y() = source.number(property.type); break;
                        case PlyRole::Z: p.z() = source.number(property.type); break;
                        default: source.skip(property.type);
                        }
                        continue;
                    }
                    const double length = source.number(property.countType);
                    if (!(length >= 0) || length != std::floor(length))
                        fail(": list length " + formatValue(length) + " is not a count");
                    // No list entry takes less than a byte.
                    if (length > static_cast<double>(source.remaining()))
                        throw Truncated{};
                    const auto n = static_cast<std::size_t>(length);
                    if (property.role != PlyRole::FaceIndices) {
                        source.skipList(n, property.type);
                        continue;
                    }
                    if (n < 3)
                        fail(" has " + std::to_string(n) + " vertices; a face needs at least 3");
                    corners += n;
                    if (corners > kMaxCorners)
                        throw InputError(field, tooMany(corners, "face corners or more", kMaxCorners));
                    for (std::size_t k = 0; k < n; ++k) {
                        const double index = source.number(property.type);
                        if (!(index >= 0 && index < static_cast<double>(header.vertexCount)))
                            fail(": vertex index " + formatValue(index) + " is out of range (the file has " +
                                 counted(header.vertexCount, "vertex") + ")");
                        if (index != std::floor(index))
                            fail(": vertex index " + formatValue(index) + " is not a whole number");
                        face.push_back(static_cast<int>(index));
                    }
                }
                if (element.name == "vertex") {
                    if (!allFinite(p))
                        fail(" is not finite");
                    mesh.vertices.push_back(p);
                } else if (element.name == "face") {
                    mesh.faces.push_back(face);
                }
            }
        } catch (const Truncated&) {
            throw InputError(field, "the PLY header says " + counted(element.count, element.name) +
                                        " but the data ends after " + std::to_string(i));
        }
    }
    return mesh;
}

PolygonMesh parsePly(std::string_view bytes, const std::string& field)
{
    const PlyHeader header = parsePlyHeader(bytes, field);
    const std::string_view data = bytes.substr(header.dataStart);
    if (header.ascii) {
        AsciiSource source(data, header.lines + 1, field);
        return readPlyData(source, header, field);
    }
    BinarySource source(data, header.littleEndian);
    return readPlyData(source, header, field);
}

// ---- STL ----

// STL repeats a vertex in every triangle that uses it. Exactly equal vertices
// are merged, so that an edge two triangles share is one edge (for the edge
// list and culling) and the vertex count is that of the solid.
class VertexMerger {
public:
    VertexMerger(PolygonMesh& mesh, const std::string& field) : mesh_(mesh), field_(field) {}

    int index(const Vec3<double>& p)
    {
        Key key{};
        for (int k = 0; k < 3; ++k) {
            const double x = p[k] + 0.0; // -0 and +0 alike
            std::memcpy(&key[std::size_t(k)], &x, sizeof x);
        }
        const auto [it, inserted] = indices_.try_emplace(key, static_cast<int>(mesh_.vertices.size()));
        if (inserted) {
            if (mesh_.vertices.size() == kMaxVertices)
                throw InputError(field_, tooMany(kMaxVertices + 1, "vertices or more", kMaxVertices));
            mesh_.vertices.push_back(p);
        }
        return it->second;
    }

private:
    using Key = std::array<std::uint64_t, 3>;
    struct KeyHash {
        std::size_t operator()(const Key& k) const
        {
            std::uint64_t h = 0x9e3779b97f4a7c15ull;
            for (const std::uint64_t x : k)
                h = (h ^ x) * 0x100000001b3ull + (h >> 29);
            return static_cast<std::size_t>(h);
        }
    };

    PolygonMesh& mesh_;
    const std::string& field_;
    std::unordered_map<Key, int, KeyHash> indices_;
};

PolygonMesh parseBinaryStl(std::string_view bytes, const std::string& field)
{
    BinarySource source(bytes, true);
    source.skipBytes(80);
    const auto count = static_cast<std::uint64_t>(source.number(ScalarType::UInt32));
    if (count > kMaxFaces)
        throw InputError(field, tooMany(count, "triangles", kMaxFaces));
    PolygonMesh mesh;
    VertexMerger merger(mesh, field);
    mesh.faces.reserve(count, 3 * count);
    for (std::uint64_t t = 0; t < count; ++t) {
        stopIfAsked(t);
        source.skipBytes(12); // the normal: recomputed from the vertices wherever it is needed
        std::array<int, 3> face;
        for (int v = 0; v < 3; ++v) {
            Vec3<double> p;
            for (int k = 0; k < 3; ++k)
                p[k] = source.number(ScalarType::Float32);
            if (!allFinite(p))
                throw InputError(field, "triangle " + std::to_string(t + 1) + ": vertex " + std::to_string(v + 1) +
                                            " is not finite");
            face[std::size_t(v)] = merger.index(p);
        }
        source.skipBytes(2); // attribute byte count
        mesh.faces.push_back(face);
    }
    return mesh;
}

// solid NAME, then per facet: facet normal nx ny nz / outer loop / vertex x y z
// (3, or more for the polygons some exporters write) / endloop / endfacet;
// endsolid NAME. Several solids may follow each other.
PolygonMesh parseAsciiStl(std::string_view bytes, const std::string& field)
{
    TextScanner in(bytes, 1);
    auto fail = [&](const std::string& reason) {
        throw InputError(field, "line " + std::to_string(in.line()) + ": " + reason);
    };
    auto expect = [&](std::string_view keyword) {
        const std::string_view word = in.next();
        if (!equalsIgnoringCase(word, keyword))
            fail("expected '" + std::string(keyword) + "' (got " + quotedWord(word) + ")");
    };
    auto number = [&] {
        const std::string_view word = in.next();
        const std::optional<double> value = parseDouble(word);
        if (!value)
            fail("expected a number (got " + quotedWord(word) + ")");
        return *value;
    };
    PolygonMesh mesh;
    VertexMerger merger(mesh, field);
    expect("solid");
    in.skipLine();
    for (std::uint64_t facets = 0;; ++facets) {
        stopIfAsked(facets);
        std::string_view word = in.next();
        if (equalsIgnoringCase(word, "endsolid")) {
            in.skipLine();
            word = in.next();
            if (word.empty())
                break;
            if (!equalsIgnoringCase(word, "solid"))
                fail("expected 'solid' or the end of the file (got " + quotedWord(word) + ")");
            in.skipLine();
            continue;
        }
        if (!equalsIgnoringCase(word, "facet"))
            fail("expected 'facet' or 'endsolid' (got " + quotedWord(word) + ")");
        expect("normal");
        for (int k = 0; k < 3; ++k)
            number(); // recomputed from the vertices wherever it is needed
        expect("outer");
        expect("loop");
        std::vector<int> face;
        for (word = in.next(); equalsIgnoringCase(word, "vertex"); word = in.next()) {
            Vec3<double> p;
            for (int k = 0; k < 3; ++k)
                p[k] = number();
            if (!allFinite(p))
                fail("the vertex is not finite");
            face.push_back(merger.index(p));
        }
        if (!equalsIgnoringCase(word, "endloop"))
            fail("expected 'vertex' or 'endloop' (got " + quotedWord(word) + ")");
        if (face.size() < 3)
            fail("a facet needs at least 3 vertices (this one has " + std::to_string(face.size()) + ")");
        expect("endfacet");
        if (mesh.faces.size() == kMaxFaces)
            fail(tooMany(kMaxFaces + 1, "facets or more", kMaxFaces));
        mesh.faces.push_back(face);
    }
    return mesh;
}

bool startsWithSolid(std::string_view bytes)
{
    return equalsIgnoringCase(Words(bytes).next(), "solid");
}

PolygonMesh parseStl(std::string_view bytes, const std::string& field)
{
    // A binary file's size follows from its triangle count; its 80-byte header
    // may start with "solid" too, so the size decides before the keyword.
    constexpr std::size_t kHeader = 84, kTriangle = 50;
    if (bytes.size() >= kHeader) {
        BinarySource source(bytes.substr(80, 4), true);
        const auto count = static_cast<std::uint64_t>(source.number(ScalarType::UInt32));
        const std::uint64_t size = kHeader + kTriangle * count;
        if (size == bytes.size())
            return parseBinaryStl(bytes, field);
        if (!startsWithSolid(bytes) || bytes.find('\0') != std::string_view::npos)
            throw InputError(field, "a binary STL of " + std::to_string(count) + " triangles takes " +
                                        std::to_string(size) + " bytes, but the file has " +
                                        std::to_string(bytes.size()));
        return parseAsciiStl(bytes, field);
    }
    if (!startsWithSolid(bytes))
        throw InputError(field, "the file is too short for a binary STL (" + std::to_string(bytes.size()) +
                                    " bytes; 84 at least) and does not start with \"solid\"");
    return parseAsciiStl(bytes, field);
}

} // namespace

MeshFormat meshFormatOf(const std::filesystem::path& file, const std::string& field)
{
    std::string extension = file.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (extension == ".obj")
        return MeshFormat::Obj;
    if (extension == ".ply")
        return MeshFormat::Ply;
    if (extension == ".stl")
        return MeshFormat::Stl;
    throw InputError(field, "must name an .obj, .ply or .stl file (got \"" + file.string() + "\")");
}

PolygonMesh parseMesh(std::string_view bytes, MeshFormat format, const std::string& field)
{
    PolygonMesh mesh;
    try {
        switch (format) {
        case MeshFormat::Obj: mesh = parseObj(bytes, field); break;
        case MeshFormat::Ply: mesh = parsePly(bytes, field); break;
        case MeshFormat::Stl: mesh = parseStl(bytes, field); break;
        }
    } catch (const Truncated&) {
        throw InputError(field, "the file ends before its data does");
    } catch (const Stopped&) {
        throw InputError(field, "reading was stopped");
    } catch (const std::bad_alloc&) {
        throw InputError(field, "the mesh is too large to hold in memory");
    }
    if (mesh.faces.empty())
        throw InputError(field, "the file holds no faces");
    return mesh;
}

PolygonMesh readMeshFile(const std::filesystem::path& file, const std::string& field)
{
    const MeshFormat format = meshFormatOf(file, field);
    // A FIFO or a device named *.obj would block or never end.
    std::error_code error;
    if (std::filesystem::exists(file, error) && !std::filesystem::is_regular_file(file, error))
        throw InputError(field, "cannot read \"" + file.string() + "\": not a regular file");
    constexpr std::uintmax_t kMaxBytes = std::uintmax_t(2) << 30;
    const std::uintmax_t size = std::filesystem::file_size(file, error);
    if (!error && size > kMaxBytes)
        throw InputError(field, "\"" + file.string() + "\" is larger than 2 GiB");
    std::ifstream in(file, std::ios::binary);
    if (!in)
        throw InputError(field, "cannot read \"" + file.string() + "\": " + std::strerror(errno));
    std::string bytes;
    if (!error)
        bytes.reserve(static_cast<std::size_t>(size)); // read in one allocation, not copied at each doubling
    std::array<char, 1 << 16> buffer;
    while (in.read(buffer.data(), buffer.size()) || in.gcount() > 0) {
        if (stopAsked()) // looked at every 64 kB
            throw InputError(field, "reading was stopped");
        bytes.append(buffer.data(), static_cast<std::size_t>(in.gcount()));
    }
    if (in.bad())
        throw InputError(field, "cannot read \"" + file.string() + "\": " + std::strerror(errno));
    return parseMesh(bytes, format, field);
}

MeshReadingStop::MeshReadingStop(const std::atomic<bool>& stop) : previous_(askedToStop)
{
    askedToStop = &stop;
}

MeshReadingStop::~MeshReadingStop()
{
    askedToStop = previous_;
}

} // namespace viewpipe
