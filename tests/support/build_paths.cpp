#include "build_paths.h"

namespace viewpipe::build {

const char* const dataDir = VIEWPIPE_DATA_DIR;
const char* const sourceDir = VIEWPIPE_SOURCE_DIR;
const char* const viewpipeExe = VIEWPIPE_EXE;
const char* const baselineDir = VIEWPIPE_BASELINE_DIR;
const char* const newBaselineDir = VIEWPIPE_NEW_BASELINE_DIR;

} // namespace viewpipe::build
