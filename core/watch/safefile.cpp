#include "safefile.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QSaveFile>
#include <QTemporaryFile>

#ifdef Q_OS_UNIX
#include <cerrno>
#include <cstring>
#include <unistd.h>
#endif

namespace Fatek::SafeFile {

QString writeAll(QFileDevice &file, const QByteArray &data)
{
    qint64 done = 0;
    while (done < data.size()) {
        const qint64 n = file.write(data.constData() + done, data.size() - done);
        if (n <= 0)
            return file.errorString();
        done += n;
    }
    if (!file.flush())
        return file.errorString();
    return {};
}

namespace {

// Why QSaveFile could not open `path`: the system's reason where Qt gives its own sentence
// ("Existing file ... is not writable" on a read-only medium).
QString openFailure(const QString &path, const QString &qtReason)
{
#ifdef Q_OS_UNIX
    const QFileInfo info(path);
    const QByteArray target
        = QFile::encodeName(info.exists() ? info.absoluteFilePath() : info.absolutePath());
    if (::access(target.constData(), W_OK) != 0)
        return QString::fromLocal8Bit(std::strerror(errno));
#else
    Q_UNUSED(path);
#endif
    return qtReason;
}

QString writeDirectly(const QString &path, const QByteArray &data)
{
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Unbuffered))
        return file.errorString();
    const QString reason = writeAll(file, data);
    file.close();
    return reason;
}

} // namespace

QString write(const QString &path, const QByteArray &data)
{
    const QFileInfo info(path);
    // QFileInfo follows links: a link to a device is a device.
    if (info.exists() && !info.isFile() && !info.isDir())
        return writeDirectly(path, data);
    QSaveFile file(path);
    // Unbuffered: each write reaches the system at once, so its result is the real one (a buffered
    // write that only fails when QSaveFile::commit() flushes is not reported by commit()).
    if (!file.open(QIODevice::WriteOnly | QIODevice::Unbuffered))
        return openFailure(path, file.errorString());
    if (QString reason = writeAll(file, data); !reason.isEmpty()) {
        file.cancelWriting();
        return reason;
    }
#ifdef Q_OS_UNIX
    // commit() syncs but ignores a failed sync; a disk that defers its "full" to the sync says
    // so here.
    if (::fsync(file.handle()) != 0) {
        const QString reason = QString::fromLocal8Bit(std::strerror(errno));
        file.cancelWriting();
        return reason;
    }
#endif
    if (!file.commit())
        return file.errorString();
    return {};
}

QString checkWritable(const QString &path)
{
    const QFileInfo info(path);
    if (info.isDir())
        return QStringLiteral("It is a folder");
    if (info.exists() && !info.isFile())
        return {}; // a device or a pipe: written directly, nothing to try beforehand
    const QString folder = info.absolutePath();
    QTemporaryFile probe(QDir(folder).filePath(QStringLiteral(".%1.XXXXXX").arg(info.fileName())));
    if (!probe.open())
        return openFailure(path, probe.errorString());
    return {};
}

} // namespace Fatek::SafeFile
