#include "ScenePainter.h"

#include "viewpipe/mesh_io.hpp"

#include <vtkActor.h>
#include <vtkAdaptiveSubdivisionFilter.h>
#include <vtkDoubleArray.h>
#include <vtkLookupTable.h>
#include <vtkTriangleFilter.h>
#include <vtkBillboardTextActor3D.h>
#include <vtkCallbackCommand.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCleanPolyData.h>
#include <vtkCommand.h>
#include <vtkConeSource.h>
#include <vtkPointData.h>
#include <vtkPointPicker.h>
#include <vtkPolyDataAlgorithm.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkPropCollection.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSphereSource.h>
#include <vtkActor2D.h>
#include <vtkCoordinate.h>
#include <vtkLegendBoxActor.h>
#include <vtkPolyDataMapper2D.h>
#include <vtkProperty2D.h>
#include <vtkTextActor.h>
#include <vtkTextRenderer.h>
#include <vtkUnsignedCharArray.h>
#include <vtkTextProperty.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "EigenVtk.h"
#include "viewpipe/classical.hpp"
#include "viewpipe/geometry.hpp"

namespace viewpipe::gui {

struct ScenePainter::Layer {
    Element element;
    bool surface;
    double opacity;
    vtkSmartPointer<vtkPolyData> original; // world coordinates
    vtkSmartPointer<vtkPolyData> shown;    // through the cumulative matrix
    vtkSmartPointer<vtkActor> actor;
};

struct ScenePainter::Label {
    Element element;
    Vec3<double> world;
    vtkSmartPointer<vtkBillboardTextActor3D> actor;
};

// A line of a view's legend: a swatch of how an element is drawn, and what it is.
struct ScenePainter::LegendEntry {
    enum class Swatch { Line, Face, Dot, Bands, Pixels };
    std::string text;
    Element element; // whose color the swatch takes (bands and pixels have their own)
    Swatch swatch;
    double opacity = 1; // as drawn over the background: ghosts are faint
};

namespace {

using Segment = std::pair<Vec3<double>, Vec3<double>>;

vtkSmartPointer<vtkPolyData> linesData(const std::vector<Segment>& segments)
{
    auto points = vtkSmartPointer<vtkPoints>::New();
    points->SetDataTypeToDouble();
    auto lines = vtkSmartPointer<vtkCellArray>::New();
    for (const Segment& s : segments) {
        const vtkIdType a = points->InsertNextPoint(s.first.data());
        const vtkIdType b = points->InsertNextPoint(s.second.data());
        const vtkIdType ids[2] = {a, b};
        lines->InsertNextCell(2, ids);
    }
    auto data = vtkSmartPointer<vtkPolyData>::New();
    data->SetPoints(points);
    data->SetLines(lines);
    return data;
}

vtkSmartPointer<vtkPolyData> facesData(const PolygonMesh& mesh)
{
    auto points = vtkSmartPointer<vtkPoints>::New();
    points->SetDataTypeToDouble();
    for (const Vec3<double>& v : mesh.vertices)
        points->InsertNextPoint(v.data());
    auto polys = vtkSmartPointer<vtkCellArray>::New();
    for (const std::vector<int>& face : mesh.faces) {
        std::vector<vtkIdType> ids(face.begin(), face.end());
        polys->InsertNextCell(vtkIdType(ids.size()), ids.data());
    }
    auto data = vtkSmartPointer<vtkPolyData>::New();
    data->SetPoints(points);
    data->SetPolys(polys);
    return data;
}

// The mesh's edges once each, in the core's order (the clip effect's too).
std::vector<Segment> meshEdges(const PolygonMesh& mesh)
{
    std::vector<Segment> edges;
    for (const auto& e : meshEdgeIndices(mesh))
        edges.emplace_back(mesh.vertices[std::size_t(e[0])], mesh.vertices[std::size_t(e[1])]);
    return edges;
}

PolygonMesh quad(const Vec3<double>& a, const Vec3<double>& b, const Vec3<double>& c, const Vec3<double>& d)
{
    return {{a, b, c, d}, {{0, 1, 2, 3}}};
}

// The segment that spans collinear points.
Segment span(const std::vector<Vec3<double>>& points)
{
    const Vec3<double> direction = (points.back() - points.front()).normalized();
    auto along = [&](const Vec3<double>& p) { return (p - points.front()).dot(direction); };
    const auto [lo, hi] = std::minmax_element(points.begin(), points.end(),
                                              [&](const auto& a, const auto& b) { return along(a) < along(b); });
    return {*lo, *hi};
}

// Meshes are read by the core's reader, which refuses hostile files (VTK 9.1's readers crash on them).
vtkSmartPointer<vtkPolyData> readMesh(const SceneObject& object, std::size_t index)
{
    return facesData(readMeshFile(object.resolvedPath, "objects[" + std::to_string(index) + "].path"));
}

// Calls `visit` with each point through `m` and the divide. Returns false,
// stopping early, when a point has no image (behind the eye, on the eye
// plane, or not finite): its element is then hidden, never drawn as NaN.
std::optional<Vec3<double>> project(const Mat4<double>& m, const Vec3<double>& p)
{
    const Vec4<double> h = m * p.homogeneous();
    if (!(h.w() > 1e-9 * h.head<3>().cwiseAbs().maxCoeff()) || !h.allFinite())
        return std::nullopt;
    return Vec3<double>(h.head<3>() / h.w());
}

template <class Visit> bool projectPoints(vtkPoints* points, const Mat4<double>& m, Visit&& visit)
{
    for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i) {
        const double* p = points->GetPoint(i);
        const std::optional<Vec3<double>> q = project(m, Vec3<double>(p[0], p[1], p[2]));
        if (!q)
            return false;
        visit(i, *q);
    }
    return true;
}

vtkSmartPointer<vtkPolyData> sourceOutput(vtkPolyDataAlgorithm* source)
{
    source->Update();
    auto data = vtkSmartPointer<vtkPolyData>::New();
    data->DeepCopy(source->GetOutput());
    data->GetPointData()->Initialize();
    auto points = vtkSmartPointer<vtkPoints>::New();
    points->SetDataTypeToDouble();
    points->DeepCopy(data->GetPoints());
    data->SetPoints(points);
    return data;
}

vtkSmartPointer<vtkPolyData> sphere(const Vec3<double>& center, double radius)
{
    auto source = vtkSmartPointer<vtkSphereSource>::New();
    source->SetCenter(center.data());
    source->SetRadius(radius);
    source->SetThetaResolution(16);
    source->SetPhiResolution(12);
    return sourceOutput(source);
}

vtkSmartPointer<vtkPolyData> arrowHead(const Vec3<double>& tip, const Vec3<double>& direction, double length)
{
    auto source = vtkSmartPointer<vtkConeSource>::New();
    const Vec3<double> d = direction.normalized();
    const Vec3<double> center = tip - d * (length / 2);
    source->SetCenter(center.data());
    source->SetDirection(d.data());
    source->SetHeight(length);
    source->SetRadius(length * 0.3);
    source->SetResolution(20);
    return sourceOutput(source);
}

// Foley's canonical parallel volume (z in [-1, 0]) to OpenGL's NDC cube, so
// that VTK's camera can show what a Foley view sees: z_gl = -2 z - w.
Mat4<double> foleyToGlClip()
{
    Mat4<double> d = Mat4<double>::Identity();
    d(2, 2) = -2;
    d(2, 3) = -1;
    return d;
}

// Faces cut into triangles no longer than a 32nd of the object's size (the
// stored level is not affine across a face seen in perspective, so colors are
// computed at many points; a mesh with many faces is fine enough as it is),
// each point carrying the level the depth buffer stores for it, or NaN where
// it stores nothing.
vtkSmartPointer<vtkPolyData> depthLevels(const PolygonMesh& faces, const Pipeline<double>& pipeline,
                                         const DepthOptions& options)
{
    // Only the points of these faces: the others must not widen the bands' range.
    auto used = vtkSmartPointer<vtkCleanPolyData>::New();
    used->SetInputData(facesData(faces));
    used->PointMergingOff();
    used->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
    auto data = vtkSmartPointer<vtkPolyData>::New();
    if (faces.faces.size() > 50000) {
        used->Update();
        data->ShallowCopy(used->GetOutput());
    } else {
        auto triangles = vtkSmartPointer<vtkTriangleFilter>::New();
        triangles->SetInputConnection(used->GetOutputPort());
        triangles->Update();
        auto fine = vtkSmartPointer<vtkAdaptiveSubdivisionFilter>::New();
        fine->SetInputConnection(triangles->GetOutputPort());
        fine->SetMaximumEdgeLength(triangles->GetOutput()->GetLength() / 32);
        fine->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
        fine->Update();
        data->ShallowCopy(fine->GetOutput());
    }
    auto levels = vtkSmartPointer<vtkDoubleArray>::New();
    levels->SetName("depth level");
    const Mat4<double> clip = pipeline.clipMatrix();
    for (vtkIdType i = 0; i < data->GetNumberOfPoints(); ++i) {
        const double* p = data->GetPoint(i);
        levels->InsertNextValue(depthLevelAt(clip, pipeline.clipVolume, Vec3<double>(p[0], p[1], p[2]), options)
                                    .value_or(std::numeric_limits<double>::quiet_NaN()));
    }
    data->GetPointData()->SetScalars(levels);
    return data;
}

// The depth bands' ramp from near (yellow) to far (violet); no red or
// orange in it, which mark z-fighting.
const double kBandRamp[][3] = {{0.99, 0.91, 0.15}, {0.37, 0.79, 0.38}, {0.13, 0.57, 0.55},
                               {0.23, 0.32, 0.55}, {0.27, 0.00, 0.33}};

// The raster effect's pixels, one color per object.
const unsigned char kRasterPalette[][3] = {{90, 140, 230}, {230, 120, 60}, {80, 190, 110}, {200, 90, 200}};

// Ghosts: how much of an edge clipped away and of a culled face still shows.
constexpr double kClippedOpacity = 0.2;
constexpr double kCulledOpacity = 0.06;

// Alternating light and dark steps along the ramp, so that neighbouring bands always differ.
vtkSmartPointer<vtkLookupTable> bandColors(const DepthBands& bands)
{
    auto table = vtkSmartPointer<vtkLookupTable>::New();
    table->SetNumberOfTableValues(bands.count);
    table->SetTableRange(bands.first, bands.first + bands.count * bands.levelsPerBand);
    for (int k = 0; k < bands.count; ++k) {
        const double t = bands.count > 1 ? 4.0 * k / (bands.count - 1) : 0;
        const int i = std::min(int(t), 3);
        const double f = t - i, shade = k % 2 ? 0.72 : 1.0;
        double c[3];
        for (int j = 0; j < 3; ++j)
            c[j] = shade * (kBandRamp[i][j] + f * (kBandRamp[i + 1][j] - kBandRamp[i][j]));
        table->SetTableValue(k, c[0], c[1], c[2], 1.0);
    }
    table->SetNanColor(0.5, 0.5, 0.5, 0.25);
    return table;
}

void colorByLevels(vtkActor* actor, vtkLookupTable* table)
{
    auto* mapper = vtkPolyDataMapper::SafeDownCast(actor->GetMapper());
    mapper->SetLookupTable(table);
    mapper->UseLookupTableScalarRangeOn();
    mapper->SetColorModeToMapScalars();
    mapper->InterpolateScalarsBeforeMappingOn(); // each pixel takes its band's color: sharp edges
    mapper->ScalarVisibilityOn();
}

// A legend's symbol: polygons in their colors within a box kSymbolWidth wide
// and 1 high, whose corners are points of every symbol so that the legend
// scales all alike.
constexpr double kSymbolWidth = 3;

vtkSmartPointer<vtkPolyData> legendSymbol(const std::vector<std::pair<std::vector<Vec2<double>>, Rgb>>& polygons)
{
    auto points = vtkSmartPointer<vtkPoints>::New();
    points->InsertNextPoint(-kSymbolWidth / 2, -0.5, 0);
    points->InsertNextPoint(kSymbolWidth / 2, 0.5, 0);
    auto cells = vtkSmartPointer<vtkCellArray>::New();
    auto colors = vtkSmartPointer<vtkUnsignedCharArray>::New();
    colors->SetNumberOfComponents(3);
    for (const auto& [corners, c] : polygons) {
        std::vector<vtkIdType> ids;
        for (const Vec2<double>& q : corners)
            ids.push_back(points->InsertNextPoint(q.x(), q.y(), 0));
        cells->InsertNextCell(vtkIdType(ids.size()), ids.data());
        const unsigned char rgb[3] = {static_cast<unsigned char>(std::lround(255 * c.r)),
                                      static_cast<unsigned char>(std::lround(255 * c.g)),
                                      static_cast<unsigned char>(std::lround(255 * c.b))};
        colors->InsertNextTypedTuple(rgb);
    }
    auto data = vtkSmartPointer<vtkPolyData>::New();
    data->SetPoints(points);
    data->SetPolys(cells);
    data->GetCellData()->SetScalars(colors);
    return data;
}

// Side by side stripes of the given colors, as tall as `halfHeight` above and below the middle.
vtkSmartPointer<vtkPolyData> stripes(const std::vector<Rgb>& colors, double halfHeight)
{
    std::vector<std::pair<std::vector<Vec2<double>>, Rgb>> polygons;
    const double width = kSymbolWidth / double(colors.size());
    for (std::size_t k = 0; k < colors.size(); ++k) {
        const double left = -kSymbolWidth / 2 + double(k) * width;
        polygons.push_back({{{left, -halfHeight}, {left + width, -halfHeight}, {left + width, halfHeight},
                             {left, halfHeight}},
                            colors[k]});
    }
    return legendSymbol(polygons);
}

vtkSmartPointer<vtkPolyData> dot(const Rgb& color)
{
    std::vector<Vec2<double>> circle;
    for (int k = 0; k < 16; ++k)
        circle.emplace_back(0.4 * std::cos(k * M_PI / 8), 0.4 * std::sin(k * M_PI / 8));
    return legendSymbol({{circle, color}});
}

Rgb blend(const Rgb& color, const double* background, double opacity)
{
    return {opacity * color.r + (1 - opacity) * background[0], opacity * color.g + (1 - opacity) * background[1],
            opacity * color.b + (1 - opacity) * background[2]};
}

std::string describeEffects(const EffectList& effects, const EffectOutcomes& outcomes, const Pipeline<double>& pipeline,
                        const std::optional<DepthBands>& bands)
{
    std::ostringstream note;
    for (const std::string& name : effects.names) {
        if (name == "clip" && outcomes.clip) {
            const ClipCounts& s = outcomes.clip->segments;
            note << "clip: " << s.inside << " edges inside, " << s.clipped << " cut, " << s.outside
                 << " outside (ghosted)\n";
        } else if (name == "divide") {
            note << (divideAddsStage(pipeline) ? "divide: stage " + pipeline.stages.back().symbol + " appended\n"
                                               : std::string("divide: none needed (parallel)\n"));
        } else if (name == "cull" && outcomes.cull) {
            note << "cull: " << outcomes.cull->culled << " of " << outcomes.cull->faces << " faces (ghosted)\n";
        } else if (name == "depth" && outcomes.depth) {
            const DepthOutcome& d = *outcomes.depth;
            note << "depth: " << depthFormatName(d.options);
            if (bands)
                note << "; each band " << (bands->levelsPerBand == 1 ? std::string("one stored value")
                                                                      : std::to_string(std::llround(bands->levelsPerBand)) +
                                                                            " stored values");
            if (!d.zFightingChecked)
                note << "; z-fighting not checked (too many faces)";
            else if (!d.zFighting.empty())
                note << "; " << d.zFighting.size() << " face pairs z-fight (orange-red)";
            note << "\n";
        } else if (name == "raster" && outcomes.raster) {
            note << "raster: " << outcomes.raster->width << " x " << outcomes.raster->height << ", "
                 << outcomes.raster->covered << " pixels covered (projected view)\n";
        }
    }
    std::string text = note.str();
    if (!text.empty())
        text.pop_back();
    return text;
}

} // namespace

