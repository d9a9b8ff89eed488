#pragma once

// The Accuracy panel: the precision ladder of `viewpipe bench` for the scene
// on screen, computed on a worker thread (the window stays responsive), shown
// as a table and as error-against-time charts.

#include <QWidget>

#include <atomic>
#include <memory>
#include <thread>
#include <variant>

#include <vtkSmartPointer.h>

#include "viewpipe/precision_ladder.hpp"
#include "viewpipe/report/style.hpp"

class QLabel;
class QProgressBar;
class QPushButton;
class QTableWidget;
class QVTKOpenGLNativeWidget;
class vtkChartMatrix;
class vtkContextView;

namespace viewpipe::gui {

class AccuracyPanel : public QWidget {
    Q_OBJECT
public:
    explicit AccuracyPanel(QWidget* parent = nullptr);
    ~AccuracyPanel() override;

    // Measures a scene in the background; a running measurement is abandoned.
    void measure(const EvaluatedScene& scene, std::size_t vertices = 1000000);
    bool isRunning() const { return running_; }
    void setTheme(report::Theme theme);
    // Forgets the results and abandons a running measurement: they belong to the previous scene.
    void clear();
    bool hasResult() const { return last_ != nullptr; }
    QTableWidget* table() { return table_; }

signals:
    void finished();

private:
    void showResult(BenchResult result);
    // Ends a measurement: shows its result, or says why it failed (the previous results stay).
    void finish(const std::variant<BenchResult, QString>& outcome);
    void drawResult();
    // The chart area's background in the theme's color.
    void paintBackground();
    // The background, then the charts drawn.
    void renderCharts();
    void stop();

    QPushButton* button_;
    QProgressBar* progress_;
    QLabel* status_;
    QTableWidget* table_;
    QVTKOpenGLNativeWidget* chartWidget_;
    vtkSmartPointer<vtkContextView> view_;
    vtkSmartPointer<vtkChartMatrix> charts_;
    std::thread worker_;
    std::shared_ptr<std::atomic<bool>> cancel_;
    bool running_ = false;
    report::Theme theme_ = report::Theme::Dark;
    std::unique_ptr<BenchResult> last_;
    std::function<std::shared_ptr<const EvaluatedScene>()> sceneSource_;

public:
    // Where the Measure button takes the scene from.
    void setSceneSource(std::function<std::shared_ptr<const EvaluatedScene>()> source) { sceneSource_ = std::move(source); }
};

} // namespace viewpipe::gui
