#include "VtkGeometry.h"
#include "MathTextRenderer.h"

#include <vtkActor.h>
#include <vtkNew.h>
#include <vtkCellArray.h>
#include <vtkIdTypeArray.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkTextProperty.h>
#include <vtkTextRenderer.h>

#include <cmath>
#include <fstream>

namespace viewpipe::gui {

vtkSmartPointer<vtkPolyData> linesData(const std::vector<Vec3<double>>& ends)
{
    auto points = vtkSmartPointer<vtkPoints>::New();
    points->SetDataTypeToDouble();
    points->SetNumberOfPoints(vtkIdType(ends.size()));
    auto lines = vtkSmartPointer<vtkCellArray>::New();
    for (std::size_t i = 0; i + 1 < ends.size(); i += 2) {
        points->SetPoint(vtkIdType(i), ends[i].data());
        points->SetPoint(vtkIdType(i + 1), ends[i + 1].data());
        const vtkIdType ids[2] = {vtkIdType(i), vtkIdType(i + 1)};
        lines->InsertNextCell(2, ids);
    }
    auto data = vtkSmartPointer<vtkPolyData>::New();
    data->SetPoints(points);
    data->SetLines(lines);
    return data;
}

vtkSmartPointer<vtkPolyData> linesData(const std::vector<Segment2>& segments)
{
    std::vector<Vec3<double>> ends;
    for (const Segment2& s : segments)
        for (const Vec2<double>& q : s)
            ends.emplace_back(q.x(), q.y(), 0);
    return linesData(ends);
}

vtkSmartPointer<vtkPolyData> facesData(const PolygonMesh& mesh)
{
    auto points = vtkSmartPointer<vtkPoints>::New();
    points->SetDataTypeToDouble();
    points->SetNumberOfPoints(vtkIdType(mesh.vertices.size()));
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i)
        points->SetPoint(vtkIdType(i), mesh.vertices[i].data());
    // Offsets and connectivity filled in one pass: a million faces take no per-cell insertion.
    auto offsets = vtkSmartPointer<vtkIdTypeArray>::New();
    auto connectivity = vtkSmartPointer<vtkIdTypeArray>::New();
    offsets->SetNumberOfValues(vtkIdType(mesh.faces.size() + 1));
    std::size_t total = 0;
    for (const std::vector<int>& face : mesh.faces)
        total += face.size();
    connectivity->SetNumberOfValues(vtkIdType(total));
    vtkIdType at = 0;
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
        offsets->SetValue(vtkIdType(f), at);
        for (int k : mesh.faces[f])
            connectivity->SetValue(at++, k);
    }
    offsets->SetValue(vtkIdType(mesh.faces.size()), at);
    auto polys = vtkSmartPointer<vtkCellArray>::New();
    polys->SetData(offsets, connectivity);
    auto data = vtkSmartPointer<vtkPolyData>::New();
    data->SetPoints(points);
    data->SetPolys(polys);
    return data;
}

vtkSmartPointer<vtkPolyData> edgesData(const PolygonMesh& mesh)
{
    std::vector<Vec3<double>> ends;
    for (const auto& e : meshEdgeIndices(mesh))
        ends.insert(ends.end(), {mesh.vertices[std::size_t(e[0])], mesh.vertices[std::size_t(e[1])]});
    return linesData(ends);
}

vtkSmartPointer<vtkActor> unlitActor(vtkPolyData* data)
{
    auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
    mapper->SetInputData(data);
    auto actor = vtkSmartPointer<vtkActor>::New();
    actor->SetMapper(mapper);
    actor->GetProperty()->LightingOff();
    return actor;
}

vtkSmartPointer<vtkPolyData> primitiveData(const Primitive& primitive)
{
    return primitive.kind == PrimitiveKind::Faces ? facesData(*primitive.faces) : linesData(primitive.segments);
}

// Text in the font the vector figures use (DejaVu Sans, Debian's fonts-dejavu-core), so that a label
// takes the same room in every picture; VTK's own font where it is missing.
Vec2<double> textSize(vtkTextProperty* font, const std::string& text, int dpi)
{
    useMathText(); // also what links the renderer (and its installation at start) into every program that measures
    int box[4] = {0, 0, 0, 0};
    vtkTextRenderer::GetInstance()->GetBoundingBox(font, text, box, dpi);
    return Vec2<double>(box[1] - box[0] + 1, box[3] - box[2] + 1);
}

Vec2<double> figureTextSize(const std::string& text, double fontSize, bool bold, int dpi)
{
    vtkNew<vtkTextProperty> font;
    useFigureFont(font, bold);
    font->SetFontSize(int(std::lround(fontSize)));
    return textSize(font, text, dpi);
}

void useFigureFont(vtkTextProperty* text, bool bold)
{
    const char* file = bold ? "/usr/share/fonts/truetype/dejavu/DejaVuSans-Bold.ttf"
                            : "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
    static const bool present = std::ifstream(file).good();
    text->SetBold(bold);
    text->SetLineSpacing(1.25); // lines of a caption apart: at VTK's 1.1 the descenders touched the next line
    if (present) {
        text->SetFontFamily(VTK_FONT_FILE);
        text->SetFontFile(file);
    }
}

} // namespace viewpipe::gui
