#include "MathTextRenderer.h"

#include <vtkFreeTypeTools.h>
#include <vtkImageData.h>
#include <vtkMathTextUtilities.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkUnicodeString.h>
#include <vtkTextProperty.h>
#include <vtkTextRenderer.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "viewpipe/error.hpp"
#include "viewpipe/math_text.hpp"

namespace viewpipe::gui {
namespace {

// FreeType in VTK 9.1 reads a std::string's bytes as characters: text beyond
// ASCII (−, ±, Greek) goes through its UTF-16 form, as VTK's own renderer does.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"
vtkUnicodeString unicode(const std::string& utf8)
{
    return vtkUnicodeString::from_utf8(utf8);
}

// One run placed on its line: x from the line's left, its baseline's height above the line's.
struct PlacedRun {
    MathRun run;
    vtkSmartPointer<vtkTextProperty> font;
    int x = 0, rise = 0, width = 0;
};

struct Line {
    std::vector<PlacedRun> runs;
    int width = 0;
};

struct Layout {
    std::vector<Line> lines;
    int width = 0, height = 0;
    int ascent = 0, descent = 0; // pixels above the first line's baseline and below the last's, scripts included
    int lineStep = 0;            // from one baseline to the next
};

// Asked for every run measured: each file looked for once.
bool fontFileExists(const std::string& file)
{
    static std::map<std::string, bool> known;
    const auto found = known.find(file);
    return found != known.end() ? found->second : (known[file] = std::ifstream(file).good());
}

// The face for a run: the oblique face of the font file where the text property names one.
vtkSmartPointer<vtkTextProperty> runFont(vtkTextProperty* base, const MathRun& run)
{
    auto font = vtkSmartPointer<vtkTextProperty>::New();
    font->ShallowCopy(base);
    font->SetJustificationToLeft();
    font->SetVerticalJustificationToBottom();
    font->SetBackgroundOpacity(0);
    font->SetFrame(false);
    font->SetOrientation(0);
    font->SetLineOffset(0);
    if (run.level != 0)
        font->SetFontSize(std::max(1, int(std::lround(base->GetFontSize() * std::pow(kScriptScale, std::abs(run.level))))));
    if (run.italic) {
        const char* file = base->GetFontFile();
        std::string name = file ? file : "";
        if (base->GetFontFamily() == VTK_FONT_FILE && name.size() > 4 && name.compare(name.size() - 4, 4, ".ttf") == 0)
            name.insert(name.size() - 4, name.find("-Bold") != std::string::npos ? "Oblique" : "-Oblique");
        if (fontFileExists(name)) { // DejaVuSans-Oblique.ttf: fonts-dejavu-extra
            font->SetFontFile(name.c_str());
        } else { // VTK's own italic face
            font->SetFontFamily(VTK_ARIAL);
            font->SetItalic(true);
        }
    }
    return font;
}

// Ascent and descent of a font, in pixels (FreeType measures them on a text of its own, the same for any text).
void verticalExtent(vtkTextProperty* font, int dpi, int& ascent, int& descent)
{
    vtkTextRenderer::Metrics m;
    vtkFreeTypeTools::GetInstance()->GetMetrics(font, unicode("Ág"), dpi, m);
    ascent = m.Ascent[1];
    descent = -m.Descent[1];
}

bool lay(vtkTextProperty* tprop, const char* str, int dpi, Layout& out)
{
    if (!str || tprop->GetOrientation() != 0)
        return false;
    vtkFreeTypeTools* freeType = vtkFreeTypeTools::GetInstance();
    std::vector<std::string> texts;
    std::stringstream all(str);
    for (std::string line; std::getline(all, line);)
        texts.push_back(line);
    if (texts.empty())
        return false;
    vtkNew<vtkTextProperty> base;
    base->ShallowCopy(tprop);
    int ascent = 0, descent = 0;
    verticalExtent(base, dpi, ascent, descent);
    out.lineStep = int(std::lround((ascent + descent) * tprop->GetLineSpacing()));
    const double size = tprop->GetFontSize();
    int firstAbove = ascent, lastBelow = descent; // a first line's superscripts may reach higher, a last's subscripts lower
    for (const std::string& text : texts) {
        std::vector<MathRun> runs;
        try {
            runs = mathRuns(text);
        } catch (const InputError&) {
            return false; // drawn as written by FreeType
        }
        Line line;
        for (const MathRun& run : runs) {
            PlacedRun placed{run, runFont(base, run)};
            vtkTextRenderer::Metrics m;
            if (!freeType->GetMetrics(placed.font, unicode(run.text), dpi, m))
                return false;
            placed.x = line.width;
            placed.width = m.BoundingBox[1] - m.BoundingBox[0] + 1;
            const double rise = run.level > 0 ? kSuperscriptRise * run.level : kSubscriptDrop * run.level;
            placed.rise = int(std::lround(rise * size * dpi / 72.0)); // VTK's font sizes are points at the dpi
            line.width += placed.width;
            const double scale = std::pow(kScriptScale, std::abs(run.level));
            if (out.lines.empty())
                firstAbove = std::max(firstAbove, placed.rise + int(std::ceil(ascent * scale)));
            if (out.lines.size() + 1 == texts.size())
                lastBelow = std::max(lastBelow, int(std::ceil(descent * scale)) - placed.rise);
            line.runs.push_back(placed);
        }
        out.width = std::max(out.width, line.width);
        out.lines.push_back(std::move(line));
    }
    out.ascent = firstAbove;
    out.descent = lastBelow;
    // The baseline's row and the ascent's top row both count, as FreeType's box has them: one row short, the
    // top row of every glyph was cut ("front (F)" read "tront (⊢)" at 12 px).
    out.height = out.ascent + out.descent + 1 + int(out.lines.size() - 1) * out.lineStep;
    return out.width > 0;
}

// The box's corner from the anchor, as FreeType's justification places it.
void anchorOffset(vtkTextProperty* tprop, const Layout& layout, int& x0, int& y0)
{
    const int w = layout.width, h = layout.height;
    x0 = tprop->GetJustification() == VTK_TEXT_CENTERED ? -w / 2 : tprop->GetJustification() == VTK_TEXT_RIGHT ? -w + 1 : 0;
    y0 = tprop->GetVerticalJustification() == VTK_TEXT_CENTERED ? -h / 2
         : tprop->GetVerticalJustification() == VTK_TEXT_TOP    ? -h + 1
                                                                 : 0;
}

class MathTextUtilities : public vtkMathTextUtilities {
public:
    static MathTextUtilities* New();
    vtkTypeMacro(MathTextUtilities, vtkMathTextUtilities)

