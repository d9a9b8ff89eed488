#include "StagePair.h"

#include <QHBoxLayout>
#include <QSplitter>

#include <QVTKOpenGLNativeWidget.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>
#include <vtkRendererCollection.h>

#include <cmath>

#include "ClickStyle.h"

namespace viewpipe::gui {

namespace {

// Labels and captions are 1.6 times the window's text: 17.6 points at 100 %.
constexpr double kLabelPoints = 17.6;

} // namespace

StagePair::StagePair(std::shared_ptr<MeshDetails> meshes, QWidget* parent) : StageViews(parent)
{
    auto makeView = [](QVTKOpenGLNativeWidget*& widget, vtkGenericOpenGLRenderWindow*& window) {
        widget = new QVTKOpenGLNativeWidget;
        auto renderWindow = vtkSmartPointer<vtkGenericOpenGLRenderWindow>::New();
        widget->setRenderWindow(renderWindow);
        renderWindow->AddRenderer(vtkSmartPointer<vtkRenderer>::New());
        window = renderWindow;
    };
    makeView(worldWidget_, worldWindow_);
    makeView(projectedWidget_, projectedWindow_);
    worldWidget_->setObjectName("worldView");
    projectedWidget_->setObjectName("projectedView");
    worldWidget_->setToolTip(tr("The world view: every element through the stages' matrices so far. "
                                "Drag to turn, wheel to zoom, click a vertex to trace it"));
    projectedWidget_->setToolTip(tr("What the camera sees: the scene projected onto the view plane"));
    worldWidget_->setMinimumSize(260, 260);
    projectedWidget_->setMinimumSize(160, 160);

    // A click picks a vertex to trace; a camera move is kept by later framing.
    auto style = vtkSmartPointer<ClickStyle>::New();
    style->onClick = [this](int x, int y) { emit vertexPicked(painter_->pickVertex(x, y)); };
    style->onCameraMoved = [this] { painter_->rememberUserCamera(); };
    worldWindow_->GetInteractor()->SetInteractorStyle(style);
    // The projected view is a fixed picture: no camera interaction.
    projectedWindow_->GetInteractor()->SetInteractorStyle(nullptr);

    painter_ = std::make_unique<ScenePainter>(worldWindow_->GetRenderers()->GetFirstRenderer(),
                                              projectedWindow_->GetRenderers()->GetFirstRenderer(), std::move(meshes));

    auto* splitter = new QSplitter(Qt::Horizontal);
    splitter->addWidget(worldWidget_);
    splitter->addWidget(projectedWidget_);
    splitter->setStretchFactor(0, 5);
    splitter->setStretchFactor(1, 3);
    splitter->setSizes({500, 300});
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(splitter);
}

StagePair::~StagePair() = default;

void StagePair::setScene(std::shared_ptr<const EvaluatedScene> scene)
{
    painter_->setScene(std::move(scene));
    painter_->markTraced(traced_);
}

void StagePair::setTraced(const std::optional<Vec3<double>>& point)
{
    traced_ = point;
    painter_->markTraced(traced_);
}

void StagePair::setTheme(report::Theme theme)
{
    painter_->setTheme(theme);
}

void StagePair::setTextScale(double scale)
{
    // Where the text leaves too little room, the caption and legend may shrink back to the size at 100 %.
    painter_->setFontSize(int(std::lround(kLabelPoints * scale)), int(std::lround(kLabelPoints)));
}

void StagePair::setTicksAndNotesShown(bool ticks, bool notes)
{
    painter_->setTicksAndNotesShown(ticks, notes);
}

void StagePair::resetView()
{
    painter_->resetView();
}

void StagePair::orbit(double yaw, double pitch, double zoom)
{
    painter_->resetView();
    painter_->orbit(yaw, pitch, zoom);
}

ScenePainter::Orbit StagePair::orbitAngles() const
{
    return painter_->orbitAngles();
}

void StagePair::renderNow()
{
    worldWindow_->Render();
    if (projectedWidget_->isVisible())
        projectedWindow_->Render();
    worldWidget_->update();
    projectedWidget_->update();
}

void StagePair::renderWorldView()
{
    if (!isVisible()) // behind the storyboard: drawn once shown
        return;
    worldWindow_->Render();
    worldWidget_->update();
}

QImage StagePair::image()
{
    return worldWidget_->grabFramebuffer();
}

void StagePair::setProjectedViewVisible(bool visible)
{
    projectedWidget_->setVisible(visible);
}

} // namespace viewpipe::gui
