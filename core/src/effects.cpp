#include "viewpipe/effects.hpp"

#include "viewpipe/exact.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <unordered_set>
#include <utility>

namespace viewpipe {
namespace {

// Each effect's name, in the order an unknown name's error lists them.
const std::array<std::pair<EffectKind, const char*>, 5> kEffectNames = {{{EffectKind::Clip, "clip"},
                                                                         {EffectKind::Divide, "divide"},
                                                                         {EffectKind::Depth, "depth"},
                                                                         {EffectKind::Raster, "raster"},
                                                                         {EffectKind::Cull, "cull"}}};

} // namespace

std::string effectName(EffectKind effect)
{
    for (const auto& [e, name] : kEffectNames)
        if (e == effect)
            return name;
    return "";
}

EffectKind effectNamed(const std::string& name, const std::string& field)
{
    std::string known;
    for (const auto& [effect, n] : kEffectNames) {
        if (name == n)
            return effect;
        known += (known.empty() ? "" : ", ") + std::string(n);
    }
    throw InputError(field, "unknown effect \"" + name + "\" (known: " + known + ")");
}

EffectList withEffect(EffectList effects, EffectKind effect, bool on)
{
    auto& listed = effects.listed;
    if (!on)
        listed.erase(std::remove(listed.begin(), listed.end(), effect), listed.end());
    else if (!effects.has(effect))
        listed.push_back(effect); // a listed effect keeps its place
    if (effect == EffectKind::Depth)
        effects.depth = on ? effects.depth.value_or(DepthOptions{}) : std::optional<DepthOptions>{};
    if (effect == EffectKind::Raster)
        effects.raster = on ? effects.raster.value_or(RasterOptions{}) : std::optional<RasterOptions>{};
    return effects;
}

EffectList withEffect(EffectList effects, const std::string& name, bool on)
{
    return withEffect(std::move(effects), effectNamed(name, "effects"), on);
}

std::string depthFormatName(const DepthOptions& options)
{
    return std::to_string(options.bits) + "-bit " + (options.floating ? "float" : "fixed point") +
           (options.reversed ? ", reversed" : "");
}

unsigned outcode(const Vec4<double>& clip, ClipVolume volume)
{
    return clipVerdict(clip, volume).outside;
}

std::vector<std::string> planeNames(unsigned code, Convention convention)
{
    const bool foley = convention == Convention::Foley;
    const std::array<std::string, 6> names = {"left", "right", "bottom", "top", foley ? "front" : "near",
                                              foley ? "back" : "far"};
    std::vector<std::string> out;
    for (int k = 0; k < 6; ++k)
        if (code & (1u << k))
            out.push_back(names[std::size_t(k)]);
    return out;
}

std::optional<std::array<double, 2>> clipSegment(const Vec4<double>& a, const Vec4<double>& b, ClipVolume volume)
{
    const std::array<double, 6> ba = clipBoundaries(a, volume), bb = clipBoundaries(b, volume);
    double t0 = 0, t1 = 1;
    for (std::size_t k = 0; k < 6; ++k) {
        if (ba[k] < 0 && bb[k] < 0)
            return std::nullopt; // both outside the same plane
        if (ba[k] >= 0 && bb[k] >= 0)
            continue;
        const double t = ba[k] / (ba[k] - bb[k]); // where the boundary value crosses zero
        if (ba[k] < 0)
            t0 = std::max(t0, t);
        else
            t1 = std::min(t1, t);
        if (t0 > t1)
            return std::nullopt;
    }
    return std::array<double, 2>{t0, t1};
}

std::vector<Vec4<double>> clipPolygon(const std::vector<Vec4<double>>& polygon, ClipVolume volume)
{
    std::vector<Vec4<double>> out = polygon;
    for (std::size_t k = 0; k < 6 && !out.empty(); ++k) {
        // Each vertex's boundary value against plane k, once: an edge's end is the next edge's start.
        const double first = clipBoundaries(out[0], volume)[k];
        double bp = first;
        std::vector<Vec4<double>> next;
        for (std::size_t i = 0; i < out.size(); ++i) {
            const std::size_t j = (i + 1) % out.size();
            const Vec4<double>& p = out[i];
            const Vec4<double>& q = out[j];
            const double bq = j == 0 ? first : clipBoundaries(q, volume)[k];
            if (bp >= 0)
                next.push_back(p);
            if ((bp >= 0) != (bq >= 0))
                next.push_back(p + (bp / (bp - bq)) * (q - p));
            bp = bq;
        }
        out = std::move(next);
    }
    return out;
}

std::vector<std::array<int, 2>> meshEdgeIndices(const PolygonMesh& mesh)
{
    std::vector<std::array<int, 2>> edges;
    std::unordered_set<std::uint64_t> seen;
    for (const auto& face : mesh.faces)
        for (std::size_t k = 0; k < face.size(); ++k) {
            const int a = face[k], b = face[(k + 1) % face.size()];
            const std::uint64_t key = (std::uint64_t(std::uint32_t(std::min(a, b))) << 32) | std::uint32_t(std::max(a, b));
            if (seen.insert(key).second)
                edges.push_back({std::min(a, b), std::max(a, b)});
        }
    return edges;
}

namespace {

template <class T> T windowDepthOf(const Vec4<T>& clip, ClipVolume volume)
{
    const T z = clip.z() / clip.w();
    return (z - T(nearPlaneZ(volume))) / T(farPlaneZ(volume) - nearPlaneZ(volume));
}

} // namespace

double windowDepth(const Vec4<double>& clip, ClipVolume volume)
{
    return windowDepthOf(clip, volume);
}

double storedDepth(double depth, const DepthOptions& options)
{
    const double d = options.reversed ? 1 - depth : depth;
    if (options.floating)
        return double(float(d));
    const double levels = std::ldexp(1.0, options.bits) - 1;
    return std::nearbyint(std::clamp(d, 0.0, 1.0) * levels);
}

double depthLevel(double depth, const DepthOptions& options)
{
    if (!options.floating)
        return storedDepth(depth, options);
    const float stored = float(std::clamp(options.reversed ? 1 - depth : depth, 0.0, 1.0));
    std::uint32_t bits;
    std::memcpy(&bits, &stored, sizeof bits);
    return double(bits);
}

std::optional<double> depthLevelAt(const Mat4<double>& clip, ClipVolume volume, const Vec3<double>& world,
                                   const DepthOptions& options)
{
    const Vec4<double> h = clip * world.homogeneous();
    if (!(h.w() > 0))
        return std::nullopt;
    const double depth = windowDepth(h, volume);
    if (!(depth >= 0 && depth <= 1))
        return std::nullopt;
    return depthLevel(depth, options);
}

DepthBands depthBands(double low, double high, int maxBands)
{
    DepthBands bands;
    for (;;) {
        const double q = bands.levelsPerBand;
        bands.first = std::floor(low / q) * q;
        bands.count = int(std::floor(high / q) - std::floor(low / q)) + 1;
        if (bands.count <= std::max(maxBands, 1))
            return bands;
        bands.levelsPerBand *= 2;
    }
}

namespace {

constexpr std::size_t kMaxFightFaces = 4000;

// The center line of the view volume in world coordinates, from the near
// (front) face to the far (back) face: where the picture's center (0, 0) lies
// at each depth.
std::array<Vec3<double>, 2> centerLine(const Pipeline<double>& p)
{
    const Mat4<double> inverse = p.clipMatrix().inverse();
    auto world = [&inverse](double z) {
        const Vec4<double> h = inverse * Vec4<double>(0, 0, z, 1);
        return Vec3<double>(h.head<3>() / h.w());
    };
    const double nearZ = nearPlaneZ(p.clipVolume), farZ = farPlaneZ(p.clipVolume);
    Vec3<double> far = world(farZ);
    // A far plane at infinity: the line ends where depth has come 99.9 % of the
    // way (a thousand times the near distance, for a perspective).
    if (!far.allFinite())
        far = world(nearZ + 0.999 * (farZ - nearZ));
    return {world(nearZ), far};
}

// The stored value at a distance along the center line, and the next place
// (before `limit`) where it changes, found by bisection.
struct CenterLine {
    const Pipeline<double>& pipeline;
    const DepthOptions& options;
    Mat4<double> clip;
    Vec3<double> nearPoint, direction;
    double length;

