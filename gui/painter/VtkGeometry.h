#pragma once

// The evaluated scene's primitives as VTK poly data (double precision points), and the pictures' font.

#include <vtkSmartPointer.h>

#include <memory>
#include <vector>

#include "viewpipe/evaluated_scene.hpp"
#include "viewpipe/report/figure.hpp"

class vtkActor;
class vtkPolyData;
class vtkTextProperty;

namespace viewpipe::gui {

// Lines from end points by pairs.
vtkSmartPointer<vtkPolyData> linesData(const std::vector<Vec3<double>>& ends);
// Lines in a picture's plane (z = 0).
vtkSmartPointer<vtkPolyData> linesData(const std::vector<Segment2>& segments);
// A mesh's vertices as VTK gets them: Exact, its own doubles (no copy), for filters that compute with
// them; Drawn, in float where VTK would draw them unshifted (one copy, uploaded as it is by every view).
enum class Coordinates { Exact, Drawn };
// A mesh's faces over its own indices (no copy; the poly data keeps the mesh).
vtkSmartPointer<vtkPolyData> facesData(const std::shared_ptr<const PolygonMesh>& mesh, Coordinates coordinates);
// A mesh's edges, once each.
vtkSmartPointer<vtkPolyData> edgesData(const PolygonMesh& mesh);
vtkSmartPointer<vtkPolyData> primitiveData(const Primitive& primitive);
// An actor drawing poly data in flat colors (lighting off: the elements are diagrams, not lit surfaces).
vtkSmartPointer<vtkActor> unlitActor(vtkPolyData* data);

// Text in the font the vector figures use (DejaVu Sans, Debian's fonts-dejavu-core), so that a label
// takes the same room in every picture; VTK's own font where it is missing.
void useFigureFont(vtkTextProperty* text, bool bold);
// The pixels a text takes in a font at a resolution: width, height.
Vec2<double> textSize(vtkTextProperty* font, const std::string& text, int dpi);
// The same for the pictures' font at a size, at 72 dots per inch: what every figure measures its texts with.
Vec2<double> figureTextSize(const std::string& text, double fontSize, bool bold, int dpi = 72);
// figureTextSize as the layouts take it.
report::FontMeasure figureFontMeasure(int dpi = 72);

} // namespace viewpipe::gui
