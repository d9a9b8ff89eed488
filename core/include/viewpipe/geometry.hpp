#pragma once

// The built-in objects as plain vertex and face lists (world coordinates).

#include <array>
#include <vector>

#include "viewpipe/linalg.hpp"

namespace viewpipe {

struct PolygonMesh {
    std::vector<Vec3<double>> vertices;
    std::vector<std::vector<int>> faces; // counter-clockwise seen from outside
};

// Foley's house: the front wall at z = 54 with vertices (0,0), (16,0), (16,10),
// (8,16), (0,10) in x, y; the same outline at z = 30; corresponding vertices
// joined.
inline PolygonMesh houseMesh()
{
    const std::array<std::array<double, 2>, 5> outline = {{{0, 0}, {16, 0}, {16, 10}, {8, 16}, {0, 10}}};
    PolygonMesh mesh;
    for (double z : {54.0, 30.0})
        for (const auto& xy : outline)
            mesh.vertices.emplace_back(xy[0], xy[1], z);
    mesh.faces.push_back({0, 1, 2, 3, 4});
    mesh.faces.push_back({9, 8, 7, 6, 5});
    for (int k = 0; k < 5; ++k) {
        const int next = (k + 1) % 5;
        mesh.faces.push_back({k, k + 5, next + 5, next});
    }
    return mesh;
}

inline PolygonMesh boxMesh(const Vec3<double>& lo, const Vec3<double>& hi)
{
    PolygonMesh mesh;
    for (int k = 0; k < 8; ++k)
        mesh.vertices.emplace_back(k & 1 ? hi.x() : lo.x(), k & 2 ? hi.y() : lo.y(), k & 4 ? hi.z() : lo.z());
    mesh.faces = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    return mesh;
}

} // namespace viewpipe
