#include "viewpipe/report/lesson_latex.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <sstream>
#include <type_traits>
#include <variant>

#include "viewpipe/exact.hpp"
#include "viewpipe/format.hpp"
#include "viewpipe/math_text.hpp"
#include "viewpipe/pipeline.hpp"
#include "viewpipe/report/latex.hpp"
#include "viewpipe/report/tikz.hpp"

namespace viewpipe::report {
namespace {

constexpr int kDigits = 4; // the matrices' decimals, as the app shows them

// A lesson's point as it states it: six significant digits, nothing below 1e-12.
std::string number(double x)
{
    return std::abs(x) < 1e-12 ? "0" : formatSignificant(x, 6);
}

std::string point(const Vec3<double>& p)
{
    return "$(" + number(p.x()) + ", " + number(p.y()) + ", " + number(p.z()) + ")$";
}

// A question's point as the lesson writes it: an expression exactly (\frac{1}{3}), a number as above.
std::string questionPoint(const Question& q)
{
    const Vec3<Exact> exact = exactPoint(q);
    std::string out;
    for (int i = 0; i < 3; ++i)
        out += (i ? ", " : "") + (q.pointTyped[std::size_t(i)].empty() ? number(q.point[i]) : exactLatex(exact[i], 6));
    return "$(" + out + ")$";
}

std::string symbol(const std::string& stageSymbol)
{
    return "$" + symbolMath(stageSymbol) + "$";
}

// Rows far enough apart for fractions in display style (as matrices.tex sets them), where there are any.
std::string rowsApart(const std::string& math)
{
    return math.find("\\frac") == std::string::npos ? "1.2" : "2";
}

// Wide matrices shrink to the line, tall ones to a quarter of the page (on a slide); others keep their size.
std::string fitted(const std::string& math)
{
    return "\\begin{adjustbox}{max width=\\linewidth,max totalheight=0.25\\textheight}{\\renewcommand{\\arraystretch}{" + rowsApart(math) +
           "}\\let\\frac\\dfrac$\\displaystyle " + math + "$}\\end{adjustbox}\\par\n";
}

std::string stageSymbol(const LessonStep& step, int stage)
{
    return buildPipeline(step.scene.camera, step.scene.effects).stages.at(std::size_t(stage - 1)).symbol();
}

std::string boxes(const std::vector<std::string>& options)
{
    std::string out;
    for (const std::string& option : options)
        out += "\\quad\\mbox{$\\square$~" + option + "}";
    return out + "\\par\n";
}

// A question as the student sees it before answering; `setUp`, where given, the view's data it needs.
std::string questionLatex(const LessonStep& step, int number, const std::string& setUp = {})
{
    const Question& q = *step.question;
    std::ostringstream out;
    out << "\\textbf{Question " << number << ".} " << texRichText(q.prompt) << "\\par\n" << setUp;
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
        out << fitted(stageMatrixLatex(step.scene, q.stage, kDigits));
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
    return stage > 0 ? fitted(stageLatex(step.scene, stage, kDigits, step.entries)) : std::string();
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

// A step's figure with its text beside it, the figure kHandoutFigureWidth of the line.
std::string beside(const std::string& file, const std::string& text)
{
    const std::string width = formatShortest(kHandoutFigureWidth);
    return "\\begin{minipage}[t]{" + width + "\\linewidth}\\vspace{0pt}" + figure(file) + "\\end{minipage}\\hfill\n"
           "\\begin{minipage}[t]{" + formatShortest(0.97 - kHandoutFigureWidth) + "\\linewidth}\\vspace{0pt}\\raggedright"
           "\\setlength{\\parskip}{0.4em}\n" + text + "\\end{minipage}\\par\n";
}

// A block that stays on one page, heading and all.
std::string unbroken(const std::string& body)
{
    return "\\begin{minipage}{\\linewidth}\\setlength{\\parskip}{0.4em}\n" + body + "\\end{minipage}\\par\\medskip\n";
}

// The set-up a problem on paper needs: the view or camera as the scene gives it, numbers as typed, and
// the effects it lists (the divide adds a stage).
std::string sceneDataLatex(const Scene& scene)
{
    // As typed, but where that takes more than eight digits (a preset computed from angles): six, said so.
    bool rounded = false;
    const auto n = [&rounded](double x) {
        if (std::isinf(x))
            return std::string(x > 0 ? "\\infty" : "-\\infty");
        const std::string typed = formatShortest(x);
        if (std::count_if(typed.begin(), typed.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); }) <= 8)
            return typed;
        rounded = true;
        return formatSignificant(x, 6);
    };
    const auto vec = [&n](const Vec3<double>& v) { return "(" + n(v.x()) + ", " + n(v.y()) + ", " + n(v.z()) + ")"; };
    std::string out;
    if (const auto* view = std::get_if<foley::ViewSpec<double>>(&scene.camera)) {
        const bool perspective = view->projection == foley::Projection::Perspective;
        out = std::string("A ") + (perspective ? "perspective" : "parallel") + " view: $\\mathit{VRP} = " + vec(view->vrp) +
              "$, $\\mathit{VPN} = " + vec(view->vpn) + "$, $\\mathit{VUP} = " + vec(view->vup) + "$, $\\mathit{PRP} = " +
              vec(view->prp) + "$, the window $[" + n(view->window.umin) + ", " + n(view->window.umax) + "] \\times [" +
              n(view->window.vmin) + ", " + n(view->window.vmax) + "]$, $F = " + n(view->front) + "$, $B = " +
              n(view->back) + "$";
    } else {
        const auto& camera = std::get<gl::Camera<double>>(scene.camera);
        out = "A camera (" + texEscaped(gl::apiTitle(camera.api)) + "'s conventions, " +
              texEscaped(gl::handednessName(camera.handedness)) + "-handed" +
              (camera.depth == gl::DepthMode::Reversed ? ", reversed depth" : "") + "): look-at eye $" +
              vec(camera.lookAt.eye) + "$, center $" + vec(camera.lookAt.center) + "$, up $" + vec(camera.lookAt.up) + "$; ";
        out += std::visit(
            [&n](const auto& box) {
                using Box = std::decay_t<decltype(box)>;
                if constexpr (std::is_same_v<Box, gl::Perspective<double>>)
                    return "a perspective of $\\mathit{fovy} = " + n(box.fovyDegrees) + "^\\circ$, aspect $" + n(box.aspect) +
                           "$, near $" + n(box.zNear) + "$, far $" + n(box.zFar) + "$";
                else
                    return std::string(std::is_same_v<Box, gl::Frustum<double>> ? "a frustum" : "an orthographic box") +
                           " $(l, r, b, t, n, f) = (" + n(box.left) + ", " + n(box.right) + ", " + n(box.bottom) + ", " +
                           n(box.top) + ", " + n(box.zNear) + ", " + n(box.zFar) + ")$";
            },
            camera.projection);
    }
    std::string effects;
    for (const EffectKind effect : scene.effects.listed)
        effects += (effects.empty() ? "" : ", ") + texEscaped(effectName(effect));
    return out + (effects.empty() ? "" : "; effects: " + effects) + (rounded ? " (numbers to six digits)." : ".");
}

const char* kPreamble = "\\usepackage{graphicx}\n\\usepackage{amsmath}\n\\usepackage{amssymb}\n\\usepackage{adjustbox}\n\\usepackage{xcolor}\n"
                        "\\setlength{\\parindent}{0pt}\n\\sloppy\n";

// An A4 document's opening, up to the lesson's title: what the handout and the problem sheet share.
std::string a4Opening(const std::string& comment, const Lesson& lesson)
{
    return comment + "\n\\documentclass[11pt,a4paper]{article}\n\\usepackage[margin=2cm]{geometry}\n" + kPreamble +
           "\\setlength{\\parskip}{0.5em}\n\\pagestyle{plain}\n\\begin{document}\n{\\Large\\bfseries " +
           texEscaped(lesson.title) + "\\par}";
}

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
        out += (out.empty() ? "" : " ") + std::string("The point ") + questionPoint(q) + ".";
    return out;
}

