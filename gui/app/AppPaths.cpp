#include "AppPaths.h"

namespace viewpipe::gui {

QString scenesDirectory()
{
    const QByteArray data = qgetenv("VIEWPIPE_DATA");
    return (data.isEmpty() ? QString(VIEWPIPE_DATA_DIR) : QString::fromLocal8Bit(data)) + "/scenes";
}

} // namespace viewpipe::gui
