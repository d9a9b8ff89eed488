#pragma once

// Scene effects: what happens after the normalizing transformation, computed
// only when a scene asks for it. Each effect is a function of the pipeline and
// the scene's geometry; the outcomes record which effects' code ran.

#include <algorithm>
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "viewpipe/geometry.hpp"
#include "viewpipe/pipeline.hpp"

namespace viewpipe {

// The depth buffer: fixed point with `bits` bits (16, 24, 32) or 32-bit
// float, standard (near 0, far 1) or reversed (near 1, far 0).
struct DepthOptions {
    int bits = 24;
    bool floating = false;
    bool reversed = false;
};

// Rasterization at a teaching size: pixels of the final image.
struct RasterOptions {
    int width = 64, height = 48;
};

// Clip: segments and polygons against the view volume, homogeneously.
// Divide: Foley's M, or OpenGL's divide into NDC, as a stage. Cull: back
// faces in canonical space. Depth: the depth buffer. Raster: the final image.
enum class EffectKind { Clip, Divide, Cull, Depth, Raster };

// "clip", "divide", "cull", "depth", "raster": as scene files and reports name it.
std::string effectName(EffectKind effect);
// The effect called `name`; throws InputError(field, "unknown effect ...") for a name that is not an effect.
EffectKind effectNamed(const std::string& name, const std::string& field);

// The effects a scene lists, in its order, with their parameters. Built with withEffect.
struct EffectList {
    std::vector<EffectKind> listed;
    std::optional<DepthOptions> depth;   // while Depth is listed
    std::optional<RasterOptions> raster; // while Raster is listed
    bool empty() const { return listed.empty(); }
    bool has(EffectKind effect) const { return std::find(listed.begin(), listed.end(), effect) != listed.end(); }
};

// "16-bit fixed point", "32-bit float, reversed": as captions and legends name it.
std::string depthFormatName(const DepthOptions& options);

inline bool operator==(const DepthOptions& a, const DepthOptions& b)
{
    return a.bits == b.bits && a.floating == b.floating && a.reversed == b.reversed;
}
inline bool operator==(const RasterOptions& a, const RasterOptions& b)
{
    return a.width == b.width && a.height == b.height;
}
// The same effects in the same order with the same parameters (the flags follow the list).
inline bool operator==(const EffectList& a, const EffectList& b)
{
    return a.listed == b.listed && a.depth == b.depth && a.raster == b.raster;
}

// The list with an effect turned on (appended, or kept in its place if listed,
// with the parameters already in `depth` or `raster`, else the defaults) or
// off (removed): what a scene's
// "effects" and the app's Effects menu both build lists with.
EffectList withEffect(EffectList effects, EffectKind effect, bool on);
// By name, as a scene lists it; throws InputError naming "effects" for a name that is not an effect.
EffectList withEffect(EffectList effects, const std::string& name, bool on);

// Whether "divide" appends a stage to this pipeline: M after a perspective
// Foley view, "divide" after an OpenGL camera; a parallel Foley view's
// canonical volume is parallel already.
template <class T> bool divideAddsStage(const Pipeline<T>& p)
{
    return p.convention == Convention::OpenGL || p.projection == ProjectionKind::Perspective;
}

// The pipeline with the effects' stages: with Divide, Foley's M is appended
// to a perspective view, and an OpenGL camera gains the divide (the identity:
// the picture is divided by w at every stage already).
// `computed`, when given, gains Divide when the divide's code ran.
template <class T>
Pipeline<T> withEffectStages(Pipeline<T> p, const EffectList& effects, std::vector<EffectKind>* computed = nullptr)
{
    if (!effects.has(EffectKind::Divide))
        return p;
    if (computed)
        computed->push_back(EffectKind::Divide);
    if (!divideAddsStage(p))
        return p;
    if (p.convention == Convention::Foley) {
        p.stages.push_back({StageKind::PerspectiveToParallel,
                            "map the canonical perspective volume onto the canonical parallel volume (the divide "
                            "by $w = -z$ follows)",
                            p.toClip});
        p.composite = p.clipMatrix();
        p.toClip = Mat4<T>::Identity();
    } else {
        p.stages.push_back({StageKind::Divide, "divide by w: clip coordinates become normalized device coordinates",
                            Mat4<T>::Identity()});
    }
    return p;
}

inline Pipeline<double> buildPipeline(const CameraSpec<double>& camera, const EffectList& effects,
                                      std::vector<EffectKind>* computed = nullptr)
{
    return withEffectStages(buildPipeline(camera), effects, computed);
}

// Which side of each clipping plane a homogeneous point lies on: bit k set
// when plane k (left, right, bottom, top, near, far) is violated.
unsigned outcode(const Vec4<double>& clip, ClipVolume volume);
std::vector<std::string> planeNames(unsigned code, Convention convention);

// Liang-Barsky in homogeneous coordinates: the parameter interval [t0, t1] of
// the segment a + t (b - a), t in [0, 1], inside the volume; empty if none.
// Works before the divide, so a segment crossing w = 0 is handled exactly.
std::optional<std::array<double, 2>> clipSegment(const Vec4<double>& a, const Vec4<double>& b, ClipVolume volume);

// Sutherland-Hodgman against the six planes, in homogeneous coordinates.
std::vector<Vec4<double>> clipPolygon(const std::vector<Vec4<double>>& polygon, ClipVolume volume);

struct ClipCounts {
    int inside = 0, clipped = 0, outside = 0;
};

struct ClipOutcome {
    ClipCounts segments, polygons;
    // Per object, per edge (in the order of meshEdges... see clipScene): the kept interval.
    std::vector<std::vector<std::optional<std::array<double, 2>>>> keptEdges;
};

struct CullOutcome {
    int faces = 0, culled = 0;
    std::vector<std::vector<bool>> culledFaces; // per object, per face
};

// Window depth in [0, 1] of a point in clip coordinates (after the divide;
// near 0, far 1), and the value a depth buffer stores for it.
double windowDepth(const Vec4<double>& clip, ClipVolume volume);
double storedDepth(double depth, const DepthOptions& options);

// The rank of the stored value among those the buffer can hold, so that
// neighbouring values are one level apart: the integer itself for fixed
// point, the bit pattern for float (which orders floats in [0, 1]).
double depthLevel(double depth, const DepthOptions& options);
// The level stored for a world point (through `clip`, a pipeline's
// clipMatrix()), if it lies in front of the eye between the near (front) and
// far (back) planes; nothing otherwise.
std::optional<double> depthLevelAt(const Mat4<double>& clip, ClipVolume volume, const Vec3<double>& world,
                                   const DepthOptions& options);

// Bands that show quantization on the scene: each holds `levelsPerBand`
// consecutive levels (a power of two, the fewest that keep the levels from
// `low` to `high` within `maxBands` bands), the first starting at `first`.
struct DepthBands {
    double first = 0, levelsPerBand = 1;
    int count = 1;
};
DepthBands depthBands(double low, double high, int maxBands);

struct DepthSample {
    double distance; // from the eye (OpenGL) or the PRP (Foley), along the view direction
    double step;     // the smallest change of distance there that changes the stored value
    bool pastFar;    // the level runs on past the far (back) plane: `step` is only a lower bound
};

// The width of one stored level at `samples` distances along the view volume's
// center line, evenly from the near (front) face to just before the far (back)
// face (at 99% of the way, where the last level still ends inside).
std::vector<DepthSample> depthResolution(const Pipeline<double>& pipeline, const DepthOptions& options, int samples);

struct DepthOutcome {
    DepthOptions options;
    std::vector<DepthSample> resolution; // from near to far
    int distinctValues = 0;              // among the scene's vertices
    int vertices = 0;
    // Faces whose order the buffer cannot resolve somewhere they overlap:
    // (object, face) pairs, found by sampling.
    std::vector<std::array<int, 4>> zFighting;
    bool zFightingChecked = true; // false for scenes with too many faces to compare pairwise
    // Samples whose verdict a rounding could have decided (near a face's edge, equal depths or a level's
    // end), decided exactly; the others are decided in double (runEffects' exactClip).
    int decidedExactly = 0;
};

// The final image through a z-buffer: for each pixel (row 0 at the bottom),
// the object and face seen there, or -1; faces are clipped homogeneously
// first, and culled when Cull is listed.
struct RasterOutcome {
    int width = 0, height = 0;
    std::vector<int> object, face;
    std::vector<double> depth; // window depth, 1 where nothing is drawn
    int covered = 0;
};

RasterOutcome rasterize(const Pipeline<double>& pipeline, const std::vector<PolygonMesh>& objects,
                        const RasterOptions& options, const std::vector<std::vector<bool>>* culled = nullptr);

struct EffectOutcomes {
    std::vector<EffectKind> computed; // the effects whose code ran, in the order it ran
    std::optional<ClipOutcome> clip;
    std::optional<CullOutcome> cull;
    std::optional<DepthOutcome> depth;
    std::optional<RasterOutcome> raster;
};

// The scene's built-in objects as polygon meshes (meshes from files are the
// caller's: core reads no files).
// `exactClip`, the clip matrix computed exactly (exactPipeline), decides the
// clip, cull and z-fighting verdicts near a boundary (a filtered predicate: double where
// its error bound cannot reach the boundary, exact arithmetic where it can);
// without it, double decides everything.
EffectOutcomes runEffects(const Pipeline<double>& pipeline, const std::vector<PolygonMesh>& objects,
                          const EffectList& effects, const Mat4<Exact>* exactClip = nullptr);

// Every edge of a mesh once, as vertex index pairs in first-seen order.
std::vector<std::array<int, 2>> meshEdgeIndices(const PolygonMesh& mesh);

} // namespace viewpipe
