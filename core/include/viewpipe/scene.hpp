#pragma once

// Scene files (JSON, see docs/scene-format.md): a camera in Foley's or
// OpenGL's terms, the objects to draw, and the effects to simulate. Parsing
// refuses unknown keys, wrong types and invalid cameras with an InputError
// naming the field path ("view.vup[2]", "objects[1].min"); "$" is the root.

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "viewpipe/effects.hpp"
#include "viewpipe/pipeline.hpp"

namespace viewpipe {

enum class ObjectType { House, Box, Mesh };

struct SceneObject {
    ObjectType type = ObjectType::House;
    Vec3<double> min = Vec3<double>::Zero(); // box only
    Vec3<double> max = Vec3<double>::Zero(); // box only
    std::string path;                        // mesh only, as written in the file
    std::filesystem::path resolvedPath;      // mesh only, `path` resolved against the scene file's folder
};

struct Scene {
    std::string name;
    CameraSpec<double> camera;
    std::vector<SceneObject> objects;
    EffectList effects;
    std::filesystem::path file; // where it was loaded from; empty for a scene made in memory
    // Numbers typed as exact expressions, by field path ("view.prp[2]": "20*sqrt(2)"); the
    // camera holds their nearest doubles. Saved as typed while the field keeps that value.
    std::map<std::string, std::string> typedExpressions;
};

inline bool operator==(const SceneObject& a, const SceneObject& b)
{
    return a.type == b.type && a.min == b.min && a.max == b.max && a.path == b.path && a.resolvedPath == b.resolvedPath;
}
// The same scene wherever it was read from: its name, camera, objects (meshes by the file they name) and effects.
inline bool operator==(const Scene& a, const Scene& b)
{
    return a.name == b.name && a.camera == b.camera && a.objects == b.objects && a.effects == b.effects &&
           a.typedExpressions == b.typedExpressions;
}
inline bool operator!=(const Scene& a, const Scene& b)
{
    return !(a == b);
}

// The scene's look-at camera; throws InputError("camera") naming `purpose`
// ("the code dialects") when the scene has a Foley view instead.
const gl::Camera<double>& lookAtCamera(const Scene& scene, const std::string& purpose);

// The camera as typed, exactly: an expression as the expression, a JSON
// number as the decimal written ("0.1" is one tenth). Include exact.hpp.
CameraSpec<Exact> exactCamera(const Scene& scene);
// The scene's pipeline, with its effects' stages, computed exactly from exactCamera.
Pipeline<Exact> exactPipeline(const Scene& scene);

// Parses and validates a scene; mesh paths are resolved against baseDir and
// must name a readable .obj, .ply or .stl file.
Scene parseScene(const std::string& text, const std::filesystem::path& baseDir);
Scene loadScene(const std::filesystem::path& file);
// The mesh paths a scene's text names, as written, each mesh object read as parseScene reads it but its file
// not looked for (those that do not read are left out; none where the text is no JSON): where the page puts
// mesh files opened with the scene.
std::vector<std::string> meshPathsNamed(const std::string& text);

// The scenes offered as presets (the app's File > Presets, the page's
// Presets list): the scene files of `scenes` and of its classical/ and apis/
// folders, by file name, each read (one that does not read is not offered).
struct Preset {
    std::string group; // "", "Classical projections", "Graphics APIs"
    Scene scene;
};
std::vector<Preset> presetScenes(const std::filesystem::path& scenes);

std::string sceneToJson(const Scene& scene);
// The scene's typed expressions whose field still holds the value typed, as
// sceneToJson writes them; an edit since has replaced the others.
std::map<std::string, std::string> heldExpressions(const Scene& scene);
// The same, to be read from `folder`: a mesh path relative to it where the two
// share a folder below the root, else absolute.
std::string sceneToJson(const Scene& scene, const std::filesystem::path& folder);
// A scene's text with the field at `path` ("view.prp[0]") set to the text typed
// into a form (the web page's Scene panel), written as sceneToJson writes
// scenes. In a number's field (`number`) a decimal ("+20.", ".5", "1e3",
// parseDouble) is that number and any other text stays text, an exact
// expression for parseScene to read or refuse; elsewhere the text stays text.
// Throws InputError(path) where the scene has no such field.
std::string withTypedField(const std::string& sceneText, const std::string& path, const std::string& typed, bool number);
// Writes to a temporary file beside the target, then renames: a failed save
// leaves the previous file untouched.
void saveScene(const Scene& scene, const std::filesystem::path& file);
void writeFileAtomically(const std::filesystem::path& file, const std::string& contents);

} // namespace viewpipe
