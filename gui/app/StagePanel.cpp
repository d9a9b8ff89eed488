#include "StagePanel.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSlider>
#include <QVBoxLayout>

#include "MathText.h"
#include "Stepper.h"
#include "viewpipe/math_text.hpp"
#include "viewpipe/stage.hpp"

namespace viewpipe::gui {

StagePanel::StagePanel(Stepper* stepper, QWidget* parent)
    : QWidget(parent), stepper_(stepper), list_(new QListWidget), wait_(new QLabel), slider_(new QSlider(Qt::Horizontal)),
      play_(new QPushButton(tr("Play")))
{
    auto* v = new QVBoxLayout(this);
    list_->setObjectName("stageList");
    list_->setWordWrap(true);
    list_->setItemDelegate(new MathItemDelegate(list_));
    list_->setToolTip(tr("The stages of the normalizing transformation: pick one to see the scene after its matrix"));
    v->addWidget(list_);
    wait_->setText(tr("<i>The stages' names follow the answer to the lesson's question.</i>"));
    wait_->setObjectName("stagesWait");
    wait_->setWordWrap(true);
    wait_->hide();
    v->addWidget(wait_);
    slider_->setObjectName("stageSlider");
    slider_->setPageStep(1);
    slider_->setToolTip(tr("Stage: 0 is the world, k is after the k-th matrix"));
    v->addWidget(slider_);
    auto* buttons = new QHBoxLayout;
    // Short labels: the row fits the dock at any text size.
    auto* previous = new QPushButton(tr("◀"));
    next_ = new QPushButton(tr("▶"));
    auto* next = next_;
    previous->setObjectName("previousButton");
    play_->setObjectName("playButton");
    next->setObjectName("nextButton");
    play_->setToolTip(tr("Play every stage from here, one transition a second; Stop holds the stage reached"));
    previous->setToolTip(tr("Previous stage (Left arrow)"));
    next->setToolTip(tr("Next stage (Right arrow)"));
    buttons->addWidget(previous);
    buttons->addWidget(play_);
    buttons->addWidget(next);
    v->addLayout(buttons);

    connect(list_, &QListWidget::currentRowChanged, this, [this](int row) {
        if (row >= 0 && row != stepper_->target())
            stepper_->goToStage(row);
    });
    connect(slider_, &QSlider::valueChanged, this, [this](int value) {
        if (value != stepper_->target())
            stepper_->goToStage(value);
    });
    connect(slider_, &QSlider::sliderReleased, this, &StagePanel::follow); // dragged past where the stepper may go
    connect(previous, &QPushButton::clicked, this, [this] { stepper_->stepBy(-1); });
    connect(next, &QPushButton::clicked, this, [this] { stepper_->stepBy(1); });
    connect(play_, &QPushButton::clicked, this, [this] {
        if (stepper_->isAnimating())
            stepper_->stop();
        else
            stepper_->play();
    });
    connect(stepper_, &Stepper::moved, this, &StagePanel::follow);
}

void StagePanel::setStages(const Pipeline<double>& pipeline)
{
    const QSignalBlocker blockList(list_);
    const QSignalBlocker blockSlider(slider_);
    list_->clear();
    for (std::size_t k = 0; k <= pipeline.stages.size(); ++k) {
        const std::string entry = stageText(pipeline.stages, k, StageText::ListEntry);
        auto* item = new QListWidgetItem(QString::fromStdString(mathPlainText(entry)));
        item->setData(MathItemDelegate::kMathRole, QString::fromStdString(entry));
        item->setData(Qt::AccessibleTextRole, QString::fromStdString(mathSpokenText(entry))); // "S sub per", not "S_per"
        list_->addItem(item);
    }
    slider_->setRange(0, int(pipeline.stages.size()));
    follow();
}

void StagePanel::setAnswersHidden(bool hidden)
{
    list_->setVisible(!hidden);
    wait_->setVisible(hidden);
}

void StagePanel::follow()
{
    const QSignalBlocker blockList(list_);
    const QSignalBlocker blockSlider(slider_);
    // Play's last stage waits until the picture gets there.
    list_->setCurrentRow(stepper_->shownStage());
    if (!slider_->isSliderDown())
        slider_->setValue(stepper_->shownStage());
    play_->setText(stepper_->isPlaying() ? tr("Stop") : tr("Play"));
    // A lesson's open question holds the stepper before the stage it asks about.
    next_->setEnabled(stepper_->target() < stepper_->lastStage());
    play_->setEnabled(stepper_->isPlaying() || stepper_->lastStage() > 0);
}

} // namespace viewpipe::gui
