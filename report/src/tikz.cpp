#include "viewpipe/report/tikz.hpp"

#include <cstdio>
#include <map>
#include <set>
#include <sstream>

namespace viewpipe {
namespace {

constexpr double kWidthCm = 16;

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

} // namespace

std::string texEscaped(const std::string& text)
{
    std::string out;
    for (std::size_t k = 0; k < text.size(); ++k) {
        const char c = text[k];
        // The signs the captions use beyond ASCII, which pdflatex does not know as text.
        bool sign = false;
        static const std::pair<std::string, std::string> signs[] = {
            {"\u00b1", "$\\pm$"},    {"\u2264", "$\\le$"},     {"\u2265", "$\\ge$"},    {"\u2212", "$-$"},
            {"\u00d7", "$\\times$"}, {"\u00b7", "$\\cdot$"},   {"\u2192", "$\\to$"},    {"\u2248", "$\\approx$"},
            {"\u00b0", "$^\\circ$"}, {"\u221e", "$\\infty$"}, {"\u2013", "--"},        {"\u2014", "---"}};
        for (const auto& [utf8, tex] : signs)
            if (text.compare(k, utf8.size(), utf8) == 0) {
                out += tex;
                k += utf8.size() - 1;
                sign = true;
                break;
            }
        if (sign)
            continue;
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

std::string texLabel(const std::string& text)
{
    static const std::map<std::string, std::string> usual = {
        {"x", "$x$"}, {"y", "$y$"}, {"z", "$z$"}, {"u", "$u$"}, {"v", "$v$"}, {"n", "$n$"}, {"s", "$s$"},
        {"-f", "$-f$"}, {"VRP", "$\\mathrm{VRP}$"}, {"PRP", "$\\mathrm{PRP}$"}, {"DOP", "$\\mathrm{DOP}$"},
        {"CW", "$\\mathrm{CW}$"}, {"front (F)", "front ($F$)"}, {"back (B)", "back ($B$)"}};
    const auto found = usual.find(text);
    if (found != usual.end())
        return found->second;
    // A plane's equation, "z = z_min" or "z = 1 (far)": math, and the words after it as text.
    if (text.size() > 4 && (text[0] == 'x' || text[0] == 'y' || text[0] == 'z') && text.compare(1, 3, " = ") == 0) {
        const std::size_t words = text.find(" (");
        std::string math = text.substr(0, words);
        if (const std::size_t min = math.find("z_min"); min != std::string::npos)
            math.replace(min, 5, "z_{\\min}");
        return "$" + math + "$" + (words == std::string::npos ? "" : texEscaped(text.substr(words)));
    }
    return texEscaped(text);
}

std::string tikzFigure(const Figure& figure, Theme theme)
{
    const double unit = kWidthCm / figure.width; // cm per pixel
    std::set<Element> used;
    for (const FigureShape& s : figure.shapes)
        used.insert(s.element);
    for (const PlacedLabel& l : figure.labels)
        used.insert(l.element);

    std::ostringstream tex;
    tex << "% A ViewPipe figure. Compile with pdflatex, or \\input it in a document that loads\n"
           "% the standalone package (see figures.tex).\n"
           "\\documentclass[tikz,border=0pt]{standalone}\n\\usepackage{amsmath}\n\\begin{document}\n"
           "% Colors and styles: change them here to restyle the figure.\n";
    tex << "\\definecolor{vpBackground}" << color(backgroundColor(theme, false)) << "\n";
    tex << "\\definecolor{vpObjectsFace}" << color(faceColor(theme)) << "\n";
    for (const Element e : used)
        tex << "\\definecolor{vp" << elementKey(e) << "}" << color(elementColor(e, theme)) << "\n";
    // One pixel of the picture is `unit` cm; line widths and the font follow.
    const double pt = unit / 2.54 * 72.27;
    tex << "\\tikzset{\n  vp label/.style={inner sep=0pt, anchor=north west, font=\\sffamily\\bfseries"
           "\\fontsize{" << number(0.8 * figure.fontSize * pt) << "}{" << number(figure.fontSize * pt) << "}\\selectfont},\n";
    tex << "  vp tick label/.style={vp label, text=vpFrame, font=\\sffamily\\fontsize{" << number(0.6 * figure.fontSize * pt)
        << "}{" << number(0.75 * figure.fontSize * pt) << "}\\selectfont},\n";
    tex << "  vp leader/.style={line width=" << number(figure.lineScale * pt) << "pt},\n";
    for (const Element e : used) {
        const std::string key = elementKey(e);
        tex << "  vp " << key << "/.style={draw=vp" << key << ", line width=" << number(figure.lineScale * lineWidthOf(e, false) * pt) << "pt, line cap=round},\n";
        tex << "  vp " << key << " face/.style={fill=vp" << (e == Element::Objects ? "ObjectsFace" : key) << ", draw=none},\n";
        tex << "  vp " << key << " label/.style={vp label, text=vp" << key << "},\n";
    }
    tex << "}\n";
    tex << "\\begin{tikzpicture}[x=" << unit << "cm, y=-" << unit << "cm]\n";
    tex << "\\fill[vpBackground] (0,0) rectangle " << point(Vec2<double>(figure.width, figure.height)) << ";\n";
    tex << "\\clip (0,0) rectangle " << point(Vec2<double>(figure.width, figure.height)) << ";\n";
    for (const FigureShape& s : figure.shapes) {
        const std::string key = elementKey(s.element);
        tex << (s.surface ? "\\fill[vp " + key + " face" : "\\draw[vp " + key);
        if (s.opacity < 1)
            tex << ", opacity=" << number(s.opacity * 100) << "/100"; // whole percent: TeX parses it
        tex << "] ";
        for (std::size_t k = 0; k < s.points.size(); ++k)
            tex << (k ? " -- " : "") << point(s.points[k]);
        tex << (s.surface ? " -- cycle;\n" : ";\n");
    }
    for (const PlacedLabel& l : figure.labels) {
        const std::string key = elementKey(l.element);
        if (l.leader) {
            const Vec2<double> end = l.box.nearest(l.anchor);
            tex << "\\draw[vp leader, draw=vp" << key << "] " << point(l.anchor) << " -- " << point(end) << ";\n";
        }
        tex << "\\node[vp " << (l.minor ? std::string("tick") : key) << " label] at " << point(l.box.min) << " {"
            << texLabel(l.text) << "};\n";
    }
    tex << "\\end{tikzpicture}\n\\end{document}\n";
    return tex.str();
}

std::string tikzFiguresDocument(const std::vector<std::pair<std::string, std::string>>& figures)
{
    std::ostringstream tex;
    tex << "% Every ViewPipe figure of this folder, each with its caption. Compile with pdflatex.\n"
           "\\documentclass{article}\n\\usepackage[margin=2cm]{geometry}\n\\usepackage{amsmath}\n"
           "\\usepackage{tikz}\n\\usepackage{standalone}\n\\begin{document}\n";
    for (const auto& [file, caption] : figures)
        tex << "\\begin{figure}[p]\n  \\centering\n  \\resizebox{\\linewidth}{!}{\\input{" << file
            << "}}\n  \\caption{" << texEscaped(caption) << "}\n\\end{figure}\n";
    tex << "\\end{document}\n";
    return tex.str();
}

} // namespace viewpipe
