#pragma once

// CSV text as the bytes of a file: the one place that decides how every CSV file the programs
// write is encoded, so that Excel on Windows opens each of them right (UTF-8 with a byte order
// mark, which Excel needs to read UTF-8; Windows line ends when asked). Text for a pipe or a
// terminal (fatek-cli's --csv on stdout) is not a file: it stays plain UTF-8, without the mark.

#include <QByteArray>
#include <QString>

namespace Fatek::CsvFile {

enum class LineEnd { Lf, CrLf };

// The UTF-8 byte order mark.
inline constexpr char Bom[] = "\xEF\xBB\xBF";

// The file's bytes: the byte order mark, then `text` (lines ended with '\n') as UTF-8, each '\n'
// made "\r\n" for CrLf (a "\r\n" already in the text stays one).
QByteArray bytes(const QString &text, LineEnd lineEnd);
// The same for text without the mark (a line appended to an existing file).
QByteArray lines(const QString &text, LineEnd lineEnd);

// The line end of a file's first line (an existing data log appended to keeps its own); Lf
// without any line end.
LineEnd lineEndOf(const QByteArray &firstLine);

} // namespace Fatek::CsvFile
