#include "AccuracyPanel.h"

#include <QHeaderView>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

#include <QVTKOpenGLNativeWidget.h>
#include <mpfr.h>
#include <vtkChartMatrix.h>
#include <vtkContextScene.h>
#include <vtkContextView.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkRenderer.h>

#include "export/AccuracyPlot.h"
#include "painter/ScenePainter.h"
#include "viewpipe/format.hpp"
#include "viewpipe/report/bench.hpp"

namespace viewpipe::gui {

namespace {

QString intro()
{
    return AccuracyPanel::tr("Error against an MPFR-256 reference and time per build and per vertex, for float, "
                             "double, long double, double-double, float128 and MPFR.");
}

} // namespace

AccuracyPanel::AccuracyPanel(QWidget* parent) : QWidget(parent)
{
    auto* layout = new QVBoxLayout(this);
    button_ = new QPushButton(tr("Measure"));
    button_->setToolTip(tr("Measure every precision on this scene: error against MPFR-256 and time, in the background"));
    progress_ = new QProgressBar;
    progress_->setRange(0, 6);
    progress_->hide();
    status_ = new QLabel(intro());
    status_->setWordWrap(true);
    table_ = new QTableWidget(0, 10);
    table_->setHorizontalHeaderLabels({tr("precision"), tr("bits"), tr("build ns"), tr("ns/vertex"),
                                       tr("N entries"), tr("corners"), tr("|RRᵀ−I|"), tr("round trip"),
                                       tr("NDC max"), tr("pixels max")});
    table_->verticalHeader()->hide();
    table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    table_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    table_->setMinimumHeight(200);
    chartWidget_ = new QVTKOpenGLNativeWidget;
    chartWidget_->setMinimumHeight(520);
    auto window = vtkSmartPointer<vtkGenericOpenGLRenderWindow>::New();
    chartWidget_->setRenderWindow(window);
    view_ = vtkSmartPointer<vtkContextView>::New();
    view_->SetRenderWindow(window);
    charts_ = vtkSmartPointer<vtkChartMatrix>::New();
    view_->GetScene()->AddItem(charts_);
    paintBackground();
    layout->addWidget(button_);
    layout->addWidget(progress_);
    layout->addWidget(status_);
    layout->addWidget(table_);
    layout->addWidget(chartWidget_, 1);
    connect(button_, &QPushButton::clicked, this, [this] {
        if (sceneSource_)
            measure(*sceneSource_());
    });
}

AccuracyPanel::~AccuracyPanel()
{
    stop();
}

void AccuracyPanel::stop()
{
    if (cancel_)
        *cancel_ = true;
    if (worker_.joinable())
        worker_.join();
    running_ = false;
}

void AccuracyPanel::measure(const EvaluatedScene& evaluated, std::size_t vertices)
{
    stop();
    running_ = true;
    button_->setEnabled(false);
    progress_->setValue(0);
    progress_->show();
    status_->setText(tr("Measuring…"));
    cancel_ = std::make_shared<std::atomic<bool>>(false);
    const Scene scene = evaluated.scene;
    const std::vector<Vec3<double>> objectPoints = evaluated.objectVertices();
    // The worker owns copies of everything it reads; results come back queued.
    worker_ = std::thread([this, scene, objectPoints, vertices, cancel = cancel_] {
        BenchOptions options;
        options.vertices = vertices;
        auto result = std::make_shared<BenchResult>();
        try {
            *result = runBench(scene, objectPoints, options, [this, cancel](int done, int, const std::string& tier) {
                if (*cancel)
                    return false;
                QMetaObject::invokeMethod(this, [this, done, tier, cancel] {
                    if (*cancel)
                        return;
                    progress_->setValue(done);
                    status_->setText(tr("Measuring %1…").arg(QString::fromStdString(tier)));
                }, Qt::QueuedConnection);
                return true;
            });
        } catch (const std::exception& e) {
            mpfr_free_cache2(MPFR_FREE_LOCAL_CACHE);
            const QString message = QString::fromStdString(e.what());
            QMetaObject::invokeMethod(this, [this, message, cancel] {
                if (!*cancel)
                    finish(message);
            }, Qt::QueuedConnection);
            return;
        }
        mpfr_free_cache2(MPFR_FREE_LOCAL_CACHE); // this thread's constants (pi …) die with it
        if (*cancel)
            return;
        QMetaObject::invokeMethod(this, [this, result, cancel] {
            if (*cancel) // abandoned after the result was sent: it belongs to another scene
                return;
            finish(*result);
        }, Qt::QueuedConnection);
    });
}

void AccuracyPanel::finish(const std::variant<BenchResult, QString>& outcome)
{
    if (worker_.joinable())
        worker_.join();
    running_ = false;
    button_->setEnabled(true);
    progress_->hide();
    if (const auto* result = std::get_if<BenchResult>(&outcome))
        showResult(*result);
    else
        status_->setText(std::get<QString>(outcome));
    emit finished();
}

void AccuracyPanel::showResult(BenchResult result)
{
    last_ = std::make_unique<BenchResult>(std::move(result));
    drawResult();
}

// Redraws the kept result (also on a theme change, which must not replace it while reading it).
void AccuracyPanel::drawResult()
{
    const BenchResult& result = *last_;
    status_->setText(tr("Reference: %1. %2 vertices timed; absolute errors, with units of each type's epsilon "
                        "in brackets; pixels at %3×%4. Corners and round trip: %5.")
                         .arg(QString::fromStdString(result.reference))
                         .arg(result.vertices)
                         .arg(result.viewport.width)
                         .arg(result.viewport.height)
                         .arg(QString::fromStdString(result.volume)));
    table_->setRowCount(int(result.rows.size()));
    for (int i = 0; i < int(result.rows.size()); ++i) {
        const BenchRow& r = result.rows[std::size_t(i)];
        auto withEps = [&r](double x) { return report::errorCell(x, r.epsilon); };
        const std::vector<std::string> cells = {r.precision,
                                                r.bits ? std::to_string(r.bits) : "-",
                                                formatSignificant(r.buildNs, 3),
                                                formatSignificant(r.vertexNs, 3),
                                                withEps(r.errors.maxRelativeError),
                                                withEps(r.errors.cornerError),
                                                withEps(r.errors.orthogonalityError),
                                                withEps(r.errors.roundtripError),
                                                withEps(r.errors.ndcMaxError),
                                                formatSignificant(r.errors.pixelMaxError, 2)};
        for (std::size_t c = 0; c < cells.size(); ++c)
            table_->setItem(i, int(c), new QTableWidgetItem(QString::fromStdString(cells[c])));
    }
    charts_->ClearItems();
    drawAccuracyCharts(charts_, result, theme_, true);
    renderCharts();
}

void AccuracyPanel::paintBackground()
{
    const double bg = theme_ == report::Theme::Dark ? 0.11 : 1.0;
    view_->GetRenderer()->SetBackground(bg, bg, bg);
}

void AccuracyPanel::renderCharts()
{
    paintBackground();
    chartWidget_->renderWindow()->Render();
    chartWidget_->update();
}

void AccuracyPanel::setTheme(report::Theme theme)
{
    theme_ = theme;
    if (last_)
        drawResult();
    else
        renderCharts(); // the empty plot area in the theme's background, not a white box in the dark
}

void AccuracyPanel::clear()
{
    stop();
    last_.reset();
    button_->setEnabled(true);
    progress_->hide();
    status_->setText(intro());
    table_->setRowCount(0);
    charts_->ClearItems();
    renderCharts();
}

} // namespace viewpipe::gui
