#include "viewpipe/stage_kind.hpp"

#include <cstddef>
#include <iterator>

namespace viewpipe {
namespace {

struct StageKindNames {
    StageKind kind;
    const char* symbol;
    const char* latex;
    const char* slug;
    bool divides;
};

// A subscript of one word is upright (\mathrm), of two words prose (\text); a name longer than a letter italic
// (\mathit); an API as people name it.
constexpr StageKindNames kStageKinds[] = {
    {StageKind::TranslateVrp, "T(-VRP)", "T(-\\mathit{VRP})", "t-vrp", false},
    {StageKind::Rotate, "R", "R", "r", false},
    {StageKind::TranslatePrp, "T(-PRP)", "T(-\\mathit{PRP})", "t-prp", false},
    {StageKind::ShearPerspective, "SH_per", "\\mathit{SH}_{\\mathrm{per}}", "sh-per", false},
    {StageKind::ScalePerspective, "S_per", "S_{\\mathrm{per}}", "s-per", false},
    {StageKind::ShearParallel, "SH_par", "\\mathit{SH}_{\\mathrm{par}}", "sh-par", false},
    {StageKind::TranslateParallel, "T_par", "T_{\\mathrm{par}}", "t-par", false},
    {StageKind::ScaleParallel, "S_par", "S_{\\mathrm{par}}", "s-par", false},
    {StageKind::PerspectiveToParallel, "M", "M", "m", false},
    {StageKind::TranslateEye, "T(-eye)", "T(-\\mathit{eye})", "t-eye", false},
    {StageKind::RotateEye, "R_eye", "R_{\\mathrm{eye}}", "r-eye", false},
    {StageKind::FlipZ, "Z_flip", "Z_{\\mathrm{flip}}", "z-flip", false},
    {StageKind::TranslateOrtho, "T_ortho", "T_{\\mathrm{ortho}}", "t-ortho", false},
    {StageKind::ScaleOrtho, "S_ortho", "S_{\\mathrm{ortho}}", "s-ortho", false},
    {StageKind::ShearFrustum, "SH_frustum", "\\mathit{SH}_{\\mathrm{frustum}}", "sh-frustum", false},
    {StageKind::ScaleFrustum, "S_frustum", "S_{\\mathrm{frustum}}", "s-frustum", false},
    {StageKind::ScaleFovy, "S_fovy", "S_{\\mathrm{fovy}}", "s-fovy", false},
    {StageKind::PerspectiveDepth, "P_depth", "P_{\\mathrm{depth}}", "p-depth", false},
    {StageKind::NdcReversed, "NDC_reversed", "\\mathit{NDC}_{\\mathrm{reversed}}", "ndc-reversed", false},
    {StageKind::NdcDirect3d, "NDC_direct3d", "\\mathit{NDC}_{\\mathrm{Direct3D}}", "ndc-direct3d", false},
    {StageKind::NdcDirect3dReversed, "NDC_direct3d_reversed", "\\mathit{NDC}_{\\text{Direct3D, reversed}}",
     "ndc-direct3d-reversed", false},
    {StageKind::NdcVulkan, "NDC_vulkan", "\\mathit{NDC}_{\\mathrm{Vulkan}}", "ndc-vulkan", false},
    {StageKind::NdcVulkanReversed, "NDC_vulkan_reversed", "\\mathit{NDC}_{\\text{Vulkan, reversed}}",
     "ndc-vulkan-reversed", false},
    {StageKind::NdcMetal, "NDC_metal", "\\mathit{NDC}_{\\mathrm{Metal}}", "ndc-metal", false},
    {StageKind::NdcMetalReversed, "NDC_metal_reversed", "\\mathit{NDC}_{\\text{Metal, reversed}}",
     "ndc-metal-reversed", false},
    {StageKind::NdcWebgpu, "NDC_webgpu", "\\mathit{NDC}_{\\mathrm{WebGPU}}", "ndc-webgpu", false},
    {StageKind::NdcWebgpuReversed, "NDC_webgpu_reversed", "\\mathit{NDC}_{\\text{WebGPU, reversed}}",
     "ndc-webgpu-reversed", false},
    {StageKind::Divide, "divide", "\\mathit{divide}", "divide", true},
};

// Row k is kind k, so a kind finds its row by its value.
constexpr bool inDeclaredOrder()
{
    for (std::size_t k = 0; k < std::size(kStageKinds); ++k)
        if (kStageKinds[k].kind != StageKind(k))
            return false;
    return std::size(kStageKinds) == std::size_t(StageKind::Divide) + 1;
}
static_assert(inDeclaredOrder(), "kStageKinds lists every StageKind once, in the order declared");

constexpr const StageKindNames& names(StageKind kind)
{
    return kStageKinds[std::size_t(kind)];
}

} // namespace

std::vector<StageKind> stageKinds()
{
    std::vector<StageKind> kinds;
    for (const StageKindNames& row : kStageKinds)
        kinds.push_back(row.kind);
    return kinds;
}

std::string stageSymbol(StageKind kind)
{
    return names(kind).symbol;
}

std::string stageSymbolMath(StageKind kind)
{
    return names(kind).latex;
}

std::string stageSlug(StageKind kind)
{
    return names(kind).slug;
}

bool stageDivides(StageKind kind)
{
    return names(kind).divides;
}

std::optional<StageKind> stageKindNamed(const std::string& symbol)
{
    for (const StageKindNames& row : kStageKinds)
        if (symbol == row.symbol)
            return row.kind;
    return std::nullopt;
}

} // namespace viewpipe
