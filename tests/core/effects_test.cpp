// Effects computed only when a scene lists them: homogeneous clipping,
// Foley's M as a stage, back-face culling.

#include "support.hpp"
#include "viewpipe/animation.hpp"
#include "viewpipe/effects.hpp"
#include "viewpipe/evaluated_scene.hpp"
#include "viewpipe/scene.hpp"

namespace viewpipe {
namespace {

Pipeline<double> house()
{
    return buildPipeline(
        foley::ViewSpec<double>{foley::Projection::Perspective, {0, 0, 0}, {0, 0, 1}, {0, 1, 0}, {8, 6, 84}, {-50, 50, -50, 50}, 60, 25});
}

// In the OpenGL clip volume, by hand: the segment from (0, 0, 0, 1) to
// (4, 0, 0, 1) leaves through x = w at t = 1/4 (Liang-Barsky: boundary
// w - x goes from 1 to -3, crossing zero at 1/4).
TEST(Clip, LiangBarskyByHand)
{
    const auto t = clipSegment({0, 0, 0, 1}, {4, 0, 0, 1}, ClipVolume::OpenGL);
    ASSERT_TRUE(t);
    EXPECT_DOUBLE_EQ((*t)[0], 0);
    EXPECT_DOUBLE_EQ((*t)[1], 0.25);
    // Entering through x = -w at t = 1/4 and leaving through y = w at t = 3/4:
    // from (-2, -2, 0, 1) to (2, 2, 0, 1) ... the square corners: boundaries
    // w + x: -1 -> 3 (t = 1/4), w - y: 3 -> -1 (t = 3/4).
    const auto u = clipSegment({-2, -2, 0, 1}, {2, 2, 0, 1}, ClipVolume::OpenGL);
    ASSERT_TRUE(u);
    EXPECT_DOUBLE_EQ((*u)[0], 0.25);
    EXPECT_DOUBLE_EQ((*u)[1], 0.75);
    EXPECT_FALSE(clipSegment({2, 0, 0, 1}, {3, 5, 0, 1}, ClipVolume::OpenGL)); // both beyond x = w
}

TEST(Clip, IsSymmetric)
{
    test::SpecGenerator random(11);
    for (int i = 0; i < 2000; ++i) {
        const Vec4<double> a(random.uniform(-3, 3), random.uniform(-3, 3), random.uniform(-3, 3), random.uniform(-1, 3));
        const Vec4<double> b(random.uniform(-3, 3), random.uniform(-3, 3), random.uniform(-3, 3), random.uniform(-1, 3));
        for (ClipVolume v : {ClipVolume::OpenGL, ClipVolume::FoleyParallel}) {
            const auto ab = clipSegment(a, b, v), ba = clipSegment(b, a, v);
            ASSERT_EQ(ab.has_value(), ba.has_value());
            if (ab) {
                EXPECT_NEAR((*ab)[0], 1 - (*ba)[1], 1e-12);
                EXPECT_NEAR((*ab)[1], 1 - (*ba)[0], 1e-12);
            }
        }
    }
}

// A segment from a point in the volume to one behind the eye crosses w = 0;
// clipped in homogeneous coordinates, what is kept has w > 0 and is inside,
// where dividing first would have thrown the far end to the other side.
TEST(Clip, SegmentCrossingTheEyePlane)
{
    const Vec4<double> inside(0.2, 0.1, 0.5, 1), behind(0.4, 0.2, 1.0, -1);
    const auto t = clipSegment(inside, behind, ClipVolume::OpenGL);
    ASSERT_TRUE(t);
    EXPECT_DOUBLE_EQ((*t)[0], 0);
    EXPECT_LT((*t)[1], 0.5); // w = 1 - 2t reaches 0 at t = 1/2
    const Vec4<double> end = inside + (*t)[1] * (behind - inside);
    EXPECT_GT(end.w(), 0);
    EXPECT_TRUE(insideClipVolume(Vec4<double>(end * (1 - 1e-12) + inside * 1e-12), ClipVolume::OpenGL));
    // A point behind the eye is outside without dividing, whatever x/w, y/w say.
    EXPECT_NE(outcode({0.1, 0.1, 0.5, -1}, ClipVolume::OpenGL), 0u);
}

// Sutherland-Hodgman by hand: the square [-2, 2]^2 (z = 0, w = 1) cut to the
// NDC square [-1, 1]^2.
TEST(Clip, SutherlandHodgmanByHand)
{
    const std::vector<Vec4<double>> square = {{-2, -2, 0, 1}, {2, -2, 0, 1}, {2, 2, 0, 1}, {-2, 2, 0, 1}};
    const std::vector<Vec4<double>> out = clipPolygon(square, ClipVolume::OpenGL);
    ASSERT_EQ(out.size(), 4u);
    for (const Vec4<double>& p : out) {
        EXPECT_DOUBLE_EQ(std::abs(p.x()), 1);
        EXPECT_DOUBLE_EQ(std::abs(p.y()), 1);
    }
    // A triangle with one corner outside x = w becomes a quadrilateral.
    const std::vector<Vec4<double>> triangle = {{0, 0, 0, 1}, {3, 0, 0, 1}, {0, 0.5, 0, 1}};
    EXPECT_EQ(clipPolygon(triangle, ClipVolume::OpenGL).size(), 4u);
}

TEST(Effects, DivideAppendsFoleysM)
{
    const EffectList effects = withEffect({}, EffectKind::Divide, true);
    const Pipeline<double> plain = house();
    const Pipeline<double> p = withEffectStages(plain, effects);
    ASSERT_EQ(p.stages.size(), 6u);
    EXPECT_EQ(p.stages[4].symbol(), "S_per");
    EXPECT_EQ(p.stages[5].symbol(), "M");
    EXPECT_TRUE(p.stages[5].matrix.isApprox(plain.toClip));
    EXPECT_TRUE(p.composite.isApprox(plain.clipMatrix()));
    EXPECT_TRUE(p.toClip.isIdentity());
    // The house vertex (16, 10, 54) lands where trace says, either way.
    EXPECT_TRUE(tracePoint(p, {16, 10, 54}).divided->isApprox(*tracePoint(plain, {16, 10, 54}).divided));
}

// OpenGL's divide is a stage of its own but no matrix: the trace divides
// there. Pictures draw every stage divided by w, so P_depth is pictured the
// same with the divide effect or without it, and the divide leaves the
// picture as it was.
TEST(Effects, OpenGlDivideIsAStageThatDivides)
{
    const gl::Camera<double> camera{{{0, 0, 0}, {0, 0, -1}, {0, 1, 0}}, gl::Perspective<double>{60, 1, 1, 10}};
    const Pipeline<double> plain = buildPipeline(CameraSpec<double>{camera});
    const Pipeline<double> p = withEffectStages(plain, withEffect({}, EffectKind::Divide, true));
    ASSERT_EQ(p.stages.size(), plain.stages.size() + 1);
    const Stage<double>& divide = p.stages.back();
    EXPECT_TRUE(divide.divides());
    EXPECT_TRUE(divide.matrix.isIdentity()); // products unchanged
    // gluPerspective(60, 1, 1, 10) takes (0, 0, -5) to clip (0, 0, 35/9, 5): z = -(11/9)(-5) - 20/9.
    const PointTrace<double> t = tracePoint(p, {0, 0, -5});
    EXPECT_TRUE(t.afterStage[p.stages.size() - 2].isApprox(Vec4<double>(0, 0, 35.0 / 9, 5)));
    EXPECT_TRUE(t.afterStage.back().isApprox(Vec4<double>(0, 0, 7.0 / 9, 1))); // divided
    EXPECT_TRUE(t.clip.isApprox(Vec4<double>(0, 0, 35.0 / 9, 5)));           // clip coordinates stay undivided
    const double pDepth = double(plain.stages.size());
    for (const double position : {pDepth - 0.5, pDepth})
        EXPECT_EQ(cumulativeAt(p.stages, position), cumulativeAt(plain.stages, position)) << position;
    EXPECT_EQ(cumulativeAt(p.stages, pDepth + 0.5), cumulativeAt(p.stages, pDepth));
    EXPECT_EQ(cumulativeAt(p.stages, pDepth + 1), plain.composite);
    EXPECT_FALSE(keepsShape(divide)); // framed on its own (as P_depth is), no ghost
    EXPECT_FALSE(ghostAt(p.stages, int(pDepth) + 1));
}

// The outcomes record the effects whose code ran: only the listed ones.
TEST(Effects, OnlyListedEffectsRun)
{
    const Pipeline<double> p = house();
    const std::vector<PolygonMesh> objects = {houseMesh()};
    const EffectOutcomes none = runEffects(p, objects, EffectList{});
    EXPECT_TRUE(none.computed.empty());
    EXPECT_FALSE(none.clip || none.cull || none.depth || none.raster);
    const EffectOutcomes clipped = runEffects(p, objects, withEffect({}, EffectKind::Clip, true));
    EXPECT_EQ(clipped.computed, std::vector<EffectKind>{EffectKind::Clip});
    EXPECT_TRUE(clipped.clip && !clipped.cull);

    // In a scene, the divide runs as the pipeline is built, before the effects that look at the objects.
    const std::string view = R"("view": {"projection": "perspective", "vrp": [0, 0, 0], "vpn": [0, 0, 1],
        "vup": [0, 1, 0], "prp": [8, 6, 84], "window": [-50, 50, -50, 50], "front": 60, "back": 25})";
    const auto listed = evaluateScene(parseScene("{" + view + R"(, "effects": ["cull", "divide", "clip"]})", "."));
    EXPECT_EQ(listed->outcomes.computed,
              (std::vector<EffectKind>{EffectKind::Divide, EffectKind::Clip, EffectKind::Cull}));
    EXPECT_FALSE(listed->outcomes.depth || listed->outcomes.raster);
    EXPECT_EQ(listed->pipeline.stages.back().symbol(), "M");
    const auto undivided = evaluateScene(parseScene("{" + view + R"(, "effects": ["raster"]})", "."));
    EXPECT_EQ(undivided->outcomes.computed, std::vector<EffectKind>{EffectKind::Raster});
    EXPECT_EQ(undivided->pipeline.stages.back().symbol(), "S_per");
}

