#include <algorithm>
#include "viewpipe/report/latex.hpp"

#include <cmath>
#include <sstream>

#include "viewpipe/format.hpp"
#include "viewpipe/math_text.hpp"
#include "viewpipe/report/stage_symbols.hpp"
#include "viewpipe/report/tikz.hpp"
#include "viewpipe/exact.hpp"

namespace viewpipe::report {

std::string exactLatex(const Exact& x, int digits)
{
    if (x.readsExactly())
        return x.latex();
    std::string s = formatSignificant(static_cast<double>(x), digits);
    const std::size_t e = s.find('e');
    if (e != std::string::npos) // 1.5e-07 -> 1.5 \times 10^{-7}
        s = s.substr(0, e) + " \\times 10^{" + std::to_string(std::stoi(s.substr(e + 1))) + "}";
    return s;
}

namespace {

// `highlighted`: entries (row, column from 1) set on a colored box (xcolor).
std::string bmatrix(const Mat4<Exact>& m, int digits, const std::vector<std::array<int, 2>>& highlighted = {})
{
    std::string out = "\\begin{bmatrix}\n";
    for (int r = 0; r < 4; ++r) {
        out += "  ";
        for (int c = 0; c < 4; ++c) {
            std::string cell = exactLatex(m(r, c), digits);
            if (std::find(highlighted.begin(), highlighted.end(), std::array<int, 2>{r + 1, c + 1}) != highlighted.end())
                cell = "\\colorbox{yellow}{$" + cell + "$}"; // a color KaTeX and xcolor both name
            out += cell + (c < 3 ? " & " : (r < 3 ? " \\\\\n" : "\n"));
        }
    }
    return out + "\\end{bmatrix}";
}


} // namespace

namespace {

// A stage's matrix, or the divide's mapping, which is no matrix.
std::string stageEquation(const Stage<Exact>& stage, int digits, const std::vector<std::array<int, 2>>& highlighted = {})
{
    if (stage.divides())
        return "\\text{divide:}\\quad (x, y, z, w) \\mapsto \\left(\\frac{x}{w}, \\frac{y}{w}, \\frac{z}{w}, 1\\right)";
    return stageSymbolMath(stage.kind) + " =\n" + bmatrix(stage.matrix, digits, highlighted);
}

} // namespace

std::string matricesLatex(const Scene& scene, int digits)
{
    const Pipeline<Exact> p = exactPipeline(scene);
    const std::vector<Mat4<Exact>> products = cumulativeProducts(p.stages);
    std::ostringstream out;
    out << "% " << scene.name << ": the stages of the normalizing transformation (column vectors, p' = M p).\n"
        << "% Made by viewpipe; needs \\usepackage{amsmath}. Exact values (fractions, square roots) where their numbers are short.\n"
        << "% Each stage in symbols and in numbers, and the product so far; each display fits a 12 cm column.\n"
        << "\\begingroup\n\\renewcommand{\\arraystretch}{1.2}\n\\setlength{\\parskip}{0pt}\n"
        << "\\setlength{\\abovedisplayskip}{4pt plus 2pt}\\setlength{\\belowdisplayskip}{4pt plus 2pt}\n"
        << "\\setlength{\\abovedisplayshortskip}{2pt plus 2pt}\\setlength{\\belowdisplayshortskip}{4pt plus 2pt}\n"
        << "\\noindent Each stage $k$ in symbols and in numbers, and $M_k$, the stages so far: "
           "a point $p$ after stage $k$ is $M_k \\, p$.\n\n";
    const std::string composite = bmatrix(p.composite, digits);
    std::size_t last = 0; // the last stage that is a matrix: its product, where it is the composite, is shown once
    for (std::size_t k = 0; k < p.stages.size(); ++k)
        last = p.stages[k].divides() ? last : k;
    const bool lastIsComposite = bmatrix(products[last], digits) == composite;
    std::string product;
    int factor = 0; // the stages so far that are matrices
    for (std::size_t k = 0; k < p.stages.size(); ++k) {
        const Stage<Exact>& stage = p.stages[k];
        const std::string symbol = stageSymbolMath(stage.kind);
        out << "% " << k + 1 << ". " << mathPlainText("$" + symbol + "$") << ": " << mathPlainText(stage.explanation) << "\n"
            << "\\par\\smallskip\\noindent\\textbf{" << k + 1 << ".}~$" << symbol << "$: " << texRichText(stage.explanation)
            << "\n";
        if (stage.divides()) {
            out << "\\[\n" << stageEquation(stage, digits) << "\n\\]\n\n";
            continue; // no factor of the product
        }
        // As the Matrices panel shows it: in symbols (where it has them), defined by its notes, then in numbers.
        const std::string symbolic = symbolicLatex(stage.kind);
        out << "\\[\n" << (symbolic.empty() ? symbol : symbolic) << "\n=\n" << bmatrix(stage.matrix, digits) << "\n\\]\n";
        const SymbolicForm form = symbolicMatrix(stage.kind);
        std::string notes;
        for (const std::string& note : form.notes)
            notes += (notes.empty() ? "" : "; ") + texRichText(note);
        if (!notes.empty())
            out << "{\\small\\noindent where " << notes << ".\\par}\n";
        if (factor++ > 0 && !(k == last && lastIsComposite)) // the first stage's product is the stage
            out << "\\[\nM_{" << k + 1 << "} = " << symbol << " \\, M_{" << product << "} =\n" << bmatrix(products[k], digits)
                << "\n\\]\n";
        product = std::to_string(k + 1);
        out << "\n";
    }
    std::string stages;
    for (const Stage<Exact>& stage : p.stages)
        if (!stage.divides())
            stages = stageSymbolMath(stage.kind) + (stages.empty() ? "" : " \\, " + stages);
    const std::string name = p.convention == Convention::OpenGL            ? "P \\, V"
                             : p.projection == ProjectionKind::Perspective ? "N_{\\mathrm{per}}"
                                                                           : "N_{\\mathrm{par}}";
    // The product on a line of its own: with the matrix beside it, it was wider than the text.
    out << "% The composite\n\\par\\smallskip\\noindent The composite:\n\\begin{align*}\n" << name << " &= " << stages
        << " \\\\\n&= " << (lastIsComposite ? "M_{" + std::to_string(last + 1) + "} = " : "") << "\n" << composite
        << "\n\\end{align*}\n";
    if (p.zmin) // Foley's vrp'_z = -PRP_n
        out << "% The front plane in the canonical perspective volume\n"
               "\\noindent The front plane in the canonical perspective volume, with $\\mathit{vrp}'_z = -\\mathit{PRP}_n$:\n"
               "\\[\nz_{\\min} = -\\frac{\\mathit{vrp}'_z + F}{\\mathit{vrp}'_z + B} = "
            << exactLatex(*p.zmin, digits) << "\n\\]\n";
    if (p.view && p.projectionMatrix)
        out << "\n% The view (gluLookAt) and projection matrices\n\\[\nV =\n" << bmatrix(*p.view, digits)
            << "\n\\]\n\\[\nP =\n" << bmatrix(*p.projectionMatrix, digits) << "\n\\]\n";
    out << "\\endgroup\n";
    return out.str();
}

std::string matricesDocument(const Scene& scene, int digits)
{
    // The standalone class sets the page to the text; a document that loads the standalone package
    // skips this preamble where it \inputs the file.
    return "% Compiles on its own (pdflatex matrices.tex), one page as wide as a 12 cm column, and\n"
           "% \\inputs into a document whose preamble has \\usepackage{amsmath} and \\usepackage{standalone}.\n"
           "\\documentclass[varwidth=12cm, border=5mm]{standalone}\n\\usepackage{amsmath}\n\\begin{document}\n" +
           matricesLatex(scene, digits) + "\\end{document}\n";
}

} // namespace viewpipe::report

