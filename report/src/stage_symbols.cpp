#include "viewpipe/report/stage_symbols.hpp"

#include <map>

namespace viewpipe {
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
    return {"1", "0", "0", "0", "0", y, "0", "0", "0", "0", z, "½", "0", "0", "0", "1"};
}

} // namespace

SymbolicForm symbolicMatrix(const std::string& symbol)
{
    static const std::map<std::string, SymbolicForm> forms = [] {
        const std::vector<std::string> dopShear = {"shx = −DOPx / DOPz,  shy = −DOPy / DOPz", "DOP = CW − PRP"};
        std::map<std::string, SymbolicForm> out = {
            {"T(-VRP)", {translation("−VRPx", "−VRPy", "−VRPz"), {}}},
            {"R",
             {{"ux", "uy", "uz", "0", "vx", "vy", "vz", "0", "nx", "ny", "nz", "0", "0", "0", "0", "1"},
              {"n = VPN / |VPN|,  u = VUP × n / |VUP × n|,  v = n × u"}}},
            {"T(-PRP)", {translation("−PRPu", "−PRPv", "−PRPn"), {}}},
            {"SH_per", {shear("shx", "shy"), dopShear}},
            {"SH_par", {shear("shx", "shy"), dopShear}},
            {"S_per",
             {diagonal("sx", "sy", "sz"),
              {"sx = 2 PRPn / ((umax − umin)(PRPn − B))", "sy = 2 PRPn / ((vmax − vmin)(PRPn − B))",
               "sz = 1 / (PRPn − B)"}}},
            {"T_par", {translation("−cu", "−cv", "−F"), {"(cu, cv) = ((umax + umin)/2, (vmax + vmin)/2) = CW"}}},
            {"S_par",
             {diagonal("sx", "sy", "sz"), {"sx = 2 / (umax − umin),  sy = 2 / (vmax − vmin),  sz = 1 / (F − B)"}}},
            {"T(-eye)", {translation("−eyex", "−eyey", "−eyez"), {}}},
            {"R_eye",
             {{"sx", "sy", "sz", "0", "ux", "uy", "uz", "0", "−fx", "−fy", "−fz", "0", "0", "0", "0", "1"},
              {"f = (center − eye) / |center − eye|,  s = f × up / |f × up|,  u = s × f"}}},
            {"SH_frustum", {shear("shx", "shy"), {"shx = (r + l) / 2n,  shy = (t + b) / 2n"}}},
            {"S_frustum", {diagonal("sx", "sy", "1"), {"sx = 2n / (r − l),  sy = 2n / (t − b)"}}},
            {"S_fovy", {diagonal("f / aspect", "f", "1"), {"f = cot(fovy / 2)"}}},
            {"P_depth",
             {{"1", "0", "0", "0", "0", "1", "0", "0", "0", "0", "A", "B", "0", "0", "−1", "0"},
              {"A = −(f + n) / (f − n),  B = −2fn / (f − n)  (f = far, n = near)"}}},
            {"T_ortho", {translation("−(l + r)/2", "−(b + t)/2", "(n + f)/2"), {}}},
            {"S_ortho", {diagonal("2 / (r − l)", "2 / (t − b)", "−2 / (f − n)"), {}}},
            {"Z_flip", {diagonal("1", "1", "−1"), {"the left-handed eye's +z becomes the −z the projection expects"}}},
            {"NDC_reversed", {diagonal("1", "1", "−1"), {"z' = −z: near at 1, far at −1"}}},
        };
        for (const std::string api : {"direct3d", "metal", "webgpu", "vulkan"}) {
            const std::string y = api == "vulkan" ? "−1" : "1";
            const std::string yNote = api == "vulkan" ? ",  y' = −y" : "";
            out["NDC_" + api] = {toZeroToOne(y, "½"), {"z' = (z + w) / 2: near at 0, far at 1" + yNote}};
            out["NDC_" + api + "_reversed"] = {toZeroToOne(y, "−½"), {"z' = (w − z) / 2: near at 1, far at 0" + yNote}};
        }
        return out;
    }();
    const auto form = forms.find(symbol);
    return form == forms.end() ? SymbolicForm{} : form->second;
}

} // namespace viewpipe