    CenterLine(const Pipeline<double>& p, const DepthOptions& o)
        : pipeline(p), options(o), clip(p.clipMatrix())
    {
        const auto [from, to] = centerLine(p);
        length = (to - from).norm();
        nearPoint = from;
        direction = (to - from) / length;
    }
    double stored(double s) const
    {
        return storedDepth(windowDepth(clip * (nearPoint + s * direction).homogeneous(), pipeline.clipVolume), options);
    }
    std::optional<double> nextChange(double from, double limit) const
    {
        const double value = stored(from);
        if (stored(limit) == value)
            return std::nullopt;
        double lo = from, hi = limit;
        for (int i = 0; i < 100 && hi - lo > 0; ++i) {
            const double mid = (lo + hi) / 2;
            if (mid == lo || mid == hi)
                break;
            (stored(mid) == value ? lo : hi) = mid;
        }
        return hi;
    }
};

// Every object's vertices in clip coordinates, computed once for all effects.
using ClipPoints = std::vector<std::vector<Vec4<double>>>;

ClipPoints clipPoints(const Mat4<double>& clip, const std::vector<PolygonMesh>& objects)
{
    ClipPoints points;
    for (const PolygonMesh& mesh : objects) {
        std::vector<Vec4<double>> h;
        h.reserve(mesh.vertices.size());
        for (const Vec3<double>& v : mesh.vertices)
            h.push_back(clip * v.homogeneous());
        points.push_back(std::move(h));
    }
    return points;
}

// Where each vertex lies against the volume, decided exactly: in double where
// every boundary value is farther from 0 than the error of computing it (the
// double clip matrix's own error against the exact one, plus the products'
// rounding), else with the exact clip matrix and the vertex's own value.
class VertexVerdicts {
public:
    VertexVerdicts(const Mat4<double>& clip, const Mat4<Exact>* exact, ClipVolume volume)
        : exact_(exact), volume_(volume)
    {
        if (!exact)
            return;
        constexpr double kRounding = 8 * std::numeric_limits<double>::epsilon();
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j) // the entry's error, rounded up, and its products' rounding
                error_(i, j) = std::abs(double(Exact(clip(i, j)) - (*exact)(i, j))) * (1 + kRounding) +
                               kRounding * std::abs(clip(i, j));
    }

