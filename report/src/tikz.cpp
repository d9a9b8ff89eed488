#include "viewpipe/report/tikz.hpp"

#include "viewpipe/error.hpp"
#include "viewpipe/format.hpp"
#include "viewpipe/math_text.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <optional>
#include <map>
#include <set>
#include <sstream>
#include <vector>

namespace viewpipe::report {
namespace {

constexpr double kWidthCm = 16;
// The size figure text is set at before it is scaled to the picture's.
constexpr double kTextPt = 10;
// How far a line's descenders reach below its baseline (about a fifth of the size): a box's bottom.
constexpr double kDescent = 0.22;

// The name each element's color and styles take in the document.
std::string elementKey(Element element)
{
    switch (element) {
    case Element::Objects: return "Objects";
    case Element::WorldAxes: return "WorldAxes";
    case Element::ViewAxes: return "ViewAxes";
    case Element::Prp: return "PRP";
    case Element::Window: return "Window";
    case Element::Dop: return "DOP";
    case Element::Volume: return "Volume";
    case Element::FrontPlane: return "FrontPlane";
    case Element::BackPlane: return "BackPlane";
    case Element::Projectors: return "Projectors";
    case Element::Canonical: return "Canonical";
    case Element::Frame: return "Frame";
    case Element::Vanishing: return "Vanishing";
    case Element::ZFighting: return "ZFighting";
    case Element::Traced: return "Traced";
    }
    return "Objects";
}

std::string number(double value)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.1f", value);
    return text;
}

std::string color(const Rgb& c)
{
    char text[64];
    std::snprintf(text, sizeof text, "{rgb}{%.3f,%.3f,%.3f}", c.r, c.g, c.b);
    return text;
}

std::string point(const Vec2<double>& p)
{
    return "(" + number(p.x()) + "," + number(p.y()) + ")";
}

// The LaTeX of the character beyond ASCII at text[k] that textSymbols() holds, and its length; none otherwise.
std::optional<std::pair<std::string, std::size_t>> texSymbolAt(const std::string& text, std::size_t k)
{
    if (static_cast<unsigned char>(text[k]) < 0x80)
        return std::nullopt;
    for (const TextSymbol& symbol : textSymbols())
        if (text.compare(k, std::strlen(symbol.utf8), symbol.utf8) == 0)
            return std::make_pair(std::string(symbol.latex), std::strlen(symbol.utf8));
    return std::nullopt;
}

// Text in a figure as the other pictures set it (math_text.hpp's runs), in
// the figure's own font: italic runs slanted, scripts as text scripts, so that
// a label's math is as bold and as sans as its words.
std::string figureText(const std::string& text)
{
    std::vector<MathRun> runs;
    try {
        runs = mathRuns(text);
    } catch (const InputError&) {
        return texEscaped(text); // read files are checked: only a program's slip gets here
    }
    // Signs the font has (textcomp's TS1 encoding): as bold as the text, where math's would be a font of its own.
    static const std::pair<std::string, std::string> ownSigns[] = {
        {"−", "\\textminus{}"}, {"±", "\\textpm{}"}, {"×", "\\texttimes{}"}, {"÷", "\\textdiv{}"}, {"°", "\\textdegree{}"}};
    std::string out;
    for (const MathRun& run : runs) {
        std::string set;
        std::size_t from = 0; // the text not yet set
        for (std::size_t k = 0; k < run.text.size(); ++k)
            for (const auto& [sign, tex] : ownSigns)
                if (run.text.compare(k, sign.size(), sign) == 0) {
                    set += texEscaped(run.text.substr(from, k - from)) + tex;
                    from = k + sign.size();
                    k = from - 1;
                    break;
                }
        set += texEscaped(run.text.substr(from));
        if (run.italic)
            set = "{\\slshape " + set + "}";
        for (int level = 0; level < std::abs(run.level); ++level)
            set = (run.level < 0 ? "\\textsubscript{" : "\\textsuperscript{") + set + "}";
        out += set;
    }
    return out;
}

} // namespace

