#pragma once

// The evaluated scene: everything the pictures of a scene show, computed once
// per accepted edit and only read afterwards by the VTK painter, the panels,
// the export, the CLI's reports and the figure writers. It holds the pipeline
// with its stages, every element as plain 3D primitives in world coordinates
// tagged with what they are, each label with its anchor, the legends, the
// marks of the projected view, and the effects' outcomes. No VTK, no Qt.

#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "viewpipe/effects.hpp"
#include "viewpipe/geometry.hpp"
#include "viewpipe/scene.hpp"
#include "viewpipe/setup.hpp"

namespace viewpipe {

// What a primitive or a label draws. Frame: the axes of the coordinates the
// current stage maps into (fixed on screen). Vanishing: vanishing points and
// the edges drawn on to them (projected view). ZFighting: faces the depth
// buffer cannot order. Traced: the vertex being traced.
enum class Element {
    Objects, WorldAxes, ViewAxes, Prp, Window, Dop, Volume, FrontPlane, BackPlane, Projectors, Canonical, Frame,
    Vanishing, ZFighting, Traced
};

enum class PrimitiveKind { Lines, Faces };

// One drawable piece of an element, in world coordinates. Lines: `segments`
// holds end points by pairs. Faces: the polygons of `faces` (shared with the
// mesh cache where they are an object's faces as read).
struct Primitive {
    Element element = Element::Objects;
    PrimitiveKind kind = PrimitiveKind::Lines;
    double opacity = 1;
    std::vector<Vec3<double>> segments;
    std::shared_ptr<const PolygonMesh> faces;
    int object = -1;            // the scene object drawn, or -1
    bool depthColored = false;  // faces colored by the level the depth buffer stores
    bool canonical = false;     // drawn where it is (not through the stage's matrix)
    double widthScale = 1;      // its lines wider than its element's (a lesson highlights it)
    Eigen::AlignedBox<double, 3> bounds;
};

// A point drawn at one size on screen whatever a stage's matrix does to the
// space around it (a sphere would be stretched by the scale and shear stages
// and blown up by the divide): a dot, or an arrowhead whose tip is `point`,
// pointing away from `from`. Drawn only while the point has an image.
struct Marker {
    enum class Shape { Dot, ArrowHead };
    Element element;
    Shape shape;
    Vec3<double> point;
    Vec3<double> from; // an arrowhead's: a point of its shaft (a dot's: the point)
    double size = 6;                          // pixels: a dot's radius, an arrowhead's length / 3
};

struct Label {
    Element element;
    std::string text; // with its math between $ signs (math_text.hpp)
    Vec3<double> anchor; // world coordinates, or the stage's where `fixed`
    // In the stage's coordinates, not moved by its matrix: the canonical
    // volume's (shown with it) and the frame axes'.
    bool fixed = false;
    // Placed right beside its anchor or left out, never led away (tick numbers).
    bool minor = false;
};

// A line of a view's legend: a swatch of how an element is drawn, and what it is.
struct LegendEntry {
    enum class Swatch { Line, Face, Dot, Bands, Pixels };
    std::string text;
    Element element; // whose color the swatch takes (bands and pixels have their own)
    Swatch swatch;
    double opacity = 1; // as drawn over the background: ghosts are faint
};

using Segment2 = std::array<Vec2<double>, 2>;

// An object's faces as the effects sort them: in front, culled away, or
// fighting for depth (all of them in front when no effect looks at faces).
struct ObjectFaces {
    std::shared_ptr<const PolygonMesh> front, culled, fighting;
};

struct EvaluatedScene {
    Scene scene;
    Pipeline<double> pipeline; // with the effects' stages
    ViewSetup<double> setup;
    std::vector<std::shared_ptr<const PolygonMesh>> meshes; // each object's, world coordinates
    EffectOutcomes outcomes;
    std::optional<DepthBands> bands; // of the levels the depth effect's faces store
    std::vector<ObjectFaces> objectFaces;
    std::vector<Primitive> primitives; // the world view's, back to front in drawing order
    std::vector<Label> labels;
    std::vector<Marker> markers; // drawn over the primitives
    std::vector<LegendEntry> worldLegend, projectedLegend;
    // The projected view's marks in the picture's coordinates as a screen shows them (x, y in [-1, 1],
    // y up: screenClipMatrix).
    std::vector<Segment2> vanishingLines;
    std::vector<Segment2> zFightingRing;
    // One line per listed effect: what it found.
    std::string effectsNote;
    // What each stage achieves, for its picture: element k (0 to the number
    // of stages) lists the facts about the set-up that hold after stage k and
    // did not before ("PRP at the origin", "DOP along the z axis"), checked on
    // the set-up's points as the pictures draw them; empty for the world.
    std::vector<std::string> stageClaims;
    // Under a projective stage what lies between the eye and the near plane
    // is thrown out towards infinity by the divide: pictures cut elements at
    // this plane (world coordinates, kept where p . (x, y, z, 1) >= 0), 9/10
    // of the way from the eye to the near (front) plane. Perspective views only.
    std::optional<Vec4<double>> nearCut;
    double size = 1; // of the whole set-up, for axes

