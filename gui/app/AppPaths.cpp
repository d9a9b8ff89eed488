#include "AppPaths.h"

namespace viewpipe::gui {

namespace {
QString dataDirectory()
{
    const QByteArray data = qgetenv("VIEWPIPE_DATA");
    return data.isEmpty() ? QString(VIEWPIPE_DATA_DIR) : QString::fromLocal8Bit(data);
}
} // namespace

QString scenesDirectory()
{
    return dataDirectory() + "/scenes";
}

QString lessonsDirectory()
{
    return dataDirectory() + "/lessons";
}

} // namespace viewpipe::gui
