#include "DepthPanel.h"

#include <QColor>
#include <QLabel>
#include <QVBoxLayout>

#include <QVTKOpenGLNativeWidget.h>
#include <vtkChartXY.h>
#include <vtkContextScene.h>
#include <vtkContextView.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkRenderer.h>

#include "export/DepthPlot.h"

namespace viewpipe::gui {

DepthPanel::DepthPanel(QWidget* parent) : QWidget(parent)
{
    auto* layout = new QVBoxLayout(this);
    summary_ = new QLabel;
    summary_->setObjectName("depthSummary");
    summary_->setWordWrap(true);
    summary_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    chartWidget_ = new QVTKOpenGLNativeWidget;
    chartWidget_->setMinimumHeight(360);
    auto window = vtkSmartPointer<vtkGenericOpenGLRenderWindow>::New();
    chartWidget_->setRenderWindow(window);
    view_ = vtkSmartPointer<vtkContextView>::New();
    view_->SetRenderWindow(window);
    chart_ = vtkSmartPointer<vtkChartXY>::New();
    view_->GetScene()->AddItem(chart_);
    layout->addWidget(summary_);
    layout->addWidget(chartWidget_, 1);
    showDepth({}, std::nullopt, report::Theme::Dark);
}

QString DepthPanel::summary() const
{
    return summary_->text();
}

void DepthPanel::showDepth(const Pipeline<double>& pipeline, const std::optional<DepthOutcome>& depth, report::Theme theme)
{
    const double bg = theme == report::Theme::Dark ? 0.11 : 1.0;
    view_->GetRenderer()->SetBackground(bg, bg, bg);
    chartWidget_->setVisible(depth.has_value());
    if (!depth) {
        summary_->setText(tr("This scene does not simulate a depth buffer. Turn it on with Effects ▸ Depth Buffer "
                             "to see its bands on the scene, its resolution against distance and the faces it "
                             "cannot order."));
        chart_->ClearPlots();
        return;
    }
    const DepthOptions& o = depth->options;
    QString text = tr("<b>%1</b> depth buffer. The scene's %2 vertices in the view volume get %3 distinct "
                      "stored values.")
                       .arg(QString::fromStdString(depthFormatName(depth->options)))
                       .arg(depth->vertices)
                       .arg(depth->distinctValues);
    if (!depth->zFightingChecked)
        text += tr(" Z-fighting is not checked: the scene has too many faces to compare pairwise.");
    else if (depth->zFighting.empty())
        text += tr(" No faces z-fight: the buffer orders every overlap.");
    else {
        const report::Rgb c = report::elementColor(Element::ZFighting, theme);
        const QString color = QColor::fromRgbF(c.r, c.g, c.b).name();
        text += QString(" <span style='color:%1'>%2</span>")
                    .arg(color, depth->zFighting.size() == 1 ? tr("1 pair of faces z-fights")
                                                             : tr("%1 pairs of faces z-fight").arg(depth->zFighting.size())) +
                tr(" (orange-red in the views, ringed in the projected view): the buffer stores the same value for "
                   "both where they overlap.");
    }
    summary_->setText(text);
    drawDepthChart(chart_, pipeline, o, theme);
    chartWidget_->renderWindow()->Render();
}

} // namespace viewpipe::gui
