#include "ProjectedView.h"

#include <vtkActor.h>
#include <vtkActor2D.h>
#include <vtkCallbackCommand.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCommand.h>
#include <vtkCoordinate.h>
#include <vtkLegendBoxActor.h>
#include <vtkLookupTable.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkPolyDataMapper2D.h>
#include <vtkProperty.h>
#include <vtkProperty2D.h>
#include <vtkRenderer.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkUnsignedCharArray.h>

#include <cmath>

#include "DepthColoring.h"
#include "EigenVtk.h"
#include "Legend.h"
#include "VtkGeometry.h"

namespace viewpipe::gui {
namespace {

vtkSmartPointer<vtkActor2D> overlay(vtkCoordinate* viewCoordinates)
{
    auto actor = vtkSmartPointer<vtkActor2D>::New();
    auto mapper = vtkSmartPointer<vtkPolyDataMapper2D>::New();
    mapper->SetTransformCoordinate(viewCoordinates);
    mapper->SetInputData(linesData(std::vector<Segment2>{}));
    actor->SetMapper(mapper);
    return actor;
}

} // namespace

// The 2D marks in picture coordinates (x, y in [-1, 1]), laid out again for
// the viewport's shape before each frame.
struct ProjectedView::Picture {
    Mat4<double> clip;
    double aspect; // the picture's width over its height
    std::vector<std::pair<vtkActor2D*, std::vector<Segment2>>> lines;
    std::vector<std::pair<Vec2<double>, int>> pixels; // lower-left corner, object
    Vec2<double> pixelSize;
    vtkActor2D* grid;
};

ProjectedView::ProjectedView(vtkRenderer* renderer)
    : renderer_(renderer), caption_(vtkSmartPointer<vtkTextActor>::New()), legend_(newLegend(true)),
      layout_(vtkSmartPointer<vtkCallbackCommand>::New())
{
    caption_->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
    caption_->SetPosition(0.02, 0.96);
    caption_->GetTextProperty()->SetVerticalJustificationToTop();
    useFigureFont(caption_->GetTextProperty(), true);
    caption_->SetPickable(false);
    vtkNew<vtkCoordinate> viewCoordinates;
    viewCoordinates->SetCoordinateSystemToView();
    rasterGrid_ = overlay(viewCoordinates);
    rasterGrid_->GetProperty()->SetOpacity(0.85);
    rasterGrid_->SetVisibility(false);
    vanishing_ = overlay(viewCoordinates);
    zFightingRing_ = overlay(viewCoordinates);
    renderer_->AddActor2D(rasterGrid_);
    renderer_->AddActor2D(vanishing_);
    renderer_->AddActor2D(zFightingRing_); // over the vanishing lines
    renderer_->AddActor2D(caption_);
    renderer_->AddActor2D(legend_);

    vtkCamera* camera = renderer_->GetActiveCamera();
    camera->SetPosition(0, 0, 0);
    camera->SetFocalPoint(0, 0, -1);
    camera->SetViewUp(0, 1, 0);
    camera->SetExplicitProjectionTransformMatrix(toVtk(Mat4<double>::Identity())); // until a scene gives its own
    camera->SetUseExplicitProjectionTransformMatrix(true);
    layout_->SetClientData(this);
    layout_->SetCallback([](vtkObject* caller, unsigned long, void* view, void*) {
        auto* renderer = static_cast<vtkRenderer*>(caller);
        const Picture* c = static_cast<ProjectedView*>(view)->picture_.get();
        if (!c)
            return;
        // The window at the picture's shape on screen, whole, in the room the caption and legend leave.
        const report::Box2 room = static_cast<ProjectedView*>(view)->layOutText();
        const int* size = renderer->GetSize();
        if (room.isEmpty())
            return; // no viewport yet
        const Vec2<double> extent = room.max - room.min;
        const double width = 0.92 * std::min(extent.x(), extent.y() * c->aspect), height = width / c->aspect;
        Mat4<double> letterbox = Mat4<double>::Identity(); // clip coordinates: x and y scaled, then moved by w
        letterbox(0, 0) = width / std::max(1, size[0]);
        letterbox(1, 1) = height / std::max(1, size[1]);
        letterbox(0, 3) = (room.min.x() + room.max.x()) / std::max(1, size[0]) - 1;
        letterbox(1, 3) = 1 - (room.min.y() + room.max.y()) / std::max(1, size[1]);
        renderer->GetActiveCamera()->SetExplicitProjectionTransformMatrix(toVtk(letterbox * c->clip));
        auto place = [&](const Vec2<double>& q) {
            return Vec2<double>(q.x() * letterbox(0, 0) + letterbox(0, 3), q.y() * letterbox(1, 1) + letterbox(1, 3));
        };
        for (const auto& [actor, segments] : c->lines) {
            std::vector<Segment2> placed;
            for (const Segment2& s : segments)
                placed.push_back({place(s[0]), place(s[1])});
            static_cast<vtkPolyDataMapper2D*>(actor->GetMapper())->SetInputData(linesData(placed));
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
                const Vec2<double> q = place(corner + d.cwiseProduct(c->pixelSize));
                points->InsertNextPoint(q.x(), q.y(), 0);
            }
            const vtkIdType ids[4] = {first, first + 1, first + 2, first + 3};
            cells->InsertNextCell(4, ids);
            colors->InsertNextTypedTuple(report::toBytes(report::kRasterPalette[std::size_t(object) % report::kRasterPalette.size()]).data());
        }
        auto grid = vtkSmartPointer<vtkPolyData>::New();
        grid->SetPoints(points);
        grid->SetPolys(cells);
        grid->GetCellData()->SetScalars(colors);
        static_cast<vtkPolyDataMapper2D*>(c->grid->GetMapper())->SetInputData(grid);
    });
    renderer_->AddObserver(vtkCommand::StartEvent, layout_);
}

