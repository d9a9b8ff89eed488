#include "viewpipe/scene.hpp"

#include "file_paths.hpp"
#include "json_fields.hpp"
#include "parse_number.hpp"

#include "viewpipe/exact.hpp"
#include "viewpipe/format.hpp"
#include "viewpipe/mesh_io.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <fcntl.h>
#include <unistd.h>

namespace viewpipe {

namespace fields {

std::string found(const Json& j)
{
    if (j.is_string()) {
        const std::string text = j.get<std::string>();
        std::size_t cut = std::min<std::size_t>(text.size(), 24);
        while (cut < text.size() && (text[cut] & 0xC0) == 0x80)
            --cut; // at a character's first byte
        return "the text " + Json(text.substr(0, cut) + (cut < text.size() ? "..." : "")).dump(); // quoted, escaped
    }
    if (j.is_number() || j.is_boolean() || j.is_null())
        return j.dump();
    return j.is_array() ? "an array" : "an object";
}

std::string child(const std::string& parent, const std::string& key)
{
    return parent.empty() ? key : parent + "." + key;
}

std::string element(const std::string& parent, std::size_t index)
{
    return parent + "[" + std::to_string(index) + "]";
}

void requireObject(const Json& j, const std::string& path, const std::set<std::string>& allowed,
                   const std::set<std::string>& required)
{
    if (!j.is_object())
        throw InputError(path.empty() ? "$" : path, "must be an object (got " + found(j) + ")");
    for (const auto& item : j.items())
        if (!allowed.count(item.key())) {
            std::string known;
            for (const std::string& k : allowed)
                known += (known.empty() ? "" : ", ") + k;
            throw InputError(child(path, item.key()), "unknown key (expected one of: " + known + ")");
        }
    for (const std::string& key : required)
        if (!j.contains(key))
            throw InputError(child(path, key), "is missing");
}

namespace {
thread_local std::map<std::string, std::string>* typedExpressions = nullptr;
} // namespace

TypedExpressions::TypedExpressions(std::map<std::string, std::string>& into) : previous_(typedExpressions)
{
    typedExpressions = &into;
}

TypedExpressions::~TypedExpressions()
{
    typedExpressions = previous_;
}

double readExpression(const std::string& text, const std::string& path)
{
    double x = 0;
    try {
        x = double(parseExact(text));
    } catch (const std::exception& error) { // the parser's reason, or arithmetic refused
        throw InputError(path, error.what());
    }
    if (!std::isfinite(x))
        throw InputError(path, "must be a finite number (" + text + " is too large for a double)");
    return x;
}

double readNumber(const Json& j, const std::string& path)
{
    if (j.is_string() && typedExpressions) {
        const std::string text = j.get<std::string>();
        const double x = readExpression(text, path);
        (*typedExpressions)[path] = text;
        return x;
    }
    if (!j.is_number())
        throw InputError(path, std::string(typedExpressions ? "must be a number or an exact expression such as "
                                                              "\"20*sqrt(2)\"" : "must be a number") +
                                   " (got " + found(j) + ")");
    const double x = j.get<double>();
    if (!std::isfinite(x))
        throw InputError(path, "must be a finite number");
    return x;
}

std::vector<double> readNumbers(const Json& j, const std::string& path, std::size_t count)
{
    if (!j.is_array() || j.size() != count)
        throw InputError(path, "must be an array of " + std::to_string(count) + " numbers");
    std::vector<double> out;
    for (std::size_t i = 0; i < count; ++i)
        out.push_back(readNumber(j[i], element(path, i)));
    return out;
}

Vec3<double> readVec3(const Json& j, const std::string& path)
{
    const std::vector<double> v = readNumbers(j, path, 3);
    return {v[0], v[1], v[2]};
}

std::string readString(const Json& j, const std::string& path)
{
    if (!j.is_string())
        throw InputError(path, "must be a string (got " + found(j) + ")");
    return j.get<std::string>();
}

namespace {

// nlohmann's DOM builder, told where each value goes, so that a number too
// large for a double is refused with its field path ("view.vrp[0]"); nlohmann
// alone reports it as a parse error at a byte.
class PathTrackingBuilder {
public:
    explicit PathTrackingBuilder(Json& root) : dom_(root) {}

    bool null() { return enter() && dom_.null(); }
    bool boolean(bool value) { return enter() && dom_.boolean(value); }
    bool number_integer(Json::number_integer_t value) { return enter() && dom_.number_integer(value); }
    bool number_unsigned(Json::number_unsigned_t value) { return enter() && dom_.number_unsigned(value); }
    bool number_float(Json::number_float_t value, const Json::string_t& text)
    {
        return enter() && dom_.number_float(value, text);
    }
    bool string(Json::string_t& value) { return enter() && dom_.string(value); }
    bool binary(Json::binary_t& value) { return enter() && dom_.binary(value); }

