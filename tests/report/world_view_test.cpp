// The world view's framing, motion and camera (world_view.hpp): the camera's
// matrices are gluLookAt's and glFrustum's (the OpenGL 2.1 reference pages,
// through the core's gl.hpp, tested against them on its own); a framed stage
// fills the picture's free area; a step between stages starts and ends
// where the stages at rest are, and moves without jumps.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "build_paths.h"
#include "viewpipe/animation.hpp"
#include "viewpipe/gl.hpp"
#include "viewpipe/report/world_view.hpp"

namespace viewpipe::report {
namespace {

namespace fs = std::filesystem;

std::shared_ptr<const EvaluatedScene> builtIn(const std::string& name)
{
    return evaluateScene(loadScene(fs::path(viewpipe::build::dataDir) / "scenes" / name));
}

double relativeError(const Mat4<double>& a, const Mat4<double>& b)
{
    return (a - b).cwiseAbs().maxCoeff() / std::max(1.0, b.cwiseAbs().maxCoeff());
}

TEST(WorldCamera, ViewIsGluLookAt)
{
    WorldCamera camera;
    camera.position = {3, -2, 5};
    camera.focalPoint = {0.5, 1, -1};
    camera.viewUp = {0.1, 1, 0.2};
    const Mat4<double> expected = gl::lookAt<double>({camera.position, camera.focalPoint, camera.viewUp});
    EXPECT_LT(relativeError(camera.view(), expected), 1e-14) << camera.view() << "\n\n" << expected;
}

TEST(WorldCamera, ProjectionIsGluPerspectiveAndItsWindowCenterShiftsTheFrustum)
{
    WorldCamera camera;
    camera.viewAngle = 40;
    camera.nearPlane = 0.5;
    camera.farPlane = 30;
    const Mat4<double> centered = gl::perspective<double>({40, 16.0 / 9, 0.5, 30});
    EXPECT_LT(relativeError(camera.projection(16.0 / 9), centered), 1e-14);

    // A window center of (cx, cy) is glFrustum with the near window moved by (cx, cy) half-widths.
    camera.windowCenter = {0.25, -0.5};
    const double top = 0.5 * std::tan(20 * M_PI / 180), right = top * 16 / 9;
    const Mat4<double> shifted = gl::frustum<double>({(0.25 - 1) * right, (0.25 + 1) * right, (-0.5 - 1) * top,
                                                      (-0.5 + 1) * top, 0.5, 30});
    EXPECT_LT(relativeError(camera.projection(16.0 / 9), shifted), 1e-14);
}

// Pixels (y down) a world point is drawn at through a camera.
Vec2<double> pixelOf(const WorldCamera& camera, const ViewFit& fit, const Vec3<double>& p)
{
    const Vec4<double> clip = camera.projection(double(fit.width) / fit.height) * camera.view() * p.homogeneous();
    return {(clip.x() / clip.w() + 1) / 2 * fit.width, (1 - clip.y() / clip.w()) / 2 * fit.height};
}

// The picture of what a framing frames, through a camera (pixels).
Eigen::AlignedBox<double, 2> pictureOf(const WorldCamera& camera, const ViewFit& fit, const Framing& framing)
{
    Eigen::AlignedBox<double, 2> picture;
    for (const Vec3<double>& p : framing.points)
        picture.extend(pixelOf(camera, fit, p));
    return picture;
}

TEST(WorldView, AFramedStageFillsTheAreaTheTextLeaves)
{
    const auto scene = builtIn("house.json");
    ViewFit fit;
    fit.sceneArea = {{100, 150}, {900, 700}}; // a caption above, a legend to the right
    const Eigen::AlignedBox<double, 2> area(Vec2<double>(100, 150), Vec2<double>(900, 700));
    for (int k = 0; k <= int(scene->pipeline.stages.size()); ++k) {
        const Framing framing = stageFraming(*scene, k);
        WorldCamera camera;
        frameOn(camera, framing, fit);
        EXPECT_NEAR(camera.direction().dot(WorldCamera{}.direction()), 1, 1e-12) << "the direction is kept";
        // What is framed drawn in the middle of the area, reaching 0.95 of the way to its edges across or up.
        const Eigen::AlignedBox<double, 2> picture = pictureOf(camera, fit, framing);
        EXPECT_LT((picture.center() - area.center()).norm(), 0.02 * 550) << "stage " << k;
        const Vec2<double> filled = picture.sizes().cwiseQuotient(area.sizes());
        EXPECT_LE(filled.maxCoeff(), 0.95 + 1e-9) << "stage " << k;
        EXPECT_GT(filled.maxCoeff(), 0.93) << "stage " << k;
        // Everything drawn lies between the near and far planes.
        for (const Vec3<double>& corner : {framing.drawn.min(), framing.drawn.max()}) {
            const double along = (corner - camera.position).dot(camera.direction());
            EXPECT_LT(camera.nearPlane, along) << "stage " << k;
            EXPECT_GT(camera.farPlane, along) << "stage " << k;
        }
    }
}

// P_depth is pictured one way: clipping-eye-plane lists the divide, and its P_depth is the
// picture and caption it has without the divide effect (the canonical cube, as in depth-corridor),
// while the divide that follows leaves the picture as it was and says so.
TEST(WorldView, PDepthIsPicturedTheSameWithOrWithoutTheDivide)
{
    const auto divided = builtIn("clipping-eye-plane.json");
    Scene plainScene = divided->scene;
    plainScene.effects = withEffect(plainScene.effects, EffectKind::Divide, false);
    const auto plain = evaluateScene(plainScene);
    const int pDepth = int(plain->pipeline.stages.size());
    ASSERT_EQ(divided->pipeline.stages[std::size_t(pDepth - 1)].symbol(), "P_depth");
    ASSERT_EQ(int(divided->pipeline.stages.size()), pDepth + 1);
    for (const FramingMode mode : {FramingMode::Together, FramingMode::PerStage}) {
        const WorldMoment a = stageAtRest(*divided, pDepth, {mode, std::nullopt}), b = stageAtRest(*plain, pDepth, {mode, std::nullopt});
        EXPECT_EQ(a.drawn, b.drawn);
        EXPECT_EQ(a.canonicalOpacity, 1);
        EXPECT_EQ(b.canonicalOpacity, 1);
        EXPECT_TRUE(a.framing.box.isApprox(b.framing.box));
        const WorldMoment after = stageAtRest(*divided, pDepth + 1, {mode, std::nullopt});
        EXPECT_EQ(after.drawn, a.drawn);
        EXPECT_TRUE(after.framing.box.isApprox(a.framing.box));
    }
    EXPECT_EQ(divided->stageClaims[std::size_t(pDepth)], plain->stageClaims[std::size_t(pDepth)]);
    EXPECT_NE(plain->stageClaims[std::size_t(pDepth)].find("cube"), std::string::npos);
    EXPECT_EQ(divided->stageClaims[std::size_t(pDepth + 1)],
              plain->stageClaims[std::size_t(pDepth)] + "; the picture stays: every stage is drawn divided by w");
}

TEST(WorldView, AFramingHoldsEveryFramedElementOfItsStage)
{
    const auto scene = builtIn("house.json");
    const int n = int(scene->pipeline.stages.size());
    for (int k = 0; k <= n; ++k) {
        const WorldMoment moment = stageAtRest(*scene, k);
        const StageShown shown(*scene, moment.drawn, moment.canonicalOpacity);
        for (const Primitive& p : scene->primitives) {
            if (!shown.draws(p) || p.kind != PrimitiveKind::Lines)
                continue;
            for (const Vec3<double>& world : p.segments) {
                const auto q = projectPoint(shown.matrixOf(p), world);
                if (q && shown.shows(world)) {
                    EXPECT_TRUE(moment.framing.drawn.contains(*q)) << "stage " << k << ": " << world.transpose();
                    if (framedElement(p.element)) {
                        EXPECT_TRUE(moment.framing.box.contains(*q)) << "stage " << k << ": " << world.transpose();
                    }
                }
            }
        }
        for (const Marker& marker : scene->markers)
            if (const auto q = projectPoint(moment.drawn, marker.point); q && shown.shows(marker.point)) {
                EXPECT_TRUE(moment.framing.box.contains(*q)) << "stage " << k << ": " << marker.point.transpose();
            }
    }
}

// Every point a stage frames is in the picture's free area, from any direction the user turns the
// view to: the PRP far out in a corner of everything was drawn half outside the app's world view,
// its label left out, when the camera stood as far as a sphere a little smaller than everything.
TEST(WorldView, EveryFramedPointIsInThePictureFromAnyDirection)
{
    const std::vector<ViewFit> fits = {ViewFit{1280, 720, {{25, 100}, {800, 700}}}, ViewFit{490, 905, {}}};
    const std::vector<Vec3<double>> directions = {WorldCamera{}.position, {1, 0, 0}, {0.2, 1, 0.1}, {-1, 0.5, -1}, {0.3, -1, 0.6}};
    int points = 0;
    for (const auto& entry : fs::recursive_directory_iterator(fs::path(viewpipe::build::dataDir) / "scenes")) {
        if (entry.path().extension() != ".json")
            continue;
        const auto scene = evaluateScene(loadScene(entry.path()));
        for (int k = 0; k <= int(scene->pipeline.stages.size()); ++k) {
            const WorldMoment moment = stageAtRest(*scene, k);
            const StageShown shown(*scene, moment.drawn, moment.canonicalOpacity);
            for (const ViewFit& fit : fits)
                for (const Vec3<double>& direction : directions) {
                    SCOPED_TRACE(entry.path().filename().string() + " stage " + std::to_string(k) + " at " +
                                 std::to_string(fit.width) + "x" + std::to_string(fit.height));
                    WorldCamera camera;
                    camera.position = direction;
                    frameOn(camera, moment.framing, fit);
                    const Box2 area = fit.sceneArea.isEmpty() ? Box2{Vec2<double>::Zero(), Vec2<double>(fit.width, fit.height)}
                                                              : fit.sceneArea;
                    for (const Primitive& p : scene->primitives) {
                        if (!shown.draws(p) || !framedElement(p.element) ||
                            (p.kind == PrimitiveKind::Faces && p.faces->vertices.size() > 20000))
                            continue;
                        for (const Vec3<double>& world : p.kind == PrimitiveKind::Lines ? p.segments : p.faces->vertices) {
                            const auto q = projectPoint(shown.matrixOf(p), world);
                            if (!q || !shown.shows(world))
                                continue;
                            const Vec2<double> px = pixelOf(camera, fit, *q);
                            ++points;
                            ASSERT_TRUE(area.grown(0.5).contains(Box2{px, px}))
                                << world.transpose() << " drawn at " << px.transpose() << ", direction " << direction.transpose();
                        }
                    }
                }
        }
    }
    EXPECT_GT(points, 10000);
}

TEST(WorldView, AStepStartsAndEndsAtTheStagesAtRestAndNeverJumps)
{
    for (const std::string name : {"house.json", "house-oblique-view.json", "opengl-perspective.json", "clipping-eye-plane.json"}) {
        const auto scene = builtIn(name);
        const int n = int(scene->pipeline.stages.size());
        for (int k = 1; k <= n; ++k)
            for (const auto& [from, to] : {std::pair{k - 1, k}, std::pair{k, k - 1}}) {
                const StageMotion motion(*scene, from, to);
                const WorldMoment start = motion.at(0), end = motion.at(1);
                const WorldMoment first = stageAtRest(*scene, from), last = stageAtRest(*scene, to);
                const std::string at = name + " " + std::to_string(from) + " -> " + std::to_string(to);
                EXPECT_LT(relativeError(start.drawn, first.drawn), 1e-12) << at;
                EXPECT_LT(relativeError(end.drawn, last.drawn), 1e-12) << at;
                // The camera's aim too.
                const WorldCamera camera;
                auto distance = [&](const Framing& framing) { return fitAim(camera, framing, ViewFit{}).distance; };
                auto focal = [&](const Framing& framing) { return fitAim(camera, framing, ViewFit{}).focalPoint; };
                for (const auto& [moment, rest] : {std::pair{start, first}, std::pair{end, last}}) {
                    EXPECT_LT((moment.framing.center - rest.framing.center).norm(), 1e-12 * rest.framing.radius) << at;
                    EXPECT_NEAR(moment.framing.radius, rest.framing.radius, 1e-12 * rest.framing.radius) << at;
                    EXPECT_NEAR(distance(moment.framing), distance(rest.framing), 1e-12 * distance(rest.framing)) << at;
                    EXPECT_LT((focal(moment.framing) - focal(rest.framing)).norm(), 1e-12 * distance(rest.framing)) << at;
                }
                EXPECT_EQ(start.canonicalOpacity, first.canonicalOpacity) << at;
                EXPECT_EQ(end.canonicalOpacity, last.canonicalOpacity) << at;
                // Smooth phases of at least a fifth of the step each: a hundredth of it changes the
                // framing by at most 1.5 / 0.2 / 100 of the distance between its phases' framings
                // (at most twice the largest radius apart: each holds what the one before held).
                double largest = 0, farthest = 0;
                for (int f = 0; f <= 100; ++f) {
                    largest = std::max(largest, motion.at(f / 100.0).framing.radius);
                    farthest = std::max(farthest, distance(motion.at(f / 100.0).framing));
                }
                for (int f = 0; f < 100; ++f) {
                    const Framing a = motion.at(f / 100.0).framing, b = motion.at((f + 1) / 100.0).framing;
                    EXPECT_LE((a.center - b.center).norm(), 0.075 * 2 * largest) << at << " at " << f;
                    EXPECT_LE(std::abs(a.radius - b.radius), 0.075 * largest) << at << " at " << f;
                    EXPECT_LE(std::abs(distance(a) - distance(b)), 0.075 * farthest) << at << " at " << f;
                    EXPECT_LE((focal(a) - focal(b)).norm(), 0.075 * farthest) << at << " at " << f;
                }
            }
    }
}

TEST(WorldView, AStepWithFixedFramingHoldsItsCamera)
{
    const auto scene = builtIn("house.json");
    const StageFramings framings = stageFramings(*scene, FramingMode::Fixed);
    const std::optional<Framing>& fixed = framings.fixed;
    ASSERT_TRUE(fixed);
    for (int k = 1; k <= int(scene->pipeline.stages.size()); ++k) {
        const StageMotion motion(*scene, k - 1, k, framings);
        for (int f = 0; f <= 10; ++f) {
            const Framing framing = motion.at(f / 10.0).framing;
            EXPECT_EQ(framing.center, fixed->center) << k << " at " << f;
            EXPECT_EQ(framing.radius, fixed->radius) << k << " at " << f;
            // and the camera stands where it stood (the framing's points count throughout)
            for (const Vec3<double>& direction : {WorldCamera{}.position, Vec3<double>(-1, 0.5, -1)}) {
                WorldCamera camera;
                camera.position = direction;
                const CameraAim aim = fitAim(camera, framing, ViewFit{}), held = fitAim(camera, *fixed, ViewFit{});
                EXPECT_DOUBLE_EQ(aim.distance, held.distance) << k << " at " << f;
                EXPECT_EQ(aim.focalPoint, held.focalPoint) << k << " at " << f;
            }
        }
    }
}

// The page's turn, hand-checked: a camera at the origin looking down -z (view the identity, projection
// gluPerspective's of 90 degrees, aspect 1, near 1, far 3: x, y, -z - 2 and -z), its focal point (2, 0, -10),
// drawn at x = 2 / 10 = 0.2 in the picture. Yaw turns about the eye's y, then pitch about its x; a zoom keeps the
// focal point where it is drawn and scales the rest about it.
TEST(TurnedCamera, TurnsAboutTheFocalPointAndZoomsAboutWhereItIsDrawn)
{
    Mat4<double> projection;
    projection << 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, -1, -2, 0, 0, -1, 0;
    const Vec3<double> focal(2, 0, -10);
    const auto eye = [&](double yaw, double pitch, const Vec3<double>& p) {
        return Vec3<double>((turnedCamera(Mat4<double>::Identity(), projection, focal, yaw, pitch, 1).view *
                             p.homogeneous()).head<3>());
    };
    EXPECT_LT((eye(90, 0, {3, 0, -10}) - Vec3<double>(2, 0, -11)).norm(), 1e-12) << "+x turned a quarter about y: -z";
    EXPECT_LT((eye(0, 90, {2, 1, -10}) - Vec3<double>(2, 0, -9)).norm(), 1e-12) << "+y turned a quarter about x: +z";
    EXPECT_LT((eye(90, 90, {3, 0, -10}) - Vec3<double>(2, 1, -10)).norm(), 1e-12) << "yaw first: +x to -z, then to +y";
    EXPECT_LT((eye(30, -20, focal) - focal).norm(), 1e-12) << "the focal point stays";

    const TurnedCamera zoomed = turnedCamera(Mat4<double>::Identity(), projection, focal, 0, 0, 2);
    const auto drawn = [&](const Vec3<double>& p) {
        const Vec4<double> h = zoomed.projection * zoomed.view * p.homogeneous();
        return Vec3<double>(h.head<3>() / h.w());
    };
    EXPECT_LT((drawn(focal) - Vec3<double>(0.2, 0, 0.8 * kTurnedDepthScale)).norm(), 1e-12) << "kept where it was drawn";
    EXPECT_LT((drawn({0, 0, -10}) - Vec3<double>(2 * 0 - 0.2, 0, 0.8 * kTurnedDepthScale)).norm(), 1e-12)
        << "at 0, twice as far from 0.2";
}

// A click picks as the app and the page pick: with the identity as the camera, a vertex at (x, y, z) is drawn at
// pixel ((x + 1) / 2 * 200, (1 - y) / 2 * 100) of a 200 x 100 view; the window's diagonal is 1000 pixels, so a
// vertex counts within 10 of the click.
TEST(PickVertex, NearestWithinAHundredthOfTheWindowThenNearestInDepth)
{
    const Mat4<double> drawn = Mat4<double>::Identity();
    const Vec2<double> size(200, 100), window(600, 800);
    const Vec3<double> behind(0, 0, 0.5), front(0, 0, -0.5), aside(0.05, 0, 0); // aside: 5 pixels right of the others
    const std::vector<Vec3<double>> vertices = {behind, front, aside};
    auto pick = [&](Vec2<double> at, std::optional<Vec4<double>> cut = std::nullopt) {
        return pickVertex(vertices, drawn, size, at, window, cut);
    };
    EXPECT_EQ(pick({100, 50}), front) << "two at the click: the one nearer the eye";
    EXPECT_EQ(pick({106, 50}), aside) << "1 pixel from aside, 6 from the others";
    EXPECT_EQ(pick({100, 59}), front) << "9 pixels off";
    EXPECT_FALSE(pick({100, 61})) << "11 pixels off: beyond a hundredth of the diagonal";
    EXPECT_EQ(pick({100, 50}, Vec4<double>(0, 0, 1, 0)), behind) << "z < 0 cut away";
    EXPECT_FALSE(pickVertex({Vec3<double>(0, 0, 1.5)}, drawn, size, {100, 50}, window, std::nullopt)) << "beyond the far plane";
}

} // namespace
} // namespace viewpipe::report
