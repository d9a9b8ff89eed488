// The graphics APIs' cameras against their own definitions: glm's sources
// (Debian's libglm-dev, included here), Microsoft's DirectXMath reference
// implementation (Inc/DirectXMathMatrix.inl, its _XM_NO_INTRINSICS_ paths,
// written out below), the Vulkan specification's clip volume (-w <= x, y <= w,
// 0 <= z <= w) and viewport transform, and the WebGPU specification's
// coordinate systems (NDC z in [0, 1], y up; framebuffer y down).

#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_transform.hpp>

#include <cmath>
#include <limits>

#include "build_paths.h"
#include "support.hpp"
#include "viewpipe/api.hpp"
#include "viewpipe/effects.hpp"
#include "viewpipe/evaluated_scene.hpp"
#include "viewpipe/scene.hpp"

namespace viewpipe {
namespace {

using gl::Api;
using gl::DepthMode;
using gl::Handedness;
using test::expectRefused;

constexpr Handedness kHands[] = {Handedness::Right, Handedness::Left};
constexpr DepthMode kDepths[] = {DepthMode::Standard, DepthMode::Reversed};

double pi()
{
    return std::acos(-1.0);
}

Mat4<double> fromGlm(const glm::dmat4& g)
{
    Mat4<double> m;
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c)
            m(r, c) = g[c][r]; // glm indexes column first
    return m;
}

glm::dvec3 toGlm(const Vec3<double>& v)
{
    return {v.x(), v.y(), v.z()};
}

void expectSameMatrix(const Mat4<double>& actual, const Mat4<double>& expected, const std::string& what)
{
    const double scale = std::max(1.0, expected.cwiseAbs().maxCoeff());
    EXPECT_LE((actual - expected).cwiseAbs().maxCoeff(), 1e-13 * scale) << what << "\nactual\n"
                                                                        << actual << "\nexpected\n"
                                                                        << expected;
}

gl::Camera<double> camera(gl::ProjectionSpec<double> projection, Api api, Handedness hand, DepthMode depth)
{
    gl::Camera<double> c{{{3, 4, 12}, {1, 0.5, -2}, {0.2, 1, 0.1}}, projection};
    c.api = api;
    c.handedness = hand;
    c.depth = depth;
    return c;
}

// DirectXMath's matrices for row vectors (p' = p M), as DirectXMathMatrix.inl computes them.
struct DirectXMath {
    static Mat4<double> perspectiveFov(double fovY, double aspect, double nearZ, double farZ, bool left)
    {
        const double height = std::cos(0.5 * fovY) / std::sin(0.5 * fovY);
        const double width = height / aspect;
        const double range = left ? farZ / (farZ - nearZ) : farZ / (nearZ - farZ);
        Mat4<double> m = Mat4<double>::Zero();
        m(0, 0) = width;
        m(1, 1) = height;
        m(2, 2) = range;
        m(2, 3) = left ? 1 : -1;
        m(3, 2) = left ? -range * nearZ : range * nearZ;
        return m;
    }
    static Mat4<double> perspectiveOffCenter(double l, double r, double b, double t, double nearZ, double farZ,
                                             bool left)
    {
        const double twoNearZ = nearZ + nearZ, rw = 1 / (r - l), rh = 1 / (t - b);
        const double range = left ? farZ / (farZ - nearZ) : farZ / (nearZ - farZ);
        Mat4<double> m = Mat4<double>::Zero();
        m(0, 0) = twoNearZ * rw;
        m(1, 1) = twoNearZ * rh;
        m(2, 0) = (left ? -1 : 1) * (l + r) * rw;
        m(2, 1) = (left ? -1 : 1) * (t + b) * rh;
        m(2, 2) = range;
        m(2, 3) = left ? 1 : -1;
        m(3, 2) = left ? -range * nearZ : range * nearZ;
        return m;
    }
    static Mat4<double> orthographicOffCenter(double l, double r, double b, double t, double nearZ, double farZ,
                                              bool left)
    {
        const double rw = 1 / (r - l), rh = 1 / (t - b);
        const double range = left ? 1 / (farZ - nearZ) : 1 / (nearZ - farZ);
        Mat4<double> m = Mat4<double>::Zero();
        m(0, 0) = rw + rw;
        m(1, 1) = rh + rh;
        m(2, 2) = range;
        m(3, 0) = -(l + r) * rw;
        m(3, 1) = -(t + b) * rh;
        m(3, 2) = left ? -range * nearZ : range * nearZ;
        m(3, 3) = 1;
        return m;
    }
    // XMMatrixLookAtLH is XMMatrixLookToLH(eye, focus - eye, up); ...RH passes eye - focus.
    static Mat4<double> lookAt(const Vec3<double>& eye, const Vec3<double>& focus, const Vec3<double>& up, bool left)
    {
        const Vec3<double> r2 = (left ? focus - eye : eye - focus).normalized();
        const Vec3<double> r0 = up.cross(r2).normalized();
        const Vec3<double> r1 = r2.cross(r0);
        Mat4<double> m = Mat4<double>::Identity(); // rows R0, R1, R2 with -R.eye, then transposed
        m.block<1, 3>(0, 0) = r0.transpose();
        m.block<1, 3>(1, 0) = r1.transpose();
        m.block<1, 3>(2, 0) = r2.transpose();
        m(0, 3) = -r0.dot(eye);
        m(1, 3) = -r1.dot(eye);
        m(2, 3) = -r2.dot(eye);
        return m.transpose();
    }
};

TEST(Api, Direct3DMatricesAreDirectXMathsForRowVectors)
{
    for (const bool left : {true, false}) {
        const Handedness hand = left ? Handedness::Left : Handedness::Right;
        const auto fov = camera(gl::Perspective<double>{50, 1.6, 0.5, 40}, Api::Direct3D, hand, DepthMode::Standard);
        expectSameMatrix(gl::asDocumented(gl::projectionMatrix(fov), Api::Direct3D),
                         DirectXMath::perspectiveFov(50 * pi() / 180, 1.6, 0.5, 40, left), "XMMatrixPerspectiveFov");
        const auto offCenter =
            camera(gl::Frustum<double>{-0.3, 0.5, -0.2, 0.4, 0.5, 40}, Api::Direct3D, hand, DepthMode::Standard);
        expectSameMatrix(gl::asDocumented(gl::projectionMatrix(offCenter), Api::Direct3D),
                         DirectXMath::perspectiveOffCenter(-0.3, 0.5, -0.2, 0.4, 0.5, 40, left),
                         "XMMatrixPerspectiveOffCenter");
        const auto ortho = camera(gl::Ortho<double>{-3, 5, -2, 4, 1, 30}, Api::Direct3D, hand, DepthMode::Standard);
        expectSameMatrix(gl::asDocumented(gl::projectionMatrix(ortho), Api::Direct3D),
                         DirectXMath::orthographicOffCenter(-3, 5, -2, 4, 1, 30, left), "XMMatrixOrthographicOffCenter");
        expectSameMatrix(gl::viewMatrix(ortho).transpose(),
                         DirectXMath::lookAt(ortho.lookAt.eye, ortho.lookAt.center, ortho.lookAt.up, left),
                         "XMMatrixLookAt");
    }
    EXPECT_TRUE(gl::rowVectors(Api::Direct3D));
    EXPECT_EQ(gl::defaultHandedness(Api::Direct3D), Handedness::Left);
}

// glm's *_NO (OpenGL) and *_ZO (Metal, WebGPU; Vulkan with clip y negated) forms.
TEST(Api, OtherApisMatricesAreGlms)
{
    const double fovy = 50, aspect = 1.6, n = 0.5, f = 40;
    for (const Api api : {Api::OpenGL, Api::Vulkan, Api::Metal, Api::WebGPU})
        for (const Handedness hand : kHands) {
            const bool left = hand == Handedness::Left, zo = api != Api::OpenGL;
            const double radians = fovy * pi() / 180;
            glm::dmat4 perspective = left ? (zo ? glm::perspectiveLH_ZO(radians, aspect, n, f)
                                                : glm::perspectiveLH_NO(radians, aspect, n, f))
                                          : (zo ? glm::perspectiveRH_ZO(radians, aspect, n, f)
                                                : glm::perspectiveRH_NO(radians, aspect, n, f));
            glm::dmat4 frustum = left ? (zo ? glm::frustumLH_ZO(-0.3, 0.5, -0.2, 0.4, n, f)
                                            : glm::frustumLH_NO(-0.3, 0.5, -0.2, 0.4, n, f))
                                      : (zo ? glm::frustumRH_ZO(-0.3, 0.5, -0.2, 0.4, n, f)
                                            : glm::frustumRH_NO(-0.3, 0.5, -0.2, 0.4, n, f));
            glm::dmat4 ortho = left ? (zo ? glm::orthoLH_ZO(-3.0, 5.0, -2.0, 4.0, 1.0, 30.0)
                                          : glm::orthoLH_NO(-3.0, 5.0, -2.0, 4.0, 1.0, 30.0))
                                    : (zo ? glm::orthoRH_ZO(-3.0, 5.0, -2.0, 4.0, 1.0, 30.0)
                                          : glm::orthoRH_NO(-3.0, 5.0, -2.0, 4.0, 1.0, 30.0));
            if (left) { // glm 0.9.9.8's frustumLH_* keep frustumRH's signs here: glm issue #982, fixed by PR #1080
                frustum[2][0] = -(0.5 + -0.3) / (0.5 - -0.3);
                frustum[2][1] = -(0.4 + -0.2) / (0.4 - -0.2);
            }
            if (api == Api::Vulkan) // the common practice: clip y negated in the matrix
                for (glm::dmat4* m : {&perspective, &frustum, &ortho})
                    for (int c = 0; c < 4; ++c)
                        (*m)[c][1] = -(*m)[c][1];
            const std::string what = gl::apiName(api) + (left ? " left" : " right");
            const auto p = camera(gl::Perspective<double>{fovy, aspect, n, f}, api, hand, DepthMode::Standard);
            expectSameMatrix(gl::projectionMatrix(p), fromGlm(perspective), what + " perspective");
            expectSameMatrix(gl::projectionMatrix(camera(gl::Frustum<double>{-0.3, 0.5, -0.2, 0.4, n, f}, api, hand,
                                                         DepthMode::Standard)),
                             fromGlm(frustum), what + " frustum");
            expectSameMatrix(gl::projectionMatrix(camera(gl::Ortho<double>{-3, 5, -2, 4, 1, 30}, api, hand,
                                                         DepthMode::Standard)),
                             fromGlm(ortho), what + " ortho");
            const glm::dmat4 view = left ? glm::lookAtLH(toGlm(p.lookAt.eye), toGlm(p.lookAt.center), toGlm(p.lookAt.up))
                                         : glm::lookAtRH(toGlm(p.lookAt.eye), toGlm(p.lookAt.center), toGlm(p.lookAt.up));
            expectSameMatrix(gl::viewMatrix(p), fromGlm(view), what + " lookAt");
        }
}

// Reversed depth with a finite far plane is the API's own function with near and far exchanged.
TEST(Api, ReversedDepthExchangesNearAndFar)
{
    for (const Api api : gl::kApis)
        for (const Handedness hand : kHands)
            for (int kind = 0; kind < 3; ++kind) {
                gl::ProjectionSpec<double> spec = gl::Perspective<double>{50, 1.6, 0.5, 40};
                gl::ProjectionSpec<double> swapped = gl::Perspective<double>{50, 1.6, 40, 0.5};
                if (kind == 1) {
                    spec = gl::Frustum<double>{-0.3, 0.5, -0.2, 0.4, 0.5, 40};
                    swapped = gl::Frustum<double>{-0.3, 0.5, -0.2, 0.4, 40, 0.5};
                } else if (kind == 2) {
                    spec = gl::Ortho<double>{-3, 5, -2, 4, 1, 30};
                    swapped = gl::Ortho<double>{-3, 5, -2, 4, 30, 1};
                }
                // The exchanged call is what applications write; ViewPipe refuses far < near for perspective
                // cameras, so build its matrix from the OpenGL form directly.
                const Mat4<double> exchanged = [&] {
                    Mat4<double> gl = std::visit(
                        [](const auto& p) -> Mat4<double> {
                            using P = std::decay_t<decltype(p)>;
                            Mat4<double> m = gl::detail::perspectiveDepth(p.zNear, p.zFar);
                            if constexpr (std::is_same_v<P, gl::Ortho<double>>)
                                return gl::ortho(p);
                            else if constexpr (std::is_same_v<P, gl::Frustum<double>>) {
                                m(0, 0) = 2 * p.zFar / (p.right - p.left); // glFrustum's 2n/(r-l) with n the near plane
                                m(0, 2) = (p.right + p.left) / (p.right - p.left);
                                m(1, 1) = 2 * p.zFar / (p.top - p.bottom);
                                m(1, 2) = (p.top + p.bottom) / (p.top - p.bottom);
                                return m;
                            } else {
                                const double f = gl::detail::cotHalfFovy(p.fovyDegrees);
                                m(0, 0) = f / p.aspect;
                                m(1, 1) = f;
                                return m;
                            }
                        },
                        swapped);
                    Mat4<double> out = gl::ndcConversion<double>(api, DepthMode::Standard) * gl;
                    return hand == Handedness::Left ? Mat4<double>(out * gl::handednessFlip<double>()) : out;
                }();
                const Mat4<double> reversed = gl::projectionMatrix(camera(spec, api, hand, DepthMode::Reversed));
                expectSameMatrix(reversed, exchanged, gl::apiName(api) + " kind " + std::to_string(kind));
            }
}

// The 8 corners of the view volume land on the corners of the API's clip volume, near and far where its
// depth range puts them, y down for Vulkan.
TEST(Api, ViewVolumeCornersMapToTheApisClipVolume)
{
    test::SpecGenerator generator(14);
    for (int i = 0; i < 60; ++i) {
        gl::Camera<double> c = generator.glCamera(i % 3);
        for (const Api api : gl::kApis)
            for (const Handedness hand : kHands)
                for (const DepthMode depth : kDepths) {
                    c.api = api;
                    c.handedness = hand;
                    c.depth = depth;
                    const Pipeline<double> p = buildPipeline(c);
                    const auto corners = gl::viewVolumeCorners(c);
                    const double nearZ = nearPlaneZ(p.clipVolume), farZ = farPlaneZ(p.clipVolume);
                    for (std::size_t k = 0; k < 8; ++k) {
                        const Vec4<double> h = p.composite * corners[k].homogeneous();
                        ASSERT_GT(h.w(), 0);
                        const Vec3<double> ndc = h.head<3>() / h.w();
                        const double x = (k % 4 == 1 || k % 4 == 2) ? 1 : -1, y = k % 4 >= 2 ? 1 : -1;
                        const Vec3<double> expected(x, gl::yDown(api) ? -y : y, k < 4 ? nearZ : farZ);
                        EXPECT_LE((ndc - expected).norm(), 1e-9)
                            << gl::apiName(api) << " " << gl::handednessName(hand) << " "
                            << gl::depthModeName(depth) << " corner " << k << ": " << ndc.transpose();
                    }
                    // The stages multiply to the composite.
                    const Mat4<double> product = cumulativeProducts(p.stages).back();
                    EXPECT_LE((product - p.composite).cwiseAbs().maxCoeff(),
                              1e-12 * std::max(1.0, p.composite.cwiseAbs().maxCoeff()));
                }
    }
    EXPECT_EQ(nearPlaneZ(ClipVolume::ZeroToOne), 0);
    EXPECT_EQ(farPlaneZ(ClipVolume::ZeroToOneReversed), 0);
    EXPECT_EQ(nearPlaneZ(ClipVolume::OpenGLReversed), 1);
}

// An infinite far plane gives the exact limit of a growing far plane: no NaN, no huge numbers.
TEST(Api, InfiniteFarIsTheLimitOfGrowingFar)
{
    for (const Api api : gl::kApis)
        for (const Handedness hand : kHands)
            for (const DepthMode depth : kDepths)
                for (const bool fovy : {true, false}) {
                    auto spec = [&](double far) -> gl::ProjectionSpec<double> {
                        if (fovy)
                            return gl::Perspective<double>{60, 1.5, 0.1, far};
                        return gl::Frustum<double>{-0.2, 0.1, -0.1, 0.1, 0.1, far};
                    };
                    const Mat4<double> infinite =
                        gl::projectionMatrix(camera(spec(std::numeric_limits<double>::infinity()), api, hand, depth));
                    ASSERT_TRUE(infinite.allFinite());
                    EXPECT_LE(infinite.cwiseAbs().maxCoeff(), 20);
                    for (const double far : {1e3, 1e6, 1e9}) {
                        const Mat4<double> finite = gl::projectionMatrix(camera(spec(far), api, hand, depth));
                        EXPECT_LE((finite - infinite).cwiseAbs().maxCoeff(), 1.0 / far) << far;
                    }
                }
    // The reversed infinite [0, 1] projection everyone quotes: z_clip = near, w = -z (right-handed).
    const Mat4<double> reversed = gl::projectionMatrix(
        camera(gl::Perspective<double>{90, 1, 0.1, std::numeric_limits<double>::infinity()}, Api::Vulkan,
               Handedness::Right, DepthMode::Reversed));
    EXPECT_EQ(reversed(2, 2), 0);
    EXPECT_DOUBLE_EQ(reversed(2, 3), 0.1);
    EXPECT_EQ(reversed(3, 2), -1);
}

// Each API's viewport transform: Vulkan's x_f = (p_x/2) x_d + o_x with o = (x + width/2, y + height/2)
// (the specification's "Controlling the Viewport"), z_f = p_z z_d + o_z; WebGPU's framebuffer y =
// (-y_ndc + 1)/2 height; Direct3D's and Metal's top-left origin; OpenGL's glViewport and glDepthRange(0, 1).
TEST(Api, WindowCoordinatesFollowEachApisViewport)
{
    const Vec3<double> topLeftNear(-1, 1, 0);
    for (const Api api : {Api::Direct3D, Api::Metal, Api::WebGPU})
        EXPECT_EQ(gl::windowCoordinates(api, topLeftNear, 640, 480), Vec3<double>(0, 0, 0)) << gl::apiName(api);
    EXPECT_EQ(gl::windowCoordinates(Api::Vulkan, Vec3<double>(-1, -1, 0), 640, 480), Vec3<double>(0, 0, 0));
    EXPECT_EQ(gl::windowCoordinates(Api::Vulkan, Vec3<double>(1, 1, 1), 640, 480), Vec3<double>(640, 480, 1));
    EXPECT_EQ(gl::windowCoordinates(Api::OpenGL, Vec3<double>(-1, -1, -1), 640, 480), Vec3<double>(0, 0, 0));
    EXPECT_EQ(gl::windowCoordinates(Api::OpenGL, Vec3<double>(0.5, 0, 1), 640, 480), Vec3<double>(480, 240, 1));
    EXPECT_FALSE(gl::windowOriginTopLeft(Api::OpenGL));
    EXPECT_TRUE(gl::windowOriginTopLeft(Api::Vulkan));
}

// DirectXMath keeps the row-vector matrix row by row, glm the column-vector matrix column by column:
// the same 16 numbers.
TEST(Api, MemoryOrderIsTheSameSixteenNumbers)
{
    const auto c = camera(gl::Frustum<double>{-0.3, 0.5, -0.2, 0.4, 0.5, 40}, Api::Direct3D, Handedness::Left,
                          DepthMode::Standard);
    const Mat4<double> documented = gl::asDocumented(gl::projectionMatrix(c), Api::Direct3D);
    const auto order = gl::memoryOrder(gl::projectionMatrix(c));
    for (int r = 0; r < 4; ++r)
        for (int col = 0; col < 4; ++col)
            EXPECT_EQ(order[std::size_t(4 * r + col)], documented(r, col)); // XMFLOAT4X4: _11, _12, ... row-major
    EXPECT_EQ(order[14], gl::projectionMatrix(c)(2, 3)); // glm: m[3][2]
    for (const Api api : gl::kApis)
        EXPECT_FALSE(gl::memoryOrderLibrary(api).empty());
}

// Where a world point lands in the picture: x and y from the top left, and its depth read with near at 0.
Vec3<double> pictureAt(const gl::Camera<double>& c, const Vec3<double>& world)
{
    const Pipeline<double> p = buildPipeline(c);
    const Vec4<double> h = p.clipMatrix() * world.homogeneous();
    const Vec3<double> window = gl::windowCoordinates(c.api, h.head<3>() / h.w(), 640, 480);
    const double fromTop = gl::windowOriginTopLeft(c.api) ? window.y() : 480 - window.y();
    return {window.x(), fromTop, windowDepth(h, p.clipVolume)};
}

TEST(Api, ConvertedCameraDrawsTheSamePicture)
{
    test::SpecGenerator generator(141);
    for (int i = 0; i < 30; ++i) {
        const gl::Camera<double> source = generator.glCamera(i % 3);
        const Pipeline<double> p = buildPipeline(source);
        const Mat4<double> inverse = p.clipMatrix().inverse();
        for (const Api api : gl::kApis)
            for (const Handedness hand : kHands)
                for (const DepthMode depth : kDepths) {
                    const gl::Camera<double> target = gl::convertCamera(source, api, hand, depth);
                    for (int k = 0; k < 5; ++k) { // points inside the view volume
                        const Vec4<double> ndc(generator.uniform(-1, 1), generator.uniform(-1, 1),
                                               generator.uniform(-0.9, 0.9), 1);
                        const Vec4<double> h = inverse * ndc;
                        const Vec3<double> world = h.head<3>() / h.w();
                        const Vec3<double> a = pictureAt(source, world), b = pictureAt(target, world);
                        EXPECT_LE(std::abs(a.x() - b.x()), 1e-12 * 640) << gl::apiName(api);
                        EXPECT_LE(std::abs(a.y() - b.y()), 1e-12 * 480) << gl::apiName(api);
                        EXPECT_LE(std::abs(a.z() - b.z()), 1e-12) << gl::apiName(api);
                    }
                }
    }
}

// The effects look at the same faces whichever API draws the same picture: culling follows the
// mirrored winding of a left-handed camera and of Vulkan's y.
TEST(Api, EffectsAgreeAcrossApisForTheSamePicture)
{
    const Scene scene = loadScene(std::string(viewpipe::build::dataDir) + "/scenes/opengl-perspective.json");
    const auto& source = std::get<gl::Camera<double>>(scene.camera);
    std::vector<PolygonMesh> objects = {houseMesh()};
    EffectList effects;
    for (const char* name : {"clip", "cull", "depth", "raster"})
        effects = withEffect(effects, name, true);
    const EffectOutcomes reference = runEffects(buildPipeline(source), objects, effects);
    ASSERT_GT(reference.cull->culled, 0);
    for (const Api api : gl::kApis)
        for (const Handedness hand : kHands)
            for (const DepthMode depth : kDepths) {
                const gl::Camera<double> target = gl::convertCamera(source, api, hand, depth);
                const EffectOutcomes o = runEffects(buildPipeline(target), objects, effects);
                const std::string what = gl::apiName(api) + " " + gl::handednessName(hand) + " " +
                                         gl::depthModeName(depth);
                EXPECT_EQ(o.cull->culledFaces, reference.cull->culledFaces) << what;
                EXPECT_EQ(o.clip->segments.inside, reference.clip->segments.inside) << what;
                EXPECT_EQ(o.raster->object, reference.raster->object) << what;
                EXPECT_EQ(o.depth->options.reversed, depth == DepthMode::Reversed) << what;
            }
}

TEST(Api, ScenesNameTheApiHandednessAndDepth)
{
    const std::string lookAt = R"("look_at": {"eye": [0, 0, 5], "center": [0, 0, 0], "up": [0, 1, 0]},
        "projection": {"type": "perspective", "fovy_deg": 60, "aspect": 1, "near": 1, "far": "infinity"})";
    auto parse = [&](const std::string& extra) {
        return parseScene(R"({"camera": {)" + lookAt + extra + "}}", ".");
    };
    const Scene direct3d = parse(R"(, "api": "direct3d")");
    const auto& d3d = std::get<gl::Camera<double>>(direct3d.camera);
    EXPECT_EQ(d3d.api, Api::Direct3D);
    EXPECT_EQ(d3d.handedness, Handedness::Left);
    const Scene vulkan = parse(R"(, "api": "vulkan", "handedness": "left", "depth": "reversed")");
    const auto& vk = std::get<gl::Camera<double>>(vulkan.camera);
    EXPECT_EQ(vk.handedness, Handedness::Left);
    EXPECT_EQ(vk.depth, DepthMode::Reversed);
    const Scene again = parseScene(sceneToJson(vulkan), ".");
    EXPECT_EQ(sceneToJson(again), sceneToJson(vulkan));
    EXPECT_EQ(sceneToJson(parse("")).find("\"api\""), std::string::npos); // OpenGL scenes stay as written
    expectRefused([&] { parse(R"(, "api": "glide")"); }, "camera.api", "\"webgpu\"");
    expectRefused([&] { parse(R"(, "api": 3)"); }, "camera.api", "string");
    expectRefused([&] { parse(R"(, "handedness": "up")"); }, "camera.handedness", "\"left\"");
    expectRefused([&] { parse(R"(, "depth": "deep")"); }, "camera.depth", "\"reversed\"");
    // Far's refusals show what was written, and glOrtho's far has no infinity.
    const auto withProjection = [](const std::string& projection) {
        return parseScene(R"({"camera": {"look_at": {"eye": [0, 0, 5], "center": [0, 0, 0], "up": [0, 1, 0]},
                                         "projection": )" + projection + "}}", ".");
    };
    expectRefused([&] { withProjection(R"({"type": "perspective", "fovy_deg": 60, "aspect": 1, "near": 1, "far": "inf"})"); },
                  "camera.projection.far", "expected a number, sqrt(...) or ( at character 1 of \"inf\"");
    expectRefused([&] { withProjection(R"({"type": "ortho", "left": -1, "right": 1, "bottom": -1, "top": 1, "near": 1, "far": "infinity"})"); },
                  "camera.projection.far", "cannot be \"infinity\" for an ortho projection");
}

