#pragma once

#include <QByteArray>
#include <QString>

class QFileDevice;

namespace Fatek::SafeFile {

// Writes a whole file so that nothing half-written can pass as saved: the one place every writer
// of the project (program backups, snapshots, watch lists, CSV exports, the raw console's traffic)
// goes through.
//
// - A regular file (or a new one) is written to a temporary file beside it, every write checked,
//   flushed and synced (fsync), then renamed over the old one (QSaveFile). On any failure the
//   temporary file is removed and the old file stays as it was.
// - A path that exists and is not a regular file (a device such as /dev/full or /dev/stdout, a
//   named pipe) is never replaced: it is opened and written directly, every write checked.
//
// Returns an empty text when the file is written, else the reason from the system in its words
// ("No space left on device"), for the caller's sentence that names the file.
QString write(const QString &path, const QByteArray &data);

// Whether write() could write `path`, found out without changing it: a regular file's folder
// takes a new file (one is created and removed at once), a device or pipe is taken as it is.
// Empty when it could, else the system's reason ("No such file or directory", "Read-only file
// system", "Not a directory"). For files written at the end of a long job (a checkout's report):
// the job is refused before it starts rather than its result lost.
QString checkWritable(const QString &path);

// Writes all of `data` to an open file (best opened Unbuffered, so each write reaches the system
// and its result is the real one), then flushes it. A short write (the disk took what fit) is
// retried, and the retry gives the system's error. Empty when written, else the reason. For the
// data log, which appends row by row.
QString writeAll(QFileDevice &file, const QByteArray &data);

} // namespace Fatek::SafeFile
