// The camera's choices (the app's Parameters, the page's Scene panel):
// switching projection type keeps the projection where the forms agree.

#include "support.hpp"
#include "viewpipe/camera_choices.hpp"

namespace viewpipe {
namespace {

using test::expectRefused;

gl::Camera<double> lookingDownZ(const gl::ProjectionSpec<double>& projection)
{
    return {{{0, 0, 5}, {0, 0, 0}, {0, 1, 0}}, projection};
}

const gl::Camera<double>& glOf(const CameraSpec<double>& camera)
{
    return std::get<gl::Camera<double>>(camera);
}

// gluPerspective's reference page: it is glFrustum with top = zNear · tan(fovy / 2) and right = top · aspect.
// So a perspective switched to glFrustum has the same matrix, and back again the same numbers.
TEST(CameraChoices, PerspectiveToFrustumKeepsTheMatrix)
{
    const CameraSpec<double> perspective = lookingDownZ(gl::Perspective<double>{90, 2, 1, 10});
    const CameraSpec<double> frustum = withChoice(perspective, "camera.projection.type", 0);
    const auto& box = std::get<gl::Frustum<double>>(glOf(frustum).projection);
    EXPECT_NEAR(box.left, -2, 1e-15);
    EXPECT_NEAR(box.right, 2, 1e-15);
    EXPECT_NEAR(box.bottom, -1, 1e-15);
    EXPECT_NEAR(box.top, 1, 1e-15);
    EXPECT_EQ(box.zNear, 1);
    EXPECT_EQ(box.zFar, 10);
    EXPECT_TRUE(gl::projectionMatrix(glOf(frustum)).isApprox(gl::projectionMatrix(glOf(perspective)), 1e-15));

    const CameraSpec<double> perspectiveAgain = withChoice(frustum, "camera.projection.type", 2);
    const auto& back = std::get<gl::Perspective<double>>(glOf(perspectiveAgain).projection);
    EXPECT_NEAR(back.fovyDegrees, 90, 1e-13);
    EXPECT_NEAR(back.aspect, 2, 1e-15);
}

// glOrtho's box is the near plane's rectangle taken to the look-at distance (5, near 0.5: ten times it); an
// infinite far becomes 1000 · near (glOrtho has none). Found: the near rectangle itself as the box showed the
// house about 2.3 times larger on the page.
TEST(CameraChoices, OrthoKeepsWhatLiesAtTheLookAtPoint)
{
    const double inf = std::numeric_limits<double>::infinity();
    const CameraSpec<double> frustum = lookingDownZ(gl::Frustum<double>{-0.3, 0.1, -0.2, 0.2, 0.5, inf});
    const CameraSpec<double> ortho = withChoice(frustum, "camera.projection.type", 1);
    const auto& box = std::get<gl::Ortho<double>>(glOf(ortho).projection);
    EXPECT_NEAR(box.left, -3, 1e-15);
    EXPECT_NEAR(box.right, 1, 1e-15);
    EXPECT_NEAR(box.bottom, -2, 1e-15);
    EXPECT_NEAR(box.top, 2, 1e-15);
    EXPECT_EQ(box.zNear, 0.5);
    EXPECT_EQ(box.zFar, 500);
    // A point in the plane of the look-at point lands where it did: same NDC x and y.
    for (const Vec3<double>& p : {Vec3<double>(0, 0, 0), Vec3<double>(1.5, -0.7, 0), Vec3<double>(-2.5, 1.9, 0)}) {
        const auto before = tracePoint(buildPipeline(frustum), p).divided, after = tracePoint(buildPipeline(ortho), p).divided;
        ASSERT_TRUE(before && after);
        EXPECT_NEAR(after->x(), before->x(), 1e-14) << p.transpose();
        EXPECT_NEAR(after->y(), before->y(), 1e-14) << p.transpose();
    }
    // And back: the frustum again (its far now finite).
    const CameraSpec<double> frustumAgain = withChoice(ortho, "camera.projection.type", 0);
    const auto& again = std::get<gl::Frustum<double>>(glOf(frustumAgain).projection);
    EXPECT_NEAR(again.left, -0.3, 1e-15);
    EXPECT_NEAR(again.top, 0.2, 1e-15);
    // The type already chosen changes nothing (an infinite far stays infinite).
    const CameraSpec<double> same = withChoice(frustum, "camera.projection.type", 0);
    EXPECT_TRUE(std::isinf(std::get<gl::Frustum<double>>(glOf(same).projection).zFar));
}

TEST(CameraChoices, ListTheConventionsChoicesWithTheCamerasOwn)
{
    gl::Camera<double> vulkan = lookingDownZ(gl::Perspective<double>{60, 1, 1, 10});
    vulkan.api = gl::Api::Vulkan;
    vulkan.depth = gl::DepthMode::Reversed;
    const std::vector<CameraChoice> choices = cameraChoices(vulkan);
    ASSERT_EQ(choices.size(), 4u);
    EXPECT_EQ(choices[0].field, "camera.api");
    EXPECT_EQ(choices[0].options[std::size_t(choices[0].chosen)], "Vulkan");
    EXPECT_EQ(choices[2].field, "camera.depth");
    EXPECT_EQ(choices[2].chosen, 1);
    // Found: a Vulkan camera offered OpenGL's calls; the forms, named for what they are.
    EXPECT_EQ(choices[3].options, (std::vector<std::string>{"frustum", "orthographic", "perspective (field of view)"}));
    EXPECT_EQ(choices[3].options[std::size_t(choices[3].chosen)], "perspective (field of view)");
    gl::Camera<double> opengl = vulkan;
    opengl.api = gl::Api::OpenGL;
    EXPECT_EQ(cameraChoices(opengl)[3].options,
              (std::vector<std::string>{"glFrustum", "glOrtho", "gluPerspective"})); // as the lecture notes call them

    const CameraSpec<double> metal = withChoice(vulkan, "camera.api", 3);
    EXPECT_EQ(glOf(metal).api, gl::Api::Metal);
    EXPECT_EQ(glOf(withChoice(metal, "camera.handedness", 1)).handedness, gl::Handedness::Left);

    foley::ViewSpec<double> view;
    view.projection = foley::Projection::Perspective;
    view.vrp = view.vpn = view.vup = view.prp = Vec3<double>::Zero();
    view.window = {-1, 1, -1, 1};
    view.front = view.back = 0;
    const std::vector<CameraChoice> foleyChoices = cameraChoices(view);
    ASSERT_EQ(foleyChoices.size(), 1u);
    EXPECT_EQ(foleyChoices[0].field, "view.projection");
    EXPECT_EQ(std::get<foley::ViewSpec<double>>(withChoice(view, "view.projection", 1)).projection,
              foley::Projection::Parallel);
}

TEST(CameraChoices, RefuseWhatTheCameraCannotChoose)
{
    const CameraSpec<double> camera = lookingDownZ(gl::Perspective<double>{60, 1, 1, 10});
    expectRefused([&] { withChoice(camera, "view.projection", 0); }, "view.projection", "not a choice");
    expectRefused([&] { withChoice(camera, "camera.api", 5); }, "camera.api", "no option 5");
    expectRefused([&] { withChoice(camera, "camera.depth", -1); }, "camera.depth", "no option -1");
}

} // namespace
} // namespace viewpipe
