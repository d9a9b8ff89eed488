#pragma once

// The lesson open in the app: its steps, the step shown, the student's
// answers (the first answer to each question, kept for the results file) and
// which answers are revealed; an edit asks every question afresh. Edits (add a step, reorder, caption, question,
// title) are checked by the core and are undoable; the lesson is saved
// atomically, and only as a file that reads back.

#include <QObject>
#include <QString>
#include <QUndoStack>

#include <functional>
#include <optional>
#include <vector>

#include "viewpipe/evaluated_scene.hpp"
#include "viewpipe/lesson.hpp"

namespace viewpipe::gui {

class LessonDocument : public QObject {
    Q_OBJECT
public:
    explicit LessonDocument(QObject* parent = nullptr);
    ~LessonDocument() override;

    bool isOpen() const { return !lesson_.steps.empty(); }
    const Lesson& lesson() const { return lesson_; }
    QString filePath() const { return filePath_; }
    bool isModified() const { return !undo_.isClean(); }
    QUndoStack* undoStack() { return &undo_; }

    // A lesson's steps evaluated (evaluateLesson), their meshes read through this
    // document's cache: may run off the GUI thread while nothing else edits the
    // lesson. Throws InputError naming the step whose scene the core refuses.
    EvaluatedLesson evaluate(const Lesson& lesson);
    // A lesson read from `path` (loadLesson), its steps evaluated, replaces the one open.
    void open(Lesson lesson, EvaluatedLesson evaluated, const QString& path);
    // Runs what making a lesson or an edit evaluates (a new step's meshes read): the app runs it
    // off the GUI thread (waitShowingProgress), saying `what` is under way; by default it runs here.
    using WorkRunner = std::function<void(const QString& what, const std::function<void()>& work)>;
    void setWorkRunner(WorkRunner runner) { runWork_ = std::move(runner); }
    // A new lesson with one step.
    void create(const std::string& title, const LessonStep& first);
    void close();
    // Throws InputError when the file cannot be written.
    void save(const QString& path);

    // Counts the lessons and versions of a lesson shown: opening one, an edit, an undo.
    int generation() const { return generation_; }
    // Counts the lessons opened, made and closed: an edit or an undo keeps it.
    int openings() const { return openings_; }
    int step() const { return step_; }
    const LessonStep& currentStep() const { return lesson_.steps.at(std::size_t(step_)); }
    // Step k's scene evaluated (as the app opens it).
    const std::shared_ptr<const EvaluatedScene>& stepScene(int step) const
    {
        return evaluated_.stepScene.at(std::size_t(step));
    }
    void goTo(int step);
    // A question open and not yet answered or revealed.
    bool isAsking() const;
    bool isRevealed(int step) const { return revealed_.at(std::size_t(step)); }
    const std::optional<Answer>& answer(int step) const { return answers_.at(std::size_t(step)); }
    // How many answers to a step's question were checked.
    int tries(int step) const { return tries_.at(std::size_t(step)); }
    // Records an answer to the current step's question (the last one checked counts) and reveals the
    // question's answer when it is right or the question's tries are used up; returns whether it is right.
    bool check(const Answer& answer);
    // Shows the answer without taking one (a lecturer asking the room); the results record it as
    // revealed, unless it shows for the lesson's editor (`forEditing`), which is no student's doing.
    void reveal(bool forEditing = false);
    // The results file, as the web page saves it.
    std::string resultsJson() const;
    // Writes the results file atomically; throws InputError when it cannot.
    void saveResults(const QString& path);
    // Answers given since the results were last saved.
    bool hasUnsavedAnswers() const { return unsavedAnswers_; }

    // Authoring: each an undoable edit; one the core refuses throws InputError and changes nothing.
    void insertStep(int at, const LessonStep& step);
    void removeStep(int step);
    void moveStep(int from, int to);
    // The lesson's title and a step's caption and question (as the lesson
    // file holds it, JSON; none for empty text): all three, or nothing.
    void setTexts(int step, const std::string& title, const std::string& caption, const std::string& question);

    // Only for undo and redo: a lesson and its steps evaluated before.
    void restore(const Lesson& lesson, const EvaluatedLesson& evaluated, int step);

signals:
    // The steps, the title or the file.
    void lessonChanged();
    // The step shown, or what is revealed of it.
    void stepChanged();

private:
    void edit(Lesson next, int step, const QString& description);
    void resetAnswers();
    EvaluatedLesson evaluateEdit(const Lesson& next, const QString& what);

    SceneEvaluator evaluator_; // the steps' meshes read once
    WorkRunner runWork_ = [](const QString&, const std::function<void()>& work) { work(); };
    Lesson lesson_;
    EvaluatedLesson evaluated_;
    QString filePath_;
    int step_ = 0;
    int generation_ = 0;
    int openings_ = 0;
    std::vector<std::optional<Answer>> answers_;
    std::vector<bool> revealed_;
    std::vector<bool> shownForEditing_; // revealed by opening the editor, not by a student
    std::vector<int> tries_;
    bool unsavedAnswers_ = false;
    QUndoStack undo_;
};

} // namespace viewpipe::gui
