#pragma once

// The one adapter between Eigen matrices and vtkMatrix4x4. Both are indexed
// (row, column); Eigen stores column-major and VTK row-major, so the copy goes
// element by element, never through raw storage.

#include <vtkMatrix4x4.h>
#include <vtkSmartPointer.h>

#include "viewpipe/linalg.hpp"

namespace viewpipe::gui {

inline vtkSmartPointer<vtkMatrix4x4> toVtk(const Mat4<double>& m)
{
    auto out = vtkSmartPointer<vtkMatrix4x4>::New();
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c)
            out->SetElement(r, c, m(r, c));
    return out;
}

inline Mat4<double> fromVtk(const vtkMatrix4x4* m)
{
    Mat4<double> out;
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c)
            out(r, c) = m->GetElement(r, c);
    return out;
}

} // namespace viewpipe::gui