    unsigned outcode(const Vec3<double>& vertex, const Vec4<double>& h) const
    {
        const std::array<double, 6> b = clipBoundaries(h, volume_);
        unsigned code = 0;
        for (int k = 0; k < 6; ++k)
            code |= b[std::size_t(k)] < 0 ? 1u << k : 0u;
        if (!exact_)
            return code;
        const double bound = 2 * clipError(vertex, h);
        if (std::all_of(b.begin(), b.end(), [bound](double x) { return std::abs(x) > bound; }))
            return code;
        return clipVerdict(exactClipPoint(vertex), volume_).outside;
    }

    Vec4<Exact> exactClipPoint(const Vec3<double>& vertex) const
    {
        return *exact_ * Vec4<Exact>(Exact(vertex.x()), Exact(vertex.y()), Exact(vertex.z()), Exact(1));
    }
    bool exact() const { return exact_ != nullptr; }

    // How far each of h's coordinates (the vertex through the double clip matrix) may lie from the exact one.
    double clipError(const Vec3<double>& vertex, const Vec4<double>& h) const
    {
        const Vec4<double> reach = error_ * vertex.homogeneous().cwiseAbs();
        return reach.maxCoeff() + 4 * std::numeric_limits<double>::epsilon() * h.cwiseAbs().maxCoeff();
    }

private:
    const Mat4<Exact>* exact_;
    ClipVolume volume_;
    Mat4<double> error_ = Mat4<double>::Zero();
};

// A face as the depth buffer sees it: its corners' x, y and window depth, its
// plane's normal in those coordinates, and the points the z-fighting check
// samples (its centroid and 4/5 of the way from it to each corner).
template <class T> struct FacePicture {
    std::vector<Vec3<T>> corners;
    Vec3<T> normal;
    std::vector<Vec3<T>> samples;
};

template <class T> FacePicture<T> facePicture(const std::vector<Vec4<T>>& clip, ClipVolume volume)
{
    FacePicture<T> face;
    for (const Vec4<T>& h : clip)
        face.corners.emplace_back(h.x() / h.w(), h.y() / h.w(), windowDepthOf(h, volume));
    const auto& v = face.corners;
    face.normal = (v[1] - v[0]).cross(v[2] - v[0]);
    Vec3<T> centroid = Vec3<T>::Zero();
    for (const Vec3<T>& q : v)
        centroid += q / T(int(v.size()));
    face.samples = {centroid};
    for (const Vec3<T>& q : v)
        face.samples.push_back(centroid + T(4) / T(5) * (q - centroid));
    return face;
}

// Which side of the edge from a to b the point q lies on (twice the signed area).
template <class T> T edgeSide(const Vec2<T>& a, const Vec2<T>& b, const Vec2<T>& q)
{
    return (b - a).x() * (q - a).y() - (b - a).y() * (q - a).x();
}

// The depth of the face's plane at q, where q lies in the (convex) projected face, its edges included.
template <class T> std::optional<T> depthAt(const FacePicture<T>& face, const Vec2<T>& q)
{
    using std::abs;
    const auto& v = face.corners;
    T sign(0);
    for (std::size_t k = 0; k < v.size(); ++k) {
        const T side = edgeSide<T>(v[k].template head<2>(), v[(k + 1) % v.size()].template head<2>(), q);
        if (side * sign < T(0))
            return std::nullopt;
        if (side != T(0))
            sign = side;
    }
    const Vec3<T>& n = face.normal;
    if (abs(n.z()) < T(1e-300))
        return std::nullopt; // seen edge-on
    return v[0].z() - (n.x() * (q.x() - v[0].x()) + n.y() * (q.y() - v[0].y())) / n.z();
}

// The value a depth buffer stores for an exact depth: storedDepth's rounding
// (to the nearest level or float, ties to even) decided exactly.
double exactStored(const Exact& depth, const DepthOptions& options)
{
    const Exact d = options.reversed ? Exact(1) - depth : depth;
    double stored = storedDepth(double(depth), options); // within a level of the exact one
    if (options.floating) {
        float f = float(stored);
        // Step to the float whose rounding interval holds d: the midpoints of floats are doubles.
        auto midpoint = [](float a, float b) { return Exact((double(a) + double(b)) / 2); };
        auto even = [](float x) { std::uint32_t bits; std::memcpy(&bits, &x, sizeof bits); return (bits & 1) == 0; };
        for (;;) {
            const float up = std::nextafter(f, 2.0f), down = std::nextafter(f, -2.0f);
            const Exact above = midpoint(f, up), below = midpoint(down, f);
            if (d > above || (d == above && !even(f)))
                f = up;
            else if (d < below || (d == below && !even(f)))
                f = down;
            else
                return double(f);
        }
    }
    const Exact scaled = (d < Exact(0) ? Exact(0) : d > Exact(1) ? Exact(1) : d) * Exact(std::ldexp(1.0, options.bits) - 1);
    const Exact half = Exact(1) / Exact(2);
    for (;;) {
        const Exact above = Exact(stored) + half, below = Exact(stored) - half;
        const bool odd = std::fmod(stored, 2.0) != 0;
        if (scaled > above || (scaled == above && odd))
            stored += 1;
        else if (scaled < below || (scaled == below && odd))
            stored -= 1;
        else
            return stored;
    }
}

// A fight at a sample: the other face covers it at a different depth that is stored alike.
bool fightsExactly(const Vec3<Exact>& sample, const FacePicture<Exact>& other, const DepthOptions& options)
{
    const std::optional<Exact> depth = depthAt(other, Vec2<Exact>(sample.head<2>()));
    return depth && *depth != sample.z() && exactStored(*depth, options) == exactStored(sample.z(), options);
}

// A face's picture in double with what bounds its error against the exact one: `error` for every
// coordinate of its corners (from the clip coordinates' error and the divide's), `samples` its samples'.
struct Face {
    int object, index;
    FacePicture<double> picture;
    double error = 0, sampleError = 0;
    double slope = 0;  // |d depth / dx| + |d depth / dy| of its plane
    double spread = 1; // the largest sum of |barycentric weights| (first three corners) over the face
};

// A sample of face a against face b in double, with whether a rounding could have decided it: the
// error bounds (first order, doubled) of b's edge tests, of both depths and of their stored values.
struct DoubleFight {
    bool fights = false, unsure = false;
};

DoubleFight fightInDouble(const Face& a, const Vec3<double>& sample, const Face& b, const DepthOptions& options,
                          bool bounded)
{
    constexpr double eps = std::numeric_limits<double>::epsilon();
    const Vec2<double> q = sample.head<2>();
    const std::optional<double> other = depthAt(b.picture, q);
    const bool fights = other && *other != sample.z() && storedDepth(*other, options) == storedDepth(sample.z(), options);
    if (!bounded)
        return {fights, false};
    const std::vector<Vec3<double>>& v = b.picture.corners;
    const double e = b.error + a.sampleError;
    bool left = false, right = false, near = false; // q certainly left or right of an edge, or near its line
    for (std::size_t k = 0; k < v.size(); ++k) {
        const Vec2<double> from = v[k].head<2>(), to = v[(k + 1) % v.size()].head<2>();
        const double size = (to - from).cwiseAbs().sum() + (q - from).cwiseAbs().sum();
        const double side = edgeSide(from, to, q);
        if (std::abs(side) <= 2 * (2 * e * size + 4 * e * e + 4 * eps * size * size))
            near = true;
        else
            (side > 0 ? left : right) = true;
    }
    if (left && right)
        return {fights, false}; // outside the face whatever the rounding
    if (near)
        return {fights, true};
    const Vec3<double>& n = b.picture.normal;
    const double e1 = (v[1] - v[0]).head<2>().cwiseAbs().sum(), e2 = (v[2] - v[0]).head<2>().cwiseAbs().sum();
    if (std::abs(n.z()) <= 2 * (2 * b.error * (e1 + e2) + 4 * b.error * b.error + 4 * eps * e1 * e2))
        return {fights, true}; // edge-on, or nearly
    if (!other)
        return {};
    const double rounding = 16 * eps * (std::abs(v[0].z()) + b.slope * ((q - v[0].head<2>()).cwiseAbs().sum() + 1));
    const double otherError = 2 * (b.spread * (1 + b.slope) * b.error + b.slope * a.sampleError + rounding);
    const double sampleError = 2 * a.sampleError;
    // The levels each depth may be stored at (storedDepth is monotonic).
    const auto levels = [&options](double depth, double error) {
        const double low = storedDepth(depth - error, options), high = storedDepth(depth + error, options);
        return std::pair{std::min(low, high), std::max(low, high)};
    };
    const auto [otherLow, otherHigh] = levels(*other, otherError);
    const auto [sampleLow, sampleHigh] = levels(sample.z(), sampleError);
    if (otherHigh < sampleLow || sampleHigh < otherLow)
        return {fights, false}; // stored apart whatever the rounding
    const bool storedAlike = otherLow == otherHigh && sampleLow == sampleHigh && otherLow == sampleLow;
    return {fights, !storedAlike || std::abs(*other - sample.z()) <= otherError + sampleError};
}

// The error bounds of a face's picture: each corner's clip coordinates may be off by `clipError`
// (VertexVerdicts), which the divide by w enlarges; its samples are averages of its corners.
void boundFace(Face& face, const std::vector<double>& clipErrors, const std::vector<Vec4<double>>& clip)
{
    constexpr double eps = std::numeric_limits<double>::epsilon();
    const std::vector<Vec3<double>>& v = face.picture.corners;
    double largest = 0;
    for (std::size_t k = 0; k < v.size(); ++k) {
        const double w = std::abs(clip[k].w()), m = v[k].cwiseAbs().maxCoeff() + 1;
        largest = std::max(largest, m);
        face.error = std::max(face.error, w > 2 * clipErrors[k] ? clipErrors[k] * m / (w - clipErrors[k]) + 4 * eps * m
                                                                : std::numeric_limits<double>::infinity());
    }
    face.sampleError = face.error + 8 * eps * largest;
    const Vec3<double>& n = face.picture.normal;
    face.slope = (std::abs(n.x()) + std::abs(n.y())) / std::abs(n.z());
    const Vec2<double> v0 = v[0].head<2>(), e1 = v[1].head<2>() - v0, e2 = v[2].head<2>() - v0;
    for (const Vec3<double>& corner : v) { // the sum of |weights| is convex: largest at a corner
        const Vec2<double> d = corner.head<2>() - v0;
        const double l1 = edgeSide<double>(Vec2<double>::Zero(), d, e2) / n.z(), l2 = edgeSide<double>(Vec2<double>::Zero(), e1, d) / n.z();
        face.spread = std::max(face.spread, std::abs(1 - l1 - l2) + std::abs(l1) + std::abs(l2));
    }
}

DepthOutcome depthOutcome(const Pipeline<double>& p, const std::vector<PolygonMesh>& objects, const ClipPoints& points,
                          const DepthOptions& options, const VertexVerdicts& verdicts)
{
    DepthOutcome out;
    out.options = options;
    out.resolution = depthResolution(p, options, 9);
    // Distinct stored values among the vertices inside the volume.
    std::vector<double> values;
    for (const std::vector<Vec4<double>>& mesh : points)
        for (const Vec4<double>& h : mesh) {
            if (!insideClipVolume(h, p.clipVolume))
                continue;
            ++out.vertices;
            values.push_back(storedDepth(windowDepth(h, p.clipVolume), options));
        }
    std::sort(values.begin(), values.end());
    out.distinctValues = int(std::unique(values.begin(), values.end()) - values.begin());

    // Z-fighting: sample each face (its centroid and points between it and the
    // corners); where another face covers the same picture point, compare the
    // two depths: different, but stored alike, is a fight. Decided for the scene
    // as typed: in double where the error bounds cannot reach a boundary (an
    // edge, equal depths, a level's end), else exactly (the exact clip matrix).
    std::vector<Face> faces;
    for (std::size_t o = 0; o < objects.size() && faces.size() <= kMaxFightFaces; ++o)
        for (std::size_t f = 0; f < objects[o].faces.size() && faces.size() <= kMaxFightFaces; ++f) {
            const FaceList::Face corners = objects[o].faces[f];
            std::vector<Vec4<double>> clip;
            std::vector<double> clipErrors;
            bool visible = corners.size() >= 3;
            for (int i : corners) {
                const Vec3<double>& vertex = objects[o].vertices[std::size_t(i)];
                clip.push_back(points[o][std::size_t(i)]);
                visible = visible && verdicts.outcode(vertex, clip.back()) == 0;
                if (verdicts.exact())
                    clipErrors.push_back(verdicts.clipError(vertex, clip.back()));
            }
            if (!visible)
                continue;
            Face face{int(o), int(f), facePicture(clip, p.clipVolume)};
            if (verdicts.exact())
                boundFace(face, clipErrors, clip);
            faces.push_back(std::move(face));
        }
    std::vector<std::optional<FacePicture<Exact>>> exactFaces(faces.size());
    auto exactFace = [&](std::size_t k) -> const FacePicture<Exact>& {
        if (!exactFaces[k]) {
            std::vector<Vec4<Exact>> clip;
            for (int i : objects[std::size_t(faces[k].object)].faces[std::size_t(faces[k].index)])
                clip.push_back(verdicts.exactClipPoint(objects[std::size_t(faces[k].object)].vertices[std::size_t(i)]));
            exactFaces[k] = facePicture(clip, p.clipVolume);
        }
        return *exactFaces[k];
    };
    // Every pair is compared: beyond kMaxFightFaces faces that would take too
    // long, and the check is skipped (zFightingChecked says so).
    out.zFightingChecked = faces.size() <= kMaxFightFaces;
    for (std::size_t a = 0; a < faces.size() && out.zFightingChecked; ++a)
        for (std::size_t b = a + 1; b < faces.size(); ++b) {
            if (faces[a].object == faces[b].object)
                continue; // an object's own faces meet only at edges
            for (std::size_t k = 0; k < faces[a].picture.samples.size(); ++k) {
                DoubleFight fight = fightInDouble(faces[a], faces[a].picture.samples[k], faces[b], options, verdicts.exact());
                if (fight.unsure) {
                    ++out.decidedExactly;
                    fight.fights = fightsExactly(exactFace(a).samples[k], exactFace(b), options);
                }
                if (fight.fights) {
                    out.zFighting.push_back({faces[a].object, faces[a].index, faces[b].object, faces[b].index});
                    break;
                }
            }
        }
    return out;
}

} // namespace

