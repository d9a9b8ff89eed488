#pragma once

// The world view and the projected view side by side: the world view steps
// through the stages (the Stepper moves its painter), the projected view shows
// what the camera sees at every stage.

#include <memory>

#include "StageViews.h"
#include "painter/MeshDetail.h"

class QVTKOpenGLNativeWidget;
class vtkGenericOpenGLRenderWindow;

namespace viewpipe::gui {

class StagePair : public StageViews {
    Q_OBJECT
public:
    // The painter draws meshes from `meshes`, shared with the window's other views.
    explicit StagePair(std::shared_ptr<MeshDetails> meshes, QWidget* parent = nullptr);
    ~StagePair() override;

    void setScene(std::shared_ptr<const EvaluatedScene> scene) override;
    void setTraced(const std::optional<Vec3<double>>& point) override;
    void setTheme(report::Theme theme) override;
    void setTextScale(double scale) override;
    void setTicksAndNotesShown(bool ticks, bool notes) override;
    void resetView() override;
    void orbit(double yaw, double pitch, double zoom) override;
    ScenePainter::Orbit orbitAngles() const override;
    void renderNow() override;
    // The world view.
    QImage image() override;

    ScenePainter* painter() { return painter_.get(); }
    // Draws the world view alone: a frame of a step between stages.
    void renderWorldView();
    void setProjectedViewVisible(bool visible);

private:
    QVTKOpenGLNativeWidget* worldWidget_ = nullptr;
    QVTKOpenGLNativeWidget* projectedWidget_ = nullptr;
    vtkGenericOpenGLRenderWindow* worldWindow_ = nullptr;
    vtkGenericOpenGLRenderWindow* projectedWindow_ = nullptr;
    std::unique_ptr<ScenePainter> painter_;
    std::optional<Vec3<double>> traced_;
};

} // namespace viewpipe::gui