// The house lies inside the default view volume: nothing is clipped. Moving
// the front plane to n = 40 cuts the house (which spans n = 30 to 54).
TEST(Effects, ClipCountsForTheHouse)
{
    const EffectList clip = withEffect({}, EffectKind::Clip, true);
    const std::vector<PolygonMesh> objects = {houseMesh()};
    const EffectOutcomes all = runEffects(house(), objects, clip);
    EXPECT_EQ(all.clip->segments.inside, 15);
    EXPECT_EQ(all.clip->segments.clipped + all.clip->segments.outside, 0);
    EXPECT_EQ(all.clip->polygons.inside, 7);
    const Pipeline<double> cut = buildPipeline(
        foley::ViewSpec<double>{foley::Projection::Perspective, {0, 0, 0}, {0, 0, 1}, {0, 1, 0}, {8, 6, 84}, {-50, 50, -50, 50}, 40, 25});
    const EffectOutcomes part = runEffects(cut, objects, clip);
    EXPECT_EQ(part.clip->segments.inside, 5);   // the back wall (z = 30)
    EXPECT_EQ(part.clip->segments.clipped, 5);  // the five edges from z = 30 to z = 54
    EXPECT_EQ(part.clip->segments.outside, 5);  // the front wall (z = 54)
    EXPECT_EQ(part.clip->polygons.outside, 1);  // the front wall
    EXPECT_EQ(part.clip->polygons.clipped, 5);  // the sides
    EXPECT_EQ(part.clip->polygons.inside, 1);   // the back wall
}