std::vector<DepthSample> depthResolution(const Pipeline<double>& pipeline, const DepthOptions& options, int samples)
{
    const CenterLine line(pipeline, options);
    std::vector<DepthSample> resolution;
    for (int k = 0; k < samples; ++k) {
        const double s = line.length * k / std::max(samples - 1, 1) * 0.99;
        // The width of the stored level that follows s: what the buffer can tell apart there.
        const std::optional<double> first = line.nextChange(s, line.length);
        const std::optional<double> second = first ? line.nextChange(*first, line.length) : std::nullopt;
        resolution.push_back({s, second ? *second - *first : line.length - s, !second});
    }
    return resolution;
}

namespace {

RasterOutcome rasterize(ClipVolume volume, bool ndcYDown, const std::vector<PolygonMesh>& objects,
                        const ClipPoints& points, const RasterOptions& options,
                        const std::vector<std::vector<bool>>* culled)
{
    const double up = ndcYDown ? -1 : 1;
    RasterOutcome out;
    out.width = options.width;
    out.height = options.height;
    const std::size_t pixels = std::size_t(options.width) * std::size_t(options.height);
    out.object.assign(pixels, -1);
    out.face.assign(pixels, -1);
    out.depth.assign(pixels, 1.0);
    for (std::size_t o = 0; o < objects.size(); ++o) {
        const PolygonMesh& mesh = objects[o];
        for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
            if (culled && (*culled)[o][f])
                continue;
            std::vector<Vec4<double>> polygon;
            for (int i : mesh.faces[f])
                polygon.push_back(points[o][std::size_t(i)]);
            polygon = clipPolygon(polygon, volume);
            // To pixels: x, y in [0, width] x [0, height], and window depth.
            std::vector<Vec3<double>> screen;
            for (const Vec4<double>& h : polygon)
                screen.emplace_back((h.x() / h.w() + 1) / 2 * options.width, (up * h.y() / h.w() + 1) / 2 * options.height,
                                    windowDepth(h, volume));
            for (std::size_t k = 1; k + 1 < screen.size(); ++k) {
                const Vec3<double>& a = screen[0];
                const Vec3<double>& b = screen[k];
                const Vec3<double>& c = screen[k + 1];
                const double area = (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
                if (area == 0)
                    continue;
                const int x0 = std::max(0, int(std::floor(std::min({a.x(), b.x(), c.x()}))));
                const int x1 = std::min(options.width - 1, int(std::ceil(std::max({a.x(), b.x(), c.x()}))));
                const int y0 = std::max(0, int(std::floor(std::min({a.y(), b.y(), c.y()}))));
                const int y1 = std::min(options.height - 1, int(std::ceil(std::max({a.y(), b.y(), c.y()}))));
                for (int y = y0; y <= y1; ++y)
                    for (int x = x0; x <= x1; ++x) {
                        // Barycentric weights of the pixel's center; depth is affine on the screen.
                        const double px = x + 0.5, py = y + 0.5;
                        const double wa = ((b.x() - px) * (c.y() - py) - (b.y() - py) * (c.x() - px)) / area;
                        const double wb = ((c.x() - px) * (a.y() - py) - (c.y() - py) * (a.x() - px)) / area;
                        const double wc = 1 - wa - wb;
                        if (wa < 0 || wb < 0 || wc < 0)
                            continue;
                        const double z = wa * a.z() + wb * b.z() + wc * c.z();
                        const std::size_t i = std::size_t(y) * std::size_t(options.width) + std::size_t(x);
                        if (z < out.depth[i]) {
                            out.depth[i] = z;
                            out.object[i] = int(o);
                            out.face[i] = int(f);
                        }
                    }
            }
        }
    }
    out.covered = int(std::count_if(out.object.begin(), out.object.end(), [](int o) { return o >= 0; }));
    return out;
}

} // namespace