    bool start_object(std::size_t size)
    {
        const bool ok = enter() && dom_.start_object(size);
        frames_.push_back({true, {}, 0});
        return ok;
    }
    bool key(Json::string_t& key)
    {
        frames_.back().key = key;
        return dom_.key(key);
    }
    bool end_object()
    {
        frames_.pop_back();
        return dom_.end_object();
    }
    bool start_array(std::size_t size)
    {
        const bool ok = enter() && dom_.start_array(size);
        frames_.push_back({false, {}, 0});
        return ok;
    }
    bool end_array()
    {
        frames_.pop_back();
        return dom_.end_array();
    }

    template <class Exception>
    bool parse_error(std::size_t position, const std::string& token, const Exception& error)
    {
        constexpr int kNumberOverflow = 406;
        if (error.id == kNumberOverflow)
            throw InputError(pendingPath(), "not a finite number");
        // NaN and Infinity as JavaScript writes them are no JSON: say so at the field, not as a stray "N".
        const std::string word = token.substr(std::min(token.size(), token.find_last_of(" \t\n\r,:[") + 1));
        for (const char* start : {"N", "n", "I", "-I", "i", "-i"})
            if (!word.empty() && word.rfind(start, 0) == 0)
                throw InputError(pendingPath(), "NaN and Infinity are not JSON numbers: write a finite number");
        return dom_.parse_error(position, token, error);
    }

private:
    struct Frame {
        bool object;
        std::string key; // objects: the key of the value being read
        std::size_t next; // arrays: the index of the next value
    };

    // A value starts: in an array, it takes the next index.
    bool enter()
    {
        if (!frames_.empty() && !frames_.back().object)
            ++frames_.back().next;
        return true;
    }

    // The path of the value being read (arrays have counted it already unless it failed to parse).
    std::string pendingPath() const
    {
        std::string path;
        for (std::size_t k = 0; k < frames_.size(); ++k) {
            const Frame& frame = frames_[k];
            const bool last = k + 1 == frames_.size();
            path = frame.object ? child(path, frame.key) : element(path, last ? frame.next : frame.next - 1);
        }
        return path.empty() ? "$" : path;
    }

