#pragma once

// A scene's objects as the core's polygon meshes (no VTK): the built-in
// objects from geometry.hpp, mesh files through the core's reader.

#include <vector>

#include "viewpipe/geometry.hpp"
#include "viewpipe/scene.hpp"

namespace viewpipe {

// Each object's mesh, in world coordinates, in the scene's order. Throws
// InputError naming "objects[k].path" for a mesh file that cannot be read.
std::vector<PolygonMesh> readObjectMeshes(const Scene& scene);

// Every vertex of the meshes, and the box around them (empty without any).
std::vector<Vec3<double>> meshVertices(const std::vector<PolygonMesh>& meshes);
Eigen::AlignedBox<double, 3> meshBounds(const std::vector<PolygonMesh>& meshes);

} // namespace viewpipe