// Seen from the PRP (8, 6, 84) in front of the house, the front wall faces
// the viewer and the back wall does not; of the five sides, the viewer at
// x = 8, y = 6 sees the ones whose outward normals point toward it.
TEST(Effects, CullBackFaces)
{
    const EffectList cull = withEffect({}, EffectKind::Cull, true);
    const EffectOutcomes o = runEffects(house(), {houseMesh()}, cull);
    ASSERT_TRUE(o.cull);
    EXPECT_EQ(o.cull->faces, 7);
    const std::vector<bool>& culled = o.cull->culledFaces[0];
    EXPECT_FALSE(culled[0]); // front wall, normal +z toward the viewer
    EXPECT_TRUE(culled[1]);  // back wall
    EXPECT_TRUE(culled[2]);  // floor (y = 0, normal -y; the eye is above it at y = 6)
    // From x = 8, between them, the walls x = 16 (normal +x) and x = 0
    // (normal -x) both face away.
    EXPECT_TRUE(culled[3]); // right wall x = 16
    EXPECT_TRUE(culled[6]); // left wall x = 0
}

TEST(Effects, SceneListsAndRefuses)
{
    const std::string view = R"("view": {"projection": "perspective", "vrp": [0, 0, 0], "vpn": [0, 0, 1],
        "vup": [0, 1, 0], "prp": [8, 6, 84], "window": [-50, 50, -50, 50], "front": 60, "back": 25})";
    const Scene s = parseScene("{" + view + R"(, "effects": ["clip", {"divide": {}}, "cull"]})", ".");
    EXPECT_EQ(s.effects.listed, (std::vector<EffectKind>{EffectKind::Clip, EffectKind::Divide, EffectKind::Cull}));
    EXPECT_NE(sceneToJson(s).find("\"clip\""), std::string::npos);
    auto refused = [&](const std::string& effects, const std::string& field, const std::string& reason) {
        test::expectRefused([&] { parseScene("{" + view + ", \"effects\": " + effects + "}", "."); }, field, reason);
    };
    refused(R"(["glow"])", "effects[0]", "unknown effect \"glow\" (known: clip, divide, depth, raster, cull)");
    refused(R"(["clip", "clip"])", "effects[1]", "listed twice");
    refused(R"([{"clip": {"planes": 4}}])", "effects[0].clip.planes", "unknown parameter");
    refused(R"([{"raster": {"width": 0}}])", "effects[0].raster.width", "1 to 4096");
    refused(R"([{"raster": {"dpi": 2}}])", "effects[0].raster.dpi", "unknown parameter (width, height)");
    refused(R"([{"depth": {"bits": 20}}])", "effects[0].depth.bits", "must be 16, 24 or 32");
    refused(R"([{"depth": {"format": "float", "bits": 16}}])", "effects[0].depth.bits", "float depth buffer has 32 bits");
    refused(R"([{"depth": {"format": "half"}}])", "effects[0].depth.format", "\"unorm\" or \"float\"");
    refused(R"([{"depth": {"reversed": 1}}])", "effects[0].depth.reversed", "true or false");
    const Scene depth = parseScene("{" + view + R"(, "effects": [{"depth": {"format": "float", "reversed": true}}]})", ".");
    EXPECT_EQ(depth.effects.depth->bits, 32);
    EXPECT_TRUE(depth.effects.depth->floating && depth.effects.depth->reversed);
    refused(R"([3])", "effects[0]", "effect name");
}

} // namespace
} // namespace viewpipe

