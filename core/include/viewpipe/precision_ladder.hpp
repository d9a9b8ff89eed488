#pragma once

// The precision ladder of `viewpipe bench` and the app's Accuracy panel: for
// each tier, the time to build the normalizing matrices and to push vertices
// through them, and the errors of the accuracy metrics (accuracy.hpp) against
// an MPFR reference (256 bits, checked against 512 and against the exact
// composite of the scene as typed); last, the exact type's costs, whose errors
// are 0. The tiers compute from the scene's numbers as doubles, the exact type
// from the scene as typed (0.1 is one tenth). Its reports (JSON and
// text) are the report library's (viewpipe/report/bench.hpp).

#include <functional>
#include <string>
#include <vector>

#include "viewpipe/accuracy.hpp"
#include "viewpipe/scene.hpp"

namespace viewpipe {

struct BenchRow {
    std::string precision; // "float", ..., "mpfr", "exact"
    // bits and epsilon 0 for "exact"
    int bits = 0;          // significand bits
    double epsilon = 0;    // 2^(1 - bits)
    double buildNs = 0;    // per matrix build, median
    double vertexNs = 0;   // per vertex (transform and divide), median
    AccuracyMetrics errors;
};

struct BenchResult {
    std::string reference; // e.g. "mpfr-256 (agrees with mpfr-512 to 3.3e-80)"
    // Where the corners and the round trip are measured: "the view volume", or
    // for an infinite far plane the part of it up to a stand-in far plane.
    std::string volume = "the view volume";
    std::size_t vertices = 0;
    Viewport viewport;
    std::vector<BenchRow> rows;
};

struct BenchOptions {
    std::size_t vertices = 1000000;
    unsigned mpfrBits = 160;
    Viewport viewport;
};

// Called before each tier with its name; return false to stop early.
using BenchProgress = std::function<bool(int done, int total, const std::string& tier)>;

// sceneVertices: the scene's object vertices in world coordinates (for the
// NDC and pixel errors). Throws InputError for bad options.
BenchResult runBench(const Scene& scene, const std::vector<Vec3<double>>& sceneVertices, const BenchOptions& options,
                     const BenchProgress& progress = {});

} // namespace viewpipe
