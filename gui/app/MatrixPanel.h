#pragma once

// The current stage's matrix, symbolic and in numbers, and the cumulative
// matrix with the entries this stage changed highlighted; below, the point
// tracer: a picked vertex's homogeneous coordinates after every stage.

#include <QWidget>

#include <array>
#include <optional>
#include <vector>

#include "viewpipe/pipeline.hpp"

class QLabel;

namespace viewpipe::gui {

// A matrix in numbers as an HTML table under its caption, as the panel shows one.
QString matrixTable(const QString& caption, const Mat4<double>& m);

class MatrixPanel : public QWidget {
    Q_OBJECT
public:
    explicit MatrixPanel(QWidget* parent = nullptr);

    // stage 0 is the world (no matrix yet); stage k shows pipeline.stages[k-1],
    // the `highlighted` entries of its matrix (row, column from 1) marked. An
    // entry is written exactly (-13/36, sqrt2/2) where `exact`, the same
    // pipeline computed exactly, has it in a form that reads so.
    void showStage(const Pipeline<double>& pipeline, const Pipeline<Exact>* exact, int stage,
                   const std::vector<std::array<int, 2>>& highlighted = {});
    // The rows up to `lastRow` (a lesson's rule, stepShows), the verdict on the
    // canonical volume (decided exactly where `exact` is given) with the last stage.
    void showTrace(const Pipeline<double>& pipeline, const Pipeline<Exact>* exact, const std::optional<Vec3<double>>& point,
                   int stage, int lastRow);
    // No matrix, and why (a lesson's question waits for its answer).
    void showWaiting(const QString& why);

    QString stageText() const;
    QString traceText() const;
    QString matricesText() const; // the tables, as HTML

private:
    QLabel* title_;
    QLabel* matrices_;
    QLabel* trace_;
};

} // namespace viewpipe::gui