std::string answerText(const LessonStep& step)
{
    const Question& q = *step.question;
    switch (q.kind) {
    case QuestionKind::Where: { // exactly (the answer a typed one is judged against), and as a decimal where that is another text
        const std::string decimal = point(q.where);
        if (!q.exact)
            return decimal;
        const std::vector<Exact>& e = *q.exact;
        const std::string exact = "$(" + exactLatex(e[0], 6) + ", " + exactLatex(e[1], 6) + ", " +
                                  exactLatex(e[2], 6) + ")$";
        return exact + (exact == decimal ? "" : " ($\\approx " + decimal.substr(1, decimal.size() - 2) + "$)");
    }
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
        const std::string decimal = number(q.entry);
        const std::string exact = q.exact ? exactLatex(q.exact->front(), 6) : decimal;
        return "$" + exact + "$" + (exact == decimal ? "" : " ($" + decimal + "$)");
    }
    case QuestionKind::Choice: return choiceLetter(std::size_t(q.correct)) + " " + q.choices[std::size_t(q.correct)];
    }
    return {};
}


std::string lessonHandoutLatex(const Lesson& lesson, const std::vector<LessonFigures>& figures)
{
    std::ostringstream out;
    out << a4Opening("% A ViewPipe lesson handout. Compile with pdflatex; the figures are the PDF files beside it.", lesson)
        << "\\vspace{0.5em}\n";
    const std::size_t n = lesson.steps.size();
    int questions = 0;
    // Each step takes the room it needs: its heading, figure and what stands beside it on one page, a
    // caption of any length after them.
    for (std::size_t k = 0; k < n; ++k) {
        const LessonStep& step = lesson.steps[k];
        const std::string heading = "\\subsection*{Step " + std::to_string(k + 1) + " of " + std::to_string(n) + "}\n";
        out << stepMark(k);
        if (step.question)
            out << unbroken(heading + beside(figures[k].asking, questionLatex(step, ++questions) +
                                                                    "\\textit{The step's text is in the answer key.}\\par\n"));
        else
            out << unbroken(heading + beside(figures[k].revealed, matrixLatex(step))) << texRichText(step.caption) << "\\par\n";
    }
    if (questions > 0) {
        out << "\\clearpage\n\\section*{Answer key}\n";
        questions = 0;
        for (std::size_t k = 0; k < n; ++k) {
            const LessonStep& step = lesson.steps[k];
            if (!step.question)
                continue;
            out << stepMark(k)
                << unbroken("\\subsection*{Question " + std::to_string(++questions) + " (step " + std::to_string(k + 1) +
                            ")}\n" + beside(figures[k].revealed, answerParagraphs(step) + matrixLatex(step)))
                << texRichText(step.caption) << "\\par\n";
        }
    }
    out << "\\end{document}\n";
    return out.str();
}