    // Every object vertex, and the box around them (empty without objects).
    std::vector<Vec3<double>> objectVertices() const;
    Eigen::AlignedBox<double, 3> objectBounds() const;
};

// Mesh files read once and kept while their path, size and modification time
// are unchanged.
class MeshCache {
public:
    // Throws InputError(field, reason) for a file that cannot be read.
    std::shared_ptr<const PolygonMesh> read(const std::filesystem::path& file, const std::string& field);

private:
    struct Entry {
        std::filesystem::file_time_type modified;
        std::uintmax_t bytes = 0;
        std::shared_ptr<const PolygonMesh> mesh;
    };
    std::map<std::filesystem::path, Entry> entries_;
};

// Builds evaluated scenes, reading meshes through its cache.
class SceneEvaluator {
public:
    // Throws InputError for a camera the core refuses or a mesh that cannot be read.
    std::shared_ptr<const EvaluatedScene> evaluate(const Scene& scene);

private:
    MeshCache cache_;
};

// Each object's mesh: the built-in objects made, mesh files read (through
// `cache` when given); throws InputError naming "objects[k].path".
std::vector<std::shared_ptr<const PolygonMesh>> objectMeshes(const Scene& scene, MeshCache* cache = nullptr);
Eigen::AlignedBox<double, 3> boundsOf(const std::vector<std::shared_ptr<const PolygonMesh>>& meshes);

// One evaluation without a cache (the CLI's: each file is read once anyway).
std::shared_ptr<const EvaluatedScene> evaluateScene(const Scene& scene);

// The caption of stage k's picture: its name (as `text` asks), and on a
// second line what the stage achieved and whether the picture was framed anew
// because the stage changed sizes.
std::string stageCaption(const EvaluatedScene& scene, std::size_t k, StageText text);

// Where stage k's picture shows the stage before it faintly (its ghost,
// ghostAt), and pictures framed together frame both: after a translation or
// rotation that moves the set-up (the objects, the view volume, VRP, PRP,
// CW) less than about its size. Moved farther, a picture of both would draw
// each small.
std::optional<Mat4<double>> shownGhost(const EvaluatedScene& scene, int k);

// The window as the projected view outlines it: the mid-section of the view
// volume's side edges (end points by pairs, world coordinates).
std::vector<Vec3<double>> pictureWindowOutline(const EvaluatedScene& scene);
// The picture's width over its height: the window's sides.
double pictureAspect(const EvaluatedScene& scene);

// How far from the origin the pictures draw, in units of w: a point farther
// has no image (projectPoint), so the framing and the clipping range leave it
// out. evaluateScene refuses a scene whose set-up or objects reach farther at
// a stage before the divide.
constexpr double kDrawnReach = 1e9;

// Whether a point before the divide has an image the pictures draw: in front of the eye, w above its
// largest coordinate over kDrawnReach (so not on the eye plane nor beyond the reach), and finite. The one
// rule of the app, the exports and the page (whose data carries kDrawnReach as "drawnReach").
bool inFrontOfEye(const Vec4<double>& h);

// A point through a cumulative matrix and the divide; nothing when it has no
// image (not inFrontOfEye).
std::optional<Vec3<double>> projectPoint(const Mat4<double>& m, const Vec3<double>& p);

// A matrix divides when w is not 1 everywhere.
bool isProjective(const Mat4<double>& m);

} // namespace viewpipe
