#include "LessonExport.h"

#include <cstdio>
#include <cstdlib>
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

// The figures' text against the pictures' at their size: a page sets them
// as wide as its text; a slide at 0.63 of its 152 mm beside the step's text,
// where 1.25 sets labels of 2.4 % of the width at 8 pt.
constexpr double kPaperFontScale = 1.0, kSlideFontScale = 1.25;

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

// What pdflatex's log says went wrong ("! ..." and the lines after it), and
// the line of the document it names ("l.123"), if any.
std::pair<std::string, int> latexError(const fs::path& log)
{
    std::ifstream in(log);
    std::string line, what;
    int after = 0, at = 0;
    while (std::getline(in, line) && what.size() < 600) {
        if (!line.empty() && line[0] == '!')
            after = 3;
        if (line.rfind("l.", 0) == 0 && at == 0)
            at = std::atoi(line.c_str() + 2);
        if (after > 0) {
            what += (what.empty() ? "" : " ") + line;
            --after;
        }
    }
    std::string squeezed; // the log pads its lines with spaces
    for (char c : what)
        if (!(c == ' ' && !squeezed.empty() && squeezed.back() == ' '))
            squeezed += c;
    return {squeezed.empty() ? "no reason given" : squeezed, at};
}

// The field of the lesson whose text is at `line` of the document: the step marked last before it.
std::string fieldAt(const fs::path& document, int line)
{
    std::ifstream in(document);
    std::string text, field = "title";
    for (int k = 1; k <= line && std::getline(in, text); ++k)
        if (text.rfind(kStepMark, 0) == 0)
            field = "steps" + text.substr(std::string(kStepMark).size());
    return field;
}

// pdflatex without its terminal talk, reading no file outside the folder
// (openin_any=p), stopped after a minute (a lesson's macros could loop).
void compile(const fs::path& folder, const std::string& document)
{
    ChildStreams quiet;
    quiet.stdoutToNull = true;
    quiet.stderrToNull = true; // its refusals are in the log, and in the message below
    quiet.workingDirectory = folder.string();
    quiet.environment = {"openin_any=p", "openout_any=p"};
    const int status = runProgram({"pdflatex", "-interaction=batchmode", "-halt-on-error", "-no-shell-escape",
                                   document + ".tex"},
                                  quiet, 60);
    if (status == -1)
        throw std::runtime_error("the handout and slides need pdflatex (TeX Live), which was not found: "
                                 "scripts/install-deps.sh --pdf installs it");
    if (status == kTimedOut)
        throw InputError("steps", "pdflatex did not finish in a minute: a caption's macros may never end");
    if (status != 0) {
        const auto [what, line] = latexError(folder / (document + ".log"));
        if (line == 0)
            throw std::runtime_error("pdflatex could not set " + document + ".tex: " + what);
        // The lesson's text is what pdflatex could not set: bad input, named by its step.
        throw InputError(fieldAt(folder / (document + ".tex"), line), "pdflatex cannot set its text: " + what);
    }
}

} // namespace

std::vector<fs::path> exportLessonPdf(const Lesson& lesson, const std::vector<int>& stepScenes,
                                      const std::vector<std::shared_ptr<const EvaluatedScene>>& scenes,
                                      const fs::path& out, int width, int height, Theme theme,
                                      const std::function<void(const std::string&)>& step)
{
    if (width < 64 || height < 64 || width > 8192 || height > 8192)
        throw InputError("--size", "must be WxH with 64 <= W, H <= 8192");
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
            const OffscreenPainter paper(scenes[s], width, height, 1, theme, false, kPaperFontScale);
            const OffscreenPainter projector(scenes[s], width, height, 1, theme, false, kSlideFontScale);
            for (std::size_t k = 0; k < lesson.steps.size(); ++k) {
                if (stepScenes[k] != int(s))
                    continue;
                const LessonStep& lessonStep = lesson.steps[k];
                step("figures of step " + std::to_string(k + 1) + " of " + std::to_string(lesson.steps.size()));
                char name[32];
                std::snprintf(name, sizeof name, "step-%02zu", k + 1);
                auto figures = [&](const OffscreenPainter& offscreen, const std::string& prefix, LessonFigures& files) {
                    files.revealed = prefix + name + ".pdf";
                    writeStepFigure(offscreen, scenes[s], lessonStep, revealedStage(lessonStep), true,
                                    tracedAt(lessonStep), theme, temporary / files.revealed);
                    if (lessonStep.question) {
                        files.asking = prefix + name + "-asking.pdf";
                        writeStepFigure(offscreen, scenes[s], lessonStep, askingStage(lessonStep), false,
                                        tracedAt(lessonStep), theme, temporary / files.asking);
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