    nlohmann::detail::json_sax_dom_parser<Json> dom_;
    std::vector<Frame> frames_;
};

// nlohmann's syntax error as a position: its byte offset counted into lines
// and columns as nlohmann's own message does, and the message's last part
// ("unexpected '}'; expected ']'").
InputError syntaxError(const Json::parse_error& error, const std::string& text)
{
    const std::size_t end = std::min<std::size_t>(error.byte, text.size());
    const std::size_t line = 1 + std::size_t(std::count(text.begin(), text.begin() + std::ptrdiff_t(end), '\n'));
    const std::size_t lineStart = text.rfind('\n', end == 0 ? std::string::npos : end - 1);
    const std::size_t column = error.byte - (lineStart == std::string::npos ? 0 : lineStart + 1);
    // "[json.exception.parse_error.101] parse error at line 4, column 3: syntax error while parsing array - ...".
    const std::string what = error.what();
    std::size_t start = what.find(": ", what.find("column"));
    start = start == std::string::npos ? 0 : start + 2;
    const std::size_t dash = what.find(" - ", start);
    return InputError::at(line, column, what.substr(dash == std::string::npos ? start : dash + 3));
}

} // namespace

std::string readInputFile(const std::filesystem::path& file, const std::string& what)
{
    std::ifstream in(file, std::ios::binary);
    if (!in)
        throw InputError("$", "cannot read the " + what + " file: " + std::strerror(errno));
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

Json parseJson(const std::string& text)
{
    Json root;
    try {
        PathTrackingBuilder builder(root);
        Json::sax_parse(text, &builder);
    } catch (const Json::parse_error& e) {
        throw syntaxError(e, text);
    }
    return root;
}

} // namespace fields

namespace {

using namespace fields;

// A depth that may be "infinity" (far plane of glFrustum and gluPerspective).
double readFar(const Json& j, const std::string& path)
{
    if (j.is_string() && j.get<std::string>() == "infinity")
        return std::numeric_limits<double>::infinity();
    if (!j.is_number() && !j.is_string())
        throw InputError(path, "must be a number or \"infinity\" (got " + found(j) + ")");
    return readNumber(j, path);
}


foley::ViewSpec<double> readView(const Json& j)
{
    const std::set<std::string> keys = {"projection", "vrp", "vpn", "vup", "prp", "window", "front", "back"};
    requireObject(j, "view", keys, keys);
    foley::ViewSpec<double> spec;
    const std::string projection = readString(j["projection"], "view.projection");
    if (projection == "perspective")
        spec.projection = foley::Projection::Perspective;
    else if (projection == "parallel")
        spec.projection = foley::Projection::Parallel;
    else
        throw InputError("view.projection", "must be \"perspective\" or \"parallel\" (got \"" + projection + "\")");
    spec.vrp = readVec3(j["vrp"], "view.vrp");
    spec.vpn = readVec3(j["vpn"], "view.vpn");
    spec.vup = readVec3(j["vup"], "view.vup");
    spec.prp = readVec3(j["prp"], "view.prp");
    const std::vector<double> w = readNumbers(j["window"], "view.window", 4);
    spec.window = {w[0], w[1], w[2], w[3]};
    spec.front = readNumber(j["front"], "view.front");
    spec.back = readNumber(j["back"], "view.back");
    foley::validate(spec);
    return spec;
}

gl::ProjectionSpec<double> readGlProjection(const Json& j)
{
    const std::string path = "camera.projection";
    if (!j.is_object())
        throw InputError(path, "must be an object (got " + found(j) + ")");
    if (!j.contains("type"))
        throw InputError(path + ".type", "is missing");
    const std::string type = readString(j["type"], path + ".type");
    auto number = [&](const char* key) { return readNumber(j[key], path + "." + key); };
    if (type == "perspective") {
        const std::set<std::string> keys = {"type", "fovy_deg", "aspect", "near", "far"};
        requireObject(j, path, keys, keys);
        gl::Perspective<double> p{number("fovy_deg"), number("aspect"), number("near"),
                                  readFar(j["far"], path + ".far")};
        gl::validate(p);
        return p;
    }
    const std::set<std::string> keys = {"type", "left", "right", "bottom", "top", "near", "far"};
    if (type == "frustum") {
        requireObject(j, path, keys, keys);
        gl::Frustum<double> p{number("left"),  number("right"), number("bottom"),
                              number("top"),   number("near"),  readFar(j["far"], path + ".far")};
        gl::validate(p);
        return p;
    }
    if (type == "ortho") {
        requireObject(j, path, keys, keys);
        if (j["far"] == "infinity")
            throw InputError(path + ".far", "cannot be \"infinity\" for an ortho projection (its depth would have no scale)");
        gl::Ortho<double> p{number("left"), number("right"), number("bottom"),
                            number("top"),  number("near"),  number("far")};
        gl::validate(p);
        return p;
    }
    throw InputError(path + ".type", "must be \"frustum\", \"ortho\" or \"perspective\" (got \"" + type + "\")");
}

gl::Camera<double> readCamera(const Json& j)
{
    requireObject(j, "camera", {"look_at", "projection", "api", "handedness", "depth"}, {"look_at", "projection"});
    const std::set<std::string> lookKeys = {"eye", "center", "up"};
    requireObject(j["look_at"], "camera.look_at", lookKeys, lookKeys);
    gl::Camera<double> camera;
    camera.lookAt = {readVec3(j["look_at"]["eye"], "camera.look_at.eye"),
                     readVec3(j["look_at"]["center"], "camera.look_at.center"),
                     readVec3(j["look_at"]["up"], "camera.look_at.up")};
    gl::eyeBasis(camera.lookAt);
    camera.projection = readGlProjection(j["projection"]);
    if (j.contains("api"))
        camera.api = gl::apiNamed(readString(j["api"], "camera.api"), "camera.api");
    camera.handedness = gl::defaultHandedness(camera.api);
    if (j.contains("handedness")) {
        const std::string handedness = readString(j["handedness"], "camera.handedness");
        if (handedness != "right" && handedness != "left")
            throw InputError("camera.handedness", "must be \"right\" (the eye looks down -z) or \"left\" (down +z) (got \"" +
                                                      handedness + "\")");
        camera.handedness = handedness == "left" ? gl::Handedness::Left : gl::Handedness::Right;
    }
    if (j.contains("depth")) {
        const std::string depth = readString(j["depth"], "camera.depth");
        if (depth != "standard" && depth != "reversed")
            throw InputError("camera.depth", "must be \"standard\" or \"reversed\" (near and far exchanged) (got \"" +
                                                 depth + "\")");
        camera.depth = depth == "reversed" ? gl::DepthMode::Reversed : gl::DepthMode::Standard;
    }
    return camera;
}

SceneObject readObject(const Json& j, const std::string& path, const std::filesystem::path& baseDir)
{
    if (!j.is_object())
        throw InputError(path, "must be an object (got " + found(j) + ")");
    if (!j.contains("type"))
        throw InputError(path + ".type", "is missing");
    const std::string type = readString(j["type"], path + ".type");
    SceneObject object;
    if (type == "house") {
        requireObject(j, path, {"type"}, {"type"});
        object.type = ObjectType::House;
    } else if (type == "box") {
        requireObject(j, path, {"type", "min", "max"}, {"type", "min", "max"});
        object.type = ObjectType::Box;
        object.min = readVec3(j["min"], path + ".min");
        object.max = readVec3(j["max"], path + ".max");
        for (int axis = 0; axis < 3; ++axis)
            if (!(object.min[axis] < object.max[axis]))
                throw InputError(path + ".max", "must exceed min on every axis (axis " + std::to_string(axis) + ")");
    } else if (type == "mesh") {
        requireObject(j, path, {"type", "path"}, {"type", "path"});
        object.type = ObjectType::Mesh;
        object.path = readString(j["path"], path + ".path");
        meshFormatOf(object.path, path + ".path");
        object.resolvedPath = baseDir / object.path;
    } else {
        throw InputError(path + ".type", "must be \"house\", \"box\" or \"mesh\" (got \"" + type + "\")");
    }
    return object;
}

// One entry of "effects": a name, or {"name": {parameters}}.
void readEffect(const Json& j, const std::string& path, EffectList& effects)
{
    std::string name;
    const Json* parameters = nullptr;
    if (j.is_string()) {
        name = j.get<std::string>();
    } else if (j.is_object() && j.size() == 1) {
        name = j.begin().key();
        parameters = &j.begin().value();
    } else {
        throw InputError(path, "must be an effect name or {\"name\": {parameters}}");
    }
    const EffectKind effect = effectNamed(name, path);
    if (effects.has(effect))
        throw InputError(path, "effect \"" + name + "\" is listed twice");
    EffectList next = withEffect(effects, effect, true);
    const std::string where = path + "." + name;
    if (parameters && !parameters->is_object())
        throw InputError(where, "parameters must be an object (got " + found(*parameters) + ")");
    std::vector<std::string> accepted;
    if (effect == EffectKind::Depth)
        accepted = {"bits", "format", "reversed"};
    else if (effect == EffectKind::Raster)
        accepted = {"width", "height"};
    if (parameters)
        for (const auto& item : parameters->items())
            if (std::find(accepted.begin(), accepted.end(), item.key()) == accepted.end()) {
                std::string known;
                for (const std::string& key : accepted)
                    known += (known.empty() ? "" : ", ") + key;
                throw InputError(where + "." + item.key(), accepted.empty()
                                                               ? "unknown parameter (\"" + name + "\" takes none)"
                                                               : "unknown parameter (" + known + ")");
            }
    if (effect == EffectKind::Depth) {
        DepthOptions depth;
        if (parameters && parameters->contains("format")) {
            const std::string format = readString((*parameters)["format"], where + ".format");
            if (format != "unorm" && format != "float")
                throw InputError(where + ".format", "must be \"unorm\" or \"float\" (got \"" + format + "\")");
            depth.floating = format == "float";
        }
        if (parameters && parameters->contains("bits")) {
            const Json& bits = (*parameters)["bits"];
            // Compared before narrowing: get<int> would wrap 2^32 + 16 to 16.
            if (!bits.is_number_integer() || (bits != 16 && bits != 24 && bits != 32))
                throw InputError(where + ".bits", "must be 16, 24 or 32 (got " + bits.dump() + ")");
            depth.bits = bits.get<int>();
        } else if (depth.floating) {
            depth.bits = 32;
        }
        if (depth.floating && depth.bits != 32)
            throw InputError(where + ".bits", "a float depth buffer has 32 bits");
        if (parameters && parameters->contains("reversed")) {
            if (!(*parameters)["reversed"].is_boolean())
                throw InputError(where + ".reversed", "must be true or false");
            depth.reversed = (*parameters)["reversed"].get<bool>();
        }
        next.depth = depth;
    }
    if (effect == EffectKind::Raster) {
        RasterOptions raster;
        for (const char* key : {"width", "height"})
            if (parameters && parameters->contains(key)) {
                const Json& value = (*parameters)[key];
                if (!value.is_number_integer() || value.get<long>() < 1 || value.get<long>() > 4096)
                    throw InputError(where + "." + key, "must be a whole number of pixels from 1 to 4096");
                (std::string(key) == "width" ? raster.width : raster.height) = value.get<int>();
            }
        next.raster = raster;
    }
    effects = std::move(next);
}

// Written in the order a person writes a scene (and in the file's own order, where it has one).
using Written = nlohmann::ordered_json;

Written vec3Json(const Vec3<double>& v)
{
    return Written::array({v.x(), v.y(), v.z()});
}

Written farJson(double zFar)
{
    return std::isinf(zFar) ? Written("infinity") : Written(zFar);
}

Written cameraJson(const CameraSpec<double>& camera)
{
    if (const auto* spec = std::get_if<foley::ViewSpec<double>>(&camera)) {
        return {{"view",
                 {{"projection", spec->projection == foley::Projection::Perspective ? "perspective" : "parallel"},
                  {"vrp", vec3Json(spec->vrp)},
                  {"vpn", vec3Json(spec->vpn)},
                  {"vup", vec3Json(spec->vup)},
                  {"prp", vec3Json(spec->prp)},
                  {"window", {spec->window.umin, spec->window.umax, spec->window.vmin, spec->window.vmax}},
                  {"front", spec->front},
                  {"back", spec->back}}}};
    }
    const auto& gl = std::get<gl::Camera<double>>(camera);
    Written projection;
    if (const auto* p = std::get_if<gl::Perspective<double>>(&gl.projection))
        projection = {{"type", "perspective"},
                      {"fovy_deg", p->fovyDegrees},
                      {"aspect", p->aspect},
                      {"near", p->zNear},
                      {"far", farJson(p->zFar)}};
    else if (const auto* p = std::get_if<gl::Frustum<double>>(&gl.projection))
        projection = {{"type", "frustum"}, {"left", p->left},   {"right", p->right},        {"bottom", p->bottom},
                      {"top", p->top},     {"near", p->zNear}, {"far", farJson(p->zFar)}};
    else {
        const auto& o = std::get<gl::Ortho<double>>(gl.projection);
        projection = {{"type", "ortho"}, {"left", o.left},   {"right", o.right}, {"bottom", o.bottom},
                      {"top", o.top},    {"near", o.zNear}, {"far", o.zFar}};
    }
    Written out = {{"look_at",
                    {{"eye", vec3Json(gl.lookAt.eye)}, {"center", vec3Json(gl.lookAt.center)}, {"up", vec3Json(gl.lookAt.up)}}},
                   {"projection", projection}};
    // The conventions only where they differ from the defaults: OpenGL scenes stay as they were written.
    if (gl.api != gl::Api::OpenGL)
        out["api"] = gl::apiName(gl.api);
    if (gl.handedness != gl::defaultHandedness(gl.api))
        out["handedness"] = gl::handednessName(gl.handedness);
    if (gl.depth != gl::DepthMode::Standard)
        out["depth"] = gl::depthModeName(gl.depth);
    return {{"camera", out}};
}

// `fresh` with its objects' keys in `old`'s order where `old` has them (a scene file as its author wrote it),
// new keys after them.
Written inOrderOf(const Written& fresh, const Written& old)
{
    if (fresh.is_array() && old.is_array() && fresh.size() == old.size()) {
        Written out = Written::array();
        for (std::size_t k = 0; k < fresh.size(); ++k)
            out.push_back(inOrderOf(fresh[k], old[k]));
        return out;
    }
    if (!fresh.is_object() || !old.is_object())
        return fresh;
    Written out = Written::object();
    for (const auto& [key, value] : old.items())
        if (fresh.contains(key))
            out[key] = inOrderOf(fresh[key], value);
    for (const auto& [key, value] : fresh.items())
        if (!out.contains(key))
            out[key] = value;
    return out;
}

// JSON as people write scenes: two-space indents, a list of numbers or words
// on one line, each number in its shortest form ("8", not "8.0").
void writeJson(std::string& out, const Written& j, int indent)
{
    const std::string pad(std::size_t(indent), ' '), inner(std::size_t(indent + 2), ' ');
    const bool flat = j.is_array() && std::none_of(j.begin(), j.end(), [](const Written& e) { return e.is_structured(); });
    if (j.is_structured() && !j.empty() && !flat) {
        out += j.is_object() ? "{\n" : "[\n";
        std::size_t k = 0;
        for (const auto& [key, value] : j.items()) {
            out += inner + (j.is_object() ? Written(key).dump() + ": " : "");
            writeJson(out, value, indent + 2);
            out += ++k < j.size() ? ",\n" : "\n";
        }
        out += pad + (j.is_object() ? "}" : "]");
    } else if (flat && !j.empty()) {
        out += "[";
        for (std::size_t k = 0; k < j.size(); ++k) {
            out += k ? ", " : "";
            writeJson(out, j[k], indent);
        }
        out += "]";
    } else if (j.is_number_float()) {
        out += formatShortest(j.get<double>());
    } else {
        out += j.dump();
    }
}

// The value at a field path ("view.prp[2]", "camera.projection.near"), or nothing.
Written* valueAt(Written& root, const std::string& path)
{
    Written* at = &root;
    std::size_t i = 0;
    while (i < path.size() && at) {
        if (path[i] == '.') {
            ++i;
        } else if (path[i] == '[') {
            const std::size_t close = path.find(']', i);
            const std::size_t index = std::stoul(path.substr(i + 1, close - i - 1));
            at = at->is_array() && index < at->size() ? &(*at)[index] : nullptr;
            i = close + 1;
        } else {
            const std::size_t end = std::min(path.find_first_of(".[", i), path.size());
            const std::string key = path.substr(i, end - i);
            at = at->is_object() && at->contains(key) ? &(*at)[key] : nullptr;
            i = end;
        }
    }
    return at;
}

Written sceneTree(const Scene& scene)
{
    Written root = {{"name", scene.name}};
    root.update(cameraJson(scene.camera));
    // An expression as typed, where the field still holds its value (an edit since replaces it).
    for (const auto& [path, text] : scene.typedExpressions)
        if (Written* value = valueAt(root, path); value && value->is_number() &&
                                                  value->get<double>() == double(parseExact(text)))
            *value = text;
    Written objects = Written::array();
    for (const SceneObject& object : scene.objects) {
        switch (object.type) {
        case ObjectType::House: objects.push_back({{"type", "house"}}); break;
        case ObjectType::Box:
            objects.push_back({{"type", "box"}, {"min", vec3Json(object.min)}, {"max", vec3Json(object.max)}});
            break;
        case ObjectType::Mesh: objects.push_back({{"type", "mesh"}, {"path", object.path}}); break;
        }
    }
    root["objects"] = objects;
    Written effects = Written::array();
    for (const EffectKind effect : scene.effects.listed) {
        if (effect == EffectKind::Depth && scene.effects.depth) {
            const DepthOptions& d = *scene.effects.depth;
            effects.push_back({{"depth", {{"bits", d.bits}, {"format", d.floating ? "float" : "unorm"}, {"reversed", d.reversed}}}});
        } else if (effect == EffectKind::Raster && scene.effects.raster) {
            effects.push_back({{"raster", {{"width", scene.effects.raster->width}, {"height", scene.effects.raster->height}}}});
        } else {
            effects.push_back(effectName(effect));
        }
    }
    root["effects"] = effects;
    return root;
}

std::string written(const Written& tree)
{
    std::string out;
    writeJson(out, tree, 0);
    return out + "\n";
}

// Where each scalar value of a JSON text lies, by its path ("/view/vrp/0"):
// read from text nlohmann-json has already accepted, so it need not check.
class ValuePlaces {
public:
    explicit ValuePlaces(const std::string& text) : text_(text) { value(""); }
    std::map<std::string, std::pair<std::size_t, std::size_t>> places;

private:
    void spaces()
    {
        while (at_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[at_])))
            ++at_;
    }
    std::string string()
    {
        const std::size_t begin = at_++;
        while (at_ < text_.size() && text_[at_] != '"')
            at_ += text_[at_] == '\\' ? 2 : 1;
        ++at_;
        return Written::parse(text_.substr(begin, at_ - begin)).get<std::string>();
    }
    void value(const std::string& path)
    {
        spaces();
        if (at_ >= text_.size())
            return;
        const char c = text_[at_];
        if (c == '{' || c == '[') {
            ++at_;
            for (std::size_t k = 0;; ++k) {
                spaces();
                if (at_ >= text_.size() || text_[at_] == '}' || text_[at_] == ']')
                    break;
                std::string key = std::to_string(k);
                if (c == '{') {
                    key = string();
                    spaces();
                    ++at_; // the colon
                }
                value(path + "/" + key);
                spaces();
                if (at_ < text_.size() && text_[at_] == ',')
                    ++at_;
            }
            ++at_;
            return;
        }
        const std::size_t begin = at_;
        if (c == '"')
            string();
        else
            while (at_ < text_.size() && std::string(",]} \t\r\n").find(text_[at_]) == std::string::npos)
                ++at_;
        places[path] = {begin, at_};
    }
    const std::string& text_;
    std::size_t at_ = 0;
};

// Whether two trees have the same objects' keys and the same arrays' lengths.
bool sameShape(const Written& a, const Written& b)
{
    if (a.is_structured() != b.is_structured() || a.is_object() != b.is_object() || a.size() != b.size())
        return false;
    if (a.is_object()) {
        for (const auto& [key, value] : a.items())
            if (!b.contains(key) || !sameShape(value, b[key]))
                return false;
    } else if (a.is_array()) {
        for (std::size_t k = 0; k < a.size(); ++k)
            if (!sameShape(a[k], b[k]))
                return false;
    }
    return true;
}

// The scalars of `fresh` that differ from `old`'s, by path.
void changedValues(const Written& fresh, const Written& old, const std::string& path,
                   std::map<std::string, std::string>& changed)
{
    if (fresh.is_object()) {
        for (const auto& [key, value] : fresh.items())
            changedValues(value, old[key], path + "/" + key, changed);
    } else if (fresh.is_array()) {
        for (std::size_t k = 0; k < fresh.size(); ++k)
            changedValues(fresh[k], old[k], path + "/" + std::to_string(k), changed);
    } else if (fresh.is_number() && old.is_number() ? fresh.get<double>() != old.get<double>() : fresh != old) {
        std::string lexeme;
        writeJson(lexeme, fresh, 0);
        changed[path] = lexeme;
    }
}

} // namespace