    bool IsAvailable() override { return true; }

    bool GetBoundingBox(vtkTextProperty* tprop, const char* str, int dpi, int bbox[4]) override
    {
        vtkTextRenderer::Metrics m;
        if (!GetMetrics(tprop, str, dpi, m))
            return false;
        std::copy(m.BoundingBox.GetData(), m.BoundingBox.GetData() + 4, bbox);
        return true;
    }

    bool GetMetrics(vtkTextProperty* tprop, const char* str, int dpi, vtkTextRenderer::Metrics& metrics) override
    {
        Layout layout;
        if (!lay(tprop, str, dpi, layout))
            return false;
        int x0 = 0, y0 = 0;
        anchorOffset(tprop, layout, x0, y0);
        const int x1 = x0 + layout.width - 1, y1 = y0 + layout.height - 1;
        metrics.BoundingBox = vtkTuple<int, 4>();
        metrics.BoundingBox[0] = x0;
        metrics.BoundingBox[1] = x1;
        metrics.BoundingBox[2] = y0;
        metrics.BoundingBox[3] = y1;
        metrics.TopLeft = vtkVector2i(x0, y1);
        metrics.TopRight = vtkVector2i(x1, y1);
        metrics.BottomLeft = vtkVector2i(x0, y0);
        metrics.BottomRight = vtkVector2i(x1, y0);
        metrics.Ascent = vtkVector2i(0, layout.ascent);
        metrics.Descent = vtkVector2i(0, -layout.descent);
        return true;
    }

