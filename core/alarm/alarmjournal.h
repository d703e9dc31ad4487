#pragma once

#include "alarmtypes.h"

#include "core/protocol/result.h"
#include "core/watch/csvfile.h"

#include <QList>
#include <QString>

#include <memory>

struct sqlite3;
struct sqlite3_stmt;

namespace Fatek {

// The alarm journal: one SQLite file (WAL) with every event (raise, acknowledge with who and a
// comment, return, shelve, unshelve, out of service) and each alarm's last state, so that active
// alarms come back after a restart. Synchronous and single-threaded: the studio and the gateway
// use it through AlarmJournalWriter (its own thread); fatek-cli reads it directly.
class AlarmJournal
{
public:
    ~AlarmJournal();
    AlarmJournal(const AlarmJournal &) = delete;
    AlarmJournal &operator=(const AlarmJournal &) = delete;

    // Opens or creates the file (its folder too) and its tables. A file that is not a journal,
    // damaged, locked by another program or not writable is refused with the reason; a file that
    // is not a journal is never changed.
    static Result<std::unique_ptr<AlarmJournal>> open(const QString &path);
    // Opens an existing journal to read (fatek-cli alarms --journal).
    static Result<std::unique_ptr<AlarmJournal>> openReadOnly(const QString &path);

    QString path() const { return m_path; }

    // One transaction: the events appended, each record's state replaced (upsert by connection and
    // alarm id; a Normal record is removed).
    Status append(const QList<AlarmEvent> &events, const QList<AlarmRecord> &records);
    // The kept states (of one connection, or every one when empty).
    Result<QList<AlarmRecord>> states(const QString &connection = {}) const;
    // Events with fromMs <= time < toMs, oldest first (of one connection, or every one).
    Result<QList<AlarmEvent>> events(qint64 fromMs, qint64 toMs,
                                     const QString &connection = {}) const;

    // CSV with a header row: time (local, ISO 8601 with the UTC offset kept with the event),
    // connection, alarm, kind, event, state, priority, group, message, value, user, comment,
    // shelved until.
    static QByteArray toCsv(const QList<AlarmEvent> &events);
    // The same as the bytes of a CSV file (CsvFile: the byte order mark, the line ends asked).
    static QByteArray toCsvFile(const QList<AlarmEvent> &events, CsvFile::LineEnd lineEnd);
    // "2026-12-07T17:23:31.253+08:00": a time as it read where it happened (the CSV's, the CLI's).
    static QString localTime(qint64 ms, int utcOffsetS);

    // The journal's format (PRAGMA user_version) and its mark (PRAGMA application_id, "FALJ"),
    // which tells a journal from another program's SQLite file.
    static constexpr int FormatVersion = 1;
    static constexpr int ApplicationId = 0x46414c4a;

private:
    explicit AlarmJournal(const QString &path);
    static Result<std::unique_ptr<AlarmJournal>> openFile(const QString &path, bool readOnly);
    static QString csvText(const QList<AlarmEvent> &events);
    Status checkAndCreate(bool readOnly);
    Status exec(const char *sql);
    Status prepareWrites();

    QString m_path;
    sqlite3 *m_db = nullptr;
    // Prepared once (append runs several times a second).
    sqlite3_stmt *m_insertEvent = nullptr;
    sqlite3_stmt *m_putState = nullptr;
    sqlite3_stmt *m_dropState = nullptr;
};

} // namespace Fatek
