#pragma once

// A seam for tests, outside the public headers: what the scene evaluators do,
// as they do it (each evaluation, each mesh file read past the cache), for a
// test that counts or slows it. Tests reach it through viewpipe_scene_seams.

#include <filesystem>

#include "viewpipe/scene.hpp"

namespace viewpipe {

class EvaluationListener {
public:
    virtual ~EvaluationListener() = default;
    virtual void evaluating(const Scene& /*scene*/) {}
    virtual void readingMesh(const std::filesystem::path& /*file*/) {}
};

// While it lives, `listener` hears every SceneEvaluator in the process (from
// any thread). One at a time.
class ListeningToEvaluations {
public:
    explicit ListeningToEvaluations(EvaluationListener& listener);
    ~ListeningToEvaluations();
    ListeningToEvaluations(const ListeningToEvaluations&) = delete;
    ListeningToEvaluations& operator=(const ListeningToEvaluations&) = delete;
};

} // namespace viewpipe