    bool RenderString(const char* str, vtkImageData* data, vtkTextProperty* tprop, int dpi, int textDims[2]) override
    {
        Layout layout;
        if (!data || !lay(tprop, str, dpi, layout))
            return false;
        int x0 = 0, y0 = 0;
        anchorOffset(tprop, layout, x0, y0);
        const int w = layout.width, h = layout.height;
        int iw = w, ih = h;
        if (powerOfTwo_) {
            iw = 1 << int(std::ceil(std::log2(std::max(1, w))));
            ih = 1 << int(std::ceil(std::log2(std::max(1, h))));
        }
        data->SetSpacing(1, 1, 1);
        data->SetExtent(x0, x0 + iw - 1, y0, y0 + ih - 1, 0, 0);
        data->AllocateScalars(VTK_UNSIGNED_CHAR, 4);
        auto* pixels = static_cast<unsigned char*>(data->GetScalarPointer());
        std::memset(pixels, 0, std::size_t(iw) * std::size_t(ih) * 4);
        if (tprop->GetBackgroundOpacity() > 0) {
            const double* c = tprop->GetBackgroundColor();
            const unsigned char fill[4] = {(unsigned char)(255 * c[0]), (unsigned char)(255 * c[1]), (unsigned char)(255 * c[2]),
                                           (unsigned char)(255 * tprop->GetBackgroundOpacity())};
            for (int y = 0; y < h; ++y)
                for (int x = 0; x < w; ++x)
                    std::memcpy(pixels + 4 * (std::size_t(y) * iw + x), fill, 4);
        }
        vtkFreeTypeTools* freeType = vtkFreeTypeTools::GetInstance();
        const bool pot = freeType->GetScaleToPowerTwo();
        freeType->SetScaleToPowerTwo(false);
        vtkNew<vtkImageData> piece;
        for (std::size_t k = 0; k < layout.lines.size(); ++k) {
            // Each line's baseline, from the image's bottom.
            const int baseline = layout.descent + int(layout.lines.size() - 1 - k) * layout.lineStep;
            const Line& line = layout.lines[k];
            const int left = tprop->GetJustification() == VTK_TEXT_CENTERED ? (w - line.width) / 2
                             : tprop->GetJustification() == VTK_TEXT_RIGHT  ? w - line.width
                                                                            : 0;
            for (const PlacedRun& run : line.runs) {
                int dims[2] = {0, 0};
                if (!freeType->RenderString(run.font, unicode(run.run.text), dpi, piece, dims))
                    continue;
                int extent[6];
                piece->GetExtent(extent);
                int runAscent = 0, runDescent = 0;
                verticalExtent(run.font, dpi, runAscent, runDescent);
                const int pw = extent[1] - extent[0] + 1;
                const auto* from = static_cast<const unsigned char*>(piece->GetScalarPointer());
                // The piece's anchor is its descent below its baseline.
                const int dy = baseline + run.rise - runDescent + extent[2], dx = left + run.x + extent[0];
                for (int y = 0; y < dims[1]; ++y)
                    for (int x = 0; x < dims[0]; ++x) {
                        const int tx = dx + x, ty = dy + y;
                        if (tx < 0 || ty < 0 || tx >= w || ty >= h)
                            continue;
                        const unsigned char* s = from + 4 * (std::size_t(y) * pw + x);
                        unsigned char* d = pixels + 4 * (std::size_t(ty) * iw + tx);
                        const double a = s[3] / 255.0, keep = 1 - a;
                        for (int c = 0; c < 3; ++c)
                            d[c] = (unsigned char)std::lround(s[c] * a + d[c] * keep);
                        d[3] = (unsigned char)std::lround(s[3] + d[3] * keep);
                    }
            }
        }
        freeType->SetScaleToPowerTwo(pot);
        if (textDims) {
            textDims[0] = w;
            textDims[1] = h;
        }
        return true;
    }

    bool StringToPath(const char*, vtkPath*, vtkTextProperty*, int) override { return false; }
    bool GetScaleToPowerOfTwo() override { return powerOfTwo_; }
    void SetScaleToPowerOfTwo(bool scale) override { powerOfTwo_ = scale; }

private:
    bool powerOfTwo_ = false;
};

vtkStandardNewMacro(MathTextUtilities);

} // namespace

void useMathText()
{
    static const bool installed = [] {
        vtkNew<MathTextUtilities> utilities;
        vtkMathTextUtilities::SetInstance(utilities);
        return true;
    }();
    (void)installed;
}

namespace {
const bool kInstalledAtStart = (useMathText(), true); // before any text actor makes VTK's text renderer
}

} // namespace viewpipe::gui
#pragma GCC diagnostic pop
