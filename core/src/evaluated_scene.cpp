#include "viewpipe/evaluated_scene.hpp"

#include "viewpipe/exact.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <functional>
#include <limits>
#include <sstream>
#include <system_error>

#include "viewpipe/animation.hpp"
#include "viewpipe/classical.hpp"
#include "viewpipe/format.hpp"
#include "viewpipe/mesh_io.hpp"
#include "seams/evaluation_listener.hpp"

namespace viewpipe {
namespace {

using Segment = std::pair<Vec3<double>, Vec3<double>>;

// Ghosts: how much of an edge clipped away and of a culled face still shows.
constexpr double kClippedOpacity = 0.2;
constexpr double kCulledOpacity = 0.06;

class Builder {
public:
    explicit Builder(EvaluatedScene& out) : out_(out) {}

    Primitive& lines(Element element, const std::vector<Segment>& segments, double opacity, int object = -1)
    {
        Primitive p;
        p.element = element;
        p.kind = PrimitiveKind::Lines;
        p.opacity = opacity;
        p.object = object;
        for (const Segment& s : segments) {
            p.segments.insert(p.segments.end(), {s.first, s.second});
            p.bounds.extend(s.first);
            p.bounds.extend(s.second);
        }
        out_.primitives.push_back(std::move(p));
        return out_.primitives.back();
    }

    Primitive& faces(Element element, std::shared_ptr<const PolygonMesh> mesh, double opacity, int object = -1)
    {
        Primitive p;
        p.element = element;
        p.kind = PrimitiveKind::Faces;
        p.opacity = opacity;
        p.object = object;
        for (const auto& face : mesh->faces)
            for (int k : face)
                p.bounds.extend(mesh->vertices[std::size_t(k)]);
        p.faces = std::move(mesh);
        out_.primitives.push_back(std::move(p));
        return out_.primitives.back();
    }

    Primitive& faces(Element element, PolygonMesh mesh, double opacity)
    {
        return faces(element, std::make_shared<const PolygonMesh>(std::move(mesh)), opacity);
    }

    void marker(const Marker& marker) { out_.markers.push_back(marker); }

