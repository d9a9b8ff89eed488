#include "ScenePainter.h"

#include <vtkActor.h>
#include <vtkActor2D.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCoordinate.h>
#include <vtkPolyDataMapper2D.h>
#include <vtkProperty2D.h>
#include <vtkUnsignedCharArray.h>
#include <vtkCallbackCommand.h>
#include <vtkCamera.h>
#include <vtkCommand.h>
#include <vtkCullerCollection.h>
#include <vtkLegendBoxActor.h>
#include <vtkLookupTable.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkPlane.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>

#include <algorithm>
#include <cmath>

#include "DepthColoring.h"
#include "EigenVtk.h"
#include "Legend.h"
#include "ProjectedView.h"
#include "VtkGeometry.h"

namespace viewpipe::gui {
namespace {

// VTK's interactor asks for 15 frames a second while the user turns the view and 0.0001 at rest.
constexpr double kStillUpdateRate = 1;

// Lines in a view's pixels (y up), one color each.
vtkSmartPointer<vtkPolyData> coloredLines2D(const std::vector<Segment2>& lines, const std::vector<report::Rgb>& colors)
{
    vtkSmartPointer<vtkPolyData> data = linesData(lines);
    auto scalars = vtkSmartPointer<vtkUnsignedCharArray>::New();
    scalars->SetNumberOfComponents(3);
    for (const report::Rgb& c : colors)
        scalars->InsertNextTypedTuple(report::toBytes(c).data());
    data->GetCellData()->SetScalars(scalars);
    return data;
}

// Filled polygons given in the view's pixels (y down), each in its color, for a 2D actor (y up).
vtkSmartPointer<vtkPolyData> polygonsData2D(const std::vector<std::vector<Vec2<double>>>& polygons,
                                            const std::vector<report::Rgb>& colors, int height)
{
    auto points = vtkSmartPointer<vtkPoints>::New();
    auto cells = vtkSmartPointer<vtkCellArray>::New();
    auto scalars = vtkSmartPointer<vtkUnsignedCharArray>::New();
    scalars->SetNumberOfComponents(3);
    for (std::size_t k = 0; k < polygons.size(); ++k) {
        std::vector<vtkIdType> ids;
        for (const Vec2<double>& p : polygons[k])
            ids.push_back(points->InsertNextPoint(p.x(), height - p.y(), 0));
        cells->InsertNextCell(vtkIdType(ids.size()), ids.data());
        scalars->InsertNextTypedTuple(report::toBytes(colors[k]).data());
    }
    auto data = vtkSmartPointer<vtkPolyData>::New();
    data->SetPoints(points);
    data->SetPolys(cells);
    data->GetCellData()->SetScalars(scalars);
    return data;
}

vtkSmartPointer<vtkActor2D> overlayActor(double lineWidth)
{
    auto coordinate = vtkSmartPointer<vtkCoordinate>::New();
    coordinate->SetCoordinateSystemToViewport();
    auto mapper = vtkSmartPointer<vtkPolyDataMapper2D>::New();
    mapper->SetTransformCoordinate(coordinate);
    mapper->SetInputData(linesData(std::vector<Segment2>{}));
    auto actor = vtkSmartPointer<vtkActor2D>::New();
    actor->SetMapper(mapper);
    actor->SetPickable(false);
    actor->GetProperty()->SetLineWidth(lineWidth);
    return actor;
}

} // namespace

void addObjectActors(const std::vector<vtkRenderer*>& renderers, const EvaluatedScene& scene, report::Theme theme)
{
    for (std::size_t o = 0; o < scene.meshes.size(); ++o) {
        const vtkSmartPointer<vtkPolyData> faces = facesData(scene.meshes[o], Coordinates::Drawn);
        const bool edges = scene.scene.objects[o].type != ObjectType::Mesh; // meshes from files: faces only
        for (vtkRenderer* renderer : renderers)
            for (const bool surface : {true, false}) {
                if (!surface && !edges)
                    continue;
                auto actor = unlitActor(surface ? faces : edgesData(*scene.meshes[o]));
                vtkProperty* p = actor->GetProperty();
                p->SetOpacity(surface ? 0.35 : 1.0);
                p->SetLineWidth(2);
                const report::Rgb c = report::styledColor(Element::Objects, surface, theme);
                p->SetColor(c.r, c.g, c.b);
                renderer->AddActor(actor);
            }
    }
}

ScenePainter::ScenePainter(vtkRenderer* world, vtkRenderer* projected, std::shared_ptr<MeshDetails> meshes)
    : world_(world), meshDetails_(std::move(meshes)), worldCaption_(vtkSmartPointer<vtkTextActor>::New()),
      effectsCaption_(vtkSmartPointer<vtkTextActor>::New()), frameAxes_(unlitActor(linesData(std::vector<Segment2>{}))),
      leaders_(overlayActor(1.5)), markers_(overlayActor(1)), tracedMarkers_(overlayActor(1)), backdrops_(overlayActor(1)), legend_(newLegend(true)), clippingRange_(vtkSmartPointer<vtkCallbackCommand>::New()),
      nearCut_(vtkSmartPointer<vtkPlane>::New())
{
    // Coinciding lines and faces are told apart by depth offsets, not by the order they are drawn in
    // (which stitched them together pixel by pixel): lines over the faces they edge, and the canonical
    // outline (setScene) over the view volume's edges, on which it lies at the last stage.
    vtkMapper::SetResolveCoincidentTopologyToPolygonOffset();
    if (projected)
        projected_ = std::make_unique<ProjectedView>(projected);
    world_->AddActor2D(markers_); // under the text's backdrops: a dot the legend stands over is hidden by it
    world_->AddActor2D(backdrops_); // under the text
    worldCaption_->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
    worldCaption_->SetPosition(0.02, 0.96);
    worldCaption_->GetTextProperty()->SetVerticalJustificationToTop();
    useFigureFont(worldCaption_->GetTextProperty(), true);
    worldCaption_->SetPickable(false);
    world_->AddActor2D(worldCaption_);
    effectsCaption_->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
    effectsCaption_->GetTextProperty()->SetVerticalJustificationToTop();
    effectsCaption_->SetPickable(false);
    useFigureFont(effectsCaption_->GetTextProperty(), false);
    world_->AddActor2D(effectsCaption_);
    frameAxes_->SetPickable(false);
    frameAxes_->SetUseBounds(false);
    world_->AddActor(frameAxes_);
    world_->AddActor2D(legend_);
    world_->AddActor2D(tracedMarkers_); // over the text: the vertex traced stays in sight where its label points
    world_->AddActor2D(leaders_);
    leftOut_ = newLabel(leftOutText_);
    leftOut_.actor->SetVisibility(false);
    // Props' bounds mean nothing under a projective matrix: no culling by them,
    // and the clipping range comes from the framing, before each frame.
    world_->GetCullers()->RemoveAllItems();
    clippingRange_->SetClientData(this);
    clippingRange_->SetCallback(
        [](vtkObject*, unsigned long, void* painter, void*) { static_cast<ScenePainter*>(painter)->beforeFrame(); });
    world_->AddObserver(vtkCommand::StartEvent, clippingRange_);
    applyStyle();
}

ScenePainter::~ScenePainter()
{
    world_->RemoveObserver(clippingRange_);
    clear();
}

void ScenePainter::clear()
{
    for (const Layer& layer : layers_)
        world_->RemoveActor(layer.actor);
    for (const Layer& ghost : ghosts_)
        world_->RemoveActor(ghost.actor);
    for (const Label& label : labels_)
        world_->RemoveActor2D(label.actor);
    ghosts_.clear();
    layers_.clear();
    labels_.clear();
}

const std::shared_ptr<MeshDetail>& ScenePainter::meshDetail(const std::shared_ptr<const PolygonMesh>& mesh)
{
    auto found = meshDetails_->find(mesh.get());
    if (found == meshDetails_->end())
        found = meshDetails_->emplace(mesh.get(), std::make_shared<MeshDetail>(mesh)).first;
    return found->second;
}

std::vector<vtkMapper*> ScenePainter::Layer::mappers() const
{
    return detail ? detail->mappers() : std::vector<vtkMapper*>{actor->GetMapper()};
}

void ScenePainter::addLayer(const Primitive& primitive, vtkSmartPointer<vtkActor> actor, std::optional<DetailedActor> detail)
{
    Layer layer{&primitive, std::move(actor), std::move(detail)};
    layer.actor->SetPickable(false);
    layer.actor->SetUseBounds(false);
    world_->AddActor(layer.actor);
    layers_.push_back(layer);
}

ScenePainter::Label ScenePainter::newLabel(const viewpipe::Label& text)
{
    // Drawn over the picture where the placement step puts it (never hidden behind a face).
    Label label{&text, vtkSmartPointer<vtkTextActor>::New()};
    label.actor->SetInput(text.text.c_str());
    label.actor->SetPickable(false);
    label.actor->GetPositionCoordinate()->SetCoordinateSystemToViewport();
    label.actor->GetTextProperty()->SetJustificationToLeft();
    label.actor->GetTextProperty()->SetVerticalJustificationToBottom();
    styleLabel(label);
    world_->AddActor2D(label.actor);
    return label;
}

void ScenePainter::addLabel(const viewpipe::Label& text)
{
    labels_.push_back(newLabel(text));
}

void ScenePainter::styleLabel(Label& label) const
{
    const report::Rgb c = report::elementColor(label.label->element, theme_);
    vtkTextProperty* text = label.actor->GetTextProperty();
    text->SetColor(c.r, c.g, c.b);
    const report::Rgb back = report::backgroundColor(theme_, false);
    text->SetBackgroundColor(back.r, back.g, back.b);
    text->SetBackgroundOpacity(report::kLabelBackdropOpacity);
    text->SetFontSize(label.label->minor ? int(report::smallTextSize(labelSize_)) : labelSize_);
    useFigureFont(text, !label.label->minor); // the font file too: tick numbers were drawn bold, measured regular
}

void ScenePainter::styleLabels()
{
    for (Label& label : labels_)
        styleLabel(label);
    for (Label& label : frameLabels_)
        styleLabel(label);
    styleLabel(leftOut_);
}

void ScenePainter::setScene(std::shared_ptr<const EvaluatedScene> scene)
{
    clear();
    tracedMarker_.reset();
    tracedLabel_.reset();
    cutting_ = false; // the new props are not cut yet
    // Keep the poly data of the meshes the new scene shares with the last one (the layers of views
    // sharing the store keep what they still draw).
    MeshDetails kept;
    for (const Primitive& p : scene->primitives)
        if (p.faces && meshDetails_->count(p.faces.get()))
            kept.emplace(p.faces.get(), meshDetails_->at(p.faces.get()));
    *meshDetails_ = std::move(kept);
    scene_ = std::move(scene);
    const EvaluatedScene& s = *scene_;

    std::vector<vtkSmartPointer<vtkPolyData>> depthColored(s.meshes.size());
    const vtkSmartPointer<vtkLookupTable> bands = s.bands ? bandColors(*s.bands) : nullptr;
    for (const Primitive& p : s.primitives) {
        if (p.depthColored && bands) { // what the depth buffer holds, in bands
            depthColored[std::size_t(p.object)] = depthLevels(p.faces, s.pipeline, *s.scene.effects.depth);
            addLayer(p, unlitActor(depthColored[std::size_t(p.object)]));
            colorByLevels(layers_.back().actor, bands);
        } else if (p.kind == PrimitiveKind::Faces) {
            DetailedActor faces(meshDetail(p.faces));
            addLayer(p, faces.actor(), faces);
        } else {
            addLayer(p, unlitActor(linesData(p.segments)));
            if (p.canonical)
                for (vtkMapper* mapper : layers_.back().mappers())
                    mapper->SetRelativeCoincidentTopologyLineOffsetParameters(0, -2);
        }
        if (report::StageShown::ghosted(p)) {
            Layer ghost{&p, unlitActor(static_cast<vtkPolyDataMapper*>(layers_.back().actor->GetMapper())->GetInput()), {}};
            ghost.actor->SetPickable(false);
            ghost.actor->SetUseBounds(false);
            ghost.actor->SetVisibility(false);
            world_->AddActor(ghost.actor);
            ghosts_.push_back(ghost);
        }
    }
    for (const viewpipe::Label& label : s.labels)
        addLabel(label);
    if (projected_)
        projected_->setScene(s, [this](const auto& mesh) { return meshDetail(mesh)->full(); }, depthColored);
    effectsNote_ = s.effectsNote;
    applyStyle();
    show(Mat4<double>::Identity(), 0);
}

void ScenePainter::show(const Mat4<double>& cumulative, double canonicalOpacity)
{
    const bool canonicalAppears = (canonicalOpacity > 0) != (canonicalOpacity_ > 0);
    canonicalOpacity_ = canonicalOpacity;
    if (canonicalAppears) { // the legend names it while it shows
        legendFontSize_ = 0;
        fitCaptions();
    }
    shownMatrix_ = cumulative;
    cutNear(cumulative);
    const vtkSmartPointer<vtkMatrix4x4> matrix = toVtk(cumulative);
    for (Layer& layer : layers_) {
        if (layer.primitive->canonical) {
            layer.actor->SetVisibility(canonicalOpacity > 0);
            layer.actor->GetProperty()->SetOpacity(canonicalOpacity);
        } else {
            layer.actor->SetUserMatrix(matrix);
        }
    }
}

void ScenePainter::setGhost(const std::optional<Mat4<double>>& ghost)
{
    const vtkSmartPointer<vtkMatrix4x4> matrix = ghost ? toVtk(*ghost) : nullptr;
    for (Layer& layer : ghosts_) {
        layer.actor->SetVisibility(ghost.has_value());
        if (ghost)
            layer.actor->SetUserMatrix(matrix);
    }
}

bool ScenePainter::shows(const Vec3<double>& world) const
{
    return report::StageShown(*scene_, shownMatrix_, canonicalOpacity_).shows(world);
}

void ScenePainter::setMoving(bool moving)
{
    moving_ = moving;
}

void ScenePainter::beforeFrame()
{
    vtkRenderWindow* window = world_->GetRenderWindow();
    const bool turning = window && window->GetDesiredUpdateRate() > kStillUpdateRate;
    for (Layer& layer : layers_)
        if (layer.detail)
            layer.detail->setMoving(moving_ || turning);
    fitClippingRange();
    fitCaptions();
    placeLabels();
}

void ScenePainter::drawMarkers(const std::vector<report::FigureShape>& shapes)
{
    for (const bool traced : {false, true}) {
        std::vector<std::vector<Vec2<double>>> polygons;
        std::vector<report::Rgb> colors;
        for (const report::FigureShape& shape : shapes)
            if ((shape.element == Element::Traced) == traced) {
                polygons.push_back(shape.points);
                colors.push_back(report::elementColor(shape.element, theme_));
            }
        static_cast<vtkPolyDataMapper2D*>((traced ? tracedMarkers_ : markers_)->GetMapper())
            ->SetInputData(polygonsData2D(polygons, colors, world_->GetSize()[1]));
    }
}

void ScenePainter::drawBackdrops()
{
    std::vector<std::vector<Vec2<double>>> polygons;
    for (const report::Box2& b : report::textBackdrops(textBoxes_[0], textBoxes_[1], textBoxes_[2], world_->GetSize()[1]))
        polygons.push_back({b.min, Vec2<double>(b.max.x(), b.min.y()), b.max, Vec2<double>(b.min.x(), b.max.y())});
    const std::vector<report::Rgb> colors(polygons.size(), report::backgroundColor(theme_, false));
    static_cast<vtkPolyDataMapper2D*>(backdrops_->GetMapper())->SetInputData(polygonsData2D(polygons, colors, world_->GetSize()[1]));
}

void ScenePainter::fitCaptions()
{
    const int* size = world_->GetSize();
    report::PictureText text;
    text.fontSize = fontSize_;
    text.minFontSize = minFontSize();
    text.caption = worldCaptionText_;
    text.note = effectsCaption_->GetVisibility() ? effectsNote_ : "";
    if (scene_)
        text.legend = report::legendShown(scene_->worldLegend, canonicalOpacity_ > 0);
    text.subject = subject_;
    text.shown = subjectShown_;
    text.legendPlace = legendPlace_;
    text.zoom = layoutZoom_;
    const report::PictureLayout& layout = layoutCache_.layout(size[0], size[1], text, viewFontMeasure(world_));
    setCaptionText(worldCaption_, layout.captionLines, layout.captionSize);
    setCaptionText(effectsCaption_, layout.noteLines, layout.noteSize);
    if (!layout.noteLines.empty()) // from its top, as the caption: the box the labels keep clear of is the layout's
        effectsCaption_->SetPosition(layout.note.min.x() / size[0], 1 - layout.note.min.y() / size[1]);
    placeLegend(legend_, world_, layout, text.legend, theme_, legendFontSize_);
    if (const int labels = int(report::labelSizeIn(layout, fontSize_)); labels != labelSize_) {
        labelSize_ = labels;
        styleLabels();
        if (projected_) // side by side, the two views' titles at one size (presenting, they jumped from one to twice it)
            projected_->applyStyle(theme_, labelSize_, minFontSize());
    }
    textBoxes_ = textBoxesShown(); // measured once a frame, for the backdrops and the labels' placement
    drawBackdrops();
    const report::Box2 area = textVisible_ ? layout.scene : report::Box2{Vec2<double>::Zero(), Vec2<double>(size[0], size[1])};
    if ((area.min - sceneArea_.min).norm() + (area.max - sceneArea_.max).norm() > 0.5) {
        sceneArea_ = area;
        if (framed_.radius > 0)
            frameOn(framed_); // the same framing, in the area the text leaves free
    }
}

report::FigureView ScenePainter::figureView() const
{
    report::FigureView view;
    view.camera =
        fromVtk(world_->GetActiveCamera()->GetCompositeProjectionTransformMatrix(world_->GetTiledAspectRatio(), -1, 1));
    view.width = world_->GetSize()[0];
    view.height = world_->GetSize()[1];
    view.frameExtent = report::frameExtent(framed_);
    view.fontSize = labelSize_;
    view.textSize = fontSize_;
    view.minFontSize = minFontSize();
    view.subject = subject_;
    view.ticks = ticksShown_;
    view.notes = notesShown_;
    view.subjectShown = subjectShown_;
    view.legendPlace = legendPlace_;
    view.zoom = layoutZoom_;
    view.lineScale = lineScale_;
    return view;
}

std::array<report::Box2, 3> ScenePainter::textBoxesShown() const
{
    // Viewport coordinates (y up) to the view's pixels (y down).
    const int height = world_->GetSize()[1];
    auto box = [&](const double* corners) {
        return report::Box2{Vec2<double>(corners[0], height - corners[3]), Vec2<double>(corners[1], height - corners[2])};
    };
    std::array<report::Box2, 3> boxes;
    for (int k = 0; k < 2; ++k) {
        vtkTextActor* caption = k == 0 ? worldCaption_.Get() : effectsCaption_.Get();
        if (caption->GetVisibility() && caption->GetInput() && *caption->GetInput()) {
            double corners[4]; // relative to the caption's position
            caption->GetBoundingBox(world_, corners);
            const double* at = caption->GetPositionCoordinate()->GetComputedDoubleViewportValue(world_);
            const double placed[4] = {corners[0] + at[0], corners[1] + at[0], corners[2] + at[1], corners[3] + at[1]};
            boxes[std::size_t(k)] = box(placed);
        }
    }
    if (legend_->GetVisibility()) {
        // Position2 is relative to Position: computed, it is the upper right corner.
        const int* low = legend_->GetPositionCoordinate()->GetComputedViewportValue(world_);
        const double x0 = low[0], y0 = low[1];
        const int* high = legend_->GetPosition2Coordinate()->GetComputedViewportValue(world_);
        const double corners[4] = {x0, double(high[0]), y0, double(high[1])};
        boxes[2] = box(corners);
    }
    return boxes;
}

void ScenePainter::placeLabels()
{
    std::vector<Segment2> leaders;
    std::vector<report::Rgb> leaderColors;
    std::vector<report::FigureShape> markerShown;
    for (Label& label : labels_)
        label.actor->SetVisibility(false);
    for (Label& label : frameLabels_)
        label.actor->SetVisibility(false);
    leftOut_.actor->SetVisibility(false);
    placed_ = {};
    if (scene_) {
        std::vector<Marker> markers = scene_->markers;
        if (tracedMarker_)
            markers.push_back(*tracedMarker_);
        const report::FigureView view = figureView();
        const report::StageShown stage(*scene_, shownMatrix_, canonicalOpacity_);
        markerShown = report::markerShapes(stage, view, markers);
        if (textVisible_)
            placeLabelsOf(stage, view, markers, leaders, leaderColors);
    }
    drawMarkers(markerShown);
    static_cast<vtkPolyDataMapper2D*>(leaders_->GetMapper())->SetInputData(coloredLines2D(leaders, leaderColors));
}

void ScenePainter::placeLabelsOf(const report::StageShown& stage, const report::FigureView& view, const std::vector<Marker>& markers,
                                 std::vector<Segment2>& leaders, std::vector<report::Rgb>& leaderColors)
{
    std::vector<Label*> all; // the scene's, the traced vertex's, then the frame's
    for (Label& label : labels_)
        all.push_back(&label);
    for (Label& label : frameLabels_)
        all.push_back(&label);
    std::vector<const viewpipe::Label*> texts;
    for (const Label* label : all)
        texts.push_back(label->label);
    vtkRenderWindow* window = world_->GetRenderWindow();
    const int dpi = window ? window->GetDPI() : 72;
    const report::LabelMeasure measure = report::labelMeasure(figureFontMeasure(dpi), labelSize_); // as the labels are set (styleLabel)
    // Viewport pixels are y up, the placement's y down.
    auto up = [&](const Vec2<double>& p) { return Vec2<double>(p.x(), view.height - p.y()); };
    std::vector<report::Box2> reserved;
    for (const report::Box2& box : textBoxes_)
        if (!box.isEmpty())
            reserved.push_back(box);
    placed_ = report::placeSceneLabels(stage, view, texts, markers, measure, reserved);
    if (placed_.leftOut) {
        leftOut_.actor->SetInput(placed_.leftOut->text.c_str());
        leftOut_.actor->SetPosition(placed_.leftOut->box.min.x(), view.height - placed_.leftOut->box.max.y());
        leftOut_.actor->SetVisibility(true);
    }
    const auto& placed = placed_.placed;
    for (std::size_t k = 0; k < all.size(); ++k) {
        if (!placed[k])
            continue;
        const report::PlacedLabel& p = *placed[k];
        all[k]->actor->SetVisibility(true);
        all[k]->actor->SetPosition(p.box.min.x(), view.height - p.box.max.y()); // the text's lower left corner
        if (p.leader) {
            leaders.push_back({up(p.anchor), up(p.box.nearest(p.anchor))});
            leaderColors.push_back(report::elementColor(p.element, theme_));
        }
    }
}

void ScenePainter::cutNear(const Mat4<double>& cumulative)
{
    // The plane in the stage's coordinates: VTK takes it there and maps it back through each prop's matrix.
    const bool cut = scene_ && scene_->nearCut && isProjective(cumulative);
    if (cut) {
        const Vec4<double> plane = cumulative.transpose().fullPivLu().solve(*scene_->nearCut);
        const Vec3<double> normal = plane.head<3>();
        nearCut_->SetNormal(normal.data());
        nearCut_->SetOrigin(Vec3<double>(-plane.w() * normal / normal.squaredNorm()).data());
    }
    if (cut == cutting_)
        return;
    cutting_ = cut;
    for (Layer& layer : layers_) {
        if (layer.primitive->canonical)
            continue;
        for (vtkMapper* mapper : layer.mappers())
            if (cut)
                mapper->AddClippingPlane(nearCut_);
            else
                mapper->RemoveAllClippingPlanes();
    }
}

void ScenePainter::showMoment(const report::WorldMoment& moment)
{
    show(moment.drawn, moment.canonicalOpacity);
    setGhost(moment.ghost);
    frameOn(moment.framing);
}

report::WorldCamera ScenePainter::camera() const
{
    vtkCamera* vtk = world_->GetActiveCamera();
    report::WorldCamera camera;
    vtk->GetPosition(camera.position.data());
    vtk->GetFocalPoint(camera.focalPoint.data());
    vtk->GetViewUp(camera.viewUp.data());
    camera.viewAngle = vtk->GetViewAngle();
    vtk->GetWindowCenter(camera.windowCenter.data());
    vtk->GetClippingRange(camera.nearPlane, camera.farPlane);
    return camera;
}

void ScenePainter::setCamera(const report::WorldCamera& camera)
{
    setVtkCamera(world_->GetActiveCamera(), camera);
}

void setVtkCamera(vtkCamera* vtk, const report::WorldCamera& camera)
{
    vtk->SetFocalPoint(camera.focalPoint.data());
    vtk->SetPosition(camera.position.data());
    vtk->SetViewUp(camera.viewUp.data());
    vtk->SetViewAngle(camera.viewAngle);
    vtk->SetWindowCenter(camera.windowCenter.x(), camera.windowCenter.y());
    vtk->SetClippingRange(camera.nearPlane, camera.farPlane);
}

report::ViewFit ScenePainter::viewFit() const
{
    const int* size = world_->GetSize();
    return {size[0], size[1], sceneArea_, userZoom_, userPan_};
}

void ScenePainter::frameOn(const report::Framing& framing)
{
    report::WorldCamera camera = this->camera();
    viewpipe::report::frameOn(camera, framing, viewFit());
    setCamera(camera);
    framed_ = framing;
    // At rest, or moving under one framing (while framings blend the text stays put); made anew only for
    // another framing or direction: every frame of a step frames the same one.
    const std::array<double, 14> outlined = {framing.box.min().x(), framing.box.min().y(), framing.box.min().z(),
                                            framing.box.max().x(), framing.box.max().y(), framing.box.max().z(),
                                            double(framing.points.size()), double(framing.shown.size()),
                                            camera.position.x() - camera.focalPoint.x(), camera.position.y() - camera.focalPoint.y(),
                                            camera.position.z() - camera.focalPoint.z(), camera.viewUp.x(), camera.viewUp.y(),
                                            camera.viewUp.z()};
    if (framing.blended.empty() && outlined != outlined_) {
        outlined_ = outlined;
        subject_ = report::subjectOutline(camera, framing);
        subjectShown_ = report::subjectOutline(camera, framing, true);
    }
    // The fixed axes run across everything framed, with their ticks and labels.
    const report::FrameMarks marks = report::frameMarks(report::frameExtent(framing), ticksShown_);
    static_cast<vtkPolyDataMapper*>(frameAxes_->GetMapper())->SetInputData(linesData(marks.lines));
    const bool sameTexts = marks.labels.size() == frameLabelTexts_.size() &&
                           std::equal(marks.labels.begin(), marks.labels.end(), frameLabelTexts_.begin(),
                                      [](const viewpipe::Label& a, const viewpipe::Label& b) { return a.text == b.text; });
    if (sameTexts) {
        for (std::size_t k = 0; k < marks.labels.size(); ++k)
            frameLabelTexts_[k].anchor = marks.labels[k].anchor; // the actors keep pointing here
    } else {
        for (const Label& label : frameLabels_)
            world_->RemoveActor2D(label.actor);
        frameLabels_.clear();
        frameLabelTexts_ = marks.labels;
        for (const viewpipe::Label& text : frameLabelTexts_)
            frameLabels_.push_back(newLabel(text));
    }
}

void ScenePainter::fitClippingRange()
{
    report::WorldCamera camera = this->camera();
    viewpipe::report::fitClippingRange(camera, framed_);
    world_->GetActiveCamera()->SetClippingRange(camera.nearPlane, camera.farPlane);
}

void ScenePainter::rememberUserCamera()
{
    const report::WorldCamera camera = this->camera();
    const report::CameraAim aim = report::fitAim(camera, framed_, viewFit());
    userZoom_ = camera.distance() / aim.distance;
    userPan_ = (camera.focalPoint - aim.focalPoint) / framed_.radius;
}

// The web page turns its points by RotX(pitch) RotY(yaw) in the default eye's
// axes: the camera turns the other way, about its up, then about its right.
void ScenePainter::orbit(double yaw, double pitch, double zoom)
{
    vtkCamera* camera = world_->GetActiveCamera();
    camera->OrthogonalizeViewUp();
    camera->Azimuth(-yaw);
    camera->Elevation(pitch);
    camera->OrthogonalizeViewUp();
    frameOn(framed_); // fitted anew from the new direction (a fit depends on it), as much zoomed and panned
    camera->Dolly(zoom);
    rememberUserCamera();
    layoutZoom_ = 1 / userZoom_;
}

ScenePainter::Orbit ScenePainter::orbitAngles() const
{
    // The direction of view in the default eye's axes is (cos p sin y, -sin p, -cos p cos y).
    const report::WorldCamera standard;
    const Vec3<double> back = standard.position.normalized();
    const Vec3<double> right = standard.viewUp.cross(back).normalized();
    const Vec3<double> up = back.cross(right);
    const Vec3<double> direction = camera().direction();
    const Vec3<double> eye(direction.dot(right), direction.dot(up), direction.dot(back));
    constexpr double degrees = 180 / 3.14159265358979323846;
    return {std::atan2(eye.x(), -eye.z()) * degrees, std::asin(std::clamp(-eye.y(), -1.0, 1.0)) * degrees, 1 / userZoom_};
}

void ScenePainter::setLegendPlace(report::LegendPlace place)
{
    legendPlace_ = place;
}

void ScenePainter::setTicksAndNotesShown(bool ticks, bool notes)
{
    ticksShown_ = ticks;
    notesShown_ = notes;
    frameOn(framed_); // the axes' marks anew
}

void ScenePainter::setProjectedLegendPlace(report::LegendPlace place)
{
    if (projected_)
        projected_->setLegendPlace(place);
}

void ScenePainter::resetView()
{
    setCamera(report::WorldCamera{});
    userZoom_ = 1;
    layoutZoom_ = 1;
    userPan_.setZero();
    frameOn(framed_); // the stage's framing at rest (the step's while it moves), as the view first showed it
}

std::optional<Vec3<double>> ScenePainter::pickVertex(int displayX, int displayY) const
{
    if (!scene_)
        return std::nullopt;
    // World view's camera after the stage's matrix: where each vertex is drawn, in pixels.
    const Mat4<double> camera =
        fromVtk(world_->GetActiveCamera()->GetCompositeProjectionTransformMatrix(world_->GetTiledAspectRatio(), -1, 1));
    const Mat4<double> drawn = camera * shownMatrix_;
    const int* size = world_->GetSize();
    const int* origin = world_->GetOrigin();
    const int* window = world_->GetRenderWindow()->GetSize();
    // VTK's display pixels run up from the window's bottom; the view's, down from its top.
    const Vec2<double> at(displayX - origin[0], size[1] - (displayY - origin[1]));
    return viewpipe::report::pickVertex(scene_->objectVertices(), drawn, Vec2<double>(size[0], size[1]), at,
                                Vec2<double>(window[0], window[1]), cutting_ ? scene_->nearCut : std::nullopt);
}

void ScenePainter::setTextVisible(bool visible)
{
    textVisible_ = visible;
    worldCaption_->SetVisibility(visible);
    effectsCaption_->SetVisibility(visible && scene_ && !scene_->effectsNote.empty());
    if (projected_)
        projected_->setTextVisible(visible);
    fitCaptions();
    placeLabels();
}

void ScenePainter::setCaptions(const std::string& world, const std::string& projected)
{
    worldCaptionText_ = world;
    fitCaptions();
    if (projected_)
        projected_->setCaption(projected);
}

void ScenePainter::markTraced(const std::optional<Vec3<double>>& point)
{
    if (tracedLabel_) { // its label comes last: added after the scene's
        world_->RemoveActor2D(labels_.back().actor);
        labels_.pop_back();
    }
    tracedMarker_.reset();
    tracedLabel_.reset();
    if (point && scene_) {
        tracedMarker_ = report::tracedMarker(*point);
        tracedLabel_ = std::make_unique<viewpipe::Label>(report::tracedLabel(*point));
        addLabel(*tracedLabel_);
        applyStyle();
    }
}

std::string ScenePainter::worldCaption() const
{
    return worldCaptionText_;
}

void ScenePainter::setTheme(report::Theme theme)
{
    theme_ = theme;
    applyStyle();
}

void ScenePainter::setLineScale(double scale)
{
    lineScale_ = scale;
    applyStyle();
}

void ScenePainter::setFontSize(int points, int minPoints)
{
    fontSize_ = points;
    minFontSize_ = minPoints;
    applyStyle();
}

void ScenePainter::applyStyle()
{
    const report::Rgb back = report::backgroundColor(theme_, false);
    world_->SetBackground(back.r, back.g, back.b);
    for (Layer& layer : layers_) {
        const Primitive& p = *layer.primitive;
        const bool surface = p.kind == PrimitiveKind::Faces;
        const report::Rgb c = report::styledColor(p.element, surface, theme_);
        vtkProperty* property = layer.actor->GetProperty();
        property->SetColor(c.r, c.g, c.b);
        property->SetOpacity(p.canonical ? canonicalOpacity_ : p.opacity);
        property->SetLineWidth(lineScale_ * report::lineWidthOf(p));
    }
    for (Layer& ghost : ghosts_) {
        const report::Rgb c = report::elementColor(ghost.primitive->element, theme_);
        ghost.actor->GetProperty()->SetColor(c.r, c.g, c.b);
        ghost.actor->GetProperty()->SetOpacity(report::kGhostOpacity);
        ghost.actor->GetProperty()->SetLineWidth(lineScale_ * report::lineWidthOf(ghost.primitive->element, false));
    }
    styleLabels();
    const report::Rgb ink = report::elementColor(Element::Objects, theme_);
    worldCaption_->GetTextProperty()->SetColor(ink.r, ink.g, ink.b);
    worldCaption_->GetTextProperty()->SetFontSize(fontSize_);
    effectsCaption_->GetTextProperty()->SetColor(ink.r, ink.g, ink.b);
    effectsCaption_->GetTextProperty()->SetFontSize(int(report::smallTextSize(fontSize_)));
    effectsCaption_->SetVisibility(textVisible_ && scene_ && !scene_->effectsNote.empty());
    const report::Rgb frame = report::elementColor(Element::Frame, theme_);
    frameAxes_->GetProperty()->SetColor(frame.r, frame.g, frame.b);
    frameAxes_->GetProperty()->SetLineWidth(1.5 * lineScale_);
    legendFontSize_ = 0; // filled anew in the theme's colors
    fitCaptions();
    if (projected_)
        projected_->applyStyle(theme_, labelSize_, minFontSize());
}

} // namespace viewpipe::gui
