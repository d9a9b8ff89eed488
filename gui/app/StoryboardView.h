#pragma once

// Every stage at once in the window: the storyboard as `export --layout
// storyboard` lays it out (layoutStoryboard), each cell a view of its own
// (a painter at its stage at rest, styled as the export styles a cell), the
// headers and footers (storyboardOverlay) painted around them. The cells
// draw the scene's meshes from one copy of their poly data; turning one turns
// them all; a click on a vertex traces it in every cell. Hidden, it draws
// nothing: what it is given waits until it is shown.

#include <memory>
#include <optional>
#include <vector>

#include "StageViews.h"
#include "painter/MeshDetail.h"
#include "viewpipe/report/storyboard.hpp"

class QVTKOpenGLNativeWidget;

namespace viewpipe::gui {

class StoryboardView : public StageViews {
    Q_OBJECT
public:
    // The cells draw meshes from `meshes`, shared with the window's other views.
    explicit StoryboardView(std::shared_ptr<MeshDetails> meshes, QWidget* parent = nullptr);
    ~StoryboardView() override;

    // Every stage of `scene`, each cell drawn anew.
    void setScene(std::shared_ptr<const EvaluatedScene> scene) override;
    // The point every cell traces: the user's, or the storyboard's own (storyboardTracedPoint).
    void setTraced(const std::optional<Vec3<double>>& point) override;
    // The stage the stepper shows, outlined.
    void setCurrentStage(int stage);
    void setTheme(report::Theme theme) override;
    void setTextScale(double scale) override;
    // A cell shows no notes: its header names the stage.
    void setTicksAndNotesShown(bool ticks, bool notes) override;
    // Every cell framed as at first, turned as at first.
    void resetView() override;
    // Every cell framed as at first, then turned and zoomed alike.
    void orbit(double yaw, double pitch, double zoom) override;
    // The cells' turn (each cell's is the same).
    ScenePainter::Orbit orbitAngles() const override;
    void renderNow() override;
    // The cells with their headers, footers and arrows.
    QImage image() override;

    int cellCount() const { return int(cells_.size()); }
    int cellStage(int k) const;
    QVTKOpenGLNativeWidget* cellWidget(int k) const;
    const ScenePainter& cellPainter(int k) const;
    const report::StoryboardLayout& layout() const { return layout_; }
    // The scene the cells draw (a lesson step's, without what it hides).
    const std::shared_ptr<const EvaluatedScene>& scene() const { return scene_; }
    // The point the cells trace.
    Vec3<double> traced() const;

protected:
    void paintEvent(QPaintEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;
    void showEvent(QShowEvent* event) override;

private:
    struct Cell;
    // The layout for the widget's size, the cells placed in it, the overlay made.
    void layOut();
    void buildCells();
    // Every other cell turned and zoomed as cell k is.
    void turnAllAs(int k);
    double labelSize() const;

    std::vector<std::unique_ptr<Cell>> cells_;
    std::shared_ptr<MeshDetails> meshes_;
    std::shared_ptr<const EvaluatedScene> scene_, cellScene_;
    std::shared_ptr<const EvaluatedScene> waiting_; // given while hidden
    report::StageFramings framings_;
    report::StoryboardLayout layout_;
    report::Figure overlay_;
    std::optional<Vec3<double>> traced_;
    report::Theme theme_ = report::Theme::Dark;
    double textScale_ = 1;
    bool ticksShown_ = true;
    int currentStage_ = -1;
    ScenePainter::Orbit turn_; // every cell's, from the first viewpoint
};

} // namespace viewpipe::gui
