#pragma once

// A layout of stage views in the middle of the window: the world and
// projected views (StagePair) or every stage at once (StoryboardView). The
// window tells every layout what to draw and how (the scene, the point traced,
// the look) and shows one; it never reaches for what a layout draws with.

#include <QImage>
#include <QWidget>

#include <memory>
#include <optional>

#include "painter/ScenePainter.h"

namespace viewpipe::gui {

class StageViews : public QWidget {
    Q_OBJECT
public:
    using QWidget::QWidget;

    // The scene every view draws (as the lesson step shown and View > Leave Out leave it).
    virtual void setScene(std::shared_ptr<const EvaluatedScene> scene) = 0;
    // The vertex every view marks and follows, or none.
    virtual void setTraced(const std::optional<Vec3<double>>& point) = 0;
    virtual void setTheme(report::Theme theme) = 0;
    // The text's size as the window's Larger and Smaller Text set it: 1 is 100 %.
    virtual void setTextScale(double scale) = 0;
    // View > Leave Out's ticks (the fixed axes' ticks and numbers) and notes (of labels left out for room).
    virtual void setTicksAndNotesShown(bool ticks, bool notes) = 0;
    // The views framed and turned as at first.
    virtual void resetView() = 0;
    // Framed as at first, then turned and zoomed as ScenePainter::orbit turns a view (a lesson step's turn).
    virtual void orbit(double yaw, double pitch, double zoom) = 0;
    virtual ScenePainter::Orbit orbitAngles() const = 0;
    // Draws what is on screen now.
    virtual void renderNow() = 0;
    // The picture on screen, as Copy Image copies it.
    virtual QImage image() = 0;

signals:
    // A vertex clicked (world coordinates), or none where a click found none.
    void vertexPicked(const std::optional<Vec3<double>>& point);
};

} // namespace viewpipe::gui
