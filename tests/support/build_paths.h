#pragma once

// Where this build's files are, for the tests and benchmarks. The paths are
// compiled into build_paths.cpp alone: the programs' own objects are the same
// in every clone, so a fresh clone takes them from the compiler cache.

namespace viewpipe::build {

extern const char* const dataDir;        // data/: scenes, lessons, meshes
extern const char* const sourceDir;      // the source tree
extern const char* const viewpipeExe;    // the viewpipe program built
extern const char* const baselineDir;    // tests/baselines: reviewed pictures
extern const char* const newBaselineDir; // where a missing baseline is written for review

} // namespace viewpipe::build
