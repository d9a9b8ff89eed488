#pragma once

// The Stages dock: the stages by name, a slider and Previous, Play and Next,
// all following the stepper; while a lesson's question waits, a note in the
// names' place (they would answer it).

#include <QWidget>

#include "viewpipe/pipeline.hpp"

class QLabel;
class QListWidget;
class QPushButton;
class QSlider;

namespace viewpipe::gui {

class Stepper;

class StagePanel : public QWidget {
    Q_OBJECT
public:
    explicit StagePanel(Stepper* stepper, QWidget* parent = nullptr);

    // The stages' names from the pipeline, the stepper's stage current.
    void setStages(const Pipeline<double>& pipeline);
    void setAnswersHidden(bool hidden);
    QListWidget* stageList() { return list_; }

private:
    void follow();

    Stepper* stepper_;
    QListWidget* list_;
    QLabel* wait_;
    QSlider* slider_;
    QPushButton* play_;
    QPushButton* next_;
};

} // namespace viewpipe::gui
