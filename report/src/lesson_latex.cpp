#include "viewpipe/report/lesson_latex.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "viewpipe/format.hpp"
#include "viewpipe/math_text.hpp"
#include "viewpipe/pipeline.hpp"
#include "viewpipe/report/latex.hpp"
#include "viewpipe/report/tikz.hpp"

namespace viewpipe {
namespace {

constexpr int kDigits = 4; // the matrices' decimals, as the app shows them

// As the web page writes numbers: six significant digits, nothing below 1e-12.
std::string number(double x)
{
    return std::abs(x) < 1e-12 ? "0" : formatSignificant(x, 6);
}

std::string point(const Vec3<double>& p)
{
    return "$(" + number(p.x()) + ", " + number(p.y()) + ", " + number(p.z()) + ")$";
}

std::string symbol(const std::string& stageSymbol)
{
    return "$" + symbolMath(stageSymbol) + "$";
}

// Wide matrices shrink to the line; narrow ones keep their size.
std::string fitted(const std::string& math)
{
    return "\\begin{adjustbox}{max width=\\linewidth}$\\displaystyle " + math + "$\\end{adjustbox}\\par\n";
}

std::string stageSymbol(const LessonStep& step, int stage)
{
    return buildPipeline(step.scene.camera, step.scene.effects).stages.at(std::size_t(stage - 1)).symbol;
}

std::string boxes(const std::vector<std::string>& options)
{
    std::string out;
    for (const std::string& option : options)
        out += "\\quad\\mbox{$\\square$~" + option + "}";
    return out + "\\par\n";
}

// A question as the student sees it before answering.
std::string questionLatex(const LessonStep& step, int number)
{
    const Question& q = *step.question;
    std::ostringstream out;
    out << "\\textbf{Question " << number << ".} " << texRichText(q.prompt) << "\\par\n";
    if (const std::string context = questionContext(step); !context.empty())
        out << texRichText(context) << "\\par\n";
    const std::string blank = "\\rule{1.4cm}{0.4pt}";
    std::vector<std::string> options;
    switch (q.kind) {
    case QuestionKind::Where:
        out << "It lands at\\\\ $($" << blank << ", " << blank << ", " << blank
            << "$)$\\par\n";
        break;
    case QuestionKind::Inside: out << boxes({"inside the view volume", "clipped away"}); break;
    case QuestionKind::SignW: out << "$w$ is " << boxes({"positive", "zero", "negative"}); break;
    case QuestionKind::WhichStage:
        out << fitted(report::stageMatrixLatex(step.scene, q.stage, kDigits));
        for (int k : offeredChoices(q))
            options.push_back(symbol(q.choices[std::size_t(k)]));
        out << boxes(options);
        break;
    case QuestionKind::Order:
        for (int k : offeredChoices(q))
            options.push_back(symbol(q.choices[std::size_t(k)]));
        out << "In any order here: " << boxes(options) << "First to last: ";
        for (std::size_t k = 0; k < q.choices.size(); ++k)
            out << (k ? ", " : "") << "\\rule{1.5cm}{0.4pt}";
        out << "\\par\n";
        break;
    case QuestionKind::Entry: out << "Entry $(" << q.row << ", " << q.column << ") = $ " << blank << "\\par\n"; break;
    case QuestionKind::Choice:
        for (std::size_t k = 0; k < q.choices.size(); ++k)
            options.push_back(texRichText(choiceLetter(k) + " " + q.choices[k]));
        for (const std::string& option : options)
            out << "$\\square$~" << option << "\\par\n";
        break;
    }
    return out.str();
}

// The stage's matrix a step shows once answered, if it shows one.
std::string matrixLatex(const LessonStep& step)
{
    const int stage = revealedStage(step);
    return stage > 0 ? fitted(report::stageLatex(step.scene, stage, kDigits, step.entries)) : std::string();
}

std::string answerParagraphs(const LessonStep& step)
{
    std::string out = "\\textbf{Answer:} " + texRichText(answerText(step)) + ".\\par\n";
    if (!step.question->explanation.empty())
        out += texRichText(step.question->explanation) + "\\par\n";
    return out;
}

// Where a step's text begins in the document: pdflatex's errors name a line, this names the step.
std::string stepMark(std::size_t k)
{
    return std::string(kStepMark) + "[" + std::to_string(k) + "]\n";
}

std::string figure(const std::string& file)
{
    return "\\includegraphics[width=\\linewidth]{" + file + "}\\par\n";
}

const char* kPreamble = "\\usepackage{graphicx}\n\\usepackage{amsmath}\n\\usepackage{amssymb}\n\\usepackage{adjustbox}\n\\usepackage{xcolor}\n"
                        "\\setlength{\\parindent}{0pt}\n\\sloppy\n";

} // namespace

std::string choiceLetter(std::size_t k)
{
    return "(" + std::string(1, char('a' + k)) + ")";
}

std::string questionContext(const LessonStep& step)
{
    const Question& q = *step.question;
    std::string out;
    if (q.kind == QuestionKind::Where || q.kind == QuestionKind::SignW)
        out = "After stage " + std::to_string(q.stage) + ", " + symbol(stageSymbol(step, q.stage)) + ".";
    if (q.kind == QuestionKind::Entry)
        out = "The matrix of stage " + std::to_string(q.stage) + ", " + symbol(stageSymbol(step, q.stage)) + ".";
    if (q.kind == QuestionKind::Where || q.kind == QuestionKind::Inside || q.kind == QuestionKind::SignW)
        out += (out.empty() ? "" : " ") + std::string("The point ") + point(q.point) + ".";
    return out;
}

std::string answerText(const LessonStep& step)
{
    const Question& q = *step.question;
    switch (q.kind) {
    case QuestionKind::Where: return point(q.where);
    case QuestionKind::Inside: return q.inside ? "inside the view volume" : "clipped away";
    case QuestionKind::SignW: return std::string("$w$ is ") + (q.signW > 0 ? "positive" : q.signW < 0 ? "negative" : "zero");
    case QuestionKind::WhichStage: return symbol(q.choices[std::size_t(q.correct)]);
    case QuestionKind::Order: {
        std::string out;
        for (const std::string& choice : q.choices)
            out += (out.empty() ? "" : ", ") + symbol(choice);
        return out;
    }
    case QuestionKind::Entry: {
        const std::string exact = report::entryLatex(step.scene, q.stage, q.row, q.column, 6);
        const std::string decimal = number(q.entry);
        return "$" + exact + "$" + (exact == decimal ? "" : " ($" + decimal + "$)");
    }
    case QuestionKind::Choice: return choiceLetter(std::size_t(q.correct)) + " " + q.choices[std::size_t(q.correct)];
    }
    return {};
}


std::string lessonHandoutLatex(const Lesson& lesson, const std::vector<LessonFigures>& figures)
{
    std::ostringstream out;
    out << "% A ViewPipe lesson handout. Compile with pdflatex; the figures are the PDF files beside it.\n"
        << "\\documentclass[11pt,a4paper]{article}\n\\usepackage[margin=2cm]{geometry}\n" << kPreamble
        << "\\setlength{\\parskip}{0.5em}\n\\pagestyle{plain}\n\\begin{document}\n"
        << "{\\Large\\bfseries " << texEscaped(lesson.title) << "\\par}\\vspace{0.5em}\n";
    const std::size_t n = lesson.steps.size();
    int questions = 0;
    for (std::size_t k = 0; k < n; ++k) {
        const LessonStep& step = lesson.steps[k];
        out << stepMark(k) << "\\subsection*{Step " << k + 1 << " of " << n << "}\n";
        if (step.question) {
            out << figure(figures[k].asking) << questionLatex(step, ++questions);
            out << "\\vspace{1em}\\textit{The step's text is in the answer key.}\\par\n";
        } else {
            out << figure(figures[k].revealed) << texRichText(step.caption) << "\\par\n" << matrixLatex(step);
        }
        out << "\\clearpage\n";
    }
    if (questions > 0) {
        out << "\\section*{Answer key}\n";
        questions = 0;
        for (std::size_t k = 0; k < n; ++k) {
            const LessonStep& step = lesson.steps[k];
            if (!step.question)
                continue;
            // Each answer whole on one page: its heading, the stage it shows, its text and matrix together.
            out << stepMark(k) << "\\begin{minipage}{\\linewidth}\\setlength{\\parskip}{0.5em}\n"
                << "\\subsection*{Question " << ++questions << " (step " << k + 1 << ")}\n"
                << figure(figures[k].revealed)
                << answerParagraphs(step) << texRichText(step.caption) << "\\par\n" << matrixLatex(step)
                << "\\end{minipage}\\par\\bigskip\n";
        }
    }
    out << "\\end{document}\n";
    return out.str();
}

std::string lessonSlidesLatex(const Lesson& lesson, const std::vector<LessonFigures>& figures)
{
    std::ostringstream out;
    out << "% A ViewPipe lesson's slides, 16:9. Compile with pdflatex; the figures are the PDF files beside it.\n"
        << "\\documentclass[11pt]{article}\n"
        << "\\usepackage[paperwidth=160mm,paperheight=90mm,margin=4mm,includefoot=false]{geometry}\n" << kPreamble
        << "\\renewcommand{\\familydefault}{\\sfdefault}\n\\pagestyle{empty}\n\\begin{document}\n";
    const std::size_t n = lesson.steps.size();
    const std::string title = texEscaped(lesson.title);
    // The figure at the left, `side` beside it, `below` under both.
    auto slide = [&](std::size_t k, const std::string& file, const std::string& side, const std::string& below) {
        out << stepMark(k);
        out << "{\\footnotesize\\textbf{" << title << "}\\hfill Step " << k + 1 << " of " << n << "}\\par\\vspace{1mm}\n"
            << "\\begin{minipage}[t]{0.63\\linewidth}\\vspace{0pt}" << figure(file) << "\\end{minipage}\\hfill\n"
            << "\\begin{minipage}[t]{0.35\\linewidth}\\vspace{0pt}\\footnotesize\\raggedright\\setlength{\\parskip}{0.4em}\n"
            << side << "\\end{minipage}\\par\\vspace{1mm}\n{\\small " << below << "\\par}\n\\clearpage\n";
    };
    int questions = 0;
    for (std::size_t k = 0; k < n; ++k) {
        const LessonStep& step = lesson.steps[k];
        if (step.question) {
            slide(k, figures[k].asking, questionLatex(step, ++questions), "");
            slide(k, figures[k].revealed, answerParagraphs(step) + matrixLatex(step), texRichText(step.caption));
        } else {
            slide(k, figures[k].revealed, matrixLatex(step), texRichText(step.caption));
        }
    }
    out << "\\end{document}\n";
    return out.str();
}

} // namespace viewpipe