void checkMeshes(const Scene& scene)
{
    for (std::size_t i = 0; i < scene.objects.size(); ++i)
        if (scene.objects[i].type == ObjectType::Mesh)
            readMesh(scene.objects[i], i);
}

namespace {

// An object's faces and, where it has them, its edges: the geometry every
// picture of it starts from.
using ObjectGeometry = std::pair<vtkSmartPointer<vtkPolyData>, std::vector<Segment>>;

ObjectGeometry objectGeometry(const SceneObject& object, std::size_t index)
{
    if (object.type == ObjectType::Mesh)
        return {readMesh(object, index), {}};
    const PolygonMesh mesh = object.type == ObjectType::House ? houseMesh() : boxMesh(object.min, object.max);
    return {facesData(mesh), meshEdges(mesh)};
}

// The faces of an object's geometry as the core's polygon mesh.
PolygonMesh polygonMesh(vtkPolyData* faces)
{
    PolygonMesh mesh;
    vtkPoints* points = faces->GetPoints();
    for (vtkIdType k = 0; k < points->GetNumberOfPoints(); ++k) {
        const double* p = points->GetPoint(k);
        mesh.vertices.emplace_back(p[0], p[1], p[2]);
    }
    vtkCellArray* polys = faces->GetPolys();
    polys->InitTraversal();
    vtkIdType count;
    const vtkIdType* ids;
    while (polys->GetNextCell(count, ids))
        mesh.faces.emplace_back(ids, ids + count);
    return mesh;
}

// Flat-shaded actors for an object's faces (translucent) and edges, colored for a theme.
std::vector<vtkSmartPointer<vtkActor>> objectActors(const ObjectGeometry& geometry, Theme theme)
{
    std::vector<vtkSmartPointer<vtkActor>> actors;
    for (bool surface : {true, false}) {
        if (!surface && geometry.second.empty())
            continue;
        auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
        mapper->SetInputData(surface ? geometry.first : linesData(geometry.second));
        auto actor = vtkSmartPointer<vtkActor>::New();
        actor->SetMapper(mapper);
        vtkProperty* p = actor->GetProperty();
        p->LightingOff();
        p->SetOpacity(surface ? 0.35 : 1.0);
        p->SetLineWidth(2);
        const Rgb c = ScenePainter::styledColor(Element::Objects, surface, theme);
        p->SetColor(c.r, c.g, c.b);
        actors.push_back(actor);
    }
    return actors;
}

} // namespace

