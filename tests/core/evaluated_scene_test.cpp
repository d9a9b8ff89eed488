// The evaluated scene: what every picture reads. Checked against Foley's
// house (CGPP ch. 6: VRP at the origin, VPN +z, PRP (8, 6, 84), window
// [-50, 50]^2, F = 60, B = 25, z_min = -24/59... see foley_test), against
// invariants of the normalizing transformation, and for the mesh cache.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <set>

#include "build_paths.h"
#include "evaluation_count.h"
#include "support.hpp"
#include "viewpipe/evaluated_scene.hpp"

namespace viewpipe {
namespace {

namespace fs = std::filesystem;

Scene house()
{
    return loadScene(std::string(viewpipe::build::dataDir) + "/scenes/house.json");
}

const Label& labelNamed(const EvaluatedScene& scene, const std::string& text)
{
    for (const Label& label : scene.labels)
        if (label.text == text)
            return label;
    ADD_FAILURE() << "no label " << text;
    static const Label none{Element::Objects, "", Vec3<double>::Zero()};
    return none;
}

std::vector<const Primitive*> primitivesOf(const EvaluatedScene& scene, Element element, PrimitiveKind kind)
{
    std::vector<const Primitive*> found;
    for (const Primitive& p : scene.primitives)
        if (p.element == element && p.kind == kind)
            found.push_back(&p);
    return found;
}

void expectNear(const Vec3<double>& a, const Vec3<double>& b, double tolerance = 1e-12)
{
    EXPECT_LE((a - b).norm(), tolerance) << a.transpose() << " vs " << b.transpose();
}

TEST(EvaluatedScene, HouseLabelsSitOnTheirElements)
{
    const auto scene = evaluateScene(house());
    expectNear(labelNamed(*scene, "VRP").anchor, Vec3<double>(0, 0, 0));
    expectNear(labelNamed(*scene, "PRP").anchor, Vec3<double>(8, 6, 84));
    expectNear(labelNamed(*scene, "CW").anchor, Vec3<double>(0, 0, 0)); // the window [-50, 50]^2 is centered on VRP
    // The DOP runs from the PRP to CW; its label sits 30% of the way.
    expectNear(labelNamed(*scene, "DOP").anchor, Vec3<double>(8, 6, 84) + 0.3 * Vec3<double>(-8, -6, -84));
    // The front plane's label at a corner of the front face, z = F = 60.
    EXPECT_DOUBLE_EQ(labelNamed(*scene, "front ($F$)").anchor.z(), 60);
    EXPECT_DOUBLE_EQ(labelNamed(*scene, "back ($B$)").anchor.z(), 25);
}

TEST(EvaluatedScene, EveryElementOfTheSetUpIsThere)
{
    const auto scene = evaluateScene(house());
    std::set<Element> elements;
    for (const Primitive& p : scene->primitives) {
        elements.insert(p.element);
        EXPECT_FALSE(p.bounds.isEmpty());
    }
    for (const Marker& m : scene->markers) // the PRP is a point: a marker only
        elements.insert(m.element);
    for (Element e : {Element::Objects, Element::WorldAxes, Element::ViewAxes, Element::Prp, Element::Window,
                      Element::Dop, Element::Volume, Element::FrontPlane, Element::BackPlane, Element::Projectors,
                      Element::Canonical})
        EXPECT_TRUE(elements.count(e)) << int(e);
    // The house's faces shared with the mesh it was made from, its edges once each.
    const auto faces = primitivesOf(*scene, Element::Objects, PrimitiveKind::Faces);
    ASSERT_EQ(faces.size(), 1u);
    EXPECT_EQ(faces[0]->faces, scene->meshes[0]);
    const auto edges = primitivesOf(*scene, Element::Objects, PrimitiveKind::Lines);
    ASSERT_EQ(edges.size(), 1u);
    EXPECT_EQ(edges[0]->segments.size(), 2u * 15u); // 5 + 5 outline edges and 5 joining them
    EXPECT_FALSE(scene->outcomes.clip || scene->outcomes.cull || scene->outcomes.depth || scene->outcomes.raster);
    EXPECT_TRUE(scene->effectsNote.empty());
}

// N_per takes the view volume onto the canonical perspective volume
// (x = +-z, y = +-z, z_min >= z >= -1), and the canonical outline drawn is that volume.
TEST(EvaluatedScene, ViewVolumeMapsOntoTheCanonicalOneDrawn)
{
    const auto scene = evaluateScene(house());
    const double zMin = *scene->pipeline.zmin;
    EXPECT_NEAR(zMin, -24.0 / 59, 1e-15);
    auto onCanonical = [&](const Vec3<double>& q) {
        EXPECT_NEAR(std::abs(q.x()), std::abs(q.z()), 1e-12);
        EXPECT_NEAR(std::abs(q.y()), std::abs(q.z()), 1e-12);
        EXPECT_TRUE(std::abs(q.z() - zMin) < 1e-12 || std::abs(q.z() + 1) < 1e-12) << q.z();
    };
    const auto volume = primitivesOf(*scene, Element::Volume, PrimitiveKind::Lines);
    ASSERT_EQ(volume.size(), 1u);
    for (const Vec3<double>& p : volume[0]->segments)
        onCanonical(scene->pipeline.composite.topRows<3>() * p.homogeneous());
    const auto canonical = primitivesOf(*scene, Element::Canonical, PrimitiveKind::Lines);
    ASSERT_EQ(canonical.size(), 1u);
    EXPECT_TRUE(canonical[0]->canonical);
    EXPECT_EQ(canonical[0]->segments.size(), 24u); // 12 edges
    for (const Vec3<double>& q : canonical[0]->segments)
        onCanonical(q);
}

// 9/10 of the way from the PRP (z = 84) to the front plane (z = F = 60): z <= 62.4 is kept.
TEST(EvaluatedScene, NearCutLiesJustBeforeTheFrontPlane)
{
    const auto scene = evaluateScene(house());
    ASSERT_TRUE(scene->nearCut);
    EXPECT_LE((*scene->nearCut - Vec4<double>(0, 0, -1, 62.4)).norm(), 1e-13);
}

// In perspective every projector passes through the center of projection.
TEST(EvaluatedScene, ProjectorsMeetAtThePrp)
{
    const auto scene = evaluateScene(house());
    const auto projectors = primitivesOf(*scene, Element::Projectors, PrimitiveKind::Lines);
    ASSERT_EQ(projectors.size(), 1u);
    ASSERT_EQ(projectors[0]->segments.size(), 8u);
    for (std::size_t k = 0; k < 8; k += 2) {
        const Vec3<double> a = projectors[0]->segments[k], b = projectors[0]->segments[k + 1];
        const Vec3<double> prp(8, 6, 84);
        EXPECT_LE((b - a).normalized().cross((prp - a).normalized()).norm(), 1e-12);
    }
}

TEST(EvaluatedScene, EffectsAreComputedOnlyWhenListed)
{
    Scene scene = house();
    scene.effects = withEffect(withEffect(scene.effects, "clip", true), "cull", true);
    const auto evaluated = evaluateScene(scene);
    EXPECT_TRUE(evaluated->outcomes.clip && evaluated->outcomes.cull);
    EXPECT_FALSE(evaluated->outcomes.depth || evaluated->outcomes.raster);
    EXPECT_NE(evaluated->effectsNote.find("clip: "), std::string::npos);
    EXPECT_NE(evaluated->effectsNote.find("cull: "), std::string::npos);
    // Culled faces are ghosted apart from the front ones; together they are the house's 7.
    const ObjectFaces& faces = evaluated->objectFaces[0];
    EXPECT_EQ(faces.front->faces.size() + faces.culled->faces.size(), 7u);
    EXPECT_EQ(int(faces.culled->faces.size()), evaluated->outcomes.cull->culled);
}

// An OpenGL camera with far = infinity (exact in the pipeline) is drawn cut short, and says so.
TEST(EvaluatedScene, InfiniteFarPlaneIsDrawnCutShort)
{
    const Scene scene = parseScene(R"({"camera": {"look_at": {"eye": [40, 30, 100], "center": [8, 8, 42], "up": [0, 1, 0]},
        "projection": {"type": "perspective", "fovy_deg": 40, "aspect": 1.5, "near": 30, "far": "infinity"}},
        "objects": [{"type": "house"}]})",
                                   ".");
    const auto evaluated = evaluateScene(scene);
    // gluPerspective's limits as f -> infinity: -(f + n) / (f - n) -> -1, -2 f n / (f - n) -> -2 n.
    EXPECT_EQ((*evaluated->pipeline.projectionMatrix)(2, 2), -1);
    EXPECT_EQ((*evaluated->pipeline.projectionMatrix)(2, 3), -60);
    EXPECT_EQ(labelNamed(*evaluated, "far at infinity (volume cut)").element, Element::BackPlane);
    for (const Primitive& p : evaluated->primitives) {
        EXPECT_TRUE(p.bounds.min().allFinite() && p.bounds.max().allFinite());
        EXPECT_NE(p.element, Element::BackPlane); // no far face: the cut end stays open
    }
}

