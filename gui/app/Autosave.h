#pragma once

// Unsaved changes survive a crash: while the document has unsaved edits, its
// scene is written every few seconds to the user's data folder, beside a lock
// held for the life of the process. A scene whose lock is stale (its process
// died) is offered for recovery at the next start.

#include <QLockFile>
#include <QObject>
#include <QString>
#include <QTimer>

#include <memory>
#include <vector>

namespace viewpipe::gui {

class Document;

struct AutosavedScene {
    QString scenePath;  // the autosaved scene
    QString sourcePath; // the file it was edited from; empty for an untitled scene
    QString lockPath;
};

class Autosave : public QObject {
    Q_OBJECT
public:
    explicit Autosave(Document* document, QObject* parent = nullptr);
    // A clean exit leaves nothing behind.
    ~Autosave() override;

    void setIntervalMilliseconds(int milliseconds) { timer_.setInterval(milliseconds); }
    // Writes now if there are unsaved changes (the timer calls it).
    void saveNow();
    QString scenePath() const { return scenePath_; }

    // $XDG_DATA_HOME/ViewPipe/autosave (or the platform's equivalent).
    static QString folder();
    // Scenes left by processes that ended without closing: their locks are stale.
    static std::vector<AutosavedScene> orphans();
    static void discard(const AutosavedScene& scene);

private:
    void onChanged();
    void remove();

    Document* document_;
    QTimer timer_;
    QString scenePath_;
    QString sourcePath_;
    std::unique_ptr<QLockFile> lock_;
    bool pending_ = false;
};

} // namespace viewpipe::gui