std::vector<Vec3<double>> objectVertices(const Scene& scene)
{
    std::vector<Vec3<double>> vertices;
    for (const PolygonMesh& mesh : objectMeshes(scene))
        vertices.insert(vertices.end(), mesh.vertices.begin(), mesh.vertices.end());
    return vertices;
}

std::vector<PolygonMesh> objectMeshes(const Scene& scene)
{
    std::vector<PolygonMesh> meshes;
    for (std::size_t i = 0; i < scene.objects.size(); ++i)
        meshes.push_back(polygonMesh(objectGeometry(scene.objects[i], i).first));
    return meshes;
}

Eigen::AlignedBox<double, 3> objectBounds(const Scene& scene)
{
    Eigen::AlignedBox<double, 3> box;
    for (const Vec3<double>& p : objectVertices(scene))
        box.extend(p);
    return box;
}

void addObjectActors(const std::vector<vtkRenderer*>& renderers, const Scene& scene, Theme theme)
{
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        const ObjectGeometry geometry = objectGeometry(scene.objects[i], i);
        for (vtkRenderer* renderer : renderers)
            for (const auto& actor : objectActors(geometry, theme))
                renderer->AddActor(actor);
    }
}

ScenePainter::ScenePainter(vtkRenderer* world, vtkRenderer* projected)
    : world_(world), projected_(projected), worldCaption_(vtkSmartPointer<vtkTextActor>::New()),
      projectedCaption_(vtkSmartPointer<vtkTextActor>::New())
{
    for (vtkTextActor* caption : {worldCaption_.GetPointer(), projectedCaption_.GetPointer()}) {
        caption->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
        caption->SetPosition(0.02, 0.96);
        caption->GetTextProperty()->SetVerticalJustificationToTop();
        caption->GetTextProperty()->SetBold(true);
        caption->SetPickable(false);
    }
    world_->AddActor2D(worldCaption_);
    effectsCaption_ = vtkSmartPointer<vtkTextActor>::New();
    effectsCaption_->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
    effectsCaption_->SetPosition(0.02, 0.02);
    effectsCaption_->SetPickable(false);
    world_->AddActor2D(effectsCaption_);
    vanishing_ = vtkSmartPointer<vtkActor2D>::New();
    auto vanishingMapper = vtkSmartPointer<vtkPolyDataMapper2D>::New();
    vtkNew<vtkCoordinate> viewCoordinates;
    viewCoordinates->SetCoordinateSystemToView();
    vanishingMapper->SetTransformCoordinate(viewCoordinates);
    vanishingMapper->SetInputData(linesData({}));
    vanishing_->SetMapper(vanishingMapper);
    vanishing_->GetProperty()->SetLineWidth(1.5);
    rasterGrid_ = vtkSmartPointer<vtkActor2D>::New();
    auto gridMapper = vtkSmartPointer<vtkPolyDataMapper2D>::New();
    gridMapper->SetTransformCoordinate(viewCoordinates);
    gridMapper->SetInputData(linesData({}));
    rasterGrid_->SetMapper(gridMapper);
    rasterGrid_->GetProperty()->SetOpacity(0.85);
    rasterGrid_->SetVisibility(false);
    zFightingRing_ = vtkSmartPointer<vtkActor2D>::New();
    auto ringMapper = vtkSmartPointer<vtkPolyDataMapper2D>::New();
    ringMapper->SetTransformCoordinate(viewCoordinates);
    ringMapper->SetInputData(linesData({}));
    zFightingRing_->SetMapper(ringMapper);
    if (projected_) {
        projected_->AddActor2D(rasterGrid_);
        projected_->AddActor2D(vanishing_);
        projected_->AddActor2D(zFightingRing_); // over the vanishing lines
    }
    frameAxes_ = vtkSmartPointer<vtkActor>::New();
    auto frameMapper = vtkSmartPointer<vtkPolyDataMapper>::New();
    frameMapper->SetInputData(linesData({}));
    frameAxes_->SetMapper(frameMapper);
    frameAxes_->GetProperty()->LightingOff();
    frameAxes_->SetPickable(false);
    world_->AddActor(frameAxes_);
    if (projected_)
        projected_->AddActor2D(projectedCaption_);
    // Legends at the right: the world view's at the top, below the caption's
    // line, the projected view's at the bottom, under the picture.
    for (const bool top : {true, false}) {
        auto legend = vtkSmartPointer<vtkLegendBoxActor>::New();
        legend->UseBackgroundOn();
        legend->SetBackgroundOpacity(0.85);
        legend->SetPickable(false);
        auto corner = vtkSmartPointer<vtkCoordinate>::New();
        corner->SetCoordinateSystemToNormalizedViewport();
        corner->SetValue(1, top ? 0.96 : 0);
        // Position: pixels from the corner; Position2: the size in pixels.
        legend->GetPositionCoordinate()->SetCoordinateSystemToViewport();
        legend->GetPositionCoordinate()->SetReferenceCoordinate(corner);
        legend->GetPosition2Coordinate()->SetCoordinateSystemToViewport();
        (top ? worldLegend_ : projectedLegend_) = legend;
    }
    world_->AddActor2D(worldLegend_);
    if (projected_)
        projected_->AddActor2D(projectedLegend_);
    applyStyle();
}

ScenePainter::~ScenePainter()
{
    clear();
}

// Object faces: a light tint under their dark (or light) edges.
Rgb ScenePainter::faceColor(Theme theme)
{
    return theme == Theme::Dark ? Rgb{0.45, 0.55, 0.80} : Rgb{0.62, 0.70, 0.90};
}

Rgb ScenePainter::styledColor(Element element, bool surface, Theme theme)
{
    return element == Element::Objects && surface ? faceColor(theme) : color(element, theme);
}