Scene parseScene(const std::string& text, const std::filesystem::path& baseDir)
{
    const Json root = parseJson(text);
    requireObject(root, "", {"name", "view", "camera", "objects", "effects"}, {});
    if (root.contains("view") == root.contains("camera"))
        throw InputError("$", "needs exactly one of \"view\" (Foley) or \"camera\" (OpenGL)");

    Scene scene;
    const TypedExpressions typed(scene.typedExpressions);
    scene.name = root.contains("name") ? readString(root["name"], "name") : std::string();
    if (root.contains("view"))
        scene.camera = readView(root["view"]);
    else
        scene.camera = readCamera(root["camera"]);
    if (root.contains("objects")) {
        const Json& objects = root["objects"];
        if (!objects.is_array())
            throw InputError("objects", "must be an array (got " + found(objects) + ")");
        for (std::size_t i = 0; i < objects.size(); ++i) {
            const SceneObject& object = scene.objects.emplace_back(readObject(objects[i], element("objects", i), baseDir));
            if (object.type == ObjectType::Mesh && !std::ifstream(object.resolvedPath))
                throw InputError(element("objects", i) + ".path",
                                 "cannot read \"" + object.resolvedPath.string() + "\": " + std::strerror(errno));
        }
    }
    if (root.contains("effects")) {
        const Json& effects = root["effects"];
        if (!effects.is_array())
            throw InputError("effects", "must be an array (got " + found(effects) + ")");
        for (std::size_t i = 0; i < effects.size(); ++i)
            readEffect(effects[i], element("effects", i), scene.effects);
    }
    return scene;
}

