#include "StoryboardView.h"

#include <QPainter>
#include <QResizeEvent>
#include <QShowEvent>

#include <QVTKOpenGLNativeWidget.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>

#include "ClickStyle.h"
#include "export/Offscreen.h"
#include "export/VectorFigure.h"
#include "painter/VtkGeometry.h"
#include "viewpipe/lesson.hpp"
#include "viewpipe/report/world_view.hpp"

namespace viewpipe::gui {

struct StoryboardView::Cell {
    int stage = 0;
    QVTKOpenGLNativeWidget* widget = new QVTKOpenGLNativeWidget;
    vtkSmartPointer<vtkGenericOpenGLRenderWindow> window = vtkSmartPointer<vtkGenericOpenGLRenderWindow>::New();
    vtkSmartPointer<vtkRenderer> renderer = vtkSmartPointer<vtkRenderer>::New();
    std::unique_ptr<ScenePainter> painter; // before the widget and its window go

    ~Cell()
    {
        painter.reset();
        delete widget;
    }
};

StoryboardView::StoryboardView(std::shared_ptr<MeshDetails> meshes, QWidget* parent)
    : StageViews(parent), meshes_(std::move(meshes))
{
    setObjectName("storyboard");
    setMinimumSize(320, 240);
    setAccessibleName(tr("Storyboard: every stage at once"));
}

StoryboardView::~StoryboardView() = default;

double StoryboardView::labelSize() const
{
    return report::storyboardLabelSize(width(), textScale_);
}

Vec3<double> StoryboardView::traced() const
{
    return traced_ ? *traced_ : report::storyboardTracedPoint(*scene_);
}

void StoryboardView::setScene(std::shared_ptr<const EvaluatedScene> scene)
{
    if (!isVisible()) { // drawn once shown
        waiting_ = std::move(scene);
        return;
    }
    waiting_.reset();
    const bool sameStages = scene_ && scene_->pipeline.stages.size() == scene->pipeline.stages.size();
    scene_ = std::move(scene);
    cellScene_ = withoutEffectsNote(scene_);
    framings_ = report::stageFramings(*cellScene_, report::FramingMode::Together);
    if (!sameStages)
        buildCells();
    for (auto& cell : cells_) {
        cell->painter->setScene(cellScene_);
        if (!sameStages) { // new cells turned as the cells were (a lesson step's turn may come before its scene)
            cell->painter->resetView();
            cell->painter->orbit(turn_.yaw, turn_.pitch, turn_.zoom);
        }
    }
    layOut();
}

void StoryboardView::buildCells()
{
    cells_.clear();
    const int stages = int(scene_->pipeline.stages.size());
    for (int k = 0; k <= stages; ++k) {
        auto cell = std::make_unique<Cell>();
        cell->stage = k;
        cell->widget->setParent(this);
        cell->widget->setObjectName(QString("storyboardCell%1").arg(k));
        cell->widget->setRenderWindow(cell->window);
        cell->window->AddRenderer(cell->renderer);
        cell->painter = std::make_unique<ScenePainter>(cell->renderer, nullptr, meshes_);
        cell->painter->setTheme(theme_);
        auto style = vtkSmartPointer<ClickStyle>::New();
        style->onClick = [this, painter = cell->painter.get()](int x, int y) { emit vertexPicked(painter->pickVertex(x, y)); };
        style->onCameraMoved = [this, k] {
            cells_[std::size_t(k)]->painter->rememberUserCamera(); // its zoom and pan too, before the others follow
            turnAllAs(k);
        };
        cell->window->GetInteractor()->SetInteractorStyle(style);
        cell->widget->show();
        cells_.push_back(std::move(cell));
    }
}

void StoryboardView::layOut()
{
    if (!scene_ || !isVisible())
        return;
    std::vector<int> stages;
    for (const auto& cell : cells_)
        stages.push_back(cell->stage);
    layout_ = report::layoutStoryboard(*scene_, stages, traced(), width(), height(), labelSize(), figureFontMeasure());
    overlay_ = layout_.cells.empty() ? report::Figure{} : storyboardOverlay(*scene_, layout_, traced(), figureFontMeasure(), 1);
    for (std::size_t k = 0; k < cells_.size(); ++k) {
        Cell& cell = *cells_[k];
        if (k >= layout_.cells.size()) { // no room for it
            cell.widget->hide();
            continue;
        }
        const report::Box2& box = layout_.cells[k].picture;
        cell.widget->setGeometry(int(box.min.x()), int(box.min.y()), int(box.max.x() - box.min.x()),
                                 int(box.max.y() - box.min.y()));
        cell.widget->show();
        styleStoryboardCell(*cell.painter, layout_.labelSize, ticksShown_, false, traced());
        cell.painter->showMoment(stageAtRest(*cellScene_, cell.stage, framings_));
        cell.widget->update(); // drawn in its next paint, or by the window's renderNow: once
    }
    update();
}

void StoryboardView::renderNow()
{
    for (const auto& cell : cells_) {
        if (!cell->widget->isVisible())
            continue;
        cell->window->Render();
        cell->widget->update();
    }
}

void StoryboardView::turnAllAs(int k)
{
    const ScenePainter& moved = *cells_[std::size_t(k)]->painter;
    const ScenePainter::Orbit turned = turn_ = moved.orbitAngles();
    for (auto& cell : cells_)
        if (cell->painter.get() != &moved) {
            cell->painter->resetView();
            cell->painter->orbit(turned.yaw, turned.pitch, turned.zoom);
        }
    renderNow();
}

void StoryboardView::resetView()
{
    turn_ = {};
    for (auto& cell : cells_)
        cell->painter->resetView();
    renderNow();
}

void StoryboardView::orbit(double yaw, double pitch, double zoom)
{
    turn_ = {yaw, pitch, zoom};
    for (auto& cell : cells_) {
        cell->painter->resetView();
        cell->painter->orbit(yaw, pitch, zoom);
    }
    renderNow();
}

ScenePainter::Orbit StoryboardView::orbitAngles() const
{
    return cells_.empty() ? turn_ : cells_.front()->painter->orbitAngles();
}

void StoryboardView::setTicksAndNotesShown(bool ticks, bool)
{
    ticksShown_ = ticks;
    layOut();
}

void StoryboardView::setTraced(const std::optional<Vec3<double>>& point)
{
    traced_ = point;
    layOut(); // every cell's mark and the footers' coordinates anew
}

void StoryboardView::setCurrentStage(int stage)
{
    currentStage_ = stage;
    update();
}

void StoryboardView::setTheme(report::Theme theme)
{
    theme_ = theme;
    for (auto& cell : cells_)
        cell->painter->setTheme(theme);
    renderNow();
    update();
}

void StoryboardView::setTextScale(double scale)
{
    textScale_ = scale;
    layOut();
}

int StoryboardView::cellStage(int k) const
{
    return cells_.at(std::size_t(k))->stage;
}

QVTKOpenGLNativeWidget* StoryboardView::cellWidget(int k) const
{
    return cells_.at(std::size_t(k))->widget;
}

const ScenePainter& StoryboardView::cellPainter(int k) const
{
    return *cells_.at(std::size_t(k))->painter;
}

QImage StoryboardView::image()
{
    renderNow();
    return grab().toImage();
}

void StoryboardView::resizeEvent(QResizeEvent* event)
{
    QWidget::resizeEvent(event);
    layOut();
}

void StoryboardView::showEvent(QShowEvent* event)
{
    QWidget::showEvent(event);
    if (waiting_)
        setScene(std::move(waiting_));
    else
        layOut(); // what changed while hidden
}

void StoryboardView::paintEvent(QPaintEvent*)
{
    QPainter painter(this);
    painter.setRenderHint(QPainter::Antialiasing);
    const report::Rgb back = report::backgroundColor(theme_, false);
    painter.fillRect(rect(), QColor::fromRgbF(back.r, back.g, back.b));
    paintFigure(painter, overlay_, theme_);
    for (std::size_t k = 0; k < layout_.cells.size() && k < cells_.size(); ++k)
        if (cells_[k]->stage == currentStage_) { // the stage the stepper is at: outlined
            const report::Box2& box = layout_.cells[k].picture;
            const report::Rgb c = report::elementColor(Element::Objects, theme_);
            painter.setPen(QPen(QColor::fromRgbF(c.r, c.g, c.b), 2));
            painter.setBrush(Qt::NoBrush);
            painter.drawRect(QRectF(box.min.x() - 2, box.min.y() - 2, box.max.x() - box.min.x() + 4,
                                    box.max.y() - box.min.y() + 4));
        }
}

} // namespace viewpipe::gui
