#pragma once

// The Depth panel: for a scene with the "depth" effect, what its buffer
// resolves: the depth step against distance (the scene's format and the usual
// others), the distinct stored values among the vertices, and the faces that
// z-fight. Without the effect it says how to turn it on.

#include <QWidget>

#include <optional>

#include <vtkSmartPointer.h>

#include "viewpipe/report/style.hpp"

class QLabel;
class QVTKOpenGLNativeWidget;
class vtkChartXY;
class vtkContextView;

namespace viewpipe::gui {

class DepthPanel : public QWidget {
    Q_OBJECT
public:
    explicit DepthPanel(QWidget* parent = nullptr);

    void showDepth(const Pipeline<double>& pipeline, const std::optional<DepthOutcome>& depth, report::Theme theme);
    QString summary() const;

private:
    QLabel* summary_;
    QVTKOpenGLNativeWidget* chartWidget_;
    vtkSmartPointer<vtkContextView> view_;
    vtkSmartPointer<vtkChartXY> chart_;
};

} // namespace viewpipe::gui
