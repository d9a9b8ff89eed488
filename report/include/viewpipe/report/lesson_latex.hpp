#pragma once
// A lesson on paper: the handout (each step the room it needs, the questions
// without their answers, an answer key at the end with the picture of each answer)
// and 16:9 slides (one per step; a question's step has a second slide with
// its answer), as LaTeX documents that pdflatex compiles (packages: geometry,
// graphicx, amsmath, amssymb, adjustbox, xcolor). The
// figures are PDF files beside the document; every number comes from the
// lesson's scenes, so nothing here can state a wrong answer.
#include <string>
#include <vector>

#include "viewpipe/lesson.hpp"

namespace viewpipe::report {

// A step's figure files: the view while its question is open (empty without
// a question) and the view once answered.
struct LessonFigures {
    std::string asking, revealed;
};

// The handout's figures are set at kHandoutFigureWidth of the text's width,
// the step's text beside them (three steps to a page), and drawn with their
// text kHandoutFigureTextScale larger, so that their labels (2.4 % of a
// picture's width, 11.6 pt across A4's 17 cm of text) still come out at 10 pt.
constexpr double kHandoutFigureWidth = 0.5;
constexpr double kHandoutFigureTextScale = 0.86 / kHandoutFigureWidth;

// Each step's text in the documents follows a line "% steps[K]" (K from 0),
// the title none: an error pdflatex reports at a line is the text of the
// step marked last before it.
constexpr const char* kStepMark = "% steps";

std::string lessonHandoutLatex(const Lesson& lesson, const std::vector<LessonFigures>& figures);
// A problem sheet: the lesson's questions numbered, each beside its picture
// as the handout shows it while asking (`figures`, the handout's), with the
// set-up it needs (the view or camera as typed, the point); then the
// solutions worked by the core: the stages' matrices up to the stage asked,
// the point after each stage, exact fractions where the numbers are ones.
std::string lessonSheetLatex(const Lesson& lesson, const std::vector<LessonFigures>& figures);
std::string lessonSlidesLatex(const Lesson& lesson, const std::vector<LessonFigures>& figures);

// A question's answer as lesson text (inline `$` math), as every writer
// states it: "$(0, 0, 0)$", "$w$ is positive", "(b) ...", an entry exactly
// and as a decimal.
std::string answerText(const LessonStep& step);
// What a question is about, as lesson text: "After stage 3, $T(-\mathit{PRP})$.
// The point $(8, 6, 84)$."; empty where the prompt says it all.
std::string questionContext(const LessonStep& step);
// A choice's letter, "(a)" for the first.
std::string choiceLetter(std::size_t k);

} // namespace viewpipe::report
