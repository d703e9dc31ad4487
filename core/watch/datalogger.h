#pragma once

#include "core/protocol/result.h"
#include "core/session/watchvalue.h"
#include "csvfile.h"
#include "watchlist.h"

#include <QDateTime>
#include <QElapsedTimer>
#include <QFile>
#include <QList>
#include <QString>
#include <QStringList>

#include <cstdint>
#include <optional>

namespace Fatek {

// Writes watch values to a CSV data log, one row per poll cycle:
//
//   timestamp,Sine (R1),R0,Y0,status
//   2026-11-23T10:35:31.458+01:00,-309,50,1,ok
//   2026-11-23T10:35:31.958+01:00,,100,0,stale Sine (R1) (timeout)
//   2026-11-23T10:35:32.458+01:00,,,,error all items (no link: connection refused)
//
// - timestamp: ISO 8601 local time with milliseconds and the UTC offset (no ambiguity at DST).
// - one column per item, headed "name (address)" or the address alone; a station other than 1
//   is added as "address@station".
// - values in the item's display format (signed, hex, float, ...); bits as 1/0 so spreadsheets
//   can plot them.
// - the same address twice (two formats): those columns say their format, "R0 [signed]",
//   "R0 [hex]"; without such a clash the header is as above.
// - a value that is not fresh (stale, refused, not read) is never written: its cell stays empty
//   and the last column, status, says which items and why, each cause once per row:
//   "stale R1, R2 (timeout); error R9 (PLC error A)", or "error all items (reason)" when no
//   item is fresh for one cause (the link is down); "ok" when every cell is fresh.
//
// The file is opened for appending: an empty or new file gets the byte order mark (UTF-8 for
// Excel) and the header, its lines ended as open() is asked (LF or CRLF); an existing log must
// have the same header (else open() refuses rather than mixing columns) and keeps its own line
// ends (those of its first line), never a second mark. A device or a named pipe
// is written only (no header check, no mark). Each row is written unbuffered and checked
// (SafeFile::writeAll): a failed write (disk full, removed medium) is returned by that row's
// writeRow with the system's reason, closes the log, and every later call returns that error.
// A row is whole or absent: what part of a failed row reached a file is cut off again, an
// existing log's cut last row is dropped before appending, and a new log whose header does not
// fit is removed (no empty file is left).
// flushIntervalMs is kept for the callers; the rows reach the system as they are written.
class DataLogger
{
public:
    enum class Quality { Good, Late, Stale, Error, Missing };
    struct Cell
    {
        std::uint64_t raw = 0;
        Quality quality = Quality::Missing;
        QString reason; // why not Good (optional)
    };

    DataLogger() = default;
    ~DataLogger();
    DataLogger(const DataLogger &) = delete;
    DataLogger &operator=(const DataLogger &) = delete;

    // `lineEnd`: a new file's line ends (an existing log keeps its own).
    Status open(const QString &path, const QList<WatchItemSpec> &items,
                CsvFile::LineEnd lineEnd = CsvFile::LineEnd::Lf);
    // One row; cells in the order of the items given to open(). Fewer cells count as Missing.
    Status writeRow(const QDateTime &time, const QList<Cell> &cells);
    Status flush();
    // Flushes and closes; returns the flush's outcome. Harmless when not open.
    Status close();

    bool isOpen() const { return m_file.isOpen(); }
    // A write failed (disk full, removed medium): the log is closed, every call returns why.
    bool writeFailed() const { return m_failure.has_value(); }
    // The last open() failed on the file system (no such folder, not writable, a folder, a full
    // disk), not on the items or on another log's columns in the file.
    bool fileProblem() const { return m_fileProblem; }
    QString path() const { return m_path; }
    qint64 rowCount() const { return m_rows; }
    QStringList columns() const { return m_columns; }
    // The open log's line ends: as asked for a new file, as found in an existing one.
    CsvFile::LineEnd lineEnd() const { return m_lineEnd; }
    // 0: flush after every row.
    void setFlushIntervalMs(int ms) { m_flushIntervalMs = ms; }

    // "2026-11-23T10:35:31.458+01:00" (local time with its offset).
    static QString timestampText(const QDateTime &time);
    // The text of one value: bits as 1/0, else ValueFormat::format.
    static QString valueText(const WatchItemSpec &item, std::uint64_t raw);
    static QString columnName(const WatchItemSpec &item);
    // The item columns' headers: columnName, unless two items would get the same header (one
    // address in two formats): then each of those says its format, "R0 [signed]", "R0 [hex]"
    // (and the same item twice in one format is numbered: "R0 [hex] #2").
    static QStringList columnNames(const QList<WatchItemSpec> &items);
    static QString csvCell(const QString &text);
    static QString qualityName(Quality quality);
    // A value's quality as a cell's (the table, the CLI and the data log say the same).
    static Quality qualityOf(ValueQuality quality);
    // The header line and one row line (without line end), as open() and writeRow() write them;
    // for output that is not a file (fatek-cli monitor --csv on stdout).
    static QString headerLine(const QList<WatchItemSpec> &items);
    static QString rowLine(const QDateTime &time, const QList<WatchItemSpec> &items,
                           const QList<Cell> &cells);

private:
    Status fail(const QString &what, const QString &reason);

    QFile m_file;
    QString m_path;
    QList<WatchItemSpec> m_items;
    QStringList m_columns;
    CsvFile::LineEnd m_lineEnd = CsvFile::LineEnd::Lf;
    qint64 m_rows = 0;
    int m_flushIntervalMs = 1000;
    QElapsedTimer m_sinceFlush;
    std::optional<ProtocolError> m_failure;
    bool m_fileProblem = false;
};

} // namespace Fatek
