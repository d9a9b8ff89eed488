// The drawing half of `viewpipe bench`: its --plot.

#include "drawing_commands.hpp"
#include "export/AccuracyPlot.h"
#include "export/VirtualDisplay.h"

namespace viewpipe::commands {

void writeBenchPlot(const BenchResult& result, const std::string& file)
{
    const gui::VirtualDisplay display;
    gui::writeAccuracyPlot(result, file, report::Theme::Light);
}

} // namespace viewpipe::commands