std::string lessonSheetLatex(const Lesson& lesson, const std::vector<LessonFigures>& figures)
{
    std::ostringstream out;
    out << a4Opening("% A ViewPipe problem sheet: the lesson's questions, then their solutions. Compile with pdflatex.", lesson)
        << "\\vspace{0.3em}{\\large Problems\\par}\\vspace{0.5em}\n";
    int number = 0;
    const Scene* before = nullptr; // the scene of the question before
    for (std::size_t k = 0; k < lesson.steps.size(); ++k) {
        const LessonStep& step = lesson.steps[k];
        if (!step.question)
            continue;
        const bool same = before && before->camera == step.scene.camera && before->effects == step.scene.effects;
        ++number;
        out << stepMark(k)
            << unbroken(beside(figures[k].asking,
                               questionLatex(step, number,
                                             (same ? "The same set-up as question " + std::to_string(number - 1) + "."
                                                   : sceneDataLatex(step.scene)) + "\\par\n")));
        before = &step.scene;
    }
    out << "\\clearpage\n\\section*{Solutions}\n";
    number = 0;
    for (std::size_t k = 0; k < lesson.steps.size(); ++k) {
        const LessonStep& step = lesson.steps[k];
        if (!step.question)
            continue;
        const Question& q = *step.question;
        std::string body = "\\subsection*{Question " + std::to_string(++number) + "}\n";
        const int stages = int(buildPipeline(step.scene.camera, step.scene.effects).stages.size());
        const bool traced = q.kind == QuestionKind::Where || q.kind == QuestionKind::SignW || q.kind == QuestionKind::Inside;
        if (traced) {
            // The stages' matrices up to the stage asked about (an inside question: all), three to a line,
            // then the point after each of them.
            const int last = q.kind == QuestionKind::Inside ? stages : q.stage;
            std::string line;
            for (int s = 1; s <= last; ++s) {
                line += (line.empty() ? "" : " \\qquad ") + stageLatex(step.scene, s, kDigits);
                if (s % 3 == 0 || s == last) {
                    body += fitted(line);
                    line.clear();
                }
            }
            const std::vector<std::string> points = tracedLatex(step.scene, exactPoint(q), last, kDigits);
            const std::vector<Stage<double>> named = buildPipeline(step.scene.camera, step.scene.effects).stages;
            std::string rows;
            for (std::size_t s = 0; s < points.size(); ++s)
                rows += (s == 0 ? std::string("world") : symbol(named[s - 1].symbol())) + " & $" + points[s] + "$ \\\\\n";
            body += "The point $(x, y, z, w)$ after each stage:\\par\n{\\renewcommand{\\arraystretch}{" + rowsApart(rows) +
                    "}\\let\\frac\\dfrac\\begin{tabular}{@{}l@{\\quad}l@{}}\n" + rows;
            body += "\\end{tabular}}\\par\n";
        } else if (q.kind == QuestionKind::Entry) {
            body += fitted(stageLatex(step.scene, q.stage, kDigits, {{q.row, q.column}}));
        } else if (q.kind == QuestionKind::WhichStage) {
            body += fitted(stageLatex(step.scene, q.stage, kDigits));
        }
        out << stepMark(k) << unbroken(body + answerParagraphs(step));
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

} // namespace viewpipe::report
