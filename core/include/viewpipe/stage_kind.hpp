#pragma once

#include <optional>
#include <string>
#include <vector>

namespace viewpipe {

// What a stage of a normalizing transformation does, whatever its numbers.
// Each kind's names and whether it divides are one row of one table
// (stage_kind.cpp): callers ask the kind, never compare its symbol.
enum class StageKind {
    // Foley's (CGPP 6.5): T(-VRP), R, then T(-PRP), SH_per, S_per or SH_par, T_par, S_par; M with the divide
    TranslateVrp,
    Rotate,
    TranslatePrp,
    ShearPerspective,
    ScalePerspective,
    ShearParallel,
    TranslateParallel,
    ScaleParallel,
    PerspectiveToParallel,
    // OpenGL's: T(-eye), R_eye, Z_flip (left-handed), then T_ortho, S_ortho or SH_frustum, S_frustum or S_fovy,
    // P_depth
    TranslateEye,
    RotateEye,
    FlipZ,
    TranslateOrtho,
    ScaleOrtho,
    ShearFrustum,
    ScaleFrustum,
    ScaleFovy,
    PerspectiveDepth,
    // OpenGL's clip coordinates to an API's (gl::ndcStageKind)
    NdcReversed,
    NdcDirect3d,
    NdcDirect3dReversed,
    NdcVulkan,
    NdcVulkanReversed,
    NdcMetal,
    NdcMetalReversed,
    NdcWebgpu,
    NdcWebgpuReversed,
    // (x, y, z, w) -> (x/w, y/w, z/w, 1): no matrix
    Divide,
};

// Every kind, in the order declared.
std::vector<StageKind> stageKinds();

// "T(-VRP)", "SH_per", "NDC_vulkan_reversed": a stable interface (reports, scripts, lesson answers).
std::string stageSymbol(StageKind kind);
// The symbol as math (math_text.hpp's subset, without $): "\mathit{SH}_{\mathrm{per}}", "T(-\mathit{VRP})".
std::string stageSymbolMath(StageKind kind);
// "t-vrp", "sh-per": the stage's part of its file names.
std::string stageSlug(StageKind kind);
// Whether the stage is the divide by w rather than a matrix.
bool stageDivides(StageKind kind);
// The kind whose symbol this is; nothing for a symbol no stage has.
std::optional<StageKind> stageKindNamed(const std::string& symbol);

} // namespace viewpipe