Rgb ScenePainter::color(Element element, Theme theme)
{
    const bool dark = theme == Theme::Dark;
    switch (element) {
    case Element::Objects: return dark ? Rgb{0.92, 0.92, 0.95} : Rgb{0.10, 0.10, 0.15};
    case Element::WorldAxes: return dark ? Rgb{0.75, 0.75, 0.75} : Rgb{0.35, 0.35, 0.35};
    case Element::ViewAxes: return dark ? Rgb{1.00, 0.65, 0.10} : Rgb{0.90, 0.55, 0.00}; // orange
    case Element::Prp: return dark ? Rgb{1.00, 0.85, 0.20} : Rgb{0.70, 0.50, 0.00};
    case Element::Window: return dark ? Rgb{0.30, 0.75, 1.00} : Rgb{0.00, 0.40, 0.80}; // sky blue
    case Element::Dop: return dark ? Rgb{0.90, 0.55, 0.80} : Rgb{0.70, 0.25, 0.55};    // reddish purple
    case Element::Volume: return dark ? Rgb{0.55, 0.65, 1.00} : Rgb{0.35, 0.45, 0.85};
    case Element::FrontPlane: return dark ? Rgb{0.35, 0.90, 0.45} : Rgb{0.10, 0.60, 0.20};
    case Element::BackPlane: return color(Element::Volume, theme); // the volume's far face; purple is the DOP's
    case Element::Projectors: return dark ? Rgb{0.60, 0.60, 0.65} : Rgb{0.55, 0.55, 0.60};
    case Element::Canonical: return dark ? Rgb{1.00, 1.00, 1.00} : Rgb{0.00, 0.00, 0.00};
    case Element::Frame: return dark ? Rgb{0.38, 0.40, 0.45} : Rgb{0.72, 0.72, 0.76};
    case Element::Vanishing: return dark ? Rgb{0.00, 0.80, 0.60} : Rgb{0.00, 0.55, 0.40}; // bluish green
    // Vermillion: in neither the depth bands' ramp nor the other elements.
    case Element::ZFighting: return dark ? Rgb{1.00, 0.37, 0.05} : Rgb{0.84, 0.30, 0.00};
    case Element::Traced: return dark ? Rgb{1.00, 1.00, 1.00} : Rgb{0.00, 0.00, 0.00};
    }
    return {1, 1, 1};
}

Rgb ScenePainter::background(Theme theme, bool projectedView)
{
    const bool dark = theme == Theme::Dark;
    if (projectedView)
        return dark ? Rgb{0.07, 0.08, 0.10} : Rgb{0.96, 0.96, 0.97};
    return dark ? Rgb{0.11, 0.12, 0.14} : Rgb{1.0, 1.0, 1.0};
}

void ScenePainter::clear()
{
    for (const Layer& layer : layers_)
        world_->RemoveActor(layer.actor);
    for (const Label& label : labels_)
        world_->RemoveActor(label.actor);
    if (projected_)
        for (const ProjectedActor& a : projectedActors_)
            projected_->RemoveActor(a.actor);
    layers_.clear();
    labels_.clear();
    projectedActors_.clear();
}

void ScenePainter::addLayer(Element element, vtkSmartPointer<vtkPolyData> geometry, bool surface, double opacity)
{
    Layer layer{element, surface, opacity, geometry, vtkSmartPointer<vtkPolyData>::New(), vtkSmartPointer<vtkActor>::New()};
    layer.shown->DeepCopy(geometry);
    auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
    mapper->SetInputData(layer.shown);
    layer.actor->SetMapper(mapper);
    layer.actor->GetProperty()->LightingOff();
    layer.actor->SetPickable(element == Element::Objects);
    world_->AddActor(layer.actor);
    layers_.push_back(layer);
}

void ScenePainter::addLabel(Element element, const std::string& text, const Vec3<double>& world)
{
    Label label{element, world, vtkSmartPointer<vtkBillboardTextActor3D>::New()};
    if (text.empty())
        return;
    label.actor->SetInput(text.c_str());
    label.actor->SetPosition(world.x(), world.y(), world.z());
    label.actor->SetPickable(false);
    label.actor->GetTextProperty()->SetBold(true);
    label.actor->GetTextProperty()->SetJustificationToLeft();
    label.actor->GetTextProperty()->SetVerticalJustificationToBottom();
    world_->AddActor(label.actor);
    labels_.push_back(label);
}