std::vector<std::string> meshPathsNamed(const std::string& text)
{
    std::vector<std::string> paths;
    Json root;
    try {
        root = parseJson(text);
    } catch (const InputError&) {
        return paths;
    }
    if (!root.is_object() || !root.contains("objects") || !root["objects"].is_array())
        return paths;
    const Json& objects = root["objects"];
    for (std::size_t i = 0; i < objects.size(); ++i) {
        try {
            const SceneObject object = readObject(objects[i], element("objects", i), {});
            if (object.type == ObjectType::Mesh)
                paths.push_back(object.path);
        } catch (const InputError&) {
        }
    }
    return paths;
}

namespace {

// Every number of a camera with its field path, as a scene file names it.
template <class T, class F> void forEachCameraNumber(CameraSpec<T>& camera, F&& visit)
{
    auto vector = [&](const std::string& path, Vec3<T>& v) {
        for (int i = 0; i < 3; ++i)
            visit(fields::element(path, std::size_t(i)), v[i]);
    };
    if (auto* spec = std::get_if<foley::ViewSpec<T>>(&camera)) {
        vector("view.vrp", spec->vrp);
        vector("view.vpn", spec->vpn);
        vector("view.vup", spec->vup);
        vector("view.prp", spec->prp);
        T* window[] = {&spec->window.umin, &spec->window.umax, &spec->window.vmin, &spec->window.vmax};
        for (std::size_t i = 0; i < 4; ++i)
            visit(fields::element("view.window", i), *window[i]);
        visit("view.front", spec->front);
        visit("view.back", spec->back);
        return;
    }
    auto& gl = std::get<gl::Camera<T>>(camera);
    vector("camera.look_at.eye", gl.lookAt.eye);
    vector("camera.look_at.center", gl.lookAt.center);
    vector("camera.look_at.up", gl.lookAt.up);
    const std::string path = "camera.projection.";
    if (auto* p = std::get_if<gl::Perspective<T>>(&gl.projection)) {
        visit(path + "fovy_deg", p->fovyDegrees);
        visit(path + "aspect", p->aspect);
        visit(path + "near", p->zNear);
        visit(path + "far", p->zFar);
        return;
    }
    std::visit(
        [&](auto& box) {
            if constexpr (!std::is_same_v<std::decay_t<decltype(box)>, gl::Perspective<T>>) {
                visit(path + "left", box.left);
                visit(path + "right", box.right);
                visit(path + "bottom", box.bottom);
                visit(path + "top", box.top);
                visit(path + "near", box.zNear);
                visit(path + "far", box.zFar);
            }
        },
        gl.projection);
}

} // namespace

