#include "viewpipe/effects.hpp"

#include <algorithm>
#include <mutex>

namespace viewpipe {
namespace {

std::mutex runsMutex;
std::map<std::string, long> runs;


// The six boundary values of a homogeneous point: inside where all are >= 0.
std::array<double, 6> boundaries(const Vec4<double>& p, ClipVolume volume)
{
    const double w = p.w();
    const double zFar = p.z() + w;                                             // z >= -w
    const double zNear = volume == ClipVolume::FoleyParallel ? -p.z() : w - p.z(); // z <= 0, or z <= w
    return {w + p.x(), w - p.x(), w + p.y(), w - p.y(), zNear, zFar};
}

} // namespace

void countEffectRun(const std::string& effect)
{
    std::lock_guard<std::mutex> lock(runsMutex);
    ++runs[effect];
}

std::map<std::string, long> effectRuns()
{
    std::lock_guard<std::mutex> lock(runsMutex);
    return runs;
}

unsigned outcode(const Vec4<double>& clip, ClipVolume volume)
{
    const std::array<double, 6> b = boundaries(clip, volume);
    unsigned code = 0;
    for (int k = 0; k < 6; ++k)
        if (b[std::size_t(k)] < 0)
            code |= 1u << k;
    return code;
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
    const std::array<double, 6> ba = boundaries(a, volume), bb = boundaries(b, volume);
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
        std::vector<Vec4<double>> next;
        for (std::size_t i = 0; i < out.size(); ++i) {
            const Vec4<double>& p = out[i];
            const Vec4<double>& q = out[(i + 1) % out.size()];
            const double bp = boundaries(p, volume)[k], bq = boundaries(q, volume)[k];
            if (bp >= 0)
                next.push_back(p);
            if ((bp >= 0) != (bq >= 0))
                next.push_back(p + (bp / (bp - bq)) * (q - p));
        }
        out = std::move(next);
    }
    return out;
}

std::vector<std::array<int, 2>> meshEdgeIndices(const PolygonMesh& mesh)
{
    std::vector<std::array<int, 2>> edges;
    for (const std::vector<int>& face : mesh.faces)
        for (std::size_t k = 0; k < face.size(); ++k) {
            const int a = face[k], b = face[(k + 1) % face.size()];
            const std::array<int, 2> key = {std::min(a, b), std::max(a, b)};
            if (std::find(edges.begin(), edges.end(), key) == edges.end())
                edges.push_back(key);
        }
    return edges;
}

EffectOutcomes runEffects(const Pipeline<double>& pipeline, const std::vector<PolygonMesh>& objects,
                          const EffectList& effects)
{
    EffectOutcomes outcomes;
    const Mat4<double> clip = pipeline.toClip * pipeline.composite;
    auto toClip = [&clip](const Vec3<double>& p) { return Vec4<double>(clip * p.homogeneous()); };
    if (effects.clip) {
        countEffectRun("clip");
        ClipOutcome c;
        for (const PolygonMesh& mesh : objects) {
            std::vector<std::optional<std::array<double, 2>>> kept;
            for (const auto& e : meshEdgeIndices(mesh)) {
                const auto interval = clipSegment(toClip(mesh.vertices[std::size_t(e[0])]),
                                                  toClip(mesh.vertices[std::size_t(e[1])]), pipeline.clipVolume);
                ClipCounts& n = c.segments;
                if (!interval)
                    ++n.outside;
                else if ((*interval)[0] == 0 && (*interval)[1] == 1)
                    ++n.inside;
                else
                    ++n.clipped;
                kept.push_back(interval);
            }
            c.keptEdges.push_back(kept);
            for (const std::vector<int>& face : mesh.faces) {
                std::vector<Vec4<double>> polygon;
                unsigned all = 0;
                for (int i : face) {
                    polygon.push_back(toClip(mesh.vertices[std::size_t(i)]));
                    all |= outcode(polygon.back(), pipeline.clipVolume);
                }
                if (all == 0)
                    ++c.polygons.inside;
                else if (clipPolygon(polygon, pipeline.clipVolume).size() >= 3)
                    ++c.polygons.clipped;
                else
                    ++c.polygons.outside;
            }
        }
        outcomes.clip = c;
    }
    if (effects.cull) {
        countEffectRun("cull");
        CullOutcome c;
        for (const PolygonMesh& mesh : objects) {
            std::vector<bool> culled;
            for (const std::vector<int>& face : mesh.faces) {
                // Signed area of the face in the picture (x, y after the
                // divide), faces wound counter-clockwise seen from outside:
                // a front face keeps that winding seen from the viewer (+z).
                double area = 0;
                bool behind = false;
                for (std::size_t k = 0; k < face.size(); ++k) {
                    const Vec4<double> p = toClip(mesh.vertices[std::size_t(face[k])]);
                    const Vec4<double> q = toClip(mesh.vertices[std::size_t(face[(k + 1) % face.size()])]);
                    behind = behind || p.w() <= 0;
                    area += (p.x() / p.w()) * (q.y() / q.w()) - (q.x() / q.w()) * (p.y() / p.w());
                }
                const bool back = !behind && area <= 0;
                culled.push_back(back);
                ++c.faces;
                c.culled += back;
            }
            c.culledFaces.push_back(culled);
        }
        outcomes.cull = c;
    }
    return outcomes;
}

} // namespace viewpipe