// What the pictures cannot draw is refused by its field: with a window 1e300 wide, stage 0 was drawn
// without its volume, window, DOP and projectors (projectPoint gave them no image, so the framing and
// the clipping range left them out) under captions and a legend that spoke of them.
TEST(EvaluatedScene, WhatThePicturesCannotDrawIsRefusedByItsField)
{
    auto refusal = [](const Scene& scene) -> std::string {
        try {
            evaluateScene(scene);
        } catch (const InputError& e) {
            return e.what();
        }
        return "";
    };
    Scene wide = house();
    auto& view = std::get<foley::ViewSpec<double>>(wide.camera);
    view.window.umax = 1e300;
    EXPECT_EQ(refusal(wide).rfind("view.window[1]: reaches a coordinate of 1e+300 in world coordinates, beyond the 1e+09 the pictures can draw", 0), 0u) << refusal(wide);
    view.window.umin = -1e300; // from -1e300 to -50: refused on its other end
    view.window.umax = -50;
    EXPECT_EQ(refusal(wide).rfind("view.window[0]: ", 0), 0u) << refusal(wide);
    // 1e8 wide is drawn: every corner of its volume has an image at stage 0.
    view.window = {-50, 1e8, -50, 50};
    const auto drawn = evaluateScene(wide);
    for (const Vec3<double>& corner : drawn->setup.volume)
        EXPECT_TRUE(projectPoint(Mat4<double>::Identity(), corner).has_value());
    // An object far out, by its index; an OpenGL far plane, by its field.
    Scene far = house();
    far.objects.push_back({ObjectType::Box, Vec3<double>(0, 0, 0), Vec3<double>(1, 1, 2e9), "", ""});
    EXPECT_EQ(refusal(far).rfind("objects[1]: reaches a coordinate of 2e+09 in world coordinates", 0), 0u) << refusal(far);
    const Scene deep = parseScene(R"({"camera": {"look_at": {"eye": [40, 30, 100], "center": [8, 8, 42], "up": [0, 1, 0]},
        "projection": {"type": "perspective", "fovy_deg": 40, "aspect": 1.5, "near": 30, "far": 1e12}},
        "objects": [{"type": "house"}]})",
                                  ".");
    EXPECT_EQ(refusal(deep).rfind("camera.projection.far: ", 0), 0u) << refusal(deep);
    // A window far too small is scaled beyond the pictures by S_per: the window is to blame, not
    // the PRP's 84, the largest number (as the message said before).
    Scene tiny = house();
    std::get<foley::ViewSpec<double>>(tiny.camera).window = {0, 2e-300, 0, 2e-300};
    EXPECT_EQ(refusal(tiny).rfind("view.window[1]: reaches a coordinate of ", 0), 0u) << refusal(tiny);
    std::get<foley::ViewSpec<double>>(tiny.camera).window = {50, 50 + 1e-9, -50, 50}; // narrow, its ends not small
    EXPECT_EQ(refusal(tiny).rfind("view.window[1]: ", 0), 0u) << refusal(tiny);
    const Scene nearZero = parseScene(R"({"camera": {"look_at": {"eye": [40, 30, 100], "center": [8, 8, 42], "up": [0, 1, 0]},
        "projection": {"type": "ortho", "left": -1e-300, "right": 1e-300, "bottom": -20, "top": 20, "near": 30, "far": 200}},
        "objects": [{"type": "house"}]})", ".");
    EXPECT_EQ(refusal(nearZero).rfind("camera.projection.", 0), 0u) << refusal(nearZero);
}

