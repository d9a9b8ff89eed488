#include "AppPaths.h"

#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QSettings>
#include <QStandardPaths>

namespace viewpipe::gui {

namespace {
QString dataDirectory()
{
    const QByteArray data = qgetenv("VIEWPIPE_DATA");
    return data.isEmpty() ? QString(VIEWPIPE_DATA_DIR) : QString::fromLocal8Bit(data);
}

constexpr const char* kDialogFolderKey = "dialogFolder";
} // namespace

QString scenesDirectory()
{
    return dataDirectory() + "/scenes";
}

QString lessonsDirectory()
{
    return dataDirectory() + "/lessons";
}

QString dialogPath(const QString& name)
{
    QString folder = QSettings().value(kDialogFolderKey).toString();
    if (folder.isEmpty() || !QDir(folder).exists())
        folder = QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation);
    if (folder.isEmpty() || !QDir(folder).exists()) // Qt's dialog takes a missing folder for a file's name
        folder = QDir::homePath();
    return name.isEmpty() ? folder : QDir(folder).filePath(name);
}

void rememberDialogFolder(const QString& chosen)
{
    if (!chosen.isEmpty())
        QSettings().setValue(kDialogFolderKey, QFileInfo(chosen).absolutePath());
}

QString chooseFileToOpen(QWidget* parent, const QString& title, const QString& filter)
{
    const QString path = QFileDialog::getOpenFileName(parent, title, dialogPath(), filter);
    rememberDialogFolder(path);
    return path;
}

bool isBuiltInFile(const QString& path)
{
    return QFileInfo(path).absoluteFilePath().startsWith(QDir(dataDirectory()).absolutePath() + "/");
}

QString chooseFileToSave(QWidget* parent, const QString& title, const QString& suggested, const QString& filter)
{
    // A document's own file stays where it is; a built-in one is a starting point, saved among the user's files.
    const QFileInfo file(suggested);
    const bool own = file.isAbsolute() && !isBuiltInFile(suggested);
    const QString path = QFileDialog::getSaveFileName(parent, title, own ? suggested : dialogPath(file.fileName()), filter);
    rememberDialogFolder(path);
    return path;
}

} // namespace viewpipe::gui
