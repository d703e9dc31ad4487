#include "safefile.h"

#include <QFile>
#include <QFileInfo>
#include <QSaveFile>

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
        return file.errorString();
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

} // namespace Fatek::SafeFile