CameraSpec<Exact> exactCamera(const Scene& scene)
{
    CameraSpec<Exact> camera = convertCamera<Exact>(scene.camera, [](double x) { return fromDecimal<Exact>(x); });
    forEachCameraNumber(camera, [&](const std::string& path, Exact& x) {
        if (const auto typed = scene.typedExpressions.find(path); typed != scene.typedExpressions.end())
            x = parseExact(typed->second);
    });
    return camera;
}

Pipeline<Exact> exactPipeline(const Scene& scene)
{
    return withEffectStages(buildPipeline(exactCamera(scene)), scene.effects);
}

const gl::Camera<double>& lookAtCamera(const Scene& scene, const std::string& purpose)
{
    const auto* camera = std::get_if<gl::Camera<double>>(&scene.camera);
    if (!camera)
        throw InputError("camera", "is missing: " + purpose +
                                       " need a look_at camera; this scene has a Foley view (\"view\"), which "
                                       "follows no graphics API");
    return *camera;
}

Scene loadScene(const std::filesystem::path& file)
{
    Scene scene = parseScene(readInputFile(file, "scene"), file.parent_path());
    scene.file = file;
    if (scene.name.empty())
        scene.name = file.stem().string();
    return scene;
}

std::vector<Preset> presetScenes(const std::filesystem::path& scenes)
{
    std::vector<Preset> presets;
    for (const auto& [folder, group] : {std::pair{"", ""}, std::pair{"classical", "Classical projections"},
                                        std::pair{"apis", "Graphics APIs"}}) {
        std::vector<std::filesystem::path> files;
        std::error_code missing;
        for (const auto& entry : std::filesystem::directory_iterator(scenes / folder, missing))
            if (entry.is_regular_file() && entry.path().extension() == ".json")
                files.push_back(entry.path());
        std::sort(files.begin(), files.end());
        for (const std::filesystem::path& file : files) {
            try {
                presets.push_back({group, loadScene(file)});
            } catch (const InputError&) {
                // a broken preset is not offered
            }
        }
    }
    return presets;
}

