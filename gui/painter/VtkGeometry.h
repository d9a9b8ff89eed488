#pragma once

// The evaluated scene's primitives as VTK poly data (double precision points).

#include <vtkSmartPointer.h>

#include <vector>

#include "viewpipe/evaluated_scene.hpp"

class vtkActor;
class vtkPolyData;

namespace viewpipe::gui {

// Lines from end points by pairs.
vtkSmartPointer<vtkPolyData> linesData(const std::vector<Vec3<double>>& ends);
// Lines in a picture's plane (z = 0).
vtkSmartPointer<vtkPolyData> linesData(const std::vector<Segment2>& segments);
vtkSmartPointer<vtkPolyData> facesData(const PolygonMesh& mesh);
// A mesh's edges, once each.
vtkSmartPointer<vtkPolyData> edgesData(const PolygonMesh& mesh);
vtkSmartPointer<vtkPolyData> primitiveData(const Primitive& primitive);
// An actor drawing poly data in flat colors (lighting off: the elements are diagrams, not lit surfaces).
vtkSmartPointer<vtkActor> unlitActor(vtkPolyData* data);

} // namespace viewpipe::gui
