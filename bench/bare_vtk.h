#pragma once

// What the benchmarks' bare VTK viewers share: a PLY file as VTK's own reader
// reads it, and an evaluated scene's primitives drawn by plain VTK actors.

#include <vtkActor.h>
#include <vtkNew.h>
#include <vtkPLYReader.h>
#include <vtkPolyData.h>
#include <vtkProperty.h>
#include <vtkSmartPointer.h>

#include <string>
#include <vector>

#include "painter/VtkGeometry.h"
#include "viewpipe/evaluated_scene.hpp"

namespace viewpipe::bench {

inline vtkSmartPointer<vtkPolyData> readWithVtk(const std::string& file)
{
    vtkNew<vtkPLYReader> reader;
    reader->SetFileName(file.c_str());
    reader->Update();
    return reader->GetOutput();
}

// One unlit actor a primitive, at the primitive's opacity.
inline std::vector<vtkSmartPointer<vtkActor>> primitiveActors(const EvaluatedScene& scene)
{
    std::vector<vtkSmartPointer<vtkActor>> actors;
    for (const Primitive& p : scene.primitives) {
        actors.push_back(gui::unlitActor(gui::primitiveData(p)));
        actors.back()->GetProperty()->SetOpacity(p.opacity);
    }
    return actors;
}

} // namespace viewpipe::bench
