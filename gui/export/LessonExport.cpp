#include "LessonExport.h"

#include <cstdio>
#include <fstream>
#include <sstream>
#include <unistd.h>

#include "Offscreen.h"
#include "Process.h"
#include "VectorFigure.h"
#include "viewpipe/report/lesson_latex.hpp"
#include "viewpipe/report/report.hpp"

namespace viewpipe::gui {
namespace fs = std::filesystem;

namespace {

// The handout's figures at 16:9; the slides' text larger, as a projector needs.
constexpr int kFigureWidth = 1280, kFigureHeight = 720;
constexpr double kSlideFontScale = 1.5;

// Step `step`'s view of `stage` as a PDF figure: its camera, its stage, the
// stage named only when the step does not hide it.
void writeStepFigure(const OffscreenPainter& offscreen, const std::shared_ptr<const EvaluatedScene>& scene,
                     const LessonStep& step, int stage, bool named, const std::optional<Vec3<double>>& traced, Theme theme,
                     const fs::path& file)
{
    ScenePainter& painter = *offscreen.painter;
    painter.setScene(scene);
    painter.resetView();
    painter.orbit(step.yaw, step.pitch, step.zoom);
    const std::string caption = named ? stageCaption(*scene, std::size_t(stage), StageText::Heading) : std::string();
    StageShown shown = showStageAtRest(offscreen, *scene, stage, caption, std::nullopt);
    shown.traced = traced;
    writeVectorFigure({&shown, painter.figureView(), caption, theme}, "pdf", file);
}

// The lines of pdflatex's log that say what went wrong ("! ..." and the line after).
std::string latexErrors(const fs::path& log)
{
    std::ifstream in(log);
    std::string line, out;
    int after = 0;
    while (std::getline(in, line) && out.size() < 600) {
        if (!line.empty() && line[0] == '!')
            after = 3;
        if (after > 0) {
            out += (out.empty() ? "" : " ") + line;
            --after;
        }
    }
    return out.empty() ? "see " + log.string() : out;
}

void compile(const fs::path& folder, const std::string& document)
{
    ChildStreams quiet;
    quiet.stdoutToNull = true;
    quiet.workingDirectory = folder.string();
    const int status = runProgram({"pdflatex", "-interaction=batchmode", "-halt-on-error", "-no-shell-escape",
                                   document + ".tex"},
                                  quiet);
    if (status == -1)
        throw std::runtime_error("the handout and slides need pdflatex (TeX Live), which was not found: "
                                 "scripts/install-deps.sh --pdf installs it");
    if (status != 0)
        throw std::runtime_error("pdflatex could not set " + document + ".tex: " + latexErrors(folder / (document + ".log")));
}

} // namespace

std::vector<fs::path> exportLessonPdf(const Lesson& lesson, const std::vector<int>& stepScenes,
                                      const std::vector<std::shared_ptr<const EvaluatedScene>>& scenes,
                                      const fs::path& out, Theme theme,
                                      const std::function<void(const std::string&)>& step)
{
    std::error_code error;
    const bool created = !fs::exists(out);
    fs::create_directories(out, error);
    if (error || !fs::is_directory(out))
        throw InputError("--out", "cannot create the folder \"" + out.string() + "\": " + error.message());
    const fs::path temporary = out / (".viewpipe-lesson-" + std::to_string(::getpid()));
    fs::remove_all(temporary, error);
    fs::create_directories(temporary);
    try {
        std::vector<LessonFigures> handout(lesson.steps.size()), slides(lesson.steps.size());
        for (std::size_t s = 0; s < scenes.size(); ++s) {
            const OffscreenPainter paper(scenes[s], kFigureWidth, kFigureHeight, 1, theme, false);
            const OffscreenPainter projector(scenes[s], kFigureWidth, kFigureHeight, 1, theme, false, kSlideFontScale);
            for (std::size_t k = 0; k < lesson.steps.size(); ++k) {
                if (stepScenes[k] != int(s))
                    continue;
                const LessonStep& lessonStep = lesson.steps[k];
                step("figures of step " + std::to_string(k + 1) + " of " + std::to_string(lesson.steps.size()));
                char name[32];
                std::snprintf(name, sizeof name, "step-%02zu", k + 1);
                auto figures = [&](const OffscreenPainter& offscreen, const std::string& prefix, LessonFigures& files) {
                    files.revealed = prefix + name + ".pdf";
                    // Once answered, the point asked about is marked (as the web page marks it).
                    const Question* question = lessonStep.question ? &*lessonStep.question : nullptr;
                    const bool aboutPoint = question && (question->kind == QuestionKind::Where ||
                                                         question->kind == QuestionKind::Inside ||
                                                         question->kind == QuestionKind::SignW);
                    writeStepFigure(offscreen, scenes[s], lessonStep, revealedStage(lessonStep), true,
                                    aboutPoint ? std::optional<Vec3<double>>(question->point) : lessonStep.trace, theme,
                                    temporary / files.revealed);
                    if (lessonStep.question) {
                        files.asking = prefix + name + "-asking.pdf";
                        writeStepFigure(offscreen, scenes[s], lessonStep, askingStage(lessonStep), false,
                                        lessonStep.trace, theme, temporary / files.asking);
                    }
                };
                figures(paper, "", handout[k]);
                figures(projector, "slide-", slides[k]);
            }
        }
        step("handout.pdf");
        writeFileAtomically(temporary / "handout.tex", lessonHandoutLatex(lesson, handout));
        compile(temporary, "handout");
        step("slides.pdf");
        writeFileAtomically(temporary / "slides.tex", lessonSlidesLatex(lesson, slides));
        compile(temporary, "slides");
        std::vector<fs::path> written;
        for (const char* file : {"handout.pdf", "slides.pdf"}) {
            fs::rename(temporary / file, out / file);
            written.push_back(out / file);
        }
        fs::remove_all(temporary);
        return written;
    } catch (...) {
        fs::remove_all(temporary, error);
        if (created)
            fs::remove(out, error); // only if still empty
        throw;
    }
}

} // namespace viewpipe::gui
