// The graphics APIs' names, as scene files and people write them.
#include "viewpipe/gl.hpp"

#include <utility>

namespace viewpipe::gl {
namespace {

struct ApiNames {
    Api api;
    const char* name;
    const char* title;
};

constexpr ApiNames kApiNames[] = {{Api::OpenGL, "opengl", "OpenGL"},
                                  {Api::Direct3D, "direct3d", "Direct3D"},
                                  {Api::Vulkan, "vulkan", "Vulkan"},
                                  {Api::Metal, "metal", "Metal"},
                                  {Api::WebGPU, "webgpu", "WebGPU"}};

} // namespace

std::string apiName(Api api)
{
    for (const ApiNames& n : kApiNames)
        if (n.api == api)
            return n.name;
    return "";
}

std::string apiTitle(Api api)
{
    for (const ApiNames& n : kApiNames)
        if (n.api == api)
            return n.title;
    return "";
}

Api apiNamed(const std::string& name, const std::string& field)
{
    std::string known;
    for (const ApiNames& n : kApiNames) {
        if (name == n.name)
            return n.api;
        known += (known.empty() ? "\"" : ", \"") + std::string(n.name) + "\"";
    }
    throw InputError(field, "must be one of " + known + " (got \"" + name + "\")");
}

StageKind ndcStageKind(Api api, DepthMode depth)
{
    const bool reversed = depth == DepthMode::Reversed;
    switch (api) {
    case Api::OpenGL: return StageKind::NdcReversed;
    case Api::Direct3D: return reversed ? StageKind::NdcDirect3dReversed : StageKind::NdcDirect3d;
    case Api::Vulkan: return reversed ? StageKind::NdcVulkanReversed : StageKind::NdcVulkan;
    case Api::Metal: return reversed ? StageKind::NdcMetalReversed : StageKind::NdcMetal;
    case Api::WebGPU: return reversed ? StageKind::NdcWebgpuReversed : StageKind::NdcWebgpu;
    }
    return StageKind::NdcReversed;
}

std::string handednessName(Handedness handedness)
{
    return handedness == Handedness::Left ? "left" : "right";
}

std::string depthModeName(DepthMode depth)
{
    return depth == DepthMode::Reversed ? "reversed" : "standard";
}

} // namespace viewpipe::gl

#include "viewpipe/api.hpp"

namespace viewpipe::gl {

std::string memoryOrderLibrary(Api api)
{
    switch (api) {
    case Api::OpenGL:
    case Api::Vulkan: return "glm::mat4: column-major, column 0 first";
    case Api::Direct3D: return "DirectXMath XMFLOAT4X4: row-major, of the row-vector matrix (the transpose): the same order";
    case Api::Metal: return "simd_float4x4: four columns, column 0 first";
    case Api::WebGPU: return "wgpu-matrix mat4 (Float32Array): column-major, column 0 first";
    }
    return "";
}

Vec3<double> windowCoordinates(Api api, const Vec3<double>& ndc, double width, double height)
{
    const double x = (ndc.x() + 1) / 2 * width;
    // Vulkan's NDC y already points down; Direct3D's, Metal's and WebGPU's point up in a y-down window.
    const double y = api == Api::Direct3D || api == Api::Metal || api == Api::WebGPU ? (1 - ndc.y()) / 2 * height
                                                                                      : (ndc.y() + 1) / 2 * height;
    const double z = zeroToOneDepth(api) ? ndc.z() : (ndc.z() + 1) / 2;
    return {x, y, z};
}

Camera<double> convertCamera(const Camera<double>& camera, Api api, Handedness handedness, DepthMode depth)
{
    Camera<double> out = camera;
    out.api = api;
    out.handedness = handedness;
    out.depth = depth;
    if (handedness == camera.handedness)
        return out;
    out.projection = std::visit(
        [](const auto& p) -> ProjectionSpec<double> {
            using P = std::decay_t<decltype(p)>;
            if constexpr (std::is_same_v<P, Perspective<double>>) {
                const double top = p.zNear / detail::cotHalfFovy(p.fovyDegrees);
                return Frustum<double>{top * p.aspect, -top * p.aspect, -top, top, p.zNear, p.zFar};
            } else {
                P mirrored = p;
                mirrored.left = -p.left;
                mirrored.right = -p.right;
                return mirrored;
            }
        },
        camera.projection);
    return out;
}

} // namespace viewpipe::gl
