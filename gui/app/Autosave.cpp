#include "Autosave.h"

#include <QDir>
#include <QFile>
#include <QStandardPaths>
#include <QUuid>

#include "Document.h"
#include "viewpipe/scene.hpp"

namespace viewpipe::gui {
namespace {

constexpr int kIntervalMilliseconds = 5000;

// One session's files share a name: NAME.json (the scene), NAME.source (the
// path it was edited from) and NAME.lock.
QString withSuffix(const QString& scenePath, const QString& suffix)
{
    return scenePath.left(scenePath.size() - int(QStringLiteral(".json").size())) + suffix;
}

} // namespace

Autosave::Autosave(Document* document, QObject* parent) : QObject(parent), document_(document)
{
    timer_.setInterval(kIntervalMilliseconds);
    connect(&timer_, &QTimer::timeout, this, &Autosave::saveNow);
    connect(document_, &Document::changed, this, &Autosave::onChanged);
    connect(document_, &Document::fileChanged, this, &Autosave::onChanged);
}

Autosave::~Autosave()
{
    remove();
}

QString Autosave::folder()
{
    return QStandardPaths::writableLocation(QStandardPaths::AppLocalDataLocation) + "/autosave";
}

void Autosave::onChanged()
{
    pending_ = document_->isModified();
    if (!pending_) {
        remove(); // saved, or back to the saved state: nothing to recover
        return;
    }
    if (!timer_.isActive())
        timer_.start();
}

void Autosave::saveNow()
{
    if (!document_->isModified()) { // saved, undone or another scene opened since the edit
        remove();
        return;
    }
    if (!pending_)
        return;
    if (!lock_) {
        QDir().mkpath(folder());
        scenePath_ = folder() + "/" + QUuid::createUuid().toString(QUuid::WithoutBraces) + ".json";
        lock_ = std::make_unique<QLockFile>(withSuffix(scenePath_, ".lock"));
        lock_->setStaleLockTime(0); // held for the life of the process, however long
        if (!lock_->tryLock(0)) {
            lock_.reset();
            return;
        }
    }
    try {
        const QString source = document_->filePath();
        if (source != sourcePath_ || !QFile::exists(withSuffix(scenePath_, ".source"))) {
            writeFileAtomically(withSuffix(scenePath_, ".source").toStdString(), source.toStdString());
            sourcePath_ = source;
        }
        saveScene(document_->scene(), scenePath_.toStdString());
        pending_ = false;
        timer_.stop();
    } catch (const std::exception&) {
        // A full disk must not interrupt the lecture: the timer tries again.
    }
}

void Autosave::remove()
{
    timer_.stop();
    pending_ = false;
    if (!lock_)
        return;
    QFile::remove(scenePath_);
    QFile::remove(withSuffix(scenePath_, ".source"));
    lock_->unlock();
    lock_.reset();
    sourcePath_.clear();
}

std::vector<AutosavedScene> Autosave::orphans()
{
    std::vector<AutosavedScene> found;
    const QDir dir(folder());
    for (const QFileInfo& info : dir.entryInfoList({"*.json"}, QDir::Files, QDir::Time)) {
        AutosavedScene scene{info.absoluteFilePath(), {}, withSuffix(info.absoluteFilePath(), ".lock")};
        // QLockFile takes over a lock whose process is gone; a live session's stays refused.
        QLockFile lock(scene.lockPath);
        lock.setStaleLockTime(0); // stale only when its process is gone, however old
        if (!lock.tryLock(0))
            continue;
        lock.unlock();
        QFile source(withSuffix(scene.scenePath, ".source"));
        if (source.open(QIODevice::ReadOnly))
            scene.sourcePath = QString::fromUtf8(source.readAll());
        found.push_back(scene);
    }
    return found;
}

void Autosave::discard(const AutosavedScene& scene)
{
    QFile::remove(scene.scenePath);
    QFile::remove(withSuffix(scene.scenePath, ".source"));
    QFile::remove(scene.lockPath);
}

} // namespace viewpipe::gui
