#include "VtkGeometry.h"
#include "MathTextRenderer.h"

#include <vtkActor.h>
#include <vtkNew.h>
#include <vtkCallbackCommand.h>
#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkTypeInt32Array.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkTextProperty.h>
#include <vtkTextRenderer.h>

#include <cmath>
#include <fstream>
#include <map>
#include <mutex>
#include <tuple>

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

namespace {

// A VTK array over a mesh's own values, without a copy; it keeps the mesh
// alive until VTK releases it. VTK's arrays are not const: those drawn are
// only read.
template <class Array, class Value>
vtkSmartPointer<Array> arrayOver(const Value* values, std::size_t count, int components,
                                 const std::shared_ptr<const PolygonMesh>& mesh)
{
    auto array = vtkSmartPointer<Array>::New();
    array->SetNumberOfComponents(components);
    array->SetArray(const_cast<Value*>(values), vtkIdType(count) * components, 1); // 1: VTK never frees it
    auto keep = vtkSmartPointer<vtkCallbackCommand>::New();
    keep->SetClientData(new std::shared_ptr<const PolygonMesh>(mesh));
    keep->SetCallback([](vtkObject*, unsigned long, void* held, void*) {
        delete static_cast<std::shared_ptr<const PolygonMesh>*>(held);
    });
    array->AddObserver(vtkCommand::DeleteEvent, keep);
    return array;
}

// Whether VTK draws a mesh's coordinates as they are, not shifted and scaled
// first: its own test (vtkOpenGLVertexBufferObject's automatic shift and
// scale), a mesh near the origin for its size, neither very large nor very small.
bool vtkDrawsUnshifted(const std::shared_ptr<const PolygonMesh>& mesh)
{
    const Eigen::AlignedBox<double, 3> box = boundsOf({mesh});
    const double diagonal2 = box.isEmpty() ? 0 : box.diagonal().squaredNorm();
    return diagonal2 > 0 && box.center().squaredNorm() / diagonal2 <= 1e6 && std::abs(std::log10(diagonal2)) <= 3;
}

// A mesh's vertices for VTK: the mesh's own doubles, or for drawing a float copy
// where VTK draws them unshifted. There VTK packs the doubles into the same
// floats itself, one copy for each view, and keeps it; a float copy it uploads
// as it is, so the views share one and the picture is the same bit for bit.
vtkSmartPointer<vtkDataArray> vertices(const std::shared_ptr<const PolygonMesh>& mesh, Coordinates coordinates)
{
    static_assert(sizeof(Vec3<double>) == 3 * sizeof(double));
    if (coordinates == Coordinates::Exact || !vtkDrawsUnshifted(mesh))
        return arrayOver<vtkDoubleArray>(mesh->vertices.data()->data(), mesh->vertices.size(), 3, mesh);
    auto floats = vtkSmartPointer<vtkFloatArray>::New();
    floats->SetNumberOfComponents(3);
    floats->SetNumberOfTuples(vtkIdType(mesh->vertices.size()));
    float* out = floats->GetPointer(0);
    for (const Vec3<double>& v : mesh->vertices)
        for (int k = 0; k < 3; ++k)
            *out++ = float(v[k]);
    return floats;
}

} // namespace

vtkSmartPointer<vtkPolyData> facesData(const std::shared_ptr<const PolygonMesh>& mesh, Coordinates coordinates)
{
    static_assert(sizeof(int) == sizeof(vtkTypeInt32));
    auto points = vtkSmartPointer<vtkPoints>::New();
    points->SetData(vertices(mesh, coordinates));
    const FaceList& faces = mesh->faces;
    auto polys = vtkSmartPointer<vtkCellArray>::New();
    polys->SetData(arrayOver<vtkTypeInt32Array>(faces.offsets().data(), faces.offsets().size(), 1, mesh),
                   arrayOver<vtkTypeInt32Array>(faces.indices().data(), faces.indices().size(), 1, mesh));
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
    return primitive.kind == PrimitiveKind::Faces ? facesData(primitive.faces, Coordinates::Drawn)
                                                  : linesData(primitive.segments);
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
    // Each text measured once: the painter measures every label before each frame, and a
    // picture's layout measures its caption's words again for each way of breaking its lines.
    using Key = std::tuple<std::string, long, bool, int>;
    static std::map<Key, Vec2<double>> measured;
    static std::mutex measuring;
    const Key key{text, std::lround(fontSize), bold, dpi};
    {
        const std::lock_guard<std::mutex> lock(measuring);
        if (const auto found = measured.find(key); found != measured.end())
            return found->second;
    }
    vtkNew<vtkTextProperty> font;
    useFigureFont(font, bold);
    font->SetFontSize(int(std::get<1>(key)));
    const Vec2<double> size = textSize(font, text, dpi);
    const std::lock_guard<std::mutex> lock(measuring);
    if (measured.size() >= 20000) // a bound for a long session's many texts
        measured.clear();
    measured.emplace(key, size);
    return size;
}

report::FontMeasure figureFontMeasure(int dpi)
{
    return [dpi](const std::string& text, double pixels, bool bold) { return figureTextSize(text, pixels, bold, dpi); };
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