std::string texEscaped(const std::string& text)
{
    std::string out;
    for (std::size_t k = 0; k < text.size(); ++k) {
        if (const auto symbol = texSymbolAt(text, k)) { // a sign pdflatex does not know as text
            out += symbol->first;
            k += symbol->second - 1;
            continue;
        }
        const char c = text[k];
        switch (c) {
        case '\\': out += "\\textbackslash{}"; break;
        case '&': case '%': case '$': case '#': case '_': case '{': case '}': out += std::string("\\") + c; break;
        case '~': out += "\\textasciitilde{}"; break;
        case '^': out += "\\textasciicircum{}"; break;
        case '<': out += "\\textless{}"; break; // OT1 fonts set the character as another
        case '>': out += "\\textgreater{}"; break;
        case '|': out += "\\textbar{}"; break;
        default: out += c;
        }
    }
    return out;
}

std::string texRichText(const std::string& text)
{
    // A line may break after a comma of the math's outer level: "(1.4237, 1.4237, -1.4237)" fits a line.
    auto breakable = [](const std::string& math) {
        std::string out;
        int depth = 0;
        for (std::size_t k = 0; k < math.size(); ++k) {
            depth += math[k] == '{' ? 1 : math[k] == '}' ? -1 : 0;
            out += math[k];
            if (math[k] == ',' && depth == 0 && (k == 0 || math[k - 1] != '\\'))
                out += "\\allowbreak";
        }
        return out;
    };
    std::vector<TextPart> parts;
    try {
        parts = mathTextParts(text);
    } catch (const InputError&) {
        return texEscaped(text); // read files are checked: only a program's slip gets here
    }
    std::string out;
    for (const TextPart& part : parts)
        if (!part.math)
            out += texEscaped(part.text);
        else if (part.text.find_first_not_of(" ") != std::string::npos) { // "$$" would be display math
            // Math holds characters beyond ASCII only in \text{…}: set as in prose.
            std::string math;
            for (std::size_t k = 0; k < part.text.size(); ++k)
                if (const auto symbol = texSymbolAt(part.text, k)) {
                    math += symbol->first;
                    k += symbol->second - 1;
                } else {
                    math += part.text[k];
                }
            out += "$" + breakable(math) + "$";
        }
    return out;
}