namespace viewpipe::report {

std::string stageLatex(const Scene& scene, int stage, int digits, const std::vector<std::array<int, 2>>& highlighted)
{
    const Pipeline<Exact> p = exactPipeline(scene);
    return stageEquation(p.stages.at(std::size_t(stage - 1)), digits, highlighted);
}

std::string stageMatrixLatex(const Scene& scene, int stage, int digits)
{
    const Pipeline<Exact> p = exactPipeline(scene);
    const Stage<Exact>& s = p.stages.at(std::size_t(stage - 1));
    return s.divides() ? stageEquation(s, digits) : bmatrix(s.matrix, digits);
}

std::string entryLatex(const Scene& scene, int stage, int row, int column, int digits)
{
    const Pipeline<Exact> p = exactPipeline(scene);
    return exactLatex(p.stages.at(std::size_t(stage - 1)).matrix(row - 1, column - 1), digits);
}

std::vector<std::string> tracedLatex(const Scene& scene, const Vec3<Exact>& point, int stages, int digits)
{
    const PointTrace<Exact> trace = tracePoint(exactPipeline(scene), point);
    const auto text = [digits](const Vec4<Exact>& q) {
        return "(" + exactLatex(q.x(), digits) + ", " + exactLatex(q.y(), digits) + ", " + exactLatex(q.z(), digits) + ", " +
               exactLatex(q.w(), digits) + ")";
    };
    std::vector<std::string> out = {text(Vec4<Exact>(point.x(), point.y(), point.z(), Exact(1)))};
    for (int k = 0; k < stages && k < int(trace.afterStage.size()); ++k)
        out.push_back(text(trace.afterStage[std::size_t(k)]));
    return out;
}

std::vector<StageLatex> stagesLatex(const Scene& scene, int digits)
{
    const Pipeline<Exact> p = exactPipeline(scene);
    const std::vector<Mat4<Exact>> products = cumulativeProducts(p.stages);
    std::vector<StageLatex> out;
    for (std::size_t k = 0; k < p.stages.size(); ++k)
        out.push_back({stageEquation(p.stages[k], digits), bmatrix(products[k], digits)});
    return out;
}

} // namespace viewpipe::report
