#include "viewpipe/report/stage_symbols.hpp"

#include "viewpipe/math_text.hpp"

namespace viewpipe::report {
namespace {

std::array<std::string, 16> translation(const std::string& x, const std::string& y, const std::string& z)
{
    return {"1", "0", "0", x, "0", "1", "0", y, "0", "0", "1", z, "0", "0", "0", "1"};
}

std::array<std::string, 16> diagonal(const std::string& x, const std::string& y, const std::string& z)
{
    return {x, "0", "0", "0", "0", y, "0", "0", "0", "0", z, "0", "0", "0", "0", "1"};
}

std::array<std::string, 16> shear(const std::string& x, const std::string& y)
{
    return {"1", "0", x, "0", "0", "1", y, "0", "0", "0", "1", "0", "0", "0", "0", "1"};
}

// OpenGL's clip coordinates to an API's whose depth runs from 0 to 1: z' = (±z + w)/2, and y' = y or -y.
std::array<std::string, 16> toZeroToOne(const std::string& y, const std::string& z)
{
    return {"1", "0", "0", "0", "0", y, "0", "0", "0", "0", z, "1/2", "0", "0", "0", "1"};
}

// An API's NDC stage: depth from 0 to 1 (reversed: from 1 to 0), y down or not.
SymbolicForm zeroToOneForm(bool reversed, bool yDown)
{
    const std::string y = yDown ? "-1" : "1", yNote = yDown ? ", $y' = -y$" : "";
    if (reversed)
        return {toZeroToOne(y, "-1/2"), {"$z' = (w - z) / 2$: near at 1, far at 0" + yNote}};
    return {toZeroToOne(y, "1/2"), {"$z' = (z + w) / 2$: near at 0, far at 1" + yNote}};
}

} // namespace

SymbolicForm symbolicMatrix(StageKind kind)
{
    const std::vector<std::string> dopShear = {
        "$\\mathit{sh}_x = -\\mathit{DOP}_x / \\mathit{DOP}_z$, $\\mathit{sh}_y = -\\mathit{DOP}_y / \\mathit{DOP}_z$",
        "$\\mathit{DOP} = \\mathit{CW} - \\mathit{PRP}$"};
    const std::string shx = "\\mathit{sh}_x", shy = "\\mathit{sh}_y";
    switch (kind) {
    case StageKind::TranslateVrp: return {translation("-\\mathit{VRP}_x", "-\\mathit{VRP}_y", "-\\mathit{VRP}_z"), {}};
    case StageKind::Rotate:
        return {{"u_x", "u_y", "u_z", "0", "v_x", "v_y", "v_z", "0", "n_x", "n_y", "n_z", "0", "0", "0", "0", "1"},
                {"$n = \\mathit{VPN} / |\\mathit{VPN}|$, $u = \\mathit{VUP} \\times n / |\\mathit{VUP} \\times n|$, "
                 "$v = n \\times u$"}};
    case StageKind::TranslatePrp: return {translation("-\\mathit{PRP}_u", "-\\mathit{PRP}_v", "-\\mathit{PRP}_n"), {}};
    case StageKind::ShearPerspective:
    case StageKind::ShearParallel: return {shear(shx, shy), dopShear};
    case StageKind::ScalePerspective:
        return {diagonal("s_x", "s_y", "s_z"),
                {"$s_x = 2 \\mathit{PRP}_n / ((u_{\\max} - u_{\\min})(\\mathit{PRP}_n - B))$",
                 "$s_y = 2 \\mathit{PRP}_n / ((v_{\\max} - v_{\\min})(\\mathit{PRP}_n - B))$",
                 "$s_z = 1 / (\\mathit{PRP}_n - B)$"}};
    case StageKind::TranslateParallel:
        return {translation("-c_u", "-c_v", "-F"),
                {"$(c_u, c_v) = ((u_{\\max} + u_{\\min})/2, (v_{\\max} + v_{\\min})/2) = \\mathit{CW}$"}};
    case StageKind::ScaleParallel:
        return {diagonal("s_x", "s_y", "s_z"),
                {"$s_x = 2 / (u_{\\max} - u_{\\min})$, $s_y = 2 / (v_{\\max} - v_{\\min})$, $s_z = 1 / (F - B)$"}};
    case StageKind::TranslateEye: return {translation("-\\mathit{eye}_x", "-\\mathit{eye}_y", "-\\mathit{eye}_z"), {}};
    case StageKind::RotateEye:
        return {{"s_x", "s_y", "s_z", "0", "u_x", "u_y", "u_z", "0", "-f_x", "-f_y", "-f_z", "0", "0", "0", "0", "1"},
                {"$f = (\\mathit{center} - \\mathit{eye}) / |\\mathit{center} - \\mathit{eye}|$, "
                 "$s = f \\times \\mathit{up} / |f \\times \\mathit{up}|$, $u = s \\times f$"}};
    case StageKind::ShearFrustum:
        return {shear(shx, shy), {"$\\mathit{sh}_x = (r + l) / 2n$, $\\mathit{sh}_y = (t + b) / 2n$"}};
    case StageKind::ScaleFrustum: return {diagonal("s_x", "s_y", "1"), {"$s_x = 2n / (r - l)$, $s_y = 2n / (t - b)$"}};
    case StageKind::ScaleFovy: return {diagonal("f / \\mathit{aspect}", "f", "1"), {"$f = \\cot(\\mathit{fovy} / 2)$"}};
    case StageKind::PerspectiveDepth:
        return {{"1", "0", "0", "0", "0", "1", "0", "0", "0", "0", "A", "B", "0", "0", "-1", "0"},
                {"$A = -(f + n) / (f - n)$, $B = -2fn / (f - n)$ ($f$ far, $n$ near)"}};
    case StageKind::TranslateOrtho: return {translation("-(l + r)/2", "-(b + t)/2", "(n + f)/2"), {}};
    case StageKind::ScaleOrtho: return {diagonal("2 / (r - l)", "2 / (t - b)", "-2 / (f - n)"), {}};
    case StageKind::FlipZ:
        return {diagonal("1", "1", "-1"), {"the left-handed eye's $+z$ becomes the $-z$ the projection expects"}};
    case StageKind::NdcReversed: return {diagonal("1", "1", "-1"), {"$z' = -z$: near at 1, far at $-1$"}};
    case StageKind::NdcDirect3d:
    case StageKind::NdcMetal:
    case StageKind::NdcWebgpu: return zeroToOneForm(false, false);
    case StageKind::NdcDirect3dReversed:
    case StageKind::NdcMetalReversed:
    case StageKind::NdcWebgpuReversed: return zeroToOneForm(true, false);
    case StageKind::NdcVulkan: return zeroToOneForm(false, true);
    case StageKind::NdcVulkanReversed: return zeroToOneForm(true, true);
    case StageKind::PerspectiveToParallel:
    case StageKind::Divide: return {};
    }
    return {};
}

std::string symbolicLatex(StageKind kind)
{
    const SymbolicForm form = symbolicMatrix(kind);
    if (form.cells[0].empty())
        return {};
    std::string rows;
    for (std::size_t r = 0; r < 4; ++r)
        for (std::size_t c = 0; c < 4; ++c)
            rows += form.cells[4 * r + c] + (c < 3 ? " & " : r < 3 ? " \\\\\n" : "\n");
    return stageSymbolMath(kind) + " = \\begin{bmatrix}\n" + rows + "\\end{bmatrix}";
}

} // namespace viewpipe::report