// Each API's canonical volume is what the last stage's claim and the labels say.
TEST(Api, StagesShowTheStepToEachApisVolume)
{
    for (const Api api : gl::kApis) {
        const auto c = camera(gl::Perspective<double>{50, 1.6, 0.5, 40}, api, Handedness::Right, DepthMode::Standard);
        const std::vector<Stage<double>> stages = gl::stages(c);
        if (api == Api::OpenGL) {
            EXPECT_EQ(stages.back().symbol(), "P_depth");
            continue;
        }
        EXPECT_EQ(stages.back().symbol(), "NDC_" + gl::apiName(api));
        EXPECT_NE(stages.back().explanation.find("$z' = (z + w)/2$, near 0, far 1"), std::string::npos);
        EXPECT_EQ(stages.back().explanation.find("$y' = -y$") != std::string::npos, api == Api::Vulkan);
    }
    const auto left = camera(gl::Ortho<double>{-3, 5, -2, 4, 1, 30}, Api::Direct3D, Handedness::Left,
                             DepthMode::Reversed);
    std::vector<std::string> symbols;
    for (const Stage<double>& s : gl::stages(left))
        symbols.push_back(s.symbol());
    EXPECT_EQ(symbols, (std::vector<std::string>{"T(-eye)", "R_eye", "Z_flip", "T_ortho", "S_ortho", "NDC_direct3d_reversed"}));
}