class MeshCacheTest : public ::testing::Test {
protected:
    void SetUp() override
    {
        dir_ = fs::temp_directory_path() / ("viewpipe-mesh-cache-" + std::to_string(::getpid()));
        fs::create_directories(dir_);
        write("v 0 0 30\nv 16 0 30\nv 8 16 30\nf 1 2 3\n");
        scene_ = house();
        SceneObject mesh;
        mesh.type = ObjectType::Mesh;
        mesh.path = "triangle.obj";
        mesh.resolvedPath = dir_ / mesh.path;
        scene_.objects.push_back(mesh);
    }
    void TearDown() override { fs::remove_all(dir_); }
    void write(const std::string& text) { std::ofstream(dir_ / "triangle.obj") << text; }

    fs::path dir_;
    Scene scene_;
};

TEST_F(MeshCacheTest, EachMeshFileIsReadOnceWhileItIsUnchanged)
{
    SceneEvaluator evaluator;
    test::EvaluationCount count;
    const ListeningToEvaluations listening(count);
    const auto first = evaluator.evaluate(scene_);
    auto edited = scene_;
    std::get<foley::ViewSpec<double>>(edited.camera).back = 20;
    const auto second = evaluator.evaluate(edited);
    EXPECT_EQ(count.evaluations, 2);
    EXPECT_EQ(count.meshReads, 1);
    EXPECT_EQ(first->meshes[1], second->meshes[1]); // the same mesh, not a copy

    write("v 0 0 30\nv 16 0 30\nv 8 16 30\nv 8 6 50\nf 1 2 3\nf 1 2 4\n"); // a different size: read again
    const auto third = evaluator.evaluate(scene_);
    EXPECT_EQ(count.meshReads, 2);
    EXPECT_EQ(third->meshes[1]->faces.size(), 2u);
    EXPECT_EQ(first->meshes[1]->faces.size(), 1u); // what was drawn before is untouched
}