RasterOutcome rasterize(const Pipeline<double>& pipeline, const std::vector<PolygonMesh>& objects,
                        const RasterOptions& options, const std::vector<std::vector<bool>>* culled)
{
    return rasterize(pipeline.clipVolume, pipeline.ndcYDown, objects, clipPoints(pipeline.clipMatrix(), objects),
                     options, culled);
}

namespace {

// The signed area of a face in the picture (x, y after the divide), and
// whether a vertex lies on or behind the eye plane.
template <class T> std::pair<T, bool> pictureArea(const std::vector<Vec4<T>>& points)
{
    T area(0);
    bool behind = false;
    for (std::size_t k = 0; k < points.size(); ++k) {
        const Vec4<T>& p = points[k];
        const Vec4<T>& q = points[(k + 1) % points.size()];
        behind = behind || p.w() <= T(0);
        if (!behind)
            area += (p.x() / p.w()) * (q.y() / q.w()) - (q.x() / q.w()) * (p.y() / p.w());
    }
    return {area, behind};
}

} // namespace

EffectOutcomes runEffects(const Pipeline<double>& pipeline, const std::vector<PolygonMesh>& objects,
                          const EffectList& effects, const Mat4<Exact>* exactClip)
{
    EffectOutcomes outcomes;
    if (!effects.has(EffectKind::Clip) && !effects.has(EffectKind::Cull) && !effects.depth && !effects.raster)
        return outcomes; // nothing that looks at the objects
    const ClipPoints points = clipPoints(pipeline.clipMatrix(), objects);
    const VertexVerdicts verdicts(pipeline.clipMatrix(), exactClip, pipeline.clipVolume);
    if (effects.has(EffectKind::Clip)) {
        outcomes.computed.push_back(EffectKind::Clip);
        ClipOutcome c;
        for (std::size_t o = 0; o < objects.size(); ++o) {
            const PolygonMesh& mesh = objects[o];
            const std::vector<Vec4<double>>& h = points[o];
            std::vector<unsigned> codes;
            for (std::size_t i = 0; i < h.size(); ++i)
                codes.push_back(verdicts.outcode(mesh.vertices[i], h[i]));
            std::vector<std::optional<std::array<double, 2>>> kept;
            for (const auto& e : meshEdgeIndices(mesh)) {
                const unsigned a = codes[std::size_t(e[0])], b = codes[std::size_t(e[1])];
                // The ends decide where they can: both inside, or both beyond one plane.
                auto interval = a == 0 && b == 0 ? std::optional<std::array<double, 2>>({0.0, 1.0})
                                : (a & b) != 0   ? std::nullopt
                                                 : clipSegment(h[std::size_t(e[0])], h[std::size_t(e[1])],
                                                               pipeline.clipVolume);
                ClipCounts& n = c.segments;
                if (!interval)
                    ++n.outside;
                else if (a == 0 && b == 0)
                    ++n.inside;
                else
                    ++n.clipped;
                kept.push_back(interval);
            }
            c.keptEdges.push_back(kept);
            for (const auto& face : mesh.faces) {
                std::vector<Vec4<double>> polygon;
                unsigned all = 0, every = ~0u;
                for (int i : face) {
                    polygon.push_back(h[std::size_t(i)]);
                    all |= codes[std::size_t(i)];
                    every &= codes[std::size_t(i)];
                }
                if (all == 0)
                    ++c.polygons.inside;
                else if (every == 0 && clipPolygon(polygon, pipeline.clipVolume).size() >= 3)
                    ++c.polygons.clipped;
                else
                    ++c.polygons.outside;
            }
        }
        outcomes.clip = c;
    }
    if (effects.depth) {
        outcomes.computed.push_back(EffectKind::Depth);
        DepthOptions options = *effects.depth;
        options.reversed = options.reversed || reversedDepth(pipeline.clipVolume); // the matrix reverses it
        outcomes.depth = depthOutcome(pipeline, objects, points, options, verdicts);
    }
    if (effects.has(EffectKind::Cull)) {
        outcomes.computed.push_back(EffectKind::Cull);
        CullOutcome c;
        for (std::size_t o = 0; o < objects.size(); ++o) {
            std::vector<bool> culled;
            for (const auto& face : objects[o].faces) {
                // Signed area of the face in the picture (x, y after the
                // divide), faces wound counter-clockwise seen from outside:
                // a front face keeps that winding seen from the viewer (+z),
                // or turns clockwise where the picture is mirrored.
                std::vector<Vec4<double>> corners;
                for (int i : face)
                    corners.push_back(points[o][std::size_t(i)]);
                auto [area, behind] = pictureArea(corners);
                double size = 0; // the terms' size: an area within 1e-9 of it, or a w near 0, is decided exactly
                for (const Vec4<double>& p : corners)
                    size = std::max(size, std::abs(p.x() / p.w()) + std::abs(p.y() / p.w()));
                const bool nearZero = std::abs(area) <= 1e-9 * size * size ||
                                      std::any_of(corners.begin(), corners.end(), [](const Vec4<double>& p) {
                                          return std::abs(p.w()) <= 1e-9 * p.head<3>().cwiseAbs().maxCoeff();
                                      });
                int sign = area > 0 ? 1 : area < 0 ? -1 : 0;
                if (verdicts.exact() && nearZero) {
                    std::vector<Vec4<Exact>> exact;
                    for (int i : face)
                        exact.push_back(verdicts.exactClipPoint(objects[o].vertices[std::size_t(i)]));
                    const auto [exactArea, exactBehind] = pictureArea(exact);
                    sign = exactArea.sign();
                    behind = exactBehind;
                }
                const bool back = !behind && (pipeline.frontFacesClockwise ? sign >= 0 : sign <= 0);
                culled.push_back(back);
                ++c.faces;
                c.culled += back;
            }
            c.culledFaces.push_back(culled);
        }
        outcomes.cull = c;
    }
    if (effects.raster) {
        outcomes.computed.push_back(EffectKind::Raster);
        outcomes.raster = rasterize(pipeline.clipVolume, pipeline.ndcYDown, objects, points, *effects.raster,
                                    outcomes.cull ? &outcomes.cull->culledFaces : nullptr);
    }
    return outcomes;
}

} // namespace viewpipe