void ScenePainter::setScene(const Scene& scene)
{
    const Pipeline<double> pipeline = buildPipeline(scene.camera, scene.effects);
    const ViewSetup<double> setup = viewSetup(scene.camera, scene.effects);

    // Read everything first: a mesh that fails leaves the previous picture.
    std::vector<ObjectGeometry> objects;
    for (std::size_t i = 0; i < scene.objects.size(); ++i)
        objects.push_back(objectGeometry(scene.objects[i], i));
    clear();

    // The size of the set-up, for axis lengths and markers.
    Eigen::AlignedBox<double, 3> box;
    for (const Vec3<double>& p : setup.volume)
        box.extend(p);
    box.extend(setup.prp);
    box.extend(setup.origin);
    for (const auto& object : objects) {
        double b[6];
        object.first->GetBounds(b);
        box.extend(Vec3<double>(b[0], b[2], b[4]));
        box.extend(Vec3<double>(b[1], b[3], b[5]));
    }
    const double size = box.diagonal().norm();
    const double axis = 0.15 * size;
    const double worldAxis = 1.5 * axis; // longer than the VRC axes, which may start at the same point
    const double marker = 0.008 * size;
    markerSize_ = marker;

    // Effects the scene lists: clipped-away edges and culled faces are ghosted,
    // faces the depth buffer cannot order are marked.
    std::vector<PolygonMesh> meshes;
    if (!scene.effects.empty())
        for (const ObjectGeometry& object : objects)
            meshes.push_back(polygonMesh(object.first));
    const EffectOutcomes outcomes = runEffects(pipeline, meshes, scene.effects);
    // Each object's faces: in front, culled, or fighting for depth.
    struct FaceSets {
        PolygonMesh front, back, fights;
        vtkSmartPointer<vtkPolyData> levels; // front faces with their stored depth levels
    };
    std::vector<FaceSets> faceSets(objects.size());
    std::optional<DepthBands> bands;
    if (outcomes.cull || outcomes.depth) {
        double low = std::numeric_limits<double>::infinity(), high = -low;
        for (std::size_t o = 0; o < objects.size(); ++o) {
            std::vector<bool> fighting(meshes[o].faces.size(), false);
            if (outcomes.depth)
                for (const auto& pair : outcomes.depth->zFighting) {
                    if (std::size_t(pair[0]) == o)
                        fighting[std::size_t(pair[1])] = true;
                    if (std::size_t(pair[2]) == o)
                        fighting[std::size_t(pair[3])] = true;
                }
            FaceSets& sets = faceSets[o];
            sets.front.vertices = sets.back.vertices = sets.fights.vertices = meshes[o].vertices;
            for (std::size_t f = 0; f < meshes[o].faces.size(); ++f) {
                const bool culled = outcomes.cull && outcomes.cull->culledFaces[o][f];
                (fighting[f] ? sets.fights : culled ? sets.back : sets.front).faces.push_back(meshes[o].faces[f]);
            }
            if (outcomes.depth && !sets.front.faces.empty()) {
                sets.levels = depthLevels(sets.front, pipeline, *scene.effects.depth);
                double range[2];
                sets.levels->GetPointData()->GetScalars()->GetRange(range); // NaN skipped
                if (range[0] <= range[1])
                    low = std::min(low, range[0]), high = std::max(high, range[1]);
            }
        }
        if (low <= high)
            bands = depthBands(low, high, 24);
    }
    const vtkSmartPointer<vtkLookupTable> bandTable = bands ? bandColors(*bands) : nullptr;
    std::vector<Vec3<double>> fighting;           // the z-fighting faces' corners
    bool clippedAway = false, culledAway = false; // ghosts the legend names
    for (std::size_t o = 0; o < objects.size(); ++o) {
        const auto& [faces, edges] = objects[o];
        const FaceSets& sets = faceSets[o];
        if (sets.levels && bandTable) {
            addLayer(Element::Objects, sets.levels, true, 0.9);
            colorByLevels(layers_.back().actor, bandTable);
        } else if (outcomes.cull || outcomes.depth) {
            addLayer(Element::Objects, facesData(sets.front), true, 0.35);
        } else {
            addLayer(Element::Objects, faces, true, 0.35);
        }
        if (!sets.back.faces.empty()) {
            addLayer(Element::Objects, facesData(sets.back), true, kCulledOpacity);
            culledAway = true;
        }
        if (!sets.fights.faces.empty()) { // outlined: far away they may be a few pixels wide
            addLayer(Element::ZFighting, facesData(sets.fights), true, 0.8);
            addLayer(Element::ZFighting, linesData(meshEdges(sets.fights)), false, 1.0);
            for (const std::vector<int>& face : sets.fights.faces)
                for (int k : face)
                    fighting.push_back(sets.fights.vertices[std::size_t(k)]);
        }
        if (outcomes.clip) {
            std::vector<Segment> kept, away;
            const auto indices = meshEdgeIndices(meshes[o]);
            for (std::size_t e = 0; e < indices.size(); ++e) {
                const Vec3<double>& a = meshes[o].vertices[std::size_t(indices[e][0])];
                const Vec3<double>& b = meshes[o].vertices[std::size_t(indices[e][1])];
                const auto& interval = outcomes.clip->keptEdges[o][e];
                if (!interval) {
                    away.emplace_back(a, b);
                    continue;
                }
                const Vec3<double> p = a + (*interval)[0] * (b - a), q = a + (*interval)[1] * (b - a);
                kept.emplace_back(p, q);
                if ((*interval)[0] > 0)
                    away.emplace_back(a, p);
                if ((*interval)[1] < 1)
                    away.emplace_back(q, b);
            }
            addLayer(Element::Objects, linesData(kept), false, 1.0);
            if (!away.empty()) {
                addLayer(Element::Objects, linesData(away), false, kClippedOpacity);
                clippedAway = true;
            }
        } else if (!edges.empty()) {
            addLayer(Element::Objects, linesData(edges), false, 1.0);
        }
    }

    if (!fighting.empty()) {
        Eigen::AlignedBox<double, 3> box;
        for (const Vec3<double>& p : fighting)
            box.extend(p);
        addLabel(Element::ZFighting, "z-fighting", box.center());
    }

    const Vec3<double> o = Vec3<double>::Zero();
    addLayer(Element::WorldAxes,
             linesData({{o, Vec3<double>::UnitX() * worldAxis}, {o, Vec3<double>::UnitY() * worldAxis}, {o, Vec3<double>::UnitZ() * worldAxis}}),
             false, 1.0);
    addLabel(Element::WorldAxes, "x", Vec3<double>::UnitX() * worldAxis);
    addLabel(Element::WorldAxes, "y", Vec3<double>::UnitY() * worldAxis);
    addLabel(Element::WorldAxes, "z", Vec3<double>::UnitZ() * worldAxis);

    const bool foley = pipeline.convention == Convention::Foley;
    const Vec3<double>& vrp = setup.origin;
    addLayer(Element::ViewAxes,
             linesData({{vrp, vrp + setup.axes.u * axis}, {vrp, vrp + setup.axes.v * axis}, {vrp, vrp + setup.axes.n * axis}}),
             false, 1.0);
    addLabel(Element::ViewAxes, foley ? "u" : "s", vrp + setup.axes.u * axis);
    addLabel(Element::ViewAxes, foley ? "v" : "u", vrp + setup.axes.v * axis);
    addLabel(Element::ViewAxes, foley ? "n" : "-f", vrp + setup.axes.n * axis);
    if (foley)
        addLabel(Element::ViewAxes, "VRP", vrp);

    const bool showCenter = setup.perspective;
    if (showCenter) {
        addLayer(Element::Prp, sphere(setup.prp, 1.6 * marker), true, 1.0);
        addLabel(Element::Prp, foley ? "PRP" : "eye", setup.prp);
    }

    std::vector<Segment> window;
    for (std::size_t k = 0; k < 4; ++k)
        window.emplace_back(setup.window[k], setup.window[(k + 1) % 4]);
    addLayer(Element::Window, linesData(window), false, 1.0);
    // In perspective, small beside its distance from the eye, or the divide would blow it up.
    const double centerMarker =
        setup.perspective ? std::min(marker, 0.05 * (setup.windowCenter - setup.prp).norm()) : marker;
    addLayer(Element::Window, sphere(setup.windowCenter, centerMarker), true, 1.0);
    addLabel(Element::Window, "CW", setup.windowCenter);

    const Vec3<double> dop = setup.windowCenter - setup.prp;
    const double head = std::min(0.06 * size, 0.4 * dop.norm());
    addLayer(Element::Dop, linesData({{setup.prp, setup.windowCenter - dop.normalized() * head}}), false, 1.0);
    addLayer(Element::Dop, arrowHead(setup.windowCenter, dop, head), true, 1.0);
    addLabel(Element::Dop, "DOP", setup.prp + 0.3 * dop);

    const auto& v = setup.volume;
    PolygonMesh sides;
    sides.vertices.assign(v.begin(), v.end());
    sides.faces = {{0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
    addLayer(Element::Volume, facesData(sides), true, 0.10);
    std::vector<Segment> volumeEdges;
    for (std::size_t k = 0; k < 4; ++k) {
        volumeEdges.emplace_back(v[k], v[(k + 1) % 4]);
        volumeEdges.emplace_back(v[k + 4], v[(k + 1) % 4 + 4]);
        volumeEdges.emplace_back(v[k], v[k + 4]);
    }
    addLayer(Element::Volume, linesData(volumeEdges), false, 0.8);
    addLayer(Element::FrontPlane, facesData(quad(v[0], v[1], v[2], v[3])), true, 0.22);
    addLayer(Element::BackPlane, facesData(quad(v[4], v[5], v[6], v[7])), true, 0.22);
    addLabel(Element::FrontPlane, foley ? "front (F)" : "near", v[3]);
    addLabel(Element::BackPlane, foley ? "back (B)" : "far", v[7]);
    addLabel(Element::Window, foley ? "window" : "", (setup.window[2] + setup.window[3]) / 2);

    std::vector<Segment> projectors;
    for (std::size_t k = 0; k < 4; ++k) {
        std::vector<Vec3<double>> along = {setup.window[k], v[k], v[k + 4]};
        if (setup.perspective)
            along.push_back(setup.prp);
        projectors.push_back(span(along));
    }
    addLayer(Element::Projectors, linesData(projectors), false, 0.7);

    std::vector<Segment> canonical;
    const auto& c = setup.canonical;
    for (std::size_t k = 0; k < 4; ++k) {
        canonical.emplace_back(c[k], c[(k + 1) % 4]);
        canonical.emplace_back(c[k + 4], c[(k + 1) % 4 + 4]);
        canonical.emplace_back(c[k], c[k + 4]);
    }
    addLayer(Element::Canonical, linesData(canonical), false, 1.0);

    if (projected_) {
        for (std::size_t o = 0; o < objects.size(); ++o) {
            const auto actors = objectActors(objects[o], theme_);
            if (faceSets[o].levels && bandTable) { // what the depth buffer holds, in bands
                vtkPolyDataMapper::SafeDownCast(actors.front()->GetMapper())->SetInputData(faceSets[o].levels);
                colorByLevels(actors.front(), bandTable);
                actors.front()->GetProperty()->SetOpacity(0.9);
            }
            for (std::size_t k = 0; k < actors.size(); ++k) // the faces, then the edges
                projectedActors_.push_back({actors[k], Element::Objects, k == 0});
            if (!faceSets[o].fights.faces.empty()) // faces the buffer cannot order, outlined over the picture
                for (const bool surface : {true, false}) {
                    auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
                    mapper->SetInputData(surface ? facesData(faceSets[o].fights)
                                                 : linesData(meshEdges(faceSets[o].fights)));
                    auto fights = vtkSmartPointer<vtkActor>::New();
                    fights->SetMapper(mapper);
                    fights->GetProperty()->LightingOff();
                    fights->GetProperty()->SetOpacity(surface ? 0.8 : 1.0);
                    fights->GetProperty()->SetLineWidth(3);
                    projectedActors_.push_back({fights, Element::ZFighting, surface});
                }
        }
        // The window's outline, at mid depth so that no clipping plane cuts it.
        std::vector<Segment> border;
        for (std::size_t k = 0; k < 4; ++k)
            border.emplace_back((v[k] + v[k + 4]) / 2, (v[(k + 1) % 4] + v[(k + 1) % 4 + 4]) / 2);
        auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
        mapper->SetInputData(linesData(border));
        auto actor = vtkSmartPointer<vtkActor>::New();
        actor->SetMapper(mapper);
        actor->GetProperty()->LightingOff();
        actor->GetProperty()->SetLineWidth(2);
        projectedActors_.push_back({actor, Element::Window, false});
        for (const ProjectedActor& a : projectedActors_)
            projected_->AddActor(a.actor);
        std::vector<Segment> edges; // of the built-in objects: meshes have none listed
        for (const ObjectGeometry& object : objects)
            edges.insert(edges.end(), object.second.begin(), object.second.end());
        setUpProjectedView(scene, pipeline, edges, outcomes.raster ? &*outcomes.raster : nullptr, fighting);
    }
    outcomes_ = outcomes;
    effectsNote_ = describeEffects(scene.effects, outcomes, pipeline, bands);
    effectsCaption_->SetInput(effectsNote_.c_str());
    effectsCaption_->SetVisibility(!effectsNote_.empty());

    // The legends name what this scene shows, each view its own.
    using Swatch = LegendEntry::Swatch;
    std::vector<LegendEntry> effectEntries; // in both views
    if (!fighting.empty())
        effectEntries.push_back({"z-fighting faces", Element::ZFighting, Swatch::Face});
    if (bands)
        effectEntries.push_back({"depth bands, near to far", Element::Objects, Swatch::Bands});
    worldEntries_ = {{foley ? "VRP and the VRC axes u, v, n" : "eye axes s, u, -f", Element::ViewAxes, Swatch::Line}};
    if (showCenter)
        worldEntries_.push_back({foley ? "PRP, center of projection" : "eye, center of projection", Element::Prp,
                                 Swatch::Dot});
    worldEntries_.insert(worldEntries_.end(),
                         {{"window and its center CW", Element::Window, Swatch::Line},
                          {"DOP, direction of projection", Element::Dop, Swatch::Line},
                          {foley ? "view volume, back plane (B)" : "view volume, far plane", Element::Volume,
                           Swatch::Line},
                          {foley ? "front plane (F)" : "near plane", Element::FrontPlane, Swatch::Face},
                          {"projectors", Element::Projectors, Swatch::Line},
                          {"canonical view volume", Element::Canonical, Swatch::Line}});
    worldEntries_.insert(worldEntries_.end(), effectEntries.begin(), effectEntries.end());
    if (clippedAway)
        worldEntries_.push_back({"clipped away (ghosted)", Element::Objects, Swatch::Line, kClippedOpacity});
    if (culledAway)
        worldEntries_.push_back({"culled faces (ghosted)", Element::Objects, Swatch::Face, kCulledOpacity});
    projectedEntries_ = {{"window", Element::Window, Swatch::Line}};
    if (projected_ && vanishing_->GetVisibility())
        projectedEntries_.push_back({"vanishing lines", Element::Vanishing, Swatch::Line});
    projectedEntries_.insert(projectedEntries_.end(), effectEntries.begin(), effectEntries.end());
    if (outcomes.raster)
        projectedEntries_.push_back({"raster pixels, a color per object", Element::Objects, Swatch::Pixels});

    applyStyle();
    show(Mat4<double>::Identity(), 0);
}

void ScenePainter::setUpProjectedView(const Scene& scene, const Pipeline<double>& pipeline, const std::vector<Segment>& edges,
                                      const RasterOutcome* raster, const std::vector<Vec3<double>>& fighting)
{
    Mat4<double> clip = pipeline.clipMatrix();
    if (pipeline.convention == Convention::Foley)
        clip = foleyToGlClip() * clip;
    vtkCamera* camera = projected_->GetActiveCamera();
    camera->SetPosition(0, 0, 0);
    camera->SetFocalPoint(0, 0, -1);
    camera->SetViewUp(0, 1, 0);
    camera->SetUseExplicitProjectionTransformMatrix(true);

    // Vanishing points, and the scene's edges along each principal axis drawn
    // on to theirs: 2D lines in the picture's coordinates (x, y in [-1, 1]).
    std::vector<Vec2<double>> picture; // pairs of end points
    const Mat4<double> image = pipeline.clipMatrix();
    for (int axis = 0; axis < 3; ++axis) {
        const std::optional<VanishingPoint> vp = vanishingPoint(scene.camera, axis);
        if (!vp)
            continue;
        const Vec2<double> target = vp->image.head<2>();
        const double arm = 0.04;
        picture.insert(picture.end(), {target - Vec2<double>(arm, 0), target + Vec2<double>(arm, 0),
                                       target - Vec2<double>(0, arm), target + Vec2<double>(0, arm)});
        for (const Segment& edge : edges) {
            const Vec3<double> d = (edge.second - edge.first).normalized();
            if (std::abs(std::abs(d[axis]) - 1) > 1e-9)
                continue;
            const std::optional<Vec3<double>> a = project(image, edge.first), b = project(image, edge.second);
            if (a && b)
                picture.insert(picture.end(), {a->head<2>(), target, b->head<2>(), target});
        }
    }
    vanishing_->SetVisibility(!picture.empty());

    // A ring around the z-fighting faces: small and far, they may lie under the vanishing lines.
    std::vector<Vec2<double>> ring; // pairs of end points
    Eigen::AlignedBox<double, 2> spot;
    for (const Vec3<double>& p : fighting)
        if (const std::optional<Vec3<double>> q = project(image, p))
            spot.extend(q->head<2>());
    if (!spot.isEmpty()) {
        const double radius = 0.5 * spot.diagonal().norm() + 0.07;
        auto at = [&](int k) -> Vec2<double> {
            return spot.center() + radius * Vec2<double>(std::cos(k * M_PI / 24), std::sin(k * M_PI / 24));
        };
        for (int k = 0; k < 48; ++k)
            ring.insert(ring.end(), {at(k), at(k + 1)});
    }
    zFightingRing_->SetVisibility(!ring.empty());

    // Keep the window square on screen whatever the viewport's shape.
    // The raster effect: its pixels as squares over the picture, one color per object.
    std::vector<std::pair<Vec2<double>, int>> pixels; // lower-left corner in NDC, object
    Vec2<double> pixelSize(0, 0);
    if (raster) {
        pixelSize = Vec2<double>(2.0 / raster->width, 2.0 / raster->height);
        for (int y = 0; y < raster->height; ++y)
            for (int x = 0; x < raster->width; ++x) {
                const int object = raster->object[std::size_t(y * raster->width + x)];
                if (object >= 0)
                    pixels.push_back({Vec2<double>(-1 + x * pixelSize.x(), -1 + y * pixelSize.y()), object});
            }
    }
    rasterGrid_->SetVisibility(raster != nullptr);

    struct Context {
        Mat4<double> clip;
        std::vector<std::pair<vtkActor2D*, std::vector<Vec2<double>>>> lines; // 2D lines: end points by pairs
        std::vector<std::pair<Vec2<double>, int>> pixels;
        Vec2<double> pixelSize;
        vtkActor2D* grid;
    };
    auto* context = new Context{clip, {{vanishing_, picture}, {zFightingRing_, ring}}, pixels, pixelSize, rasterGrid_};
    auto update = vtkSmartPointer<vtkCallbackCommand>::New();
    update->SetClientData(context);
    update->SetClientDataDeleteCallback([](void* data) { delete static_cast<Context*>(data); });
    update->SetCallback([](vtkObject* caller, unsigned long, void* data, void*) {
        auto* renderer = static_cast<vtkRenderer*>(caller);
        auto* c = static_cast<Context*>(data);
        const double aspect = renderer->GetTiledAspectRatio();
        Mat4<double> letterbox = Mat4<double>::Identity();
        if (aspect > 1)
            letterbox(0, 0) = 1 / aspect;
        else
            letterbox(1, 1) = aspect;
        letterbox(0, 0) *= 0.92;
        letterbox(1, 1) *= 0.92;
        renderer->GetActiveCamera()->SetExplicitProjectionTransformMatrix(toVtk(letterbox * c->clip));
        auto place = [&](const Vec2<double>& q) { return Vec3<double>(q.x() * letterbox(0, 0), q.y() * letterbox(1, 1), 0); };
        for (const auto& [actor, ends] : c->lines) {
            std::vector<Segment> lines;
            for (std::size_t i = 0; i + 1 < ends.size(); i += 2)
                lines.emplace_back(place(ends[i]), place(ends[i + 1]));
            static_cast<vtkPolyDataMapper2D*>(actor->GetMapper())->SetInputData(linesData(lines));
        }
        // Raster pixels: a square each, with a gap so the grid shows.
        auto points = vtkSmartPointer<vtkPoints>::New();
        auto cells = vtkSmartPointer<vtkCellArray>::New();
        auto colors = vtkSmartPointer<vtkUnsignedCharArray>::New();
        colors->SetNumberOfComponents(3);
        for (const auto& [corner, object] : c->pixels) {
            const vtkIdType first = points->GetNumberOfPoints();
            for (const Vec2<double>& d : {Vec2<double>(0.06, 0.06), Vec2<double>(0.94, 0.06), Vec2<double>(0.94, 0.94),
                                          Vec2<double>(0.06, 0.94)}) {
                const Vec2<double> q = corner + d.cwiseProduct(c->pixelSize);
                points->InsertNextPoint(q.x() * letterbox(0, 0), q.y() * letterbox(1, 1), 0);
            }
            const vtkIdType ids[4] = {first, first + 1, first + 2, first + 3};
            cells->InsertNextCell(4, ids);
            colors->InsertNextTypedTuple(kRasterPalette[object % 4]);
        }
        auto grid = vtkSmartPointer<vtkPolyData>::New();
        grid->SetPoints(points);
        grid->SetPolys(cells);
        grid->GetCellData()->SetScalars(colors);
        static_cast<vtkPolyDataMapper2D*>(c->grid->GetMapper())->SetInputData(grid);
    });
    projected_->RemoveObservers(vtkCommand::StartEvent);
    projected_->AddObserver(vtkCommand::StartEvent, update);
    update->Execute(projected_, vtkCommand::StartEvent, nullptr); // the first frame needs the matrix too
}

void ScenePainter::show(const Mat4<double>& cumulative, double canonicalOpacity)
{
    const bool canonicalAppears = (canonicalOpacity > 0) != (canonicalOpacity_ > 0);
    canonicalOpacity_ = canonicalOpacity;
    if (canonicalAppears) // the legend names it while it shows
        fillLegend(worldLegend_, world_, worldEntries_, true);
    shownMatrix_ = cumulative;
    for (Layer& layer : layers_) {
        if (layer.element == Element::Canonical) {
            layer.actor->SetVisibility(canonicalOpacity > 0);
            layer.actor->GetProperty()->SetOpacity(canonicalOpacity);
            continue;
        }
        placeLayer(layer, cumulative);
    }
    for (Label& label : labels_)
        placeLabel(label, cumulative);
}

void ScenePainter::placeLayer(Layer& layer, const Mat4<double>& cumulative)
{
    vtkPoints* to = layer.shown->GetPoints();
    const bool visible = projectPoints(layer.original->GetPoints(), cumulative,
                                       [to](vtkIdType i, const Vec3<double>& q) { to->SetPoint(i, q.data()); });
    to->Modified();
    layer.actor->SetVisibility(visible);
}

void ScenePainter::placeLabel(Label& label, const Mat4<double>& cumulative)
{
    const std::optional<Vec3<double>> q = project(cumulative, label.world);
    label.actor->SetVisibility(q.has_value());
    if (q)
        label.actor->SetPosition(q->x(), q->y(), q->z());
}

ScenePainter::Framing ScenePainter::framingOf(const std::vector<Mat4<double>>& cumulatives, bool withCanonical) const
{
    Eigen::AlignedBox<double, 3> box;
    for (const Layer& layer : layers_) {
        const bool canonical = layer.element == Element::Canonical;
        if (canonical && !withCanonical)
            continue;
        for (const Mat4<double>& m : cumulatives) {
            Eigen::AlignedBox<double, 3> layerBox;
            if (projectPoints(layer.original->GetPoints(), canonical ? Mat4<double>::Identity() : m,
                              [&](vtkIdType, const Vec3<double>& q) { layerBox.extend(q); }))
                box.extend(layerBox);
        }
    }
    if (box.isEmpty())
        return {};
    return {box.center(), std::max(1e-9, 0.5 * box.diagonal().norm())};
}

void ScenePainter::frame()
{
    frameOn(framingOf({shownMatrix_}, canonicalOpacity_ > 0));
}

void ScenePainter::frameOn(const Framing& framing)
{
    vtkCamera* camera = world_->GetActiveCamera();
    Vec3<double> direction;
    camera->GetDirectionOfProjection(direction.data());
    const double distance = userZoom_ * fitDistance(framing.radius);
    const Vec3<double> focal = framing.center + userPan_ * framing.radius;
    const Vec3<double> position = focal - direction * distance;
    camera->SetFocalPoint(focal.data());
    camera->SetPosition(position.data());
    framed_ = framing;
    // The fixed axes reach across everything in view.
    const double reach = framing.center.norm() + 1.5 * framing.radius;
    auto* mapper = static_cast<vtkPolyDataMapper*>(frameAxes_->GetMapper());
    mapper->SetInputData(linesData({{-reach * Vec3<double>::UnitX(), reach * Vec3<double>::UnitX()},
                                    {-reach * Vec3<double>::UnitY(), reach * Vec3<double>::UnitY()},
                                    {-reach * Vec3<double>::UnitZ(), reach * Vec3<double>::UnitZ()}}));
    world_->ResetCameraClippingRange();
}

double ScenePainter::fitDistance(double radius) const
{
    // Fit the bounding sphere in the narrower of the two view angles; it
    // overstates what most directions see, so come a little closer.
    const double halfVertical = world_->GetActiveCamera()->GetViewAngle() * M_PI / 360;
    const double half = std::min(halfVertical, std::atan(std::tan(halfVertical) * world_->GetTiledAspectRatio()));
    return 0.95 * radius / std::sin(half);
}

void ScenePainter::rememberUserCamera()
{
    vtkCamera* camera = world_->GetActiveCamera();
    Vec3<double> focal;
    camera->GetFocalPoint(focal.data());
    userZoom_ = camera->GetDistance() / fitDistance(framed_.radius);
    userPan_ = (focal - framed_.center) / framed_.radius;
}

void ScenePainter::resetView()
{
    vtkCamera* camera = world_->GetActiveCamera();
    camera->SetFocalPoint(0, 0, 0);
    camera->SetPosition(1.7, 0.9, 1.0); // from the +x side, above: depth (z) runs across the picture
    camera->SetViewUp(0, 1, 0);
    camera->SetViewAngle(30);
    userZoom_ = 1;
    userPan_.setZero();
    frame();
}

std::optional<Vec3<double>> ScenePainter::pickVertex(int displayX, int displayY) const
{
    auto picker = vtkSmartPointer<vtkPointPicker>::New();
    picker->SetTolerance(0.01);
    if (!picker->Pick(displayX, displayY, 0, world_) || picker->GetPointId() < 0)
        return std::nullopt;
    for (const Layer& layer : layers_)
        if (layer.actor.GetPointer() == picker->GetActor()) {
            const double* p = layer.original->GetPoint(picker->GetPointId());
            return Vec3<double>(p[0], p[1], p[2]);
        }
    return std::nullopt;
}

void ScenePainter::setTextVisible(bool visible)
{
    worldCaption_->SetVisibility(visible);
    effectsCaption_->SetVisibility(visible && !effectsNote_.empty());
    projectedCaption_->SetVisibility(visible);
    for (Label& label : labels_)
        label.actor->SetVisibility(visible && project(shownMatrix_, label.world).has_value());
}

void ScenePainter::setCaptions(const std::string& world, const std::string& projected)
{
    worldCaption_->SetInput(world.c_str());
    projectedCaption_->SetInput(projected.c_str());
}

void ScenePainter::markTraced(const std::optional<Vec3<double>>& point)
{
    auto isTraced = [](const auto& item) { return item.element == Element::Traced; };
    for (const Layer& layer : layers_)
        if (isTraced(layer))
            world_->RemoveActor(layer.actor);
    for (const Label& label : labels_)
        if (isTraced(label))
            world_->RemoveActor(label.actor);
    layers_.erase(std::remove_if(layers_.begin(), layers_.end(), isTraced), layers_.end());
    labels_.erase(std::remove_if(labels_.begin(), labels_.end(), isTraced), labels_.end());
    if (!point)
        return;
    addLayer(Element::Traced, sphere(*point, 2.5 * markerSize_), true, 1.0);
    addLabel(Element::Traced, "traced", *point);
    applyStyle();
    // Only the new marker needs placing at the stage shown: the scene's layers are there already.
    placeLayer(layers_.back(), shownMatrix_);
    placeLabel(labels_.back(), shownMatrix_);
}

std::string ScenePainter::worldCaption() const
{
    return worldCaption_->GetInput();
}

void ScenePainter::setTheme(Theme theme)
{
    theme_ = theme;
    applyStyle();
}

void ScenePainter::setLineScale(double scale)
{
    lineScale_ = scale;
    applyStyle();
}

void ScenePainter::setFontSize(int points)
{
    fontSize_ = points;
    applyStyle();
}

void ScenePainter::applyStyle()
{
    const Rgb worldBackground = background(theme_, false), projectedBackground = background(theme_, true);
    world_->SetBackground(worldBackground.r, worldBackground.g, worldBackground.b);
    if (projected_)
        projected_->SetBackground(projectedBackground.r, projectedBackground.g, projectedBackground.b);
    for (Layer& layer : layers_) {
        const Rgb c = styledColor(layer.element, layer.surface, theme_);
        vtkProperty* p = layer.actor->GetProperty();
        p->SetColor(c.r, c.g, c.b);
        p->SetOpacity(layer.element == Element::Canonical ? canonicalOpacity_ : layer.opacity);
        const bool emphasised = layer.element == Element::WorldAxes || layer.element == Element::ViewAxes ||
                                layer.element == Element::Canonical || layer.element == Element::Dop ||
                                layer.element == Element::ZFighting;
        p->SetLineWidth(lineScale_ * (layer.surface ? 1 : (emphasised ? 3.5 : 2.0)));
    }
    for (Label& label : labels_) {
        const Rgb c = color(label.element, theme_);
        label.actor->GetTextProperty()->SetColor(c.r, c.g, c.b);
        label.actor->GetTextProperty()->SetFontSize(fontSize_);
    }
    for (vtkTextActor* caption : {worldCaption_.GetPointer(), projectedCaption_.GetPointer()}) {
        const Rgb c = color(Element::Objects, theme_);
        caption->GetTextProperty()->SetColor(c.r, c.g, c.b);
        caption->GetTextProperty()->SetFontSize(fontSize_);
    }
    const Rgb note = color(Element::Objects, theme_);
    effectsCaption_->GetTextProperty()->SetColor(note.r, note.g, note.b);
    effectsCaption_->GetTextProperty()->SetFontSize(std::max(8, fontSize_ * 3 / 4));
    const Rgb vanishing = color(Element::Vanishing, theme_), fights = color(Element::ZFighting, theme_);
    vanishing_->GetProperty()->SetColor(vanishing.r, vanishing.g, vanishing.b);
    vanishing_->GetProperty()->SetOpacity(0.85);
    zFightingRing_->GetProperty()->SetColor(fights.r, fights.g, fights.b);
    zFightingRing_->GetProperty()->SetLineWidth(2.5);
    const Rgb frame = color(Element::Frame, theme_);
    frameAxes_->GetProperty()->SetColor(frame.r, frame.g, frame.b);
    frameAxes_->GetProperty()->SetLineWidth(1.5 * lineScale_);
    for (const ProjectedActor& a : projectedActors_) {
        const Rgb c = styledColor(a.element, a.surface, theme_);
        a.actor->GetProperty()->SetColor(c.r, c.g, c.b);
    }
    fillLegend(worldLegend_, world_, worldEntries_, true);
    if (projected_)
        fillLegend(projectedLegend_, projected_, projectedEntries_, false);
}

void ScenePainter::fillLegend(vtkLegendBoxActor* legend, vtkRenderer* renderer, const std::vector<LegendEntry>& entries,
                              bool top)
{
    std::vector<const LegendEntry*> shown;
    for (const LegendEntry& entry : entries)
        if (entry.element != Element::Canonical || canonicalOpacity_ > 0)
            shown.push_back(&entry);
    legend->SetNumberOfEntries(int(shown.size()));
    legend->SetVisibility(!shown.empty());
    const double* back = renderer->GetBackground();
    legend->SetBackgroundColor(back[0], back[1], back[2]);
    const Rgb border = color(Element::Frame, theme_), ink = color(Element::Objects, theme_);
    legend->GetProperty()->SetColor(border.r, border.g, border.b);
    vtkTextProperty* text = legend->GetEntryTextProperty();
    text->SetColor(ink.r, ink.g, ink.b);
    text->SetFontSize(std::max(8, fontSize_ * 2 / 3));
    text->Modified(); // new entries take the font and color from it at the next build only if it changed

    using Swatch = LegendEntry::Swatch;
    vtkRenderWindow* window = renderer->GetRenderWindow();
    const int dpi = window ? window->GetDPI() : 72;
    int textWidth = 0, textHeight = 0;
    for (std::size_t k = 0; k < shown.size(); ++k) {
        const LegendEntry& entry = *shown[k];
        const Rgb c = blend(styledColor(entry.element, entry.swatch == Swatch::Face, theme_), back, entry.opacity);
        vtkSmartPointer<vtkPolyData> symbol;
        if (entry.swatch == Swatch::Dot) {
            symbol = dot(c);
        } else if (entry.swatch == Swatch::Bands || entry.swatch == Swatch::Pixels) {
            std::vector<Rgb> colors;
            if (entry.swatch == Swatch::Bands)
                for (const auto& rgb : kBandRamp)
                    colors.push_back({rgb[0], rgb[1], rgb[2]});
            else
                for (const auto& rgb : kRasterPalette)
                    colors.push_back({rgb[0] / 255.0, rgb[1] / 255.0, rgb[2] / 255.0});
            symbol = stripes(colors, 0.4);
        } else {
            symbol = stripes({c}, entry.swatch == Swatch::Line ? 0.12 : 0.4);
        }
        legend->SetEntrySymbol(int(k), symbol);
        legend->SetEntryString(int(k), entry.text.c_str());
        int box[4];
        vtkTextRenderer::GetInstance()->GetBoundingBox(text, entry.text, box, dpi);
        textWidth = std::max(textWidth, box[1] - box[0] + 1);
        textHeight = std::max(textHeight, box[3] - box[2] + 1);
    }
    // VTK fits the text to the box: a box made to the text's size keeps the
    // font size asked for. Symbols take kSymbolWidth times the text's height.
    const int padding = std::max(3, fontSize_ / 4), margin = std::max(4, fontSize_ / 2);
    legend->SetPadding(padding);
    const double width = textWidth + kSymbolWidth * textHeight + 2 * padding + 2;
    const double height = double(shown.size()) * std::ceil(1.3 * textHeight) + 2 * padding;
    legend->GetPosition2Coordinate()->SetValue(width, height);
    legend->GetPositionCoordinate()->SetValue(-width - margin, top ? -height - 1.6 * fontSize_ : margin);
}

} // namespace viewpipe::gui