TEST_F(MeshCacheTest, AFileThatCannotBeReadIsRefusedByItsField)
{
    write("v 0 0 0\nf 1 2 3\n");
    SceneEvaluator evaluator;
    test::expectRefused([&] { evaluator.evaluate(scene_); }, "objects[1].path", "out of range");
    write("v 0 0 30\nv 16 0 30\nv 8 16 30\nf 1 2 3\n"); // mended: read, not taken from a cache
    EXPECT_EQ(evaluator.evaluate(scene_)->meshes[1]->faces.size(), 1u);
}

// Each stage's picture says what the stage achieved, as checked on the set-up.
TEST(EvaluatedScene, StagesClaimWhatTheyAchieve)
{
    // The house: VRP at the origin and VPN along z already, so T(-VRP) and R are identities here.
    const auto house = evaluateScene(loadScene(std::string(viewpipe::build::dataDir) + "/scenes/house.json"));
    EXPECT_EQ(house->stageClaims, (std::vector<std::string>{"", "the identity here: nothing moves",
                                                            "the identity here: nothing moves", "PRP at the origin",
                                                            "DOP along the $z$ axis",
                                                            "sides on $x = \\pm z$, $y = \\pm z$; back at $z = -1$, "
                                                            "front at $z_{\\min} = -\\frac{24}{59}$"}));
    const auto gl = evaluateScene(loadScene(std::string(viewpipe::build::dataDir) + "/scenes/opengl-perspective.json"));
    EXPECT_EQ(gl->stageClaims,
              (std::vector<std::string>{"", "eye at the origin",
                                        "$s, u, -f$ along $x, y, -z$: the eye looks down $-z$; DOP along the $z$ axis",
                                        "sides on $x = \\pm z$, $y = \\pm z$",
                                        "the volume is the cube $-1 \\le x, y, z \\le 1$: near at $z = -1$, far at $z = 1$"}));
    const auto parallel =
        evaluateScene(loadScene(std::string(viewpipe::build::dataDir) + "/scenes/house-parallel-oblique.json"));
    EXPECT_EQ(parallel->stageClaims.back(), "the volume is $-1 \\le x, y \\le 1$, $-1 \\le z \\le 0$");
}