std::string sceneToJson(const Scene& scene)
{
    return written(sceneTree(scene));
}

std::string withTypedField(const std::string& sceneText, const std::string& path, const std::string& typed, bool number)
{
    Written tree = Written::parse(sceneText);
    Written* value = valueAt(tree, path);
    if (!value)
        throw InputError(path, "is not a field of the scene");
    const std::size_t first = typed.find_first_not_of(" \t\n\r"), last = typed.find_last_not_of(" \t\n\r");
    const std::string text = first == std::string::npos ? "" : typed.substr(first, last - first + 1);
    const std::optional<double> decimal = number ? parseDouble(text) : std::nullopt;
    if (decimal && std::isfinite(*decimal))
        *value = *decimal;
    else
        *value = text;
    return written(tree);
}

std::map<std::string, std::string> heldExpressions(const Scene& scene)
{
    Written tree = sceneTree(scene);
    std::map<std::string, std::string> held;
    for (const auto& [path, text] : scene.typedExpressions)
        if (const Written* value = valueAt(tree, path); value && value->is_string())
            held.emplace(path, text);
    return held;
}

void writeFileAtomically(const std::filesystem::path& file, const std::string& contents)
{
    // Unique per process and per call: two runs, or two threads, never share a temporary file.
    static std::atomic<unsigned> counter{0};
    std::filesystem::path temporary = file;
    temporary += ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
    const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
    if (fd < 0)
        throw InputError(file.string(), std::string("cannot write: ") + std::strerror(errno));
    std::size_t written = 0;
    while (written < contents.size()) {
        const ssize_t n = ::write(fd, contents.data() + written, contents.size() - written);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            break;
        written += std::size_t(n);
    }
    // fsync before the rename: after a power cut the file is the old one or the new one, never empty.
    const bool complete = written == contents.size() && ::fsync(fd) == 0;
    const int savedErrno = errno;
    ::close(fd);
    std::error_code error;
    if (!complete) {
        std::filesystem::remove(temporary, error);
        throw InputError(file.string(), std::string("cannot write: ") + std::strerror(savedErrno));
    }
    std::filesystem::rename(temporary, file, error);
    if (error) {
        std::error_code ignored;
        std::filesystem::remove(temporary, ignored);
        throw InputError(file.string(), "cannot replace the file: " + error.message());
    }
}

