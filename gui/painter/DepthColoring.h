#pragma once

// Faces colored by the value the depth buffer stores for them, in bands that
// show its quantization (the depth effect).

#include <vtkSmartPointer.h>

#include <memory>

#include "viewpipe/effects.hpp"

class vtkActor;
class vtkLookupTable;
class vtkPolyData;

namespace viewpipe::gui {

// Faces cut into triangles no longer than a 32nd of the object's size (the
// stored level is not affine across a face seen in perspective, so colors are
// computed at many points; a mesh with many faces is fine enough as it is),
// each point carrying the level the depth buffer stores for it, or NaN where
// it stores nothing.
vtkSmartPointer<vtkPolyData> depthLevels(const std::shared_ptr<const PolygonMesh>& faces, const Pipeline<double>& pipeline,
                                         const DepthOptions& options);

// The bands' colors (bandColor) by level, grey where the buffer stores nothing.
vtkSmartPointer<vtkLookupTable> bandColors(const DepthBands& bands);

// Each pixel of the actor's faces takes its band's color: sharp edges between bands.
void colorByLevels(vtkActor* actor, vtkLookupTable* table);

} // namespace viewpipe::gui
