#pragma once

// Small files the GUI tests write.

#include <QByteArray>
#include <QFile>
#include <QString>

// Writes `bytes` to `path`, replacing it; false if it cannot.
inline bool writeFile(const QString& path, const QByteArray& bytes)
{
    QFile file(path);
    return file.open(QIODevice::WriteOnly) && file.write(bytes) == bytes.size();
}