    void label(Element element, const std::string& text, const Vec3<double>& anchor, bool fixed = false)
    {
        if (!text.empty())
            out_.labels.push_back({element, text, anchor, fixed});
    }

private:
    EvaluatedScene& out_;
};

std::vector<Segment> meshEdges(const PolygonMesh& mesh)
{
    std::vector<Segment> edges;
    for (const auto& e : meshEdgeIndices(mesh))
        edges.emplace_back(mesh.vertices[std::size_t(e[0])], mesh.vertices[std::size_t(e[1])]);
    return edges;
}

PolygonMesh quad(const Vec3<double>& a, const Vec3<double>& b, const Vec3<double>& c, const Vec3<double>& d)
{
    return {{a, b, c, d}, {{0, 1, 2, 3}}};
}

// The segment that spans collinear points.
Segment span(const std::vector<Vec3<double>>& points)
{
    const Vec3<double> direction = (points.back() - points.front()).normalized();
    auto along = [&](const Vec3<double>& p) { return (p - points.front()).dot(direction); };
    const auto [lo, hi] = std::minmax_element(points.begin(), points.end(),
                                              [&](const auto& a, const auto& b) { return along(a) < along(b); });
    return {*lo, *hi};
}

std::vector<Segment> boxEdges(const std::array<Vec3<double>, 8>& corners)
{
    std::vector<Segment> edges;
    for (std::size_t k = 0; k < 4; ++k) {
        edges.emplace_back(corners[k], corners[(k + 1) % 4]);
        edges.emplace_back(corners[k + 4], corners[(k + 1) % 4 + 4]);
        edges.emplace_back(corners[k], corners[k + 4]);
    }
    return edges;
}

// The lowest and highest level the depth buffer stores on these faces: at the
// vertices (the level is monotonic in eye depth, which is affine across a
// face), and, for a face partly outside the depth range, at points across it.
std::optional<DepthBands> bandsOf(const std::vector<const PolygonMesh*>& meshes, const Pipeline<double>& pipeline,
                                  const DepthOptions& options)
{
    const Mat4<double> clip = pipeline.clipMatrix();
    double low = std::numeric_limits<double>::infinity(), high = -low;
    auto extend = [&](const Vec3<double>& p) {
        if (const std::optional<double> level = depthLevelAt(clip, pipeline.clipVolume, p, options))
            low = std::min(low, *level), high = std::max(high, *level);
    };
    for (const PolygonMesh* mesh : meshes)
        for (const auto& face : mesh->faces) {
            bool partial = false;
            for (int k : face) {
                const Vec3<double>& p = mesh->vertices[std::size_t(k)];
                partial = partial || !depthLevelAt(clip, pipeline.clipVolume, p, options);
                extend(p);
            }
            if (!partial)
                continue;
            constexpr int n = 32;
            const Vec3<double>& a = mesh->vertices[std::size_t(face[0])];
            for (std::size_t t = 1; t + 1 < face.size(); ++t) {
                const Vec3<double>& b = mesh->vertices[std::size_t(face[t])];
                const Vec3<double>& c = mesh->vertices[std::size_t(face[t + 1])];
                for (int i = 0; i <= n; ++i)
                    for (int j = 0; i + j <= n; ++j)
                        extend(a + (double(i) / n) * (b - a) + (double(j) / n) * (c - a));
            }
        }
    if (!(low <= high))
        return std::nullopt;
    return depthBands(low, high, 24);
}

std::string describeEffects(const EffectList& effects, const EffectOutcomes& outcomes, const Pipeline<double>& pipeline,
                            const std::optional<DepthBands>& bands)
{
    std::ostringstream note;
    for (const EffectKind effect : effects.listed) {
        if (effect == EffectKind::Clip && outcomes.clip) {
            const ClipCounts& s = outcomes.clip->segments;
            note << "clip: " << s.inside << " edges inside, " << s.clipped << " cut, " << s.outside
                 << " outside (ghosted)\n";
        } else if (effect == EffectKind::Divide) {
            note << (divideAddsStage(pipeline)
                         ? "divide: stage $" + stageSymbolMath(pipeline.stages.back().kind) + "$ appended\n"
                         : std::string("divide: none needed (parallel)\n"));
        } else if (effect == EffectKind::Cull && outcomes.cull) {
            note << "cull: " << outcomes.cull->culled << " of " << outcomes.cull->faces << " faces (ghosted)\n";
        } else if (effect == EffectKind::Depth && outcomes.depth) {
            const DepthOutcome& d = *outcomes.depth;
            note << "depth: " << depthFormatName(d.options);
            if (bands)
                note << "; each band "
                     << (bands->levelsPerBand == 1 ? std::string("one stored value")
                                                   : std::to_string(std::llround(bands->levelsPerBand)) +
                                                         " stored values");
            if (!d.zFightingChecked)
                note << "; z-fighting not checked (too many faces)";
            else if (!d.zFighting.empty())
                note << "; " << d.zFighting.size() << " face pairs z-fight (orange-red)";
            note << "\n";
        } else if (effect == EffectKind::Raster && outcomes.raster) {
            note << "raster: " << outcomes.raster->width << " x " << outcomes.raster->height << ", "
                 << outcomes.raster->covered << " pixels covered (projected view)\n";
        }
    }
    std::string text = note.str();
    if (!text.empty())
        text.pop_back();
    return text;
}

// Vanishing points, and the edges along each principal axis drawn on to
// theirs, in the picture's coordinates.
std::vector<Segment2> vanishingLines(const CameraSpec<double>& camera, const Pipeline<double>& pipeline,
                                     const std::vector<Segment>& edges)
{
    std::vector<Segment2> picture;
    const Mat4<double> image = screenClipMatrix(pipeline);
    for (int axis = 0; axis < 3; ++axis) {
        if (!vanishingPoint(camera, axis))
            continue;
        const Vec4<double> h = image * Vec4<double>::Unit(axis); // the image of the axis' direction
        const Vec2<double> target = h.head<2>() / h.w();
        const double arm = 0.04;
        picture.push_back({target - Vec2<double>(arm, 0), target + Vec2<double>(arm, 0)});
        picture.push_back({target - Vec2<double>(0, arm), target + Vec2<double>(0, arm)});
        for (const Segment& edge : edges) {
            const Vec3<double> d = (edge.second - edge.first).normalized();
            if (std::abs(std::abs(d[axis]) - 1) > 1e-9)
                continue;
            const std::optional<Vec3<double>> a = projectPoint(image, edge.first), b = projectPoint(image, edge.second);
            if (a && b) {
                picture.push_back({a->head<2>(), target});
                picture.push_back({b->head<2>(), target});
            }
        }
    }
    return picture;
}

// A ring around the z-fighting faces: small and far, they may lie under the vanishing lines.
std::vector<Segment2> ringAround(const std::vector<Vec3<double>>& points, const Mat4<double>& image)
{
    Eigen::AlignedBox<double, 2> spot;
    for (const Vec3<double>& p : points)
        if (const std::optional<Vec3<double>> q = projectPoint(image, p))
            spot.extend(q->head<2>());
    std::vector<Segment2> ring;
    if (spot.isEmpty())
        return ring;
    const double radius = 0.5 * spot.diagonal().norm() + 0.07;
    auto at = [&](int k) -> Vec2<double> {
        return spot.center() + radius * Vec2<double>(std::cos(k * M_PI / 24), std::sin(k * M_PI / 24));
    };
    for (int k = 0; k < 48; ++k)
        ring.push_back({at(k), at(k + 1)});
    return ring;
}

// An infinite far plane has no face to draw: the camera whose volume is
// drawn ends it just past the farthest object (at least four times as far as
// the near plane); `cut` says so. The pipeline keeps the exact infinite one.
CameraSpec<double> drawnCamera(const CameraSpec<double>& camera, const Eigen::AlignedBox<double, 3>& objects, bool& cut)
{
    CameraSpec<double> drawn = camera;
    cut = false;
    auto* gl = std::get_if<gl::Camera<double>>(&drawn);
    if (!gl)
        return drawn;
    const Vec3<double> forward = (gl->lookAt.center - gl->lookAt.eye).normalized();
    std::visit(
        [&](auto& p) {
            if (!std::isinf(p.zFar))
                return;
            double reach = 4 * p.zNear;
            if (!objects.isEmpty())
                for (int k = 0; k < 8; ++k)
                    reach = std::max(reach, 1.2 * (objects.corner(Eigen::AlignedBox<double, 3>::CornerType(k)) -
                                                   gl->lookAt.eye).dot(forward));
            p.zFar = reach;
            cut = true;
        },
        gl->projection);
    return drawn;
}

std::shared_ptr<const PolygonMesh> objectMesh(const SceneObject& object, std::size_t index, MeshCache* cache)
{
    if (object.type == ObjectType::Mesh) {
        const std::string field = "objects[" + std::to_string(index) + "].path";
        if (cache)
            return cache->read(object.resolvedPath, field);
        return std::make_shared<const PolygonMesh>(readMeshFile(object.resolvedPath, field));
    }
    return std::make_shared<const PolygonMesh>(object.type == ObjectType::House ? houseMesh()
                                                                                 : boxMesh(object.min, object.max));
}

// Each object's faces as the effects sort them: in front, culled, or fighting for depth.
std::vector<ObjectFaces> sortFaces(const std::vector<std::shared_ptr<const PolygonMesh>>& meshes,
                                   const EffectOutcomes& outcomes)
{
    std::vector<ObjectFaces> sorted;
    for (std::size_t o = 0; o < meshes.size(); ++o) {
        ObjectFaces sets;
        if (!outcomes.cull && !outcomes.depth) {
            sets.front = meshes[o];
            sorted.push_back(std::move(sets));
            continue;
        }
        std::vector<bool> fighting(meshes[o]->faces.size(), false);
        if (outcomes.depth)
            for (const auto& pair : outcomes.depth->zFighting) {
                if (std::size_t(pair[0]) == o)
                    fighting[std::size_t(pair[1])] = true;
                if (std::size_t(pair[2]) == o)
                    fighting[std::size_t(pair[3])] = true;
            }
        PolygonMesh front, culled, fights;
        front.vertices = culled.vertices = fights.vertices = meshes[o]->vertices;
        for (std::size_t f = 0; f < meshes[o]->faces.size(); ++f) {
            const bool isCulled = outcomes.cull && outcomes.cull->culledFaces[o][f];
            (fighting[f] ? fights : isCulled ? culled : front).faces.push_back(meshes[o]->faces[f]);
        }
        sets.front = std::make_shared<const PolygonMesh>(std::move(front));
        sets.culled = std::make_shared<const PolygonMesh>(std::move(culled));
        sets.fighting = std::make_shared<const PolygonMesh>(std::move(fights));
        sorted.push_back(std::move(sets));
    }
    return sorted;
}

// What the objects' primitives showed, for the labels, marks and legends.
struct ObjectsShown {
    std::vector<Vec3<double>> fighting; // the z-fighting faces' corners
    std::vector<Segment> builtInEdges;  // meshes from files have none drawn
    bool clippedAway = false, culledAway = false;
};

// The objects' faces and edges: ghosts for what was clipped away or culled,
// the faces the depth buffer cannot order outlined.
ObjectsShown addObjects(Builder& add, const EvaluatedScene& out)
{
    const EffectOutcomes& outcomes = out.outcomes;
    ObjectsShown shown;
    for (std::size_t o = 0; o < out.meshes.size(); ++o) {
        const int object = int(o);
        const PolygonMesh& mesh = *out.meshes[o];
        const ObjectFaces& sets = out.objectFaces[o];
        Primitive& front = add.faces(Element::Objects, sets.front, out.bands ? 0.9 : 0.35, object);
        front.depthColored = out.bands.has_value() && !sets.front->faces.empty();
        if (sets.culled && !sets.culled->faces.empty()) {
            add.faces(Element::Objects, sets.culled, kCulledOpacity, object);
            shown.culledAway = true;
        }
        if (sets.fighting && !sets.fighting->faces.empty()) { // outlined: far away they may be a few pixels wide
            add.faces(Element::ZFighting, sets.fighting, 0.8, object);
            add.lines(Element::ZFighting, meshEdges(*sets.fighting), 1.0, object);
            for (const auto& face : sets.fighting->faces)
                for (int k : face)
                    shown.fighting.push_back(sets.fighting->vertices[std::size_t(k)]);
        }
        const std::vector<Segment> edges =
            out.scene.objects[o].type == ObjectType::Mesh ? std::vector<Segment>{} : meshEdges(mesh);
        shown.builtInEdges.insert(shown.builtInEdges.end(), edges.begin(), edges.end());
        if (!outcomes.clip) {
            if (!edges.empty())
                add.lines(Element::Objects, edges, 1.0, object);
            continue;
        }
        std::vector<Segment> kept, away;
        const auto indices = meshEdgeIndices(mesh);
        for (std::size_t e = 0; e < indices.size(); ++e) {
            const Vec3<double>& a = mesh.vertices[std::size_t(indices[e][0])];
            const Vec3<double>& b = mesh.vertices[std::size_t(indices[e][1])];
            const auto& interval = outcomes.clip->keptEdges[o][e];
            if (!interval) {
                away.emplace_back(a, b);
                continue;
            }
            const Vec3<double> p = a + (*interval)[0] * (b - a), q = a + (*interval)[1] * (b - a);
            kept.emplace_back(p, q);
            if ((*interval)[0] > 0)
                away.emplace_back(a, p);
            if ((*interval)[1] < 1)
                away.emplace_back(q, b);
        }
        add.lines(Element::Objects, kept, 1.0, object);
        if (!away.empty()) {
            add.lines(Element::Objects, away, kClippedOpacity, object);
            shown.clippedAway = true;
        }
    }
    if (!shown.fighting.empty()) {
        Eigen::AlignedBox<double, 3> spot;
        for (const Vec3<double>& p : shown.fighting)
            spot.extend(p);
        add.label(Element::ZFighting, "z-fighting", spot.center());
    }
    return shown;
}

// The canonical volume's planes, named on their faces (math): x = -z ... z = z_min for
// Foley's perspective volume, x = 1 ... z = 0 for its parallel one (also a
// perspective view's after M, with Divide), and the cube of normalized device
// coordinates for OpenGL; and two of its corners (Foley's front ones at z_min as the textbook writes it,
// exactly where it reads so: 24/59, not 0.407).
void addCanonicalLabels(Builder& add, const Pipeline<double>& pipeline, const ViewSetup<double>& setup,
                        const std::optional<Exact>& exactZmin)
{
    const bool foley = pipeline.convention == Convention::Foley;
    const bool perspective = setup.perspectiveCanonical;
    const auto& c = setup.canonical; // the front face, then the back one, each from (-x, -y) counter-clockwise
    auto center = [&](std::initializer_list<std::size_t> corners) {
        Vec3<double> sum = Vec3<double>::Zero();
        for (std::size_t k : corners)
            sum += c[k];
        return Vec3<double>(sum / double(corners.size()));
    };
    // A camera's planes are named by where its API puts them: z from its depth
    // range, and top and bottom because Vulkan's y points down.
    auto plane = [&](const char* axis, double value, const char* end) {
        return "$" + std::string(axis) + " = " + formatSignificant(value, 3) + "$" +
               (foley || !*end ? "" : std::string(" (") + end + ")");
    };
    const std::vector<std::pair<std::string, Vec3<double>>> planes = {
        {perspective ? "$x = -z$" : plane("x", c[1].x(), ""), center({1, 2, 5, 6})},
        {perspective ? "$x = z$" : plane("x", c[0].x(), ""), center({0, 3, 4, 7})},
        {perspective ? "$y = -z$" : plane("y", c[2].y(), "image top"), center({2, 3, 6, 7})},
        {perspective ? "$y = z$" : plane("y", c[0].y(), "image bottom"), center({0, 1, 4, 5})},
        {perspective ? "$z = z_{\\min}$" : plane("z", c[0].z(), "near"), center({0, 1, 2, 3})},
        {plane("z", c[4].z(), "far"), center({4, 5, 6, 7})}};
    for (const auto& [text, anchor] : planes)
        add.label(Element::Canonical, text, anchor, true);
    const bool exactFront = perspective && foley && pipeline.zmin && exactZmin && exactZmin->readsExactly();
    auto coordinate = [&](double value) {
        if (exactFront && std::abs(value) == std::abs(*pipeline.zmin))
            return (value == *pipeline.zmin ? *exactZmin : -*exactZmin).latex();
        return formatSignificant(value, 3);
    };
    // Two opposite corners with their coordinates: the front face's upper right, the back face's lower left.
    for (const std::size_t k : {std::size_t(2), std::size_t(4)})
        add.label(Element::Canonical,
                  "$(" + coordinate(c[k].x()) + ", " + coordinate(c[k].y()) + ", " + coordinate(c[k].z()) + ")$", c[k],
                  true);
}

// The viewing set-up: the world and view axes, VRP, PRP, the window and CW,
// the DOP, the view volume with its planes, the projectors, the canonical volume.
void addSetUp(Builder& add, const EvaluatedScene& out, bool farCut, const std::optional<Exact>& exactZmin)
{
    const ViewSetup<double>& setup = out.setup;
    const double axis = 0.15 * out.size;
    const double worldAxis = 1.5 * axis; // longer than the VRC axes, which may start at the same point
    const Vec3<double> o = Vec3<double>::Zero();
    add.lines(Element::WorldAxes,
              {{o, Vec3<double>::UnitX() * worldAxis}, {o, Vec3<double>::UnitY() * worldAxis},
               {o, Vec3<double>::UnitZ() * worldAxis}},
              1.0);
    add.label(Element::WorldAxes, "$x$", Vec3<double>::UnitX() * worldAxis);
    add.label(Element::WorldAxes, "$y$", Vec3<double>::UnitY() * worldAxis);
    add.label(Element::WorldAxes, "$z$", Vec3<double>::UnitZ() * worldAxis);

    const bool foley = out.pipeline.convention == Convention::Foley;
    const Vec3<double>& vrp = setup.origin;
    // A left-handed eye's axes: x = up x f = -s, y = u, z = f (glm's lookAtLH calls its x axis s).
    const double mirror = setup.leftHanded ? -1 : 1;
    add.lines(Element::ViewAxes,
              {{vrp, vrp + mirror * setup.axes.u * axis},
               {vrp, vrp + setup.axes.v * axis},
               {vrp, vrp + mirror * setup.axes.n * axis}},
              1.0);
    add.label(Element::ViewAxes, foley ? "$u$" : "$s$", vrp + mirror * setup.axes.u * axis);
    add.label(Element::ViewAxes, foley ? "$v$" : "$u$", vrp + setup.axes.v * axis);
    add.label(Element::ViewAxes, foley ? "$n$" : setup.leftHanded ? "$f$" : "$-f$", vrp + mirror * setup.axes.n * axis);
    if (foley)
        add.label(Element::ViewAxes, "VRP", vrp);

    if (setup.perspective) {
        add.marker({Element::Prp, Marker::Shape::Dot, setup.prp, setup.prp, 7});
        add.label(Element::Prp, foley ? "PRP" : "eye", setup.prp);
    }

    std::vector<Segment> window;
    for (std::size_t k = 0; k < 4; ++k)
        window.emplace_back(setup.window[k], setup.window[(k + 1) % 4]);
    add.lines(Element::Window, window, 1.0);
    add.marker({Element::Window, Marker::Shape::Dot, setup.windowCenter, setup.windowCenter, 5});
    add.label(Element::Window, "CW", setup.windowCenter);

    const Vec3<double> dop = setup.windowCenter - setup.prp;
    add.lines(Element::Dop, {{setup.prp, setup.windowCenter}}, 1.0);
    add.marker({Element::Dop, Marker::Shape::ArrowHead, setup.windowCenter, setup.windowCenter - 0.05 * dop, 6});
    add.label(Element::Dop, "DOP", setup.prp + 0.3 * dop);

    const auto& v = setup.volume;
    PolygonMesh sides;
    sides.vertices.assign(v.begin(), v.end());
    sides.faces = {{0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
    add.faces(Element::Volume, std::move(sides), 0.10);
    add.lines(Element::Volume, boxEdges(v), 0.8);
    add.faces(Element::FrontPlane, quad(v[0], v[1], v[2], v[3]), 0.22);
    if (!farCut) // a volume cut short has no far face: its end stays open
        add.faces(Element::BackPlane, quad(v[4], v[5], v[6], v[7]), 0.22);
    add.label(Element::FrontPlane, foley ? "front ($F$)" : "near", v[3]);
    add.label(Element::BackPlane, foley ? "back ($B$)" : farCut ? "far at infinity (volume cut)" : "far", v[7]);
    add.label(Element::Window, foley ? "window" : "", (setup.window[2] + setup.window[3]) / 2);

    std::vector<Segment> projectors;
    for (std::size_t k = 0; k < 4; ++k) {
        std::vector<Vec3<double>> along = {setup.window[k], v[k], v[k + 4]};
        if (setup.perspective)
            along.push_back(setup.prp);
        projectors.push_back(span(along));
    }
    add.lines(Element::Projectors, projectors, 0.7);
    add.lines(Element::Canonical, boxEdges(setup.canonical), 1.0).canonical = true; // drawn where it is
    addCanonicalLabels(add, out.pipeline, setup, exactZmin);
}

// The legends name what this scene shows, each view its own.
void fillLegends(EvaluatedScene& out, const ObjectsShown& shown, bool farCut)
{
    const bool foley = out.pipeline.convention == Convention::Foley;
    using Swatch = LegendEntry::Swatch;
    std::vector<LegendEntry> effectEntries; // in both views
    if (!shown.fighting.empty())
        effectEntries.push_back({"z-fighting faces", Element::ZFighting, Swatch::Face});
    if (out.bands)
        effectEntries.push_back({"depth bands, near to far", Element::Objects, Swatch::Bands});
    auto& world = out.worldLegend;
    world = {{foley                     ? "VRP and the VRC axes $u, v, n$"
              : out.setup.leftHanded ? "eye axes $s = \\mathit{up} \\times f$, $u, f$ (left-handed)"
                                     : "eye axes $s, u, -f$",
              Element::ViewAxes, Swatch::Line}};
    if (out.setup.perspective)
        world.push_back(
            {foley ? "PRP, center of projection" : "eye, center of projection", Element::Prp, Swatch::Dot});
    world.insert(world.end(), {{"window and its center CW", Element::Window, Swatch::Line},
                               {"DOP, direction of projection", Element::Dop, Swatch::Line},
                               {foley   ? "view volume, back plane ($B$)"
                                : farCut ? "view volume, cut short of its far plane at infinity"
                                         : "view volume, far plane",
                                Element::Volume, Swatch::Line},
                               {foley ? "front plane ($F$)" : "near plane", Element::FrontPlane, Swatch::Face},
                               {"projectors", Element::Projectors, Swatch::Line},
                               {"canonical view volume", Element::Canonical, Swatch::Line}});
    world.insert(world.end(), effectEntries.begin(), effectEntries.end());
    if (shown.clippedAway)
        world.push_back({"clipped away (ghosted)", Element::Objects, Swatch::Line, kClippedOpacity});
    if (shown.culledAway)
        world.push_back({"culled faces (ghosted)", Element::Objects, Swatch::Face, kCulledOpacity});
    auto& projected = out.projectedLegend;
    projected = {{"window", Element::Window, Swatch::Line}};
    if (!out.vanishingLines.empty())
        projected.push_back({"vanishing lines", Element::Vanishing, Swatch::Line});
    projected.insert(projected.end(), effectEntries.begin(), effectEntries.end());
    if (out.outcomes.raster)
        projected.push_back({"raster pixels, a color per object", Element::Objects, Swatch::Pixels});
}

// A fact about the set-up that a stage may make true, checked on the images of its points.
struct Fact {
    std::string text;
    std::function<bool(const std::function<std::optional<Vec3<double>>(const Vec3<double>&)>&)> holds;
};

// Each stage's claims: the facts it makes true. `scale` is the one the facts compare
// within, set here to each stage's volume size.
std::vector<std::string> claimsAtStages(const Pipeline<double>& pipeline, const ViewSetup<double>& s,
                                        const std::vector<Fact>& facts, double& scale)
{
    using Image = std::function<std::optional<Vec3<double>>(const Vec3<double>&)>;
    using V = Vec3<double>;
    std::vector<std::string> claims(pipeline.stages.size() + 1);
    std::vector<bool> before(facts.size());
    for (std::size_t k = 0; k <= pipeline.stages.size(); ++k) {
        const Mat4<double> m = cumulativeAt(pipeline.stages, double(k));
        const Image image = [&](const V& p) { return projectPoint(m, p); };
        scale = 1;
        for (const V& c : s.volume)
            if (const std::optional<V> q = image(c))
                scale = std::max(scale, q->cwiseAbs().maxCoeff());
        for (std::size_t f = 0; f < facts.size(); ++f) {
            const bool now = facts[f].holds(image);
            if (now && !before[f] && k > 0)
                claims[k] += (claims[k].empty() ? "" : "; ") + facts[f].text;
            before[f] = now;
        }
        if (k > 0 && pipeline.stages[k - 1].divides()) // what the last matrix made true still holds, and shows
            claims[k] = claims[k - 1] + (claims[k - 1].empty() ? "" : "; ") +
                        "the picture stays: every stage is drawn divided by w";
        else if (k > 0 && claims[k].empty() && pipeline.stages[k - 1].matrix.isIdentity(0))
            claims[k] = "the identity here: nothing moves";
    }
    return claims;
}

std::vector<std::string> stageClaims(const Pipeline<double>& pipeline, const ViewSetup<double>& s, bool farCut,
                                     const std::optional<Exact>& exactZmin)
{
    using Image = std::function<std::optional<Vec3<double>>(const Vec3<double>&)>;
    using V = Vec3<double>;
    const bool foley = pipeline.convention == Convention::Foley;
    // Equal to within 1e-9 of the volume's size at that stage (or of 1).
    double scale = 1;
    auto same = [&](double a, double b) { return std::abs(a - b) <= 1e-9 * scale; };
    auto corners = [&](const Image& image, const std::function<bool(const V&, std::size_t)>& each) {
        for (std::size_t k = 0; k < 8; ++k) {
            const std::optional<V> c = image(s.volume[k]);
            if (!c || !each(*c, k))
                return false;
        }
        return true;
    };
    auto atOrigin = [&](const V& p) {
        return [&, p](const Image& image) {
            const std::optional<V> q = image(p);
            return q && same(q->norm(), 0);
        };
    };
    std::vector<Fact> facts = {{foley ? "VRP at the origin" : "eye at the origin", atOrigin(s.origin)}};
    if (foley && s.perspective)
        facts.push_back({"PRP at the origin", atOrigin(s.prp)});
    const Mat3<double> eyeRows = s.leftHanded ? Mat3<double>(Vec3<double>(-1, 1, -1).asDiagonal() * s.axes.rotation())
                                              : s.axes.rotation();
    facts.push_back({foley          ? "$u, v, n$ along $x, y, z$"
                     : s.leftHanded ? "$s, u, f$ along $x, y, z$: the eye looks down $+z$"
                                    : "$s, u, -f$ along $x, y, -z$: the eye looks down $-z$",
                     [&](const Image& image) {
                         const std::optional<V> o = image(s.origin);
                         for (int k = 0; k < 3 && o; ++k) {
                             const std::optional<V> tip = image(s.origin + eyeRows.row(k).transpose());
                             if (!tip || !same(((*tip - *o).normalized() - V::Unit(k)).norm(), 0))
                                 return false;
                         }
                         return o.has_value();
                     }});
    facts.push_back({"DOP along the $z$ axis", [&](const Image& image) {
                         const std::optional<V> from = image(s.prp), to = image(s.windowCenter);
                         return from && to && same(from->x(), to->x()) && same(from->y(), to->y()) &&
                                !same(from->z(), to->z());
                     }});
    if (s.perspective)
        facts.push_back({"sides on $x = \\pm z$, $y = \\pm z$", [&](const Image& image) {
                             return corners(image, [&](const V& c, std::size_t) {
                                 return same(std::abs(c.x()), std::abs(c.z())) && same(std::abs(c.y()), std::abs(c.z()));
                             });
                         }});
    if (s.perspective && foley && pipeline.zmin)
        facts.push_back({"back at $z = -1$, front at $z_{\\min} = " +
                             (exactZmin && exactZmin->readsExactly() ? exactZmin->latex()
                                                                     : formatSignificant(*pipeline.zmin, 3)) +
                             "$",
                         [&](const Image& image) {
                             return corners(image, [&](const V& c, std::size_t k) {
                                 return same(c.z(), k < 4 ? *pipeline.zmin : -1.0);
                             });
                         }});
    if (!s.perspective) // T_par's and glOrtho's centring translation
        facts.push_back({foley ? "the front face's center at the origin" : "the volume's center at the origin",
                         [&](const Image& image) {
                             V sum = V::Zero();
                             for (std::size_t k = 0; k < (foley ? 4u : 8u); ++k) {
                                 const std::optional<V> c = image(s.volume[k]);
                                 if (!c)
                                     return false;
                                 sum += *c;
                             }
                             return same(sum.norm() / (foley ? 4 : 8), 0);
                         }});
    if (!s.perspective && foley)
        facts.push_back({"the volume is $-1 \\le x, y \\le 1$, $-1 \\le z \\le 0$", [&](const Image& image) {
                             return corners(image, [&](const V& c, std::size_t k) {
                                 return same(std::abs(c.x()), 1) && same(std::abs(c.y()), 1) && same(c.z(), k < 4 ? 0 : -1);
                             });
                         }});
    // OpenGL's cube after the projection, then the API's volume after the step to its clip coordinates.
    // A volume cut short of its far plane at infinity reaches the sides and the near face; its cut face
    // lies between near and far.
    auto volumeIs = [&](const std::array<V, 8>& canonical) {
        return [&, canonical](const Image& image) {
            return corners(image, [&](const V& c, std::size_t k) {
                if (!farCut || k < 4)
                    return same((c - canonical[k]).norm(), 0);
                const double nearZ = canonical[0].z(), farZ = canonical[4].z();
                return same(c.x(), canonical[k].x()) && same(c.y(), canonical[k].y()) &&
                       (c.z() - nearZ) * (farZ - c.z()) > 0;
            });
        };
    };
    const std::string cut = farCut ? " (far at infinity: the volume drawn is cut short of it)" : "";
    if (!foley) {
        std::array<V, 8> cube;
        for (std::size_t k = 0; k < 8; ++k)
            cube[k] = V((k % 4 == 1 || k % 4 == 2) ? 1 : -1, k % 4 >= 2 ? 1 : -1, k < 4 ? -1 : 1);
        facts.push_back({"the volume is the cube $-1 \\le x, y, z \\le 1$: near at $z = -1$, far at $z = 1$" + cut,
                         volumeIs(cube)});
        if (s.canonical != cube) {
            const double nearZ = s.canonical[0].z(), farZ = s.canonical[4].z();
            facts.push_back({"the volume is $-1 \\le x, y \\le 1$, $" + formatSignificant(std::min(nearZ, farZ), 3) +
                                 " \\le z \\le " + formatSignificant(std::max(nearZ, farZ), 3) + "$" +
                                 (s.canonical[0].y() > 0 ? "; $y$ points down in the image" : "") + cut,
                             volumeIs(s.canonical)});
        }
    }

    return claimsAtStages(pipeline, s, facts, scale);
}

// The camera's number farthest in size from the rest, by its field: what a set-up reaching beyond the
// pictures is refused on. Far larger (a window 1e300 wide), or far smaller: a window 2e-300 wide is
// scaled up by S_per beyond the pictures (blaming the largest number named the PRP's 84). A window's
// width and height count as its upper ends'.
std::string outlyingCameraField(const CameraSpec<double>& camera)
{
    std::vector<std::pair<std::string, double>> sizes; // finite, nonzero
    auto consider = [&](const std::string& name, double value) {
        if (std::isfinite(value) && value != 0)
            sizes.emplace_back(name, std::abs(value));
    };
    auto considerPoint = [&](const std::string& name, const Vec3<double>& v) {
        for (int k = 0; k < 3; ++k)
            consider(name + "[" + std::to_string(k) + "]", v[k]);
    };
    if (const auto* view = std::get_if<foley::ViewSpec<double>>(&camera)) {
        considerPoint("view.vrp", view->vrp);
        considerPoint("view.prp", view->prp);
        const foley::Window<double>& w = view->window;
        const double window[] = {w.umin, w.umax, w.vmin, w.vmax};
        for (int k = 0; k < 4; ++k)
            consider("view.window[" + std::to_string(k) + "]", window[k]);
        consider("view.window[1]", w.umax - w.umin);
        consider("view.window[3]", w.vmax - w.vmin);
        consider("view.front", view->front);
        consider("view.back", view->back);
    } else {
        const auto& gl = std::get<gl::Camera<double>>(camera);
        considerPoint("camera.look_at.eye", gl.lookAt.eye);
        considerPoint("camera.look_at.center", gl.lookAt.center);
        std::visit(
            [&](const auto& p) {
                if constexpr (std::is_same_v<std::decay_t<decltype(p)>, gl::Perspective<double>>) {
                    consider("camera.projection.aspect", p.aspect);
                } else {
                    consider("camera.projection.left", p.left);
                    consider("camera.projection.right", p.right);
                    consider("camera.projection.bottom", p.bottom);
                    consider("camera.projection.top", p.top);
                    consider("camera.projection.right", p.right - p.left);
                    consider("camera.projection.top", p.top - p.bottom);
                }
                consider("camera.projection.near", p.zNear);
                consider("camera.projection.far", p.zFar);
            },
            gl.projection);
    }
    if (sizes.empty())
        return "camera";
    std::vector<double> logs;
    for (const auto& size : sizes)
        logs.push_back(std::log(size.second));
    std::vector<double> sorted = logs;
    std::nth_element(sorted.begin(), sorted.begin() + std::ptrdiff_t(sorted.size() / 2), sorted.end());
    const double typical = sorted[sorted.size() / 2];
    std::size_t outlier = 0;
    for (std::size_t k = 1; k < sizes.size(); ++k)
        if (std::abs(logs[k] - typical) > std::abs(logs[outlier] - typical))
            outlier = k;
    return sizes[outlier].first;
}

// Refuses, by its field, a scene that reaches beyond kDrawnReach at a stage before the divide: the
// pictures would frame and draw it without what lies there (a window 1e300 wide lost its volume, window,
// DOP and projectors) while the captions and legend still spoke of it. An object out there in world
// coordinates is its own field; otherwise the camera sets where things go, by its number farthest in size from the rest.
void requireDrawable(const EvaluatedScene& out)
{
    std::vector<Mat4<double>> undivided{Mat4<double>::Identity()}; // cumulative, each stage before the divide
    for (const Stage<double>& stage : out.pipeline.stages) {
        const Mat4<double> next = stage.matrix * undivided.back();
        if (isProjective(next))
            break;
        undivided.push_back(next);
    }
    // Refused at the first stage where a point has no image, with the largest coordinate there.
    auto requireWithin = [&](const std::vector<Vec3<double>>& points, std::size_t stages, const std::string& field) {
        for (std::size_t stage = 0; stage < stages; ++stage) {
            double farthest = 0;
            for (const Vec3<double>& p : points)
                if (!projectPoint(undivided[stage], p))
                    farthest = std::max(farthest, (undivided[stage] * p.homogeneous()).head<3>().cwiseAbs().maxCoeff());
            if (farthest > 0)
                throw InputError(field, "reaches a coordinate of " + formatNumber(farthest) + " " +
                                            (stage == 0 ? "in world coordinates" : "after " + out.pipeline.stages[stage - 1].symbol()) +
                                            ", beyond the " + formatNumber(kDrawnReach) + " the pictures can draw");
        }
    };
    std::vector<Vec3<double>> corners;
    for (std::size_t k = 0; k < out.meshes.size(); ++k) {
        const Eigen::AlignedBox<double, 3> box = boundsOf({out.meshes[k]});
        const std::size_t from = corners.size();
        for (int c = 0; c < 8 && !box.isEmpty(); ++c)
            corners.push_back(box.corner(Eigen::AlignedBox<double, 3>::CornerType(c)));
        requireWithin({corners.begin() + std::ptrdiff_t(from), corners.end()}, 1, "objects[" + std::to_string(k) + "]");
    }
    const ViewSetup<double>& s = out.setup;
    corners.insert(corners.end(), s.volume.begin(), s.volume.end());
    corners.insert(corners.end(), s.window.begin(), s.window.end());
    corners.insert(corners.end(), {s.windowCenter, s.origin, s.prp});
    requireWithin(corners, undivided.size(), outlyingCameraField(out.scene.camera));
}

std::shared_ptr<const EvaluatedScene> evaluate(const Scene& scene, MeshCache* cache)
{
    auto evaluated = std::make_shared<EvaluatedScene>();
    EvaluatedScene& out = *evaluated;
    out.scene = scene;
    std::vector<EffectKind> staged; // the divide runs first, as the pipeline is built
    out.pipeline = buildPipeline(scene.camera, scene.effects, &staged);
    out.meshes = objectMeshes(scene, cache);
    bool farCut = false;
    const CameraSpec<double> drawn = drawnCamera(scene.camera, out.objectBounds(), farCut);
    out.setup = viewSetup(drawn, scene.effects);
    requireDrawable(out);

    // The size of the set-up, for axis lengths and markers.
    Eigen::AlignedBox<double, 3> box = out.objectBounds();
    for (const Vec3<double>& p : out.setup.volume)
        box.extend(p);
    box.extend(out.setup.prp);
    box.extend(out.setup.origin);
    out.size = box.diagonal().norm();
    if (out.setup.perspective) { // just before the near (front) plane, so that its face is never cut
        const Vec3<double> ahead = -out.setup.axes.n;
        const double nearDistance = (out.setup.volume[0] - out.setup.prp).dot(ahead);
        if (nearDistance > 0)
            out.nearCut = Vec4<double>(ahead.x(), ahead.y(), ahead.z(), -ahead.dot(out.setup.prp) - 0.9 * nearDistance);
    }

    std::vector<PolygonMesh> meshes; // the effects take them by value
    if (!scene.effects.empty())
        for (const auto& mesh : out.meshes)
            meshes.push_back(*mesh);
    // The scene as typed, exactly: the clip, cull and z-fighting verdicts near a boundary, and z_min as Foley writes it.
    const bool verdicts = scene.effects.has(EffectKind::Clip) || scene.effects.has(EffectKind::Cull) || scene.effects.depth;
    std::optional<Pipeline<Exact>> exact;
    if (verdicts || out.pipeline.zmin) {
        try {
            exact = exactPipeline(scene);
        } catch (const std::exception&) { // refused exactly where double accepted: double decides
        }
    }
    const Mat4<Exact> exactClip = exact && verdicts ? exact->clipMatrix() : Mat4<Exact>();
    out.outcomes = runEffects(out.pipeline, meshes, scene.effects, exact && verdicts ? &exactClip : nullptr);
    out.outcomes.computed.insert(out.outcomes.computed.begin(), staged.begin(), staged.end());
    out.objectFaces = sortFaces(out.meshes, out.outcomes);
    if (out.outcomes.depth) {
        std::vector<const PolygonMesh*> fronts;
        for (const ObjectFaces& sets : out.objectFaces)
            fronts.push_back(sets.front.get());
        out.bands = bandsOf(fronts, out.pipeline, *scene.effects.depth);
    }

    Builder add(out);
    const ObjectsShown shown = addObjects(add, out);
    addSetUp(add, out, farCut, exact ? exact->zmin : std::nullopt);
    out.vanishingLines = vanishingLines(drawn, out.pipeline, shown.builtInEdges); // x and y do not depend on the far plane
    out.zFightingRing = ringAround(shown.fighting, screenClipMatrix(out.pipeline));
    out.effectsNote = describeEffects(scene.effects, out.outcomes, out.pipeline, out.bands);
    fillLegends(out, shown, farCut);
    out.stageClaims = stageClaims(out.pipeline, out.setup, farCut, exact ? exact->zmin : std::nullopt);
    return evaluated;
}

// The test seam's listener (seams/evaluation_listener.hpp); null: nobody listens.
std::atomic<EvaluationListener*> listening{nullptr};

} // namespace

std::vector<Vec3<double>> EvaluatedScene::objectVertices() const
{
    std::vector<Vec3<double>> vertices;
    for (const auto& mesh : meshes)
        vertices.insert(vertices.end(), mesh->vertices.begin(), mesh->vertices.end());
    return vertices;
}

Eigen::AlignedBox<double, 3> EvaluatedScene::objectBounds() const
{
    return boundsOf(meshes);
}

std::vector<std::shared_ptr<const PolygonMesh>> objectMeshes(const Scene& scene, MeshCache* cache)
{
    std::vector<std::shared_ptr<const PolygonMesh>> meshes;
    for (std::size_t i = 0; i < scene.objects.size(); ++i)
        meshes.push_back(objectMesh(scene.objects[i], i, cache));
    return meshes;
}

Eigen::AlignedBox<double, 3> boundsOf(const std::vector<std::shared_ptr<const PolygonMesh>>& meshes)
{
    Eigen::AlignedBox<double, 3> box;
    for (const auto& mesh : meshes)
        for (const Vec3<double>& p : mesh->vertices)
            box.extend(p);
    return box;
}

std::shared_ptr<const PolygonMesh> MeshCache::read(const std::filesystem::path& file, const std::string& field)
{
    std::error_code error;
    const auto modified = std::filesystem::last_write_time(file, error);
    const std::uintmax_t bytes = error ? 0 : std::filesystem::file_size(file, error);
    if (!error) {
        const auto found = entries_.find(file);
        if (found != entries_.end() && found->second.modified == modified && found->second.bytes == bytes)
            return found->second.mesh;
    }
    if (EvaluationListener* listener = listening.load())
        listener->readingMesh(file);
    auto mesh = std::make_shared<const PolygonMesh>(readMeshFile(file, field)); // reports a missing file
    if (!error)
        entries_[file] = {modified, bytes, mesh};
    return mesh;
}

std::shared_ptr<const EvaluatedScene> SceneEvaluator::evaluate(const Scene& scene)
{
    if (EvaluationListener* listener = listening.load())
        listener->evaluating(scene);
    return viewpipe::evaluate(scene, &cache_);
}

ListeningToEvaluations::ListeningToEvaluations(EvaluationListener& listener)
{
    listening = &listener;
}

ListeningToEvaluations::~ListeningToEvaluations()
{
    listening = nullptr;
}

std::shared_ptr<const EvaluatedScene> evaluateScene(const Scene& scene)
{
    return evaluate(scene, nullptr);
}

std::string stageCaption(const EvaluatedScene& scene, std::size_t k, StageText text)
{
    const auto& stages = scene.pipeline.stages;
    std::string note = k < scene.stageClaims.size() ? scene.stageClaims[k] : "";
    if (k > 0 && framedTogether(stages, int(k)).first == int(k) && !stages[k - 1].divides()) // the divide changes none
        note += std::string(note.empty() ? "" : " ") + "(framed anew: this stage changes sizes)";
    if (shownGhost(scene, int(k)))
        note += std::string(note.empty() ? "" : " ") + "(faint: where it was before)";
    return stageText(stages, k, text) + (note.empty() ? "" : "\n" + note);
}

std::optional<Mat4<double>> shownGhost(const EvaluatedScene& scene, int k)
{
    constexpr double kFarther = 1.2; // the box about both ends at most this much larger than the stage's own
    const std::optional<Mat4<double>> ghost = ghostAt(scene.pipeline.stages, k);
    if (!ghost)
        return std::nullopt;
    std::vector<Vec3<double>> points = {scene.setup.origin, scene.setup.windowCenter};
    if (scene.setup.perspective)
        points.push_back(scene.setup.prp);
    for (const Primitive& p : scene.primitives)
        if (!p.canonical && (p.element == Element::Objects || p.element == Element::Volume) && !p.bounds.isEmpty())
            for (int c = 0; c < 8; ++c)
                points.push_back(p.bounds.corner(Eigen::AlignedBox<double, 3>::CornerType(c)));
    Eigen::AlignedBox<double, 3> own, both;
    const Mat4<double> at = cumulativeAt(scene.pipeline.stages, double(k));
    for (const Vec3<double>& p : points) {
        if (const std::optional<Vec3<double>> q = projectPoint(at, p))
            own.extend(*q);
        if (const std::optional<Vec3<double>> q = projectPoint(*ghost, p))
            both.extend(*q);
    }
    both.extend(own);
    return both.diagonal().norm() <= kFarther * own.diagonal().norm() ? ghost : std::nullopt;
}

bool inFrontOfEye(const Vec4<double>& h)
{
    return h.w() > h.head<3>().cwiseAbs().maxCoeff() / kDrawnReach && h.allFinite();
}

std::optional<Vec3<double>> projectPoint(const Mat4<double>& m, const Vec3<double>& p)
{
    const Vec4<double> h = m * p.homogeneous();
    if (!inFrontOfEye(h))
        return std::nullopt;
    return Vec3<double>(h.head<3>() / h.w());
}

bool isProjective(const Mat4<double>& m)
{
    return m(3, 0) != 0 || m(3, 1) != 0 || m(3, 2) != 0 || m(3, 3) != 1;
}

std::vector<Vec3<double>> pictureWindowOutline(const EvaluatedScene& scene)
{
    const auto& v = scene.setup.volume;
    std::vector<Vec3<double>> border;
    for (std::size_t k = 0; k < 4; ++k)
        border.insert(border.end(), {(v[k] + v[k + 4]) / 2, (v[(k + 1) % 4] + v[(k + 1) % 4 + 4]) / 2});
    return border;
}

double pictureAspect(const EvaluatedScene& scene)
{
    const std::vector<Vec3<double>> border = pictureWindowOutline(scene); // bottom, right, top, left
    const double width = (border[1] - border[0]).norm(), height = (border[3] - border[2]).norm();
    return height > 0 && std::isfinite(width / height) ? width / height : 1;
}

} // namespace viewpipe
