#pragma once
// A lesson on paper: the handout (one A4 page per step, the questions without
// their answers, an answer key at the end with the picture of each answer)
// and 16:9 slides (one per step; a question's step has a second slide with
// its answer), as LaTeX documents that pdflatex compiles (packages: geometry,
// graphicx, amsmath, amssymb, adjustbox, xcolor). The
// figures are PDF files beside the document; every number comes from the
// lesson's scenes, so nothing here can state a wrong answer.
#include <string>
#include <vector>

#include "viewpipe/lesson.hpp"

namespace viewpipe {

// A step's figure files: the view while its question is open (empty without
// a question) and the view once answered.
struct LessonFigures {
    std::string asking, revealed;
};

// Each step's text in the documents follows a line "% steps[K]" (K from 0),
// the title none: an error pdflatex reports at a line is the text of the
// step marked last before it.
constexpr const char* kStepMark = "% steps";

std::string lessonHandoutLatex(const Lesson& lesson, const std::vector<LessonFigures>& figures);
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

} // namespace viewpipe
