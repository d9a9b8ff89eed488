#include "LessonPanel.h"

#include <QAction>
#include <QButtonGroup>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QMouseEvent>
#include <QListWidget>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QTimer>
#include <QShortcut>
#include <QRadioButton>
#include <QScrollArea>
#include <QTextDocumentFragment>
#include <QUndoStack>
#include <QVBoxLayout>

#include <algorithm>

#include "LessonDocument.h"
#include "MathText.h"
#include "MatrixPanel.h"
#include "viewpipe/math_text.hpp"
#include "viewpipe/pipeline.hpp"
#include "viewpipe/report/latex.hpp"
#include "viewpipe/report/lesson_latex.hpp"

namespace viewpipe::gui {
namespace {

QString symbolHtml(const std::string& symbol)
{
    return mathHtml("$" + symbolMath(symbol) + "$");
}

// A choice's text beside its radio button, wrapped and with its math set; a click on it picks the choice.
class ChoiceLabel : public QLabel {
public:
    ChoiceLabel(const QString& html, QRadioButton* radio) : radio_(radio)
    {
        setText(html);
        setWordWrap(true);
        setTextFormat(Qt::RichText);
        setCursor(Qt::PointingHandCursor);
    }

protected:
    void mouseReleaseEvent(QMouseEvent* event) override
    {
        QLabel::mouseReleaseEvent(event);
        if (radio_->isEnabled())
            radio_->click();
    }

private:
    QRadioButton* radio_;
};

// A list as tall as its rows at the text size of the moment (presenting enlarges it): nothing to scroll.
class FittedList : public QListWidget {
public:
    QSize sizeHint() const override
    {
        int height = 2 * frameWidth();
        for (int row = 0; row < count(); ++row)
            height += sizeHintForRow(row);
        return {QListWidget::sizeHint().width(), height};
    }
    QSize minimumSizeHint() const override { return {QListWidget::minimumSizeHint().width(), sizeHint().height()}; }

protected:
    void changeEvent(QEvent* event) override
    {
        QListWidget::changeEvent(event);
        if (event->type() == QEvent::FontChange)
            updateGeometry();
    }
};

QLabel* richLabel(const QString& name)
{
    auto* label = new QLabel;
    label->setObjectName(name);
    label->setWordWrap(true);
    label->setTextFormat(Qt::RichText);
    return label;
}

} // namespace

LessonPanel::LessonPanel(LessonDocument* lesson, QWidget* parent) : QWidget(parent), lesson_(lesson)
{
    auto* layout = new QVBoxLayout(this);
    title_ = richLabel("lessonTitle");
    layout->addWidget(title_);
    auto* stepRow = new QHBoxLayout;
    stepLabel_ = new QLabel;
    stepLabel_->setObjectName("lessonStep");
    auto* previous = new QPushButton(tr("◀ Step"));
    auto* next = new QPushButton(tr("Step ▶"));
    previous->setObjectName("lessonPrevious");
    next->setObjectName("lessonNext");
    previous->setToolTip(tr("The previous step (Page Up)"));
    next->setToolTip(tr("The next step, or the answer of a question not answered yet (Page Down)"));
    stepRow->addWidget(stepLabel_, 1);
    stepRow->addWidget(previous);
    stepRow->addWidget(next);
    layout->addLayout(stepRow);
    caption_ = richLabel("lessonCaption");
    layout->addWidget(caption_);

    buildQuestion();
    layout->addWidget(question_);

    saveResults_ = new QPushButton(tr("Save My Answers…"));
    saveResults_->setObjectName("saveResultsButton");
    saveResults_->setToolTip(tr("Your answers and whether each was right, as a JSON file (the web page saves the same)"));
    layout->addWidget(saveResults_, 0, Qt::AlignLeft);

    buildEditor();
    layout->addWidget(editor_);
    layout->addStretch();

    connect(previous, &QPushButton::clicked, this, [this] {
        if (applyPendingEdits())
            lesson_->goTo(lesson_->step() - 1);
    });
    connect(next, &QPushButton::clicked, this, [this] {
        if (applyPendingEdits())
            lesson_->goTo(lesson_->step() + 1);
    });
    connect(saveResults_, &QPushButton::clicked, this, &LessonPanel::saveResultsRequested);

    connect(lesson_, &LessonDocument::lessonChanged, this, &LessonPanel::refreshLesson);
    connect(lesson_, &LessonDocument::stepChanged, this, &LessonPanel::refreshStep);
    refreshLesson();
    refreshStep();
}

void LessonPanel::buildQuestion()
{
    question_ = new QGroupBox(tr("Question"));
    question_->setObjectName("lessonQuestion");
    auto* q = new QVBoxLayout(question_);
    prompt_ = richLabel("questionPrompt");
    about_ = richLabel("questionAbout");
    q->addWidget(prompt_);
    q->addWidget(about_);
    inputs_ = new QWidget;
    q->addWidget(inputs_);
    auto* buttons = new QHBoxLayout;
    check_ = new QPushButton(tr("Check"));
    check_->setObjectName("checkButton");
    check_->setToolTip(tr("Check your answer (Enter), then see the stage it is about"));
    reveal_ = new QPushButton(tr("Show Answer"));
    reveal_->setObjectName("revealButton");
    reveal_->setToolTip(tr("Show the answer without answering: for a class that predicted aloud"));
    buttons->addWidget(check_);
    buttons->addWidget(reveal_);
    buttons->addStretch();
    q->addLayout(buttons);
    feedback_ = richLabel("feedback");
    q->addWidget(feedback_);
    // Enter checks, whatever in the question has the focus (a choice, the order, a number).
    for (const auto key : {Qt::Key_Return, Qt::Key_Enter}) {
        auto* enter = new QShortcut(QKeySequence(key), question_);
        enter->setContext(Qt::WidgetWithChildrenShortcut);
        connect(enter, &QShortcut::activated, this, &LessonPanel::checkAnswer);
    }
    connect(check_, &QPushButton::clicked, this, &LessonPanel::checkAnswer);
    connect(reveal_, &QPushButton::clicked, lesson_, &LessonDocument::reveal);
}

void LessonPanel::buildEditor()
{
    // Authoring, folded away until asked for.
    editor_ = new QGroupBox(tr("Edit the lesson"));
    editor_->setObjectName("lessonEditor");
    editor_->setCheckable(true);
    editor_->setChecked(false);
    auto* e = new QVBoxLayout(editor_);
    auto* editorContent = new QWidget;
    auto* c = new QVBoxLayout(editorContent);
    c->setContentsMargins(0, 0, 0, 0);
    c->addWidget(new QLabel(tr("Title")));
    titleEdit_ = new QLineEdit;
    titleEdit_->setObjectName("titleEdit");
    c->addWidget(titleEdit_);
    steps_ = new QListWidget;
    steps_->setObjectName("lessonSteps");
    steps_->setToolTip(tr("The steps: pick one to show it"));
    steps_->setMaximumHeight(160);
    steps_->setWordWrap(true); // the numbers stay in view
    steps_->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    c->addWidget(steps_);
    auto* stepButtons = new QHBoxLayout;
    auto* add = new QPushButton(tr("Add Step From View"));
    add->setObjectName("addStepButton");
    add->setToolTip(tr("A new step after this one: the scene, stage and world view as they are now"));
    auto* up = new QPushButton(tr("Up"));
    auto* down = new QPushButton(tr("Down"));
    auto* remove = new QPushButton(tr("Remove"));
    up->setObjectName("moveUpButton");
    down->setObjectName("moveDownButton");
    remove->setObjectName("removeStepButton");
    // Two rows: the panel stays as narrow as its dock at any text size.
    c->addWidget(add);
    stepButtons->addWidget(up);
    stepButtons->addWidget(down);
    stepButtons->addWidget(remove);
    stepButtons->addStretch();
    c->addLayout(stepButtons);
    auto wrapped = [](const QString& text) {
        auto* label = new QLabel(text);
        label->setWordWrap(true);
        return label;
    };
    c->addWidget(wrapped(tr("Caption (math between $ signs)")));
    captionEdit_ = new QPlainTextEdit;
    captionEdit_->setObjectName("captionEdit");
    captionEdit_->setMaximumHeight(110);
    c->addWidget(captionEdit_);
    c->addWidget(wrapped(tr("Question, as the lesson file holds it (JSON; empty for none)")));
    questionEdit_ = new QPlainTextEdit;
    questionEdit_->setObjectName("questionEdit");
    questionEdit_->setMaximumHeight(160);
    c->addWidget(questionEdit_);
    auto* applyRow = new QHBoxLayout;
    auto* apply = new QPushButton(tr("Apply"));
    apply->setObjectName("applyEditsButton");
    apply->setToolTip(tr("Check the title, caption and question and make them the step's (undoable)"));
    QAction* undo = lesson_->undoStack()->createUndoAction(this, tr("Undo"));
    QAction* redo = lesson_->undoStack()->createRedoAction(this, tr("Redo"));
    auto* undoButton = new QPushButton(tr("Undo"));
    auto* redoButton = new QPushButton(tr("Redo"));
    undoButton->setObjectName("lessonUndo");
    redoButton->setObjectName("lessonRedo");
    connect(undoButton, &QPushButton::clicked, undo, &QAction::trigger);
    connect(redoButton, &QPushButton::clicked, redo, &QAction::trigger);
    connect(lesson_->undoStack(), &QUndoStack::canUndoChanged, undoButton, &QPushButton::setEnabled);
    connect(lesson_->undoStack(), &QUndoStack::canRedoChanged, redoButton, &QPushButton::setEnabled);
    undoButton->setEnabled(false);
    redoButton->setEnabled(false);
    applyRow->addWidget(apply);
    applyRow->addWidget(undoButton);
    applyRow->addWidget(redoButton);
    applyRow->addStretch();
    c->addLayout(applyRow);
    editError_ = richLabel("editError");
    editError_->setStyleSheet("color: #c0392b");
    c->addWidget(editError_);
    e->addWidget(editorContent);
    editorContent->setVisible(false);
    connect(editor_, &QGroupBox::toggled, editorContent, &QWidget::setVisible);
    connect(editor_, &QGroupBox::toggled, this, [this](bool open) {
        if (open && lesson_->isAsking())
            lesson_->reveal(true); // the question's file form and the captions give the answer
        // Leaving the editor applies what was typed; a refused edit opens it again, with the reason. Put out
        // of reach (presenting), it keeps what was typed for later.
        if (!open && editor_->isVisibleTo(this))
            applyPendingEdits();
    });

    connect(titleEdit_, &QLineEdit::returnPressed, this, &LessonPanel::applyPendingEdits);
    connect(steps_, &QListWidget::currentRowChanged, this, [this](int row) {
        if (row < 0 || row == lesson_->step())
            return;
        if (applyPendingEdits()) {
            lesson_->goTo(row);
        } else {
            const QSignalBlocker quiet(steps_);
            steps_->setCurrentRow(lesson_->step()); // the step with the refused edit stays
        }
    });
    auto guarded = [this](const std::function<void()>& edit) {
        try {
            edit();
            editError_->clear();
        } catch (const InputError& error) {
            editError_->setText(QString::fromStdString(error.what()).toHtmlEscaped());
        }
    };
    connect(add, &QPushButton::clicked, this, &LessonPanel::addStepRequested);
    connect(up, &QPushButton::clicked, this, [this, guarded] { guarded([this] { lesson_->moveStep(lesson_->step(), lesson_->step() - 1); }); });
    connect(down, &QPushButton::clicked, this, [this, guarded] { guarded([this] { lesson_->moveStep(lesson_->step(), lesson_->step() + 1); }); });
    connect(remove, &QPushButton::clicked, this, [this, guarded] { guarded([this] { lesson_->removeStep(lesson_->step()); }); });
    connect(apply, &QPushButton::clicked, this, [this, guarded] { guarded([this] { applyEdits(); }); });
}

void LessonPanel::refreshLesson()
{
    const Lesson& lesson = lesson_->lesson();
    title_->setText("<b>" + QString::fromStdString(lesson.title).toHtmlEscaped() + "</b>");
    const QSignalBlocker quiet(steps_);
    steps_->clear();
    for (std::size_t k = 0; k < lesson.steps.size(); ++k) {
        const LessonStep& step = lesson.steps[k];
        QString text = QString::fromStdString(step.caption).simplified();
        if (text.size() > 60)
            text = text.left(57) + "…";
        steps_->addItem(QString("%1. %2%3").arg(k + 1).arg(step.question ? tr("[?] ") : "", text));
    }
    refreshStep();
}

void LessonPanel::refreshStep()
{
    const bool open = lesson_->isOpen();
    setEnabled(open);
    if (!open) {
        stepLabel_->setText(tr("No lesson open: Lesson ▸ Open Lesson…"));
        caption_->clear();
        question_->hide();
        return;
    }
    const int k = lesson_->step();
    const LessonStep& step = lesson_->currentStep();
    const int n = int(lesson_->lesson().steps.size());
    stepLabel_->setText(tr("Step %1 of %2").arg(k + 1).arg(n));
    {
        const QSignalBlocker quiet(steps_);
        steps_->setCurrentRow(k);
    }
    if (editorsFor_ != k || editorsGeneration_ != lesson_->generation()) { // what was typed and not applied stays
        editorsFor_ = k;
        editorsGeneration_ = lesson_->generation();
        titleEdit_->setText(QString::fromStdString(lesson_->lesson().title));
        captionEdit_->setPlainText(QString::fromStdString(step.caption));
        questionEdit_->setPlainText(step.question ? QString::fromStdString(questionToJson(*step.question)) : QString());
    }
    if (editor_->isChecked() && lesson_->isAsking()) { // the editor shows the answers: so does the step
        QTimer::singleShot(0, lesson_, [lesson = lesson_] { lesson->reveal(true); });
    }
    const bool asking = lesson_->isAsking();
    // The caption may give the answer away: it waits for it.
    caption_->setText(asking ? "<i>" + tr("The step's text follows the answer.") + "</i>" : mathHtml(step.caption));
    question_->setVisible(step.question.has_value());
    saveResults_->setVisible(std::any_of(lesson_->lesson().steps.begin(), lesson_->lesson().steps.end(),
                                         [](const LessonStep& s) { return s.question.has_value(); }));
    if (!step.question)
        return;
    const Question& q = *step.question;
    prompt_->setText(mathHtml(q.prompt));
    QString about = mathHtml(report::questionContext(step));
    if (q.kind == QuestionKind::WhichStage)
        about = matrixTable(tr("The matrix"),
                            buildPipeline(step.scene.camera, step.scene.effects).stages.at(std::size_t(q.stage - 1)).matrix);
    about_->setText(about);
    about_->setVisible(!about.isEmpty());
    if (inputsFor_ != k || inputsGeneration_ != lesson_->generation())
        buildInputs();
    inputs_->setEnabled(asking);
    check_->setEnabled(asking);
    reveal_->setEnabled(asking);
    if (asking) {
        // A wrong answer with tries left: try again, the answer not shown.
        const int left = q.tries - lesson_->tries(k);
        const QString again = left == 1 ? tr("Try again: one more try before the answer is shown.")
                                        : tr("Try again: %1 more tries before the answer is shown.").arg(left);
        feedback_->setText(lesson_->tries(k) == 0 ? QString() : "<b>" + tr("Not quite.") + "</b> " + again);
        askingShown_ = k;
        return;
    }
    const std::optional<Answer>& answer = lesson_->answer(k);
    const QString answerHtml = mathHtml(report::answerText(step));
    QString said = !answer                 ? tr("The answer: %1.").arg(answerHtml)
                   : isRight(q, *answer) ? tr("<b>Right.</b> The answer: %1.").arg(answerHtml)
                                         : tr("<b>Not quite:</b> the answer is %1.").arg(answerHtml);
    if (!q.explanation.empty())
        said += "<br>" + mathHtml(q.explanation);
    feedback_->setText(said);
    if (askingShown_ == k) // just answered: the answer into view, below the fold of a small screen, once laid out
        QTimer::singleShot(100, this, [this] {
            for (QWidget* up = parentWidget(); up; up = up->parentWidget())
                if (auto* scroll = qobject_cast<QScrollArea*>(up))
                    return scroll->ensureWidgetVisible(feedback_);
        });
    askingShown_ = -1;
}

void LessonPanel::buildInputs()
{
    const int k = lesson_->step();
    const Question& q = *lesson_->currentStep().question;
    inputsFor_ = k;
    inputsGeneration_ = lesson_->generation();
    auto* fresh = new QWidget;
    auto* layout = new QVBoxLayout(fresh);
    layout->setContentsMargins(0, 0, 0, 0);
    auto line = [&](const QString& name, const QString& placeholder) {
        auto* edit = new QLineEdit;
        edit->setObjectName(name);
        edit->setPlaceholderText(placeholder);
        connect(edit, &QLineEdit::returnPressed, this, &LessonPanel::checkAnswer);
        return edit;
    };
    // A radio button sets no rich text and does not wrap: its text is a label beside it.
    // `spoken`: each as a screen reader says it (math in words); else the text's own.
    auto radios = [&](const QStringList& texts, const QStringList& spoken = {}) {
        auto* group = new QButtonGroup(fresh);
        for (int i = 0; i < texts.size(); ++i) {
            auto* radio = new QRadioButton;
            radio->setObjectName(QString("choice%1").arg(i));
            radio->setAccessibleName(spoken.isEmpty() ? QTextDocumentFragment::fromHtml(texts[i]).toPlainText() : spoken[i]);
            auto* label = new ChoiceLabel(texts[i], radio);
            label->setObjectName(QString("choiceText%1").arg(i));
            auto* row = new QHBoxLayout;
            row->addWidget(radio, 0, Qt::AlignTop);
            row->addWidget(label, 1);
            layout->addLayout(row);
            group->addButton(radio, i);
        }
    };
    switch (q.kind) {
    case QuestionKind::Where: {
        auto* row = new QHBoxLayout;
        row->addWidget(line("answerX", "x"));
        row->addWidget(line("answerY", "y"));
        row->addWidget(line("answerZ", "z"));
        layout->addLayout(row);
        auto* tolerance = new QLabel(tr("Right within %1 % of the answer's length, or within %2 where it is shorter than 1.")
                                         .arg(q.tolerance * 100)
                                         .arg(q.tolerance));
        tolerance->setWordWrap(true);
        layout->addWidget(tolerance);
        break;
    }
    case QuestionKind::Inside: radios({tr("inside the view volume"), tr("clipped away")}); break;
    case QuestionKind::SignW: radios({tr("w is positive"), tr("w is zero"), tr("w is negative")}); break;
    case QuestionKind::WhichStage: {
        QStringList texts, spoken;
        for (int c : offeredChoices(q)) {
            texts << symbolHtml(q.choices[std::size_t(c)]);
            spoken << QString::fromStdString(mathSpokenText("$" + symbolMath(q.choices[std::size_t(c)]) + "$"));
        }
        radios(texts, spoken);
        break;
    }
    case QuestionKind::Choice: {
        QStringList texts, spoken;
        for (std::size_t k = 0; k < q.choices.size(); ++k) {
            texts << mathHtml(report::choiceLetter(k) + " " + q.choices[k]);
            spoken << QString::fromStdString(mathSpokenText(report::choiceLetter(k) + " " + q.choices[k]));
        }
        radios(texts, spoken);
        break;
    }
    case QuestionKind::Entry:
        layout->addWidget(line("answerEntry", tr("a decimal, a fraction p/q or a root (sqrt, √)"))); // no number: one could be the answer
        break;
    case QuestionKind::Order: {
        auto* list = new FittedList;
        list->setObjectName("orderList");
        list->setItemDelegate(new MathItemDelegate(list));
        list->setDragDropMode(QAbstractItemView::InternalMove);
        list->setToolTip(tr("Drag the stages into the order they apply to a point, first at the top"));
        for (int c : offeredChoices(q)) {
            const std::string& symbol = q.choices[std::size_t(c)];
            auto* item = new QListWidgetItem(QString::fromStdString(symbol));
            item->setData(Qt::UserRole, c);
            item->setData(MathItemDelegate::kMathRole, QString::fromStdString("$" + symbolMath(symbol) + "$"));
            list->addItem(item);
        }
        list->setVerticalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
        layout->addWidget(list);
        auto* row = new QHBoxLayout;
        for (const auto& [text, name, by] : {std::tuple{tr("Earlier"), "orderUp", -1}, std::tuple{tr("Later"), "orderDown", 1}}) {
            auto* button = new QPushButton(text);
            button->setObjectName(name);
            connect(button, &QPushButton::clicked, list, [list, by = by] {
                const int row = list->currentRow(), to = row + by;
                if (row < 0 || to < 0 || to >= list->count())
                    return;
                list->insertItem(to, list->takeItem(row));
                list->setCurrentRow(to);
            });
            row->addWidget(button);
        }
        row->addStretch();
        layout->addLayout(row);
        break;
    }
    }
    delete inputs_->parentWidget()->layout()->replaceWidget(inputs_, fresh); // the old widget's item is ours
    delete inputs_;
    inputs_ = fresh;
}

bool LessonPanel::checkAnswer()
{
    if (!lesson_->isAsking())
        return false;
    const Question& q = *lesson_->currentStep().question;
    Answer answer;
    // A field's number, its text kept beside it for the results. A text that is no number is refused with
    // the core's reason ("z: is empty: ...", "entry: unexpected ..."), and no try is counted.
    std::optional<QString> refused;
    auto typed = [this, &answer, &refused](const char* name, const char* field) {
        answer.typed.push_back(inputs_->findChild<QLineEdit*>(name)->text().toStdString());
        try {
            return typedNumber(answer.typed.back(), field);
        } catch (const InputError& e) {
            if (!refused)
                refused = QString::fromStdString(e.what()) + ".";
            return 0.0;
        }
    };
    auto chosen = [this]() {
        for (QRadioButton* radio : inputs_->findChildren<QRadioButton*>())
            if (radio->isChecked())
                return radio->objectName().mid(6).toInt();
        return -1;
    };
    switch (q.kind) {
    case QuestionKind::Where: {
        const double x = typed("answerX", "x"), y = typed("answerY", "y"), z = typed("answerZ", "z");
        answer.where = {x, y, z};
        break;
    }
    case QuestionKind::Entry: answer.entry = typed("answerEntry", "entry"); break;
    case QuestionKind::Order:
        for (int row = 0; row < inputs_->findChild<QListWidget*>("orderList")->count(); ++row)
            answer.order.push_back(inputs_->findChild<QListWidget*>("orderList")->item(row)->data(Qt::UserRole).toInt());
        break;
    default: {
        const int picked = chosen();
        if (picked < 0) {
            feedback_->setText(tr("Pick one answer."));
            return false;
        }
        answer.inside = picked == 0;
        answer.signW = picked == 0 ? 1 : picked == 1 ? 0 : -1;
        answer.choice = q.kind == QuestionKind::WhichStage ? offeredChoices(q)[std::size_t(picked)] : picked;
        break;
    }
    }
    if (refused) {
        feedback_->setText(refused->toHtmlEscaped());
        return false;
    }
    lesson_->check(answer);
    return true;
}

void LessonPanel::openEditor()
{
    editor_->setChecked(true);
}

void LessonPanel::setEditorAvailable(bool available)
{
    editor_->setVisible(available);
    if (!available)
        editor_->setChecked(false);
}

bool LessonPanel::applyPendingEdits()
{
    if (!lesson_->isOpen())
        return true;
    try {
        applyEdits(); // nothing changed: no edit
        editError_->clear();
        return true;
    } catch (const InputError& e) {
        openEditor();
        editError_->setText(QString::fromStdString(e.what()).toHtmlEscaped());
        emit message(tr("The step's edits are not applied: %1").arg(QString::fromStdString(e.what())));
        return false;
    }
}

void LessonPanel::discardPendingEdits()
{
    editorsFor_ = -1;
    editError_->clear();
    refreshStep();
}

void LessonPanel::applyEdits()
{
    lesson_->setTexts(lesson_->step(), titleEdit_->text().toStdString(), captionEdit_->toPlainText().toStdString(),
                      questionEdit_->toPlainText().toStdString());
}

} // namespace viewpipe::gui
