#include "viewpipe/scene_objects.hpp"

#include <string>

#include "viewpipe/mesh_io.hpp"

namespace viewpipe {

std::vector<PolygonMesh> readObjectMeshes(const Scene& scene)
{
    std::vector<PolygonMesh> meshes;
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        const SceneObject& object = scene.objects[i];
        if (object.type == ObjectType::Mesh)
            meshes.push_back(readMeshFile(object.resolvedPath, "objects[" + std::to_string(i) + "].path"));
        else
            meshes.push_back(object.type == ObjectType::House ? houseMesh() : boxMesh(object.min, object.max));
    }
    return meshes;
}

std::vector<Vec3<double>> meshVertices(const std::vector<PolygonMesh>& meshes)
{
    std::vector<Vec3<double>> vertices;
    for (const PolygonMesh& mesh : meshes)
        vertices.insert(vertices.end(), mesh.vertices.begin(), mesh.vertices.end());
    return vertices;
}

Eigen::AlignedBox<double, 3> meshBounds(const std::vector<PolygonMesh>& meshes)
{
    Eigen::AlignedBox<double, 3> box;
    for (const Vec3<double>& p : meshVertices(meshes))
        box.extend(p);
    return box;
}

} // namespace viewpipe
