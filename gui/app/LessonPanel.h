#pragma once

// The Lesson panel: the step's caption and question. A question is answered
// here (typed coordinates or an entry, a choice clicked, stages put in
// order), checked, then revealed: the view plays the transition to the stage
// asked about and the explanation appears. Below, the lesson is edited: add
// the current view as a step, reorder, caption, question, title. Intent goes
// to the LessonDocument; the main window shows the step's scene and stage.

#include <QWidget>

class QGroupBox;
class QLabel;
class QLineEdit;
class QListWidget;
class QPlainTextEdit;
class QPushButton;

namespace viewpipe::gui {

class LessonDocument;

class LessonPanel : public QWidget {
    Q_OBJECT
public:
    explicit LessonPanel(LessonDocument* lesson, QWidget* parent = nullptr);

    // Checks what the inputs hold, as the Check button does; false when they hold no whole answer.
    bool checkAnswer();
    // The editing below the lesson: opened (as for a new lesson), or out of
    // reach (while presenting). Opening it shows the answers: a question's
    // file form holds its answer.
    void openEditor();
    void setEditorAvailable(bool available);
    // Makes the title, caption and question typed in the editor the lesson's
    // (before the step changes, a save or a close); false, with the reason
    // shown, when the core refuses them.
    bool applyPendingEdits();
    // The editor shows the lesson's texts again, what was typed dropped.
    void discardPendingEdits();

signals:
    void addStepRequested();
    void saveResultsRequested();
    void message(const QString& text);

private:
    void refreshLesson();
    void refreshStep();
    void buildQuestion();
    void buildEditor();
    void buildInputs();
    void applyEdits();

    LessonDocument* lesson_;
    QLabel* title_;
    QLabel* stepLabel_;
    QLabel* caption_;
    QGroupBox* question_;
    QLabel* prompt_;
    QLabel* about_;
    QWidget* inputs_ = nullptr;
    QPushButton* check_;
    QPushButton* reveal_;
    QLabel* feedback_;
    QPushButton* saveResults_;
    QGroupBox* editor_;
    QLineEdit* titleEdit_;
    QListWidget* steps_;
    QPlainTextEdit* captionEdit_;
    QPlainTextEdit* questionEdit_;
    QLabel* editError_;
    // The step, and the lesson's generation, the inputs and editors were filled for: a
    // refresh for an answer or a save keeps what was typed.
    int inputsFor_ = -1, inputsGeneration_ = -1;
    int editorsFor_ = -1, editorsGeneration_ = -1;
    int askingShown_ = -1; // the step whose question was last shown waiting
};

} // namespace viewpipe::gui
