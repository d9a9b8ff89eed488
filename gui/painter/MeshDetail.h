#pragma once

// A mesh's poly data at full detail and, for a large mesh, a decimated copy
// to draw while the view moves (ParaView's way of keeping motion smooth on
// software renderers): the copy is made once per mesh, off the GUI thread;
// until it is ready the full mesh is drawn. Every picture at rest, and every
// export, draws the full mesh.

#include <vtkActor.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkSmartPointer.h>

#include <future>
#include <map>
#include <memory>
#include <vector>

#include "viewpipe/geometry.hpp"

namespace viewpipe::gui {

class MeshDetail {
public:
    // Meshes with fewer faces are drawn at full detail while moving too.
    static constexpr std::size_t kLargeFaces = 100'000;
    // About as many triangles as the decimated copy has (llvmpipe draws them in a few milliseconds).
    static constexpr double kCoarseTriangles = 30'000;

    explicit MeshDetail(std::shared_ptr<const PolygonMesh> mesh);
    ~MeshDetail();
    MeshDetail(const MeshDetail&) = delete;
    MeshDetail& operator=(const MeshDetail&) = delete;

    bool large() const { return mesh_->faces.size() >= kLargeFaces; }
    vtkPolyData* full() const { return full_; }
    // The decimated copy once it is made; null before, and for a small mesh. Never waits.
    vtkPolyData* coarse();

private:
    std::shared_ptr<const PolygonMesh> mesh_;
    vtkSmartPointer<vtkPolyData> full_, coarse_;
    std::future<vtkSmartPointer<vtkPolyData>> making_;
};

// An actor that draws a mesh from its decimated copy while the view moves
// (once the copy is made) and from the full mesh at rest. Its property is
// shared by both: color and opacity are styled once.
class DetailedActor {
public:
    explicit DetailedActor(std::shared_ptr<MeshDetail> mesh);
    vtkActor* actor() const { return actor_; }
    void setMoving(bool moving);
    // Both mappers, for what applies to whichever is drawn (the near cut).
    std::vector<vtkMapper*> mappers() const;

private:
    std::shared_ptr<MeshDetail> mesh_;
    vtkSmartPointer<vtkActor> actor_;
    vtkSmartPointer<vtkPolyDataMapper> full_, coarse_;
};

// Each mesh's poly data by mesh: one copy, however many views draw the mesh.
using MeshDetails = std::map<const PolygonMesh*, std::shared_ptr<MeshDetail>>;

} // namespace viewpipe::gui