// The picture of Vulkan's volume says where its y points: the last stage's claim and the planes' labels.
TEST(Api, VulkansVolumeIsLabelledWithItsYDown)
{
    const Scene scene = loadScene(std::string(viewpipe::build::dataDir) + "/scenes/apis/vulkan.json");
    const std::shared_ptr<const EvaluatedScene> evaluated = evaluateScene(scene);
    EXPECT_EQ(evaluated->stageClaims.back(), "the volume is $-1 \\le x, y \\le 1$, $0 \\le z \\le 1$; $y$ points down in the image");
    std::set<std::string> labels;
    for (const Label& label : evaluated->labels)
        if (label.element == Element::Canonical)
            labels.insert(label.text);
    for (const char* text : {"$y = -1$ (image top)", "$y = 1$ (image bottom)", "$z = 0$ (near)", "$z = 1$ (far)", "$x = 1$"})
        EXPECT_TRUE(labels.count(text)) << text;
}

} // namespace
// With the far plane at infinity the volume drawn is cut short: the claim still holds for what is drawn
// (sides and near face on the canonical volume, the cut face between near and far) and says so.
TEST(Api, AVolumeCutShortOfAnInfiniteFarIsStillClaimed)
{
    const Scene scene = loadScene(std::string(viewpipe::build::dataDir) + "/scenes/apis/vulkan-reversed-infinite.json");
    EXPECT_EQ(evaluateScene(scene)->stageClaims.back(),
              "the volume is $-1 \\le x, y \\le 1$, $0 \\le z \\le 1$; $y$ points down in the image "
              "(far at infinity: the volume drawn is cut short of it)");
}

} // namespace viewpipe