namespace viewpipe {
namespace {

// The depth-resolution formula against measured quantization: for
// gluPerspective, window depth d(s) = f (s - n) / ((f - n) s) at eye distance
// s, so one level of a b-bit buffer spans ds = (f - n) s^2 / (f n (2^b - 1)).
TEST(Depth, ResolutionFollowsTheFormula)
{
    const double n = 1, f = 1000;
    const gl::Camera<double> camera{{{0, 0, 0}, {0, 0, -1}, {0, 1, 0}}, gl::Perspective<double>{60, 1, n, f}};
    const Pipeline<double> p = buildPipeline(camera);
    for (int bits : {16, 24}) {
        EffectList effects;
        effects.depth = DepthOptions{bits, false, false};
        effects = withEffect(effects, EffectKind::Depth, true);
        const DepthOutcome d = *runEffects(p, {}, effects).depth;
        ASSERT_EQ(d.resolution.size(), 9u);
        for (const DepthSample& sample : d.resolution) {
            const double s = n + sample.distance;
            const double formula = (f - n) * s * s / (f * n * (std::ldexp(1.0, bits) - 1));
            EXPECT_EQ(sample.pastFar, sample.step >= f - s - 1e-9 * f) << bits << " bits at " << s;
            if (formula > 0.5 * (f - s))
                continue; // the level runs past the far plane
            // First order in the level's width: a level of width ds changes s^2 by about 2 ds / s.
            EXPECT_NEAR(sample.step / formula, 1, 0.01 + 3 * formula / s) << bits << " bits at " << s;
        }
    }
    // A 32-bit float buffer, reversed, resolves the far range far better than 24-bit fixed point.
    EffectList fixed, reversed;
    fixed.depth = DepthOptions{24, false, false};
    reversed.depth = DepthOptions{32, true, true};
    const double fixedStep = runEffects(p, {}, fixed).depth->resolution[7].step;
    const double floatStep = runEffects(p, {}, reversed).depth->resolution[7].step;
    EXPECT_LT(floatStep, fixedStep / 100);
}

// Two walls 1 mm apart, 300 units away: a 16-bit buffer cannot order them; a
// reversed 32-bit float buffer can.
TEST(Depth, FlagsZFighting)
{
    const gl::Camera<double> camera{{{0, 0, 0}, {0, 0, -1}, {0, 1, 0}}, gl::Perspective<double>{60, 1, 0.1, 1000}};
    const Pipeline<double> p = buildPipeline(camera);
    const std::vector<PolygonMesh> walls = {boxMesh({-50, -50, -301}, {50, 50, -300}),
                                            boxMesh({-20, -20, -300.001}, {20, 20, -299.001})};
    EffectList effects;
    effects.depth = DepthOptions{16, false, false};
    EXPECT_FALSE(runEffects(p, walls, effects).depth->zFighting.empty());
    effects.depth = DepthOptions{32, true, true};
    EXPECT_TRUE(runEffects(p, walls, effects).depth->zFighting.empty());
}

// The level stored for a point at eye distance s, against window depth
// d(s) = f (s - n) / ((f - n) s) of gluPerspective written out by hand.
TEST(Depth, LevelsAtPoints)
{
    const double n = 1, f = 100;
    const gl::Camera<double> camera{{{0, 0, 0}, {0, 0, -1}, {0, 1, 0}}, gl::Perspective<double>{60, 1, n, f}};
    const Pipeline<double> p = buildPipeline(camera);
    const DepthOptions unorm16{16, false, false};
    for (double s : {1.5, 2.0, 10.0, 37.0, 99.0}) {
        const double d = f * (s - n) / ((f - n) * s);
        const std::optional<double> level = depthLevelAt(p.clipMatrix(), p.clipVolume, {0.1, -0.2, -s}, unorm16);
        ASSERT_TRUE(level) << s;
        EXPECT_EQ(*level, std::nearbyint(d * 65535)) << s;
    }
    // Nothing is stored for points before the near plane, past the far plane or behind the eye.
    EXPECT_FALSE(depthLevelAt(p.clipMatrix(), p.clipVolume, {0, 0, -0.5}, unorm16));
    EXPECT_FALSE(depthLevelAt(p.clipMatrix(), p.clipVolume, {0, 0, -101}, unorm16));
    EXPECT_FALSE(depthLevelAt(p.clipMatrix(), p.clipVolume, {0, 0, 5}, unorm16));
    // Float levels are the bit patterns: neighbouring floats are one level apart, in order.
    const DepthOptions float32{32, true, false};
    const float half = 0.5f;
    EXPECT_EQ(depthLevel(std::nextafter(half, 1.0f), float32) - depthLevel(half, float32), 1);
    EXPECT_LT(depthLevel(0.25, float32), depthLevel(0.5, float32));
    EXPECT_EQ(depthLevel(0.25, {32, true, true}), depthLevel(0.75, float32)); // reversed: 1 - d
    EXPECT_EQ(depthLevel(0.5, unorm16), storedDepth(0.5, unorm16));
}

// Bands hold a power of two of levels and the fewest that fit the count.
TEST(Depth, BandsCoverTheLevels)
{
    const DepthBands one = depthBands(100, 120, 32);
    EXPECT_EQ(one.levelsPerBand, 1);
    EXPECT_EQ(one.first, 100);
    EXPECT_EQ(one.count, 21);
    const DepthBands wide = depthBands(1000, 60000, 24);
    EXPECT_EQ(wide.levelsPerBand, 4096); // 2048 would need 30 bands
    EXPECT_LE(wide.first, 1000);
    EXPECT_GT(wide.first + wide.count * wide.levelsPerBand, 60000);
    EXPECT_LE(wide.count, 24);
    EXPECT_GT(depthBands(1000, 60000, 30).count, 24);
}

// The resolution curve is the outcome's, sampled more densely: its 9-sample
// form is the one `pipeline --json` reports, and the step grows with distance.
TEST(Depth, ResolutionCurve)
{
    const gl::Camera<double> camera{{{0, 0, 0}, {0, 0, -1}, {0, 1, 0}}, gl::Perspective<double>{60, 1, 1, 1000}};
    const Pipeline<double> p = buildPipeline(camera);
    EffectList effects = withEffect({}, EffectKind::Depth, true);
    const DepthOutcome outcome = *runEffects(p, {}, effects).depth;
    const std::vector<DepthSample> nine = depthResolution(p, *effects.depth, 9);
    ASSERT_EQ(nine.size(), outcome.resolution.size());
    for (std::size_t k = 0; k < nine.size(); ++k)
        EXPECT_EQ(nine[k].step, outcome.resolution[k].step);
    const std::vector<DepthSample> curve = depthResolution(p, *effects.depth, 65);
    ASSERT_EQ(curve.size(), 65u);
    EXPECT_EQ(curve[8].distance, nine[1].distance);
    for (std::size_t k = 1; k < curve.size(); ++k)
        EXPECT_GT(curve[k].step, curve[k - 1].step);
}

// Turning effects on and off keeps the list's order and the flags in step;
// parameters set before turning an effect on are kept.
TEST(Effects, TurnedOnAndOff)
{
    EffectList list = withEffect(withEffect({}, EffectKind::Clip, true), EffectKind::Cull, true);
    EXPECT_EQ(list.listed, (std::vector<EffectKind>{EffectKind::Clip, EffectKind::Cull}));
    EXPECT_TRUE(list.has(EffectKind::Clip) && list.has(EffectKind::Cull) && !list.has(EffectKind::Divide));
    list.depth = DepthOptions{16, false, true};
    list = withEffect(list, EffectKind::Depth, true);
    EXPECT_EQ(list.depth->bits, 16);
    EXPECT_TRUE(list.depth->reversed);
    list = withEffect(list, "raster", true); // by name, as a scene lists it
    EXPECT_EQ(list.raster->width, 64);
    list.depth->bits = 24;
    EXPECT_EQ(withEffect(list, EffectKind::Depth, true).listed,
              (std::vector<EffectKind>{EffectKind::Clip, EffectKind::Cull, EffectKind::Depth, EffectKind::Raster}));
    list = withEffect(withEffect(list, EffectKind::Clip, false), EffectKind::Depth, false);
    EXPECT_EQ(list.listed, (std::vector<EffectKind>{EffectKind::Cull, EffectKind::Raster}));
    EXPECT_FALSE(list.has(EffectKind::Clip) || list.depth);
    EXPECT_TRUE(withEffect(list, EffectKind::Raster, false).listed == std::vector<EffectKind>{EffectKind::Cull});
    for (const EffectKind effect :
         {EffectKind::Clip, EffectKind::Divide, EffectKind::Cull, EffectKind::Depth, EffectKind::Raster})
        EXPECT_EQ(effectNamed(effectName(effect), "effects"), effect);
    try {
        withEffect(list, "fog", true);
        ADD_FAILURE() << "fog is not an effect";
    } catch (const InputError& e) {
        EXPECT_EQ(e.field(), "effects");
        EXPECT_NE(std::string(e.reason()).find("fog"), std::string::npos);
    }
}

TEST(Depth, StoredValues)
{
    EXPECT_EQ(storedDepth(0.5, {16, false, false}), std::nearbyint(0.5 * 65535));
    EXPECT_EQ(storedDepth(0.25, {16, false, true}), std::nearbyint(0.75 * 65535));
    EXPECT_EQ(storedDepth(1.0 / 3, {32, true, false}), double(float(1.0 / 3)));
    EXPECT_EQ(windowDepth({0, 0, -1, 1}, ClipVolume::OpenGL), 0);   // near
    EXPECT_EQ(windowDepth({0, 0, 0, 1}, ClipVolume::FoleyParallel), 0); // Foley's front
    EXPECT_EQ(windowDepth({0, 0, -2, 2}, ClipVolume::FoleyParallel), 1); // Foley's back
}

} // namespace
} // namespace viewpipe