// The canonical volume's planes and two corners are named where they are (not moved by a stage).
TEST(EvaluatedScene, CanonicalVolumeIsLabelled)
{
    const auto scene = evaluateScene(house());
    std::map<std::string, Vec3<double>> at;
    for (const Label& label : scene->labels)
        if (label.element == Element::Canonical) {
            EXPECT_TRUE(label.fixed);
            at[label.text] = label.anchor;
        }
    const double zmin = -24.0 / 59; // Foley's house: z_min = -(PRP_n - F) / (PRP_n - B) = -24/59
    expectNear(at.at("$z = -1$"), Vec3<double>(0, 0, -1));
    expectNear(at.at("$z = z_{\\min}$"), Vec3<double>(0, 0, zmin));
    expectNear(at.at("$x = -z$"), Vec3<double>((-zmin + 1) / 2, 0, (zmin - 1) / 2));
    // The front corner as the textbook writes it (found: 0.407); math: real minus signs.
    expectNear(at.at("$(\\frac{24}{59}, \\frac{24}{59}, -\\frac{24}{59})$"), Vec3<double>(-zmin, -zmin, zmin));
    expectNear(at.at("$(-1, -1, -1)$"), Vec3<double>(-1, -1, -1));
}

// With Divide, the house ends after M in Foley's canonical parallel volume (x, y in [-1, 1], z in [-1, 0]): its planes
// are named as that volume's, not as the perspective one's (x = z, ..., z = z_min).
TEST(EvaluatedScene, TheVolumeAfterMIsNamedAsTheParallelOne)
{
    Scene divided = house();
    divided.effects = withEffect(divided.effects, EffectKind::Divide, true);
    const auto scene = evaluateScene(divided);
    ASSERT_EQ(scene->pipeline.stages.back().symbol(), "M");
    std::map<std::string, Vec3<double>> at;
    for (const Label& label : scene->labels)
        if (label.element == Element::Canonical)
            at[label.text] = label.anchor;
    for (const char* perspective : {"$x = z$", "$x = -z$", "$y = z$", "$y = -z$", "$z = z_{\\min}$"})
        EXPECT_EQ(at.count(perspective), 0u) << perspective;
    expectNear(at.at("$x = 1$"), Vec3<double>(1, 0, -0.5));
    expectNear(at.at("$y = -1$"), Vec3<double>(0, -1, -0.5));
    expectNear(at.at("$z = 0$"), Vec3<double>(0, 0, 0));
    expectNear(at.at("$z = -1$"), Vec3<double>(0, 0, -1));
    expectNear(at.at("$(1, 1, 0)$"), Vec3<double>(1, 1, 0));
}

TEST(EvaluatedScene, PointsAreMarkedWhereTheyAre)
{
    // The house scene: PRP (8, 6, 84); CW at the origin (the window [-50, 50]^2 about VRP); the DOP's head at CW.
    const auto scene = evaluateScene(house());
    ASSERT_EQ(scene->markers.size(), 3u);
    std::map<Element, const Marker*> marker;
    for (const Marker& m : scene->markers)
        marker[m.element] = &m;
    expectNear(marker.at(Element::Prp)->point, Vec3<double>(8, 6, 84));
    expectNear(marker.at(Element::Window)->point, Vec3<double>(0, 0, 0));
    const Marker& head = *marker.at(Element::Dop);
    EXPECT_EQ(head.shape, Marker::Shape::ArrowHead);
    expectNear(head.point, Vec3<double>(0, 0, 0));
    EXPECT_NEAR((head.point - head.from).normalized().dot(Vec3<double>(-8, -6, -84).normalized()), 1, 1e-15);
}

} // namespace
} // namespace viewpipe

