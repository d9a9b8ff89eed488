#pragma once

// Counts what an evaluator does, through its listener (evaluated_scene.hpp):
// how many scenes it evaluated and mesh files it read.

#include "viewpipe/evaluated_scene.hpp"

namespace viewpipe::test {

struct EvaluationCount : EvaluationListener {
    long evaluations = 0, meshReads = 0;
    void evaluating(const Scene&) override { ++evaluations; }
    void readingMesh(const std::filesystem::path&) override { ++meshReads; }
};

} // namespace viewpipe::test
