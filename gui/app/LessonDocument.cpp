#include "LessonDocument.h"

#include <QFileInfo>
#include <QUndoCommand>

namespace viewpipe::gui {
namespace {

class LessonEdit : public QUndoCommand {
public:
    struct State {
        Lesson lesson;
        EvaluatedLesson evaluated;
        int step;
    };
    LessonEdit(LessonDocument* document, State before, State after, const QString& text)
        : QUndoCommand(text), document_(document), before_(std::move(before)), after_(std::move(after))
    {
    }
    void undo() override { document_->restore(before_.lesson, before_.evaluated, before_.step); }
    void redo() override { document_->restore(after_.lesson, after_.evaluated, after_.step); }

private:
    LessonDocument* document_;
    State before_, after_;
};

std::filesystem::path folderOf(const QString& path)
{
    return path.isEmpty() ? std::filesystem::current_path()
                          : std::filesystem::path(QFileInfo(path).absolutePath().toStdString());
}

} // namespace

LessonDocument::LessonDocument(QObject* parent) : QObject(parent)
{
    connect(&undo_, &QUndoStack::cleanChanged, this, &LessonDocument::lessonChanged);
}

LessonDocument::~LessonDocument()
{
    const QSignalBlocker silent(&undo_);
    undo_.clear();
}

EvaluatedLesson LessonDocument::evaluate(const Lesson& lesson)
{
    return evaluateLesson(lesson, &evaluator_);
}

void LessonDocument::open(Lesson lesson, EvaluatedLesson evaluated, const QString& path)
{
    ++generation_;
    ++openings_;
    undo_.clear();
    lesson_ = std::move(lesson);
    evaluated_ = std::move(evaluated);
    filePath_ = path;
    step_ = 0;
    resetAnswers();
    emit lessonChanged();
    emit stepChanged();
}

void LessonDocument::create(const std::string& title, const LessonStep& first)
{
    Lesson lesson{title, {first}};
    const std::filesystem::path folder = folderOf({});
    parseLesson(lessonToJson(lesson, folder), folder); // as every edit is checked
    EvaluatedLesson evaluated = evaluateEdit(lesson, tr("Making the lesson"));
    ++generation_;
    ++openings_;
    undo_.clear();
    undo_.resetClean(); // never saved: closing it asks
    lesson_ = std::move(lesson);
    evaluated_ = std::move(evaluated);
    filePath_.clear();
    step_ = 0;
    resetAnswers();
    emit lessonChanged();
    emit stepChanged();
}

void LessonDocument::close()
{
    ++generation_;
    ++openings_;
    undo_.clear();
    lesson_ = Lesson{};
    evaluated_ = EvaluatedLesson{};
    filePath_.clear();
    step_ = 0;
    resetAnswers();
    emit lessonChanged();
    emit stepChanged();
}

void LessonDocument::save(const QString& path)
{
    const std::filesystem::path folder = folderOf(path);
    const std::string text = lessonToJson(lesson_, folder);
    parseLesson(text, folder); // only a file that reads back is written
    try {
        writeFileAtomically(path.toStdString(), text);
    } catch (const std::exception& e) {
        throw InputError("$", std::string("cannot write the lesson: ") + e.what());
    }
    filePath_ = path;
    undo_.setClean();
    emit lessonChanged();
}

void LessonDocument::goTo(int step)
{
    if (!isOpen())
        return;
    step_ = std::clamp(step, 0, int(lesson_.steps.size()) - 1);
    emit stepChanged();
}

bool LessonDocument::isAsking() const
{
    return isOpen() && currentStep().question && !revealed_[std::size_t(step_)];
}

bool LessonDocument::check(const Answer& answer)
{
    if (!isAsking()) // the answer shown cannot change what was given
        return false;
    const Question& question = *currentStep().question;
    const std::size_t k = std::size_t(step_);
    const bool right = isRight(question, answer);
    answers_[k] = answer;
    ++tries_[k];
    unsavedAnswers_ = true;
    revealed_[k] = right || tries_[k] >= question.tries;
    emit stepChanged();
    return right;
}

void LessonDocument::reveal(bool forEditing)
{
    if (!isOpen() || !currentStep().question)
        return;
    const std::size_t k = std::size_t(step_);
    if (!revealed_[k] && !answers_[k]) {
        if (forEditing)
            shownForEditing_[k] = true; // the lecturer's doing, not the student's: not in the results
        else
            unsavedAnswers_ = true; // shown unanswered: the results say so
    }
    revealed_[k] = true;
    emit stepChanged();
}

std::string LessonDocument::resultsJson() const
{
    std::vector<bool> shownToStudent = revealed_;
    for (std::size_t k = 0; k < shownToStudent.size(); ++k)
        shownToStudent[k] = shownToStudent[k] && !shownForEditing_[k];
    return resultsToJson(lesson_, answers_, shownToStudent, tries_);
}

void LessonDocument::saveResults(const QString& path)
{
    try {
        writeFileAtomically(path.toStdString(), resultsJson());
    } catch (const std::exception& e) {
        throw InputError("$", std::string("cannot write the results: ") + e.what());
    }
    unsavedAnswers_ = false;
}

void LessonDocument::edit(Lesson next, int step, const QString& description)
{
    // The core reads the edited lesson as it would read the file: a bad edit changes nothing.
    const std::filesystem::path folder = folderOf(filePath_);
    const std::string text = lessonToJson(next, folder);
    parseLesson(text, folder);
    if (text == lessonToJson(lesson_, folder))
        return; // nothing changed: no edit to undo
    EvaluatedLesson evaluated = evaluateEdit(next, tr("Updating the lesson"));
    undo_.push(new LessonEdit(this, {lesson_, evaluated_, step_}, {std::move(next), std::move(evaluated), step}, description));
}

EvaluatedLesson LessonDocument::evaluateEdit(const Lesson& next, const QString& what)
{
    EvaluatedLesson evaluated;
    runWork_(what + QString::fromUtf8("…"), [&] { evaluated = evaluateLesson(next, &evaluator_, &evaluated_); });
    return evaluated;
}

void LessonDocument::restore(const Lesson& lesson, const EvaluatedLesson& evaluated, int step)
{
    ++generation_;
    lesson_ = lesson;
    evaluated_ = evaluated;
    step_ = std::clamp(step, 0, int(lesson_.steps.size()) - 1);
    resetAnswers(); // an edited lesson is asked afresh
    emit lessonChanged();
    emit stepChanged();
}

void LessonDocument::resetAnswers()
{
    answers_.assign(lesson_.steps.size(), std::nullopt);
    revealed_.assign(lesson_.steps.size(), false);
    shownForEditing_.assign(lesson_.steps.size(), false);
    tries_.assign(lesson_.steps.size(), 0);
    unsavedAnswers_ = false;
}

void LessonDocument::insertStep(int at, const LessonStep& step)
{
    Lesson next = lesson_;
    at = std::clamp(at, 0, int(next.steps.size()));
    next.steps.insert(next.steps.begin() + at, step);
    edit(std::move(next), at, tr("Add Step"));
}

void LessonDocument::removeStep(int step)
{
    if (lesson_.steps.size() < 2)
        throw InputError("steps", "a lesson keeps at least one step");
    Lesson next = lesson_;
    next.steps.erase(next.steps.begin() + step);
    edit(std::move(next), std::min(step, int(next.steps.size()) - 1), tr("Remove Step"));
}

void LessonDocument::moveStep(int from, int to)
{
    if (to < 0 || to >= int(lesson_.steps.size()) || from == to)
        return;
    Lesson next = lesson_;
    LessonStep moved = next.steps[std::size_t(from)];
    next.steps.erase(next.steps.begin() + from);
    next.steps.insert(next.steps.begin() + to, std::move(moved));
    edit(std::move(next), to, tr("Move Step"));
}

void LessonDocument::setTexts(int step, const std::string& title, const std::string& caption, const std::string& question)
{
    Lesson next = lesson_;
    next.title = title;
    LessonStep& edited = next.steps.at(std::size_t(step));
    edited.caption = caption;
    if (question.find_first_not_of(" \t\n\r") == std::string::npos) {
        edited.question.reset();
    } else {
        try {
            edited.question = parseQuestion(question, edited.scene);
        } catch (const InputError& e) { // named as the file names it, as the caption's refusals are
            throw InputError("steps[" + std::to_string(step) + "]." + e.field(), e.reason());
        }
    }
    edit(std::move(next), step, tr("Edit Step %1").arg(step + 1));
}

} // namespace viewpipe::gui
