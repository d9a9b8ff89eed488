#include "MeshDetail.h"
#include "VtkGeometry.h"

#include <vtkActor.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkQuadricClustering.h>

#include <algorithm>
#include <cmath>

#include "viewpipe/evaluated_scene.hpp"

namespace viewpipe::gui {
namespace {

constexpr double kMostCubes = 1 << 20; // the clustering keeps about 90 bytes a cube while it runs

// Triangles are clustered into cubes of one size, chosen from the mesh's area
// so that the copy has about kCoarseTriangles triangles (two a cube crossed),
// larger where the cubes across the mesh's box would be too many.
vtkSmartPointer<vtkPolyData> decimated(const std::shared_ptr<const PolygonMesh>& shared)
{
    const PolygonMesh& mesh = *shared;
    double area = 0;
    for (const auto& face : mesh.faces)
        for (std::size_t k = 1; k + 1 < face.size(); ++k) {
            const Vec3<double>& a = mesh.vertices[std::size_t(face[0])];
            area += 0.5 * (mesh.vertices[std::size_t(face[k])] - a).cross(mesh.vertices[std::size_t(face[k + 1])] - a).norm();
        }
    Eigen::AlignedBox<double, 3> box = boundsOf({shared}); // not const: VTK takes the origin as double*
    const Vec3<double> extent = box.diagonal();
    double side = area > 0 ? std::sqrt(2 * area / MeshDetail::kCoarseTriangles) : extent.norm() / 100;
    const auto cubes = [&] { return (extent / side).array().ceil().max(1).prod(); };
    while (side > 0 && cubes() > kMostCubes)
        side *= 1.25;
    if (!(side > 0))
        return vtkSmartPointer<vtkPolyData>::New(); // every vertex at one point: nothing to draw
    vtkNew<vtkQuadricClustering> clustering;
    clustering->SetDivisionOrigin(box.min().data()); // cubes of this side from the corner
    clustering->SetDivisionSpacing(side, side, side);
    clustering->CopyCellDataOff();
    clustering->SetInputData(facesData(shared, Coordinates::Exact)); // its own VTK objects over the mesh: nothing the GUI thread draws is touched
    clustering->Update();
    return clustering->GetOutput();
}

} // namespace

MeshDetail::MeshDetail(std::shared_ptr<const PolygonMesh> mesh) : mesh_(std::move(mesh)), full_(facesData(mesh_, Coordinates::Drawn))
{
    if (large())
        making_ = std::async(std::launch::async, [mesh = mesh_] { return decimated(mesh); });
}

MeshDetail::~MeshDetail()
{
    if (making_.valid())
        making_.wait(); // it reads the mesh
}

vtkPolyData* MeshDetail::coarse()
{
    if (making_.valid() && making_.wait_for(std::chrono::seconds(0)) == std::future_status::ready)
        coarse_ = making_.get();
    return coarse_;
}

DetailedActor::DetailedActor(std::shared_ptr<MeshDetail> mesh)
    : mesh_(std::move(mesh)), actor_(unlitActor(mesh_->full())),
      full_(static_cast<vtkPolyDataMapper*>(actor_->GetMapper()))
{
    if (mesh_->large())
        coarse_ = vtkSmartPointer<vtkPolyDataMapper>::New();
}

void DetailedActor::setMoving(bool moving)
{
    vtkPolyData* coarse = moving && coarse_ ? mesh_->coarse() : nullptr;
    if (coarse && coarse_->GetInput() != coarse)
        coarse_->SetInputData(coarse);
    vtkMapper* drawn = coarse ? coarse_.Get() : full_.Get();
    if (actor_->GetMapper() != drawn)
        actor_->SetMapper(drawn);
}

std::vector<vtkMapper*> DetailedActor::mappers() const
{
    return coarse_ ? std::vector<vtkMapper*>{full_, coarse_} : std::vector<vtkMapper*>{full_};
}

} // namespace viewpipe::gui