namespace {

std::set<Element> usedElements(const Figure& figure)
{
    std::set<Element> used = {Element::Objects, Element::Frame}; // the note's ink, the legend's border
    for (const FigureShape& s : figure.shapes)
        used.insert(s.element);
    for (const PlacedLabel& l : figure.labels)
        used.insert(l.element);
    for (const LegendEntry* entry : figure.legend)
        used.insert(entry->element);
    return used;
}

// The document's start: its class, the colors and the styles of the elements `used`, for text and lines
// sized as `sizes` has them, one pixel `unit` cm.
void writePreamble(std::ostream& tex, const std::set<Element>& used, const Figure& sizes, double unit, Theme theme)
{
    tex << "% A ViewPipe figure. Compile with pdflatex, or \\input it in a document that loads\n"
           "% tikz and the standalone package (see figures.tex); it needs no other package and no\n"
           "% font set-up: its text is set at 10 pt and scaled, in Helvetica (psnfss).\n"
           "\\documentclass[tikz,border=0pt]{standalone}\n\\begin{document}\n"
           "% Colors and styles: change them here to restyle the figure.\n";
    tex << "\\definecolor{vpBackground}" << color(backgroundColor(theme, false)) << "\n";
    tex << "\\definecolor{vpObjectsFace}" << color(faceColor(theme)) << "\n";
    for (const Element e : used)
        tex << "\\definecolor{vp" << elementKey(e) << "}" << color(elementColor(e, theme)) << "\n";
    // One pixel of the picture is `unit` cm; line widths and the font follow.
    const double pt = unit / 2.54 * 72.27;
    // Text as large as the picture's: labels and tick numbers take the same share of the width. It is set at
    // 10 pt and scaled, so that the math fonts of its signs and scripts are asked for at 10, 7 and 5 pt, sizes
    // Computer Modern has: no document needs more fonts for it. Helvetica (psnfss), as the pictures' DejaVu
    // Sans, has a bold oblique for a bold label's math, and is scalable.
    const double labelScale = sizes.fontSize * pt / kTextPt, smallScale = smallTextSize(sizes.fontSize) * pt / kTextPt;
    const std::string font = "\\fontfamily{phv}\\fontsize{" + number(kTextPt) + "}{" + number(1.2 * kTextPt) + "}";
    tex << "\\tikzset{\n  vp text/.style={inner sep=0pt, transform shape},\n"
        << "  vp label/.style={vp text, anchor=base, scale=" << formatShortest(labelScale) << ", font=" << font
        << "\\bfseries\\selectfont},\n";
    tex << "  vp tick label/.style={vp text, anchor=base, scale=" << formatShortest(smallScale)
        << ", text=vpFrame, font=" << font << "\\selectfont},\n";
    tex << "  vp backdrop/.style={fill=vpBackground, fill opacity=" << formatShortest(kLabelBackdropOpacity) << "},\n";
    tex << "  vp leader/.style={line width=" << number(sizes.lineScale * pt) << "pt},\n";
    tex << "  vp small text/.style={vp text, anchor=west, scale=" << formatShortest(smallScale)
        << ", text=vpObjects, font=" << font << "\\selectfont},\n";
    for (const Element e : used) {
        const std::string key = elementKey(e);
        tex << "  vp " << key << "/.style={draw=vp" << key << ", line width=" << number(sizes.lineScale * lineWidthOf(e, false) * pt) << "pt, line cap=round},\n";
        tex << "  vp " << key << " face/.style={fill=vp" << (e == Element::Objects ? "ObjectsFace" : key) << ", draw=none},\n";
        tex << "  vp " << key << " label/.style={vp label, text=vp" << key << "},\n";
    }
    tex << "}\n";
}

// What a figure draws, in its own pixels: its shapes, its text's backdrops, labels, note and legend.
void writeDrawing(std::ostream& tex, const Figure& figure)
{
    const PictureLayout& layout = figure.layout;
    for (const FigureShape& s : figure.shapes) {
        const std::string key = elementKey(s.element);
        tex << (s.surface ? "\\fill[vp " + key + " face" : "\\draw[vp " + key);
        if (s.color) { // a depth band's
            const std::array<unsigned char, 3> c = toBytes(*s.color);
            tex << ", fill={rgb,255:red," << int(c[0]) << ";green," << int(c[1]) << ";blue," << int(c[2]) << "}";
        }
        if (s.opacity < 1)
            tex << ", opacity=" << number(s.opacity * 100) << "/100"; // whole percent: TeX parses it
        tex << "] ";
        for (std::size_t k = 0; k < s.points.size(); ++k)
            tex << (k ? " -- " : "") << point(s.points[k]);
        tex << (s.surface ? " -- cycle;\n" : ";\n");
    }
    // The text's backdrops over what runs behind it, as every picture draws them.
    for (const Box2& box : textBackdrops(layout, figure.height))
        tex << "\\fill[vpBackground] " << point(box.min) << " rectangle " << point(box.max) << ";\n";
    // Each label as the other pictures draw it: its leader to the box's nearest point (the line the placement
    // kept off every other label), the box's backdrop, the text on the box's baseline. Helvetica is narrower
    // than DejaVu Sans: the text is centered in the box measured for it.
    for (const PlacedLabel& l : figure.labels) {
        const std::string key = elementKey(l.element);
        if (l.leader)
            tex << "\\draw[vp leader, draw=vp" << key << "] " << point(l.anchor) << " -- " << point(l.box.nearest(l.anchor)) << ";\n";
        tex << "\\fill[vp backdrop] " << point(l.box.min) << " rectangle " << point(l.box.max) << ";\n";
        const double size = l.minor ? smallTextSize(figure.fontSize) : figure.fontSize;
        const Vec2<double> base((l.box.min.x() + l.box.max.x()) / 2, l.box.max.y() - kDescent * size);
        // A minor label takes its element's ink where that is not the tick numbers' (a storyboard's footer).
        const std::string ink = l.minor && l.element != Element::Frame ? ", text=vp" + key : "";
        tex << "\\node[vp " << (l.minor ? std::string("tick") : key) << " label" << ink << "] at " << point(base) << " {"
            << figureText(l.text) << "};\n";
    }
    // The effects' note, line by line, and the legend, where the picture has them.
    for (std::size_t k = 0; k < layout.noteLines.size(); ++k) {
        // The box's bottom is the last line's descenders (about a fifth of the size below its baseline).
        const double baseline = layout.note.max.y() - kDescent * layout.noteSize - double(layout.noteLines.size() - 1 - k) * layout.noteLine;
        tex << "\\node[vp small text, anchor=base west] at " << point(Vec2<double>(layout.note.min.x(), baseline))
            << " {" << figureText(layout.noteLines[k]) << "};\n";
    }
    if (!figure.legend.empty()) {
        tex << "\\draw[draw=vpFrame] " << point(layout.legend.min) << " rectangle "
            << point(layout.legend.max) << ";\n";
        for (std::size_t k = 0; k < figure.legend.size(); ++k) {
            const LegendEntry& entry = *figure.legend[k];
            const LegendRow row = legendRow(layout, k);
            const double h = row.textHeight;
            const Vec2<double> c = row.swatchCenter;
            const std::string key = elementKey(entry.element);
            const std::string fill = entry.swatch == LegendEntry::Swatch::Face && entry.element == Element::Objects
                                         ? "vpObjectsFace" : "vp" + key;
            const std::string opacity = entry.opacity < 1 ? ", opacity=" + number(entry.opacity * 100) + "/100" : "";
            const std::vector<Rgb> ramp = entry.swatch == LegendEntry::Swatch::Bands    ? std::vector<Rgb>(kBandRamp.begin(), kBandRamp.end())
                                          : entry.swatch == LegendEntry::Swatch::Pixels ? std::vector<Rgb>(kRasterPalette.begin(), kRasterPalette.end())
                                                                                        : std::vector<Rgb>{};
            if (entry.swatch == LegendEntry::Swatch::Dot) {
                tex << "\\fill[" << fill << opacity << "] " << point(c) << " circle[radius=" << number(0.2 * h) << "];\n";
            } else if (!ramp.empty()) {
                for (std::size_t j = 0; j < ramp.size(); ++j) {
                    const double w = 1.5 * h / double(ramp.size()), x = c.x() - 0.75 * h + double(j) * w;
                    char rgb[64];
                    std::snprintf(rgb, sizeof rgb, "{rgb,1:red,%.3f;green,%.3f;blue,%.3f}", ramp[j].r, ramp[j].g, ramp[j].b);
                    tex << "\\fill[fill=" << rgb << "] " << point(Vec2<double>(x, c.y() - 0.2 * h)) << " rectangle "
                        << point(Vec2<double>(x + w, c.y() + 0.2 * h)) << ";\n";
                }
            } else {
                const double half = entry.swatch == LegendEntry::Swatch::Line ? 0.06 * h : 0.2 * h;
                tex << "\\fill[" << fill << opacity << "] " << point(Vec2<double>(c.x() - 0.75 * h, c.y() - half))
                    << " rectangle " << point(Vec2<double>(c.x() + 0.75 * h, c.y() + half)) << ";\n";
            }
            tex << "\\node[vp small text] at " << point(Vec2<double>(row.textLeft, (row.row.min.y() + row.row.max.y()) / 2))
                << " {" << figureText(entry.text) << "};\n";
        }
    }
}

} // namespace

