#pragma once

// Counts what the evaluators do, through the test seam (evaluation_listener.hpp,
// heard while a ListeningToEvaluations lives): how many scenes they evaluated
// and mesh files they read.

#include "evaluation_listener.hpp"

namespace viewpipe::test {

struct EvaluationCount : EvaluationListener {
    long evaluations = 0, meshReads = 0;
    void evaluating(const Scene&) override { ++evaluations; }
    void readingMesh(const std::filesystem::path&) override { ++meshReads; }
};

} // namespace viewpipe::test