ProjectedView::~ProjectedView()
{
    renderer_->RemoveObserver(layout_);
    clear();
}

void ProjectedView::clear()
{
    for (const StyledActor& a : actors_)
        renderer_->RemoveActor(a.actor);
    actors_.clear();
}

void ProjectedView::setScene(const EvaluatedScene& scene,
                             const std::function<vtkSmartPointer<vtkPolyData>(const std::shared_ptr<const PolygonMesh>&)>& dataOf,
                             const std::vector<vtkSmartPointer<vtkPolyData>>& depthColored)
{
    clear();
    const std::optional<vtkSmartPointer<vtkLookupTable>> bands =
        scene.bands ? std::optional(bandColors(*scene.bands)) : std::nullopt;
    for (std::size_t o = 0; o < scene.meshes.size(); ++o) {
        const bool levels = depthColored[o] && bands;
        auto faces = unlitActor(levels ? depthColored[o] : dataOf(scene.meshes[o]));
        faces->GetProperty()->SetOpacity(levels ? 0.9 : 0.35);
        if (levels)
            colorByLevels(faces, *bands);
        actors_.push_back({faces, Element::Objects, true});
        if (scene.scene.objects[o].type != ObjectType::Mesh) // meshes from files: faces only
            actors_.push_back({unlitActor(edgesData(*scene.meshes[o])), Element::Objects, false});
        const auto& fighting = scene.objectFaces[o].fighting;
        if (fighting && !fighting->faces.empty()) // faces the buffer cannot order, outlined over the picture
            for (const bool surface : {true, false}) {
                auto actor = unlitActor(surface ? facesData(fighting, Coordinates::Drawn) : edgesData(*fighting));
                actor->GetProperty()->SetOpacity(surface ? 0.8 : 1.0);
                actors_.push_back({actor, Element::ZFighting, surface});
            }
    }
    // The window's outline, at mid depth so that no clipping plane cuts it.
    actors_.push_back({unlitActor(linesData(pictureWindowOutline(scene))), Element::Window, false});
    for (const StyledActor& a : actors_)
        renderer_->AddActor(a.actor);

    const Mat4<double> clip = screenClipMatrix(scene.pipeline);
    std::vector<std::pair<Vec2<double>, int>> pixels;
    Vec2<double> pixelSize(0, 0);
    if (const auto& raster = scene.outcomes.raster) {
        pixelSize = Vec2<double>(2.0 / raster->width, 2.0 / raster->height);
        for (int y = 0; y < raster->height; ++y)
            for (int x = 0; x < raster->width; ++x) {
                const int object = raster->object[std::size_t(y * raster->width + x)];
                if (object >= 0)
                    pixels.push_back({Vec2<double>(-1 + x * pixelSize.x(), -1 + y * pixelSize.y()), object});
            }
    }
    rasterGrid_->SetVisibility(scene.outcomes.raster.has_value());
    vanishing_->SetVisibility(!scene.vanishingLines.empty());
    zFightingRing_->SetVisibility(!scene.zFightingRing.empty());
    picture_ = std::make_unique<Picture>(Picture{
        clip, pictureAspect(scene), {{vanishing_, scene.vanishingLines}, {zFightingRing_, scene.zFightingRing}}, pixels, pixelSize, rasterGrid_});
    layout_->Execute(renderer_, vtkCommand::StartEvent, nullptr); // the first frame needs the matrix too
    entries_ = scene.projectedLegend;
    legendFontSize_ = 0;
}