std::string tikzFigure(const Figure& figure, Theme theme)
{
    const double unit = kWidthCm / figure.width; // cm per pixel
    // The document sets the caption: the picture begins below its band (and above any label or the legend).
    const PictureLayout& layout = figure.layout;
    double top = layout.caption.isEmpty() ? 0 : layout.caption.max.y() + 0.25 * figure.fontSize;
    if (!layout.legend.isEmpty())
        top = std::min(top, layout.legend.min.y() - 1);
    top = std::min(top, layout.scene.min.y()); // a stage beside the caption runs up beside it
    for (const PlacedLabel& l : figure.labels)
        top = std::min(top, l.box.min.y() - 1);
    top = std::max(0.0, std::floor(top));

    std::ostringstream tex;
    writePreamble(tex, usedElements(figure), figure, unit, theme);
    tex << "\\begin{tikzpicture}[x=" << unit << "cm, y=-" << unit << "cm]\n";
    const std::string corner = point(Vec2<double>(0, top)), far = point(Vec2<double>(figure.width, figure.height));
    tex << "\\fill[vpBackground] " << corner << " rectangle " << far << ";\n";
    tex << "\\clip " << corner << " rectangle " << far << ";\n";
    writeDrawing(tex, figure);
    tex << "\\end{tikzpicture}\n\\end{document}\n";
    return tex.str();
}

