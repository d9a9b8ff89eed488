#pragma once

// How a saved file (a lesson, a scene) names another file it points at.

#include <filesystem>

namespace viewpipe {

// `file` as named from `folder`: relative where the two share a folder below
// the file system's root (they are moved together), else absolute (a path up
// through the root, "../../work/...", breaks as soon as either moves).
inline std::filesystem::path pathFrom(const std::filesystem::path& folder, const std::filesystem::path& file)
{
    namespace fs = std::filesystem;
    const fs::path to = fs::weakly_canonical(fs::absolute(file)), from = fs::weakly_canonical(fs::absolute(folder));
    int shared = 0; // components in common, the root itself one of them
    for (auto a = to.begin(), b = from.begin(); a != to.end() && b != from.end() && *a == *b; ++a, ++b)
        ++shared;
    return shared > 1 ? to.lexically_relative(from) : to;
}

} // namespace viewpipe