std::string sceneToJson(const Scene& scene, const std::filesystem::path& folder)
{
    Scene moved = scene;
    for (SceneObject& object : moved.objects)
        if (object.type == ObjectType::Mesh)
            object.path = pathFrom(folder, object.resolvedPath).generic_string();
    return sceneToJson(moved);
}

void saveScene(const Scene& scene, const std::filesystem::path& file)
{
    // As the file replaced, or the one the scene was read from, was written: its values edited in place where
    // only values changed, else its keys' order kept. A diff shows the edits.
    std::string original;
    Written old;
    for (const std::filesystem::path& source : {file, scene.file}) {
        std::ifstream in(source, std::ios::binary);
        if (source.empty() || !in)
            continue;
        original.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
        if ((old = Written::parse(original, nullptr, false)).is_object())
            break;
    }
    const Written fresh = Written::parse(sceneToJson(scene, std::filesystem::absolute(file).parent_path()));
    if (!old.is_object()) {
        writeFileAtomically(file, written(fresh));
        return;
    }
    if (sameShape(fresh, old)) {
        std::map<std::string, std::string> changed;
        changedValues(fresh, old, "", changed);
        const ValuePlaces places(original);
        std::vector<std::pair<std::pair<std::size_t, std::size_t>, std::string>> edits;
        for (const auto& [path, lexeme] : changed)
            if (const auto place = places.places.find(path); place != places.places.end())
                edits.push_back({place->second, lexeme});
        if (edits.size() == changed.size()) {
            std::sort(edits.begin(), edits.end(), [](const auto& a, const auto& b) { return a.first.first > b.first.first; });
            for (const auto& [place, lexeme] : edits) // from the end: the places before stay where they are
                original.replace(place.first, place.second - place.first, lexeme);
            writeFileAtomically(file, original);
            return;
        }
    }
    writeFileAtomically(file, written(inOrderOf(fresh, old)));
}

} // namespace viewpipe