std::string tikzStoryboard(const Storyboard& storyboard, Theme theme)
{
    const StoryboardLayout& layout = storyboard.layout;
    const double unit = kWidthCm / layout.width;
    std::set<Element> used = usedElements(storyboard.overlay);
    for (const Figure& cell : storyboard.cells)
        used.merge(usedElements(cell));
    std::ostringstream tex;
    writePreamble(tex, used, storyboard.overlay, unit, theme);
    tex << "\\begin{tikzpicture}[x=" << unit << "cm, y=-" << unit << "cm]\n";
    tex << "\\fill[vpBackground] (0,0) rectangle " << point(Vec2<double>(layout.width, layout.height)) << ";\n";
    for (std::size_t k = 0; k < storyboard.cells.size(); ++k) {
        const Box2& box = layout.cells[k].picture;
        const Figure& cell = storyboard.cells[k];
        tex << "% " << (layout.cells[k].stage == 0 ? std::string("the world") : "stage " + std::to_string(layout.cells[k].stage)) << "\n";
        tex << "\\begin{scope}[shift={" << point(box.min) << "}]\n";
        tex << "\\clip (0,0) rectangle " << point(Vec2<double>(cell.width, cell.height)) << ";\n";
        writeDrawing(tex, cell);
        tex << "\\end{scope}\n";
    }
    writeDrawing(tex, storyboard.overlay);
    tex << "\\end{tikzpicture}\n\\end{document}\n";
    return tex.str();
}

std::string tikzFiguresDocument(const std::vector<std::pair<std::string, std::string>>& figures)
{
    std::ostringstream tex;
    tex << "% Every ViewPipe figure of this folder, one a page with its caption. Compile with pdflatex.\n"
           "% To use a figure in your own document, load tikz and standalone in its preamble (the\n"
           "% figures need nothing else) and \\input the figure, scaled as you like:\n"
           "%   \\resizebox{\\linewidth}{!}{\\input{" << (figures.empty() ? std::string("NN-SLUG-tikz") : figures.front().first) << "}}\n"
           "\\documentclass[a4paper]{article}\n\\usepackage[margin=2cm]{geometry}\n\\usepackage{amsmath}\n"
           "\\usepackage{caption} % a line break in a caption\n"
           "\\usepackage{tikz}\n\\usepackage{standalone}\n\\begin{document}\n";
    for (const auto& [file, caption] : figures) {
        // The caption's lines (the stage, what it achieved) kept apart; the list of figures takes the first.
        std::vector<std::string> lines;
        std::istringstream in(caption);
        for (std::string line; std::getline(in, line);)
            lines.push_back(texRichText(line));
        std::string joined;
        for (const std::string& line : lines)
            joined += (joined.empty() ? "" : "\\\\ ") + line;
        tex << "\\begin{figure}[p]\n  \\centering\n  \\resizebox{\\linewidth}{!}{\\input{" << file
            << "}}\n  \\caption[{" << (lines.empty() ? "" : lines.front()) << "}]{" << joined
            << "}\n\\end{figure}\n\\clearpage\n";
    }
    tex << "\\end{document}\n";
    return tex.str();
}

} // namespace viewpipe::report
