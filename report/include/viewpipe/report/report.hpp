#pragma once

// The CLI's views of core results: human-readable tables and the JSON objects
// that scripts rely on (docs/cli.md). One place formats both, for every
// precision the CLI offers.

#include <nlohmann/json.hpp>

#include <ostream>
#include <string>

#include "viewpipe/exact.hpp"
#include "viewpipe/scene.hpp"

namespace viewpipe::report {

enum class Precision { Float, Double, LongDouble, Float128, Mpfr, Exact };

// "float", "double", "long-double", "float128", "mpfr" (with mpfrBits), "exact".
struct PrecisionChoice {
    Precision type = Precision::Double;
    unsigned mpfrBits = 256;
};

PrecisionChoice parsePrecision(const std::string& name, unsigned mpfrBits = 256);
std::string precisionName(const PrecisionChoice& precision);

// With effects listed, "effects" reports `outcomes` (the evaluated scene's).
nlohmann::json pipelineJson(const Scene& scene, const PrecisionChoice& precision, const EffectOutcomes& outcomes);
void printPipeline(std::ostream& out, const Scene& scene, const PrecisionChoice& precision,
                   const EffectOutcomes& outcomes);

// The point as typed (exact); its verdict (inside, on which planes) is decided
// exactly for the scene as typed, in every precision.
nlohmann::json traceJson(const Scene& scene, const Vec3<Exact>& point, const PrecisionChoice& precision);
void printTrace(std::ostream& out, const Scene& scene, const Vec3<Exact>& point, const PrecisionChoice& precision);

// `viewpipe trace --api all|NAME`: the point through the scene's camera
// numbers under every API (or the one named), handedness and depth: clip
// coordinates, NDC, and window coordinates in a width x height viewport.
// Throws InputError("--api") for a Foley view or an unknown API.
nlohmann::json apiTraceJson(const Scene& scene, const Vec3<double>& point, const std::string& api, int width,
                            int height);
void printApiTrace(std::ostream& out, const Scene& scene, const Vec3<double>& point, const std::string& api,
                   int width, int height);

// `viewpipe classify`: the classical projection a scene's camera realizes.
nlohmann::json classifyJson(const Scene& scene);
void printClassification(std::ostream& out, const Scene& scene);

} // namespace viewpipe::report