void ProjectedView::applyStyle(report::Theme theme, int fontSize, int minFontSize)
{
    const report::Rgb back = report::backgroundColor(theme, true);
    renderer_->SetBackground(back.r, back.g, back.b);
    for (const StyledActor& a : actors_) {
        const report::Rgb c = report::styledColor(a.element, a.surface, theme);
        a.actor->GetProperty()->SetColor(c.r, c.g, c.b);
        a.actor->GetProperty()->SetLineWidth(a.element == Element::ZFighting ? 3 : 2);
    }
    theme_ = theme;
    fontSize_ = fontSize;
    minFontSize_ = minFontSize;
    legendFontSize_ = 0; // filled anew in the theme's colors
    const report::Rgb ink = report::elementColor(Element::Objects, theme);
    caption_->GetTextProperty()->SetColor(ink.r, ink.g, ink.b);
    const report::Rgb vanishing = report::elementColor(Element::Vanishing, theme), fights = report::elementColor(Element::ZFighting, theme);
    vanishing_->GetProperty()->SetColor(vanishing.r, vanishing.g, vanishing.b);
    vanishing_->GetProperty()->SetOpacity(0.85);
    vanishing_->GetProperty()->SetLineWidth(1.5);
    zFightingRing_->GetProperty()->SetColor(fights.r, fights.g, fights.b);
    zFightingRing_->GetProperty()->SetLineWidth(2.5);
}

void ProjectedView::setCaption(const std::string& text)
{
    captionText_ = text;
}

void ProjectedView::setTextVisible(bool visible)
{
    textVisible_ = visible;
    caption_->SetVisibility(visible);
}

void ProjectedView::setLegendPlace(report::LegendPlace place)
{
    legendPlace_ = place;
}

report::Box2 ProjectedView::layOutText()
{
    const int* size = renderer_->GetSize();
    report::PictureText text;
    text.fontSize = fontSize_;
    text.minFontSize = std::min(fontSize_, minFontSize_);
    text.caption = captionText_;
    text.legend = report::legendShown(entries_, false);
    text.legendPlace = legendPlace_;
    const report::PictureLayout& layout = layoutCache_.layout(size[0], size[1], text, viewFontMeasure(renderer_));
    setCaptionText(caption_, layout.captionLines, layout.captionSize);
    placeLegend(legend_, renderer_, layout, text.legend, theme_, legendFontSize_);
    return textVisible_ && !layout.scene.isEmpty() ? layout.scene : report::Box2{Vec2<double>::Zero(), Vec2<double>(size[0], size[1])};
}

} // namespace viewpipe::gui
