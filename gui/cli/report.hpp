#pragma once

// The CLI's views of core results: human-readable tables and the JSON objects
// that scripts rely on (docs/cli.md). One place formats both, for every
// precision the CLI offers.

#include <nlohmann/json.hpp>

#include <ostream>
#include <string>

#include "viewpipe/scene.hpp"

namespace viewpipe::cli {

enum class Precision { Float, Double, LongDouble };

Precision parsePrecision(const std::string& name);
std::string precisionName(Precision precision);

nlohmann::json pipelineJson(const Scene& scene, Precision precision);
void printPipeline(std::ostream& out, const Scene& scene, Precision precision);

nlohmann::json traceJson(const Scene& scene, const Vec3<double>& point, Precision precision);
void printTrace(std::ostream& out, const Scene& scene, const Vec3<double>& point, Precision precision);

} // namespace viewpipe::cli