namespace viewpipe {
namespace {

// A square covering x, y in [-0.5, 0.5] of NDC covers the middle half of a
// 64 x 48 image in each direction: 32 x 24 pixels, by hand.
TEST(Raster, SquareByHand)
{
    const gl::Camera<double> camera{{{0, 0, 0}, {0, 0, -1}, {0, 1, 0}}, gl::Ortho<double>{-2, 2, -2, 2, 0.5, 10}};
    const Pipeline<double> p = buildPipeline(camera);
    const PolygonMesh square{{{-1, -1, -5}, {1, -1, -5}, {1, 1, -5}, {-1, 1, -5}}, {{0, 1, 2, 3}}};
    const RasterOutcome r = rasterize(p, {square}, {64, 48});
    EXPECT_EQ(r.covered, 32 * 24);
    EXPECT_EQ(r.object[std::size_t(24 * 64 + 32)], 0);  // the center
    EXPECT_EQ(r.object[0], -1);                          // a corner
    // A nearer square in front hides the first where they overlap.
    const PolygonMesh front{{{0, 0, -2}, {3, 0, -2}, {3, 3, -2}, {0, 3, -2}}, {{0, 1, 2, 3}}};
    const RasterOutcome both = rasterize(p, {square, front}, {64, 48});
    EXPECT_EQ(both.object[std::size_t(36 * 64 + 40)], 1); // upper right: the front square
    EXPECT_EQ(both.object[std::size_t(18 * 64 + 24)], 0); // lower left: the first square
}

} // namespace
} // namespace viewpipe
