#include "alarmjournal.h"

#include "alarmmessages.h"

#include "core/watch/csvfield.h"
#include "core/watch/csvfile.h"

#include <QDateTime>
#include <QDir>
#include <QFileInfo>

#include <sqlite3.h>

#include <cstdint>

namespace Fatek {

namespace {

// Long enough to ride over another connection's commit (the studio and fatek-cli reading the same
// file), short enough that a file held open for writing is reported while the operator waits.
constexpr int BusyTimeoutMs = 1000;

const char *const CreateSql = R"(
CREATE TABLE events (
    id INTEGER PRIMARY KEY,
    time_ms INTEGER NOT NULL,
    utc_offset_s INTEGER NOT NULL,
    connection TEXT NOT NULL,
    alarm_id TEXT NOT NULL,
    kind TEXT NOT NULL,
    event TEXT NOT NULL,
    state TEXT NOT NULL,
    priority TEXT NOT NULL,
    message TEXT NOT NULL,
    alarm_group TEXT NOT NULL,
    value TEXT NOT NULL,
    user TEXT NOT NULL,
    comment TEXT NOT NULL,
    shelved_until_ms INTEGER NOT NULL
);
CREATE INDEX events_time ON events (time_ms);
CREATE TABLE states (
    connection TEXT NOT NULL,
    alarm_id TEXT NOT NULL,
    state TEXT NOT NULL,
    since_ms INTEGER NOT NULL,
    raised_ms INTEGER NOT NULL,
    shelved_until_ms INTEGER NOT NULL,
    condition_active INTEGER NOT NULL,
    PRIMARY KEY (connection, alarm_id)
) WITHOUT ROWID;
)";

const char *const EventColumns = "id, time_ms, utc_offset_s, connection, alarm_id, kind, event, "
                                 "state, priority, message, alarm_group, value, user, comment, "
                                 "shelved_until_ms";

struct StmtDeleter
{
    void operator()(sqlite3_stmt *stmt) const { sqlite3_finalize(stmt); }
};
using Stmt = std::unique_ptr<sqlite3_stmt, StmtDeleter>;

// SQLite copies the text at once (SQLITE_TRANSIENT, whose macro is a C cast).
sqlite3_destructor_type transient()
{
    return reinterpret_cast<sqlite3_destructor_type>(static_cast<std::intptr_t>(-1));
}

bool isBusy(int rc)
{
    return (rc & 0xff) == SQLITE_BUSY || (rc & 0xff) == SQLITE_LOCKED;
}

QString reasonOf(sqlite3 *db)
{
    return QString::fromUtf8(sqlite3_errmsg(db));
}

std::string text(const QString &s)
{
    return s.toStdString();
}

void bindText(sqlite3_stmt *stmt, int index, const QString &value)
{
    const QByteArray utf8 = value.toUtf8();
    sqlite3_bind_text(stmt, index, utf8.constData(), static_cast<int>(utf8.size()), transient());
}

QString columnText(sqlite3_stmt *stmt, int column)
{
    const auto *data = reinterpret_cast<const char *>(sqlite3_column_text(stmt, column));
    return QString::fromUtf8(data, sqlite3_column_bytes(stmt, column));
}

} // namespace

QString AlarmJournal::localTime(qint64 ms, int offsetS)
{
    const QDateTime utc = QDateTime::fromMSecsSinceEpoch(ms, Qt::UTC);
    const QString local = utc.addSecs(offsetS).toString(QStringLiteral("yyyy-MM-ddTHH:mm:ss.zzz"));
    const int minutes = (offsetS < 0 ? -offsetS : offsetS) / 60;
    return local + (offsetS < 0 ? QLatin1Char('-') : QLatin1Char('+'))
           + QStringLiteral("%1:%2")
                 .arg(minutes / 60, 2, 10, QLatin1Char('0'))
                 .arg(minutes % 60, 2, 10, QLatin1Char('0'));
}

AlarmJournal::AlarmJournal(const QString &path)
    : m_path(path)
{}

AlarmJournal::~AlarmJournal()
{
    sqlite3_finalize(m_insertEvent);
    sqlite3_finalize(m_putState);
    sqlite3_finalize(m_dropState);
    // Closing the last connection checkpoints the WAL into the file and removes it.
    sqlite3_close(m_db);
}

Result<std::unique_ptr<AlarmJournal>> AlarmJournal::open(const QString &path)
{
    return openFile(path, false);
}

Result<std::unique_ptr<AlarmJournal>> AlarmJournal::openReadOnly(const QString &path)
{
    return openFile(path, true);
}

Result<std::unique_ptr<AlarmJournal>> AlarmJournal::openFile(const QString &path, bool readOnly)
{
    const std::string file = text(QDir::toNativeSeparators(path));
    const QFileInfo info(path);
    if (readOnly && !info.exists())
        return makeError(ErrorKind::InvalidRequest, msg<MsgId::JournalMissing>(file));
    if (!readOnly && !QDir().mkpath(info.absolutePath()))
        return makeError(
            ErrorKind::InvalidRequest,
            msg<MsgId::JournalOpenFailed>(
                file, Message::text("cannot create its folder "
                                    + text(QDir::toNativeSeparators(info.absolutePath())))));
    std::unique_ptr<AlarmJournal> journal(new AlarmJournal(path));
    const int flags = readOnly ? SQLITE_OPEN_READONLY : SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE;
    const int rc = sqlite3_open_v2(path.toUtf8().constData(), &journal->m_db, flags, nullptr);
    if (rc != SQLITE_OK)
        return makeError(ErrorKind::InvalidRequest,
                         msg<MsgId::JournalOpenFailed>(
                             file, Message::text(journal->m_db ? text(reasonOf(journal->m_db))
                                                               : sqlite3_errstr(rc))));
    sqlite3_extended_result_codes(journal->m_db, 1);
    sqlite3_busy_timeout(journal->m_db, BusyTimeoutMs);
    if (Status checked = journal->checkAndCreate(readOnly); !checked)
        return checked.error();
    if (!readOnly) {
        if (Status prepared = journal->prepareWrites(); !prepared)
            return prepared.error();
    }
    return journal;
}

// What the file is, read before anything is written (a file that is not ours stays untouched);
// a new or empty file gets the tables, WAL and our mark in one transaction.
Status AlarmJournal::checkAndCreate(bool readOnly)
{
    const std::string file = text(QDir::toNativeSeparators(m_path));
    struct Header
    {
        int applicationId = 0;
        int version = 0;
        int tables = 0;
    };
    auto readHeader = [this, &file]() -> Result<Header> {
        Header header;
        const char *sql = "SELECT (SELECT application_id FROM pragma_application_id), "
                          "(SELECT user_version FROM pragma_user_version), "
                          "(SELECT count(*) FROM sqlite_schema)";
        sqlite3_stmt *raw = nullptr;
        int rc = sqlite3_prepare_v2(m_db, sql, -1, &raw, nullptr);
        Stmt stmt(raw);
        if (rc == SQLITE_OK) {
            rc = sqlite3_step(raw);
            if (rc == SQLITE_ROW) {
                header.applicationId = sqlite3_column_int(raw, 0);
                header.version = sqlite3_column_int(raw, 1);
                header.tables = sqlite3_column_int(raw, 2);
                return header;
            }
        }
        if (isBusy(rc))
            return makeError(ErrorKind::InvalidRequest, msg<MsgId::JournalLocked>(file));
        return makeError(ErrorKind::InvalidRequest,
                         msg<MsgId::JournalOpenFailed>(file, Message::text(text(reasonOf(m_db)))));
    };
    auto judge = [&file](const Header &header) -> Status {
        if (header.applicationId != ApplicationId
            && (header.applicationId != 0 || header.tables != 0))
            return makeError(ErrorKind::InvalidRequest, msg<MsgId::JournalNotJournal>(file));
        if (header.version > FormatVersion)
            return makeError(ErrorKind::InvalidRequest,
                             msg<MsgId::JournalNewer>(file, header.version, FormatVersion));
        return Ok{};
    };

    Result<Header> header = readHeader();
    if (!header)
        return header.error();
    if (Status fits = judge(*header); !fits)
        return fits;
    if (readOnly) {
        // An empty SQLite file is no journal to read (nothing was ever recorded in it).
        if (header->applicationId != ApplicationId)
            return makeError(ErrorKind::InvalidRequest, msg<MsgId::JournalNotJournal>(file));
        return Ok{};
    }
    // WAL: a reader (fatek-cli, the summary's query) never waits for the writer, and a commit is
    // one append to the log. Persistent in the file; a no-op once set.
    if (Status wal = exec("PRAGMA journal_mode=WAL"); !wal)
        return wal;
    // FULL: a committed event survives a power cut too, not only a crash of the program.
    if (Status sync = exec("PRAGMA synchronous=FULL"); !sync)
        return sync;
    // The write lock, taken now: a file another program holds is reported at open, not at the
    // first alarm. Read again inside it: another process may have created the tables meanwhile.
    if (Status begun = exec("BEGIN IMMEDIATE"); !begun)
        return begun;
    header = readHeader();
    Status made = header ? judge(*header) : Status(header.error());
    if (made && header->tables == 0) {
        made = exec(CreateSql);
        if (made)
            made = exec(("PRAGMA application_id=" + std::to_string(ApplicationId)).c_str());
        if (made)
            made = exec(("PRAGMA user_version=" + std::to_string(FormatVersion)).c_str());
    }
    if (made)
        made = exec("COMMIT");
    if (!made)
        sqlite3_exec(m_db, "ROLLBACK", nullptr, nullptr, nullptr);
    return made;
}

Status AlarmJournal::exec(const char *sql)
{
    const int rc = sqlite3_exec(m_db, sql, nullptr, nullptr, nullptr);
    if (rc == SQLITE_OK)
        return Ok{};
    const std::string file = text(QDir::toNativeSeparators(m_path));
    if (isBusy(rc))
        return makeError(ErrorKind::InvalidRequest, msg<MsgId::JournalLocked>(file));
    return makeError(ErrorKind::InvalidRequest,
                     msg<MsgId::JournalWriteFailed>(file, Message::text(text(reasonOf(m_db)))));
}

Status AlarmJournal::prepareWrites()
{
    const std::pair<sqlite3_stmt **, const char *> statements[] = {
        {&m_insertEvent,
         "INSERT INTO events (time_ms, utc_offset_s, connection, alarm_id, kind, event, state, "
         "priority, message, alarm_group, value, user, comment, shelved_until_ms) "
         "VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10, ?11, ?12, ?13, ?14)"},
        {&m_putState,
         "INSERT OR REPLACE INTO states (connection, alarm_id, state, since_ms, raised_ms, "
         "shelved_until_ms, condition_active) VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7)"},
        {&m_dropState, "DELETE FROM states WHERE connection = ?1 AND alarm_id = ?2"},
    };
    for (const auto &[stmt, sql] : statements) {
        if (sqlite3_prepare_v3(m_db, sql, -1, SQLITE_PREPARE_PERSISTENT, stmt, nullptr)
            != SQLITE_OK)
            return makeError(ErrorKind::InvalidRequest,
                             msg<MsgId::JournalOpenFailed>(text(QDir::toNativeSeparators(m_path)),
                                                           Message::text(text(reasonOf(m_db)))));
    }
    return Ok{};
}

Status AlarmJournal::append(const QList<AlarmEvent> &events, const QList<AlarmRecord> &records)
{
    if (events.isEmpty() && records.isEmpty())
        return Ok{};
    if (!m_insertEvent)
        return makeError(ErrorKind::ReadOnly,
                         msg<MsgId::JournalWriteFailed>(text(QDir::toNativeSeparators(m_path)),
                                                        Message::text("opened to read only")));
    if (Status begun = exec("BEGIN IMMEDIATE"); !begun)
        return begun;
    // Each statement is stepped once and reset; the first failure rolls the whole batch back.
    auto run = [this](sqlite3_stmt *stmt) -> Status {
        const int rc = sqlite3_step(stmt);
        sqlite3_reset(stmt);
        sqlite3_clear_bindings(stmt);
        if (rc == SQLITE_DONE)
            return Ok{};
        const std::string file = text(QDir::toNativeSeparators(m_path));
        if (isBusy(rc))
            return makeError(ErrorKind::InvalidRequest, msg<MsgId::JournalLocked>(file));
        return makeError(ErrorKind::InvalidRequest,
                         msg<MsgId::JournalWriteFailed>(file, Message::text(text(reasonOf(m_db)))));
    };
    Status done = Ok{};
    for (const AlarmEvent &e : events) {
        sqlite3_stmt *s = m_insertEvent;
        sqlite3_bind_int64(s, 1, e.timeMs);
        sqlite3_bind_int(s, 2, e.utcOffsetS);
        bindText(s, 3, e.connection);
        bindText(s, 4, e.alarmId);
        bindText(s, 5, Alarms::kindName(e.kind));
        bindText(s, 6, Alarms::eventName(e.type));
        bindText(s, 7, Alarms::stateName(e.state));
        bindText(s, 8, Alarms::priorityName(e.priority));
        bindText(s, 9, e.message);
        bindText(s, 10, e.group);
        bindText(s, 11, e.value);
        bindText(s, 12, e.user);
        bindText(s, 13, e.comment);
        sqlite3_bind_int64(s, 14, e.shelvedUntilMs);
        if (done = run(s); !done)
            break;
    }
    for (qsizetype i = 0; done && i < records.size(); ++i) {
        const AlarmRecord &r = records.at(i);
        if (r.state == AlarmState::Normal) {
            // Nothing to bring back: an alarm in Normal starts so anyway.
            bindText(m_dropState, 1, r.connection);
            bindText(m_dropState, 2, r.alarmId);
            done = run(m_dropState);
            continue;
        }
        sqlite3_stmt *s = m_putState;
        bindText(s, 1, r.connection);
        bindText(s, 2, r.alarmId);
        bindText(s, 3, Alarms::stateName(r.state));
        sqlite3_bind_int64(s, 4, r.sinceMs);
        sqlite3_bind_int64(s, 5, r.raisedMs);
        sqlite3_bind_int64(s, 6, r.shelvedUntilMs);
        sqlite3_bind_int(s, 7, r.conditionActive ? 1 : 0);
        done = run(s);
    }
    if (done)
        done = exec("COMMIT");
    if (!done)
        sqlite3_exec(m_db, "ROLLBACK", nullptr, nullptr, nullptr);
    return done;
}

Result<QList<AlarmRecord>> AlarmJournal::states(const QString &connection) const
{
    const std::string file = text(QDir::toNativeSeparators(m_path));
    auto failed = [&]() -> ProtocolError {
        return makeError(ErrorKind::InvalidRequest,
                         msg<MsgId::JournalReadFailed>(file, Message::text(text(reasonOf(m_db)))));
    };
    sqlite3_stmt *raw = nullptr;
    if (sqlite3_prepare_v2(m_db,
                           "SELECT connection, alarm_id, state, since_ms, raised_ms, "
                           "shelved_until_ms, condition_active FROM states "
                           "WHERE ?1 = '' OR connection = ?1 ORDER BY connection, alarm_id",
                           -1, &raw, nullptr)
        != SQLITE_OK)
        return failed();
    Stmt stmt(raw);
    bindText(raw, 1, connection);
    QList<AlarmRecord> records;
    int rc = SQLITE_ROW;
    while ((rc = sqlite3_step(raw)) == SQLITE_ROW) {
        AlarmRecord r;
        r.connection = columnText(raw, 0);
        r.alarmId = columnText(raw, 1);
        const QString stateText = columnText(raw, 2);
        const std::optional<AlarmState> state = Alarms::stateFromName(stateText);
        if (!state)
            return makeError(
                ErrorKind::MalformedResponse,
                msg<MsgId::JournalStateUnknown>(file, text(r.alarmId), "state", text(stateText)));
        r.state = *state;
        r.sinceMs = sqlite3_column_int64(raw, 3);
        r.raisedMs = sqlite3_column_int64(raw, 4);
        r.shelvedUntilMs = sqlite3_column_int64(raw, 5);
        r.conditionActive = sqlite3_column_int(raw, 6) != 0;
        records.append(r);
    }
    if (rc != SQLITE_DONE)
        return failed();
    return records;
}

Result<QList<AlarmEvent>> AlarmJournal::events(qint64 fromMs, qint64 toMs,
                                               const QString &connection) const
{
    const std::string file = text(QDir::toNativeSeparators(m_path));
    auto failed = [&]() -> ProtocolError {
        return makeError(ErrorKind::InvalidRequest,
                         msg<MsgId::JournalReadFailed>(file, Message::text(text(reasonOf(m_db)))));
    };
    const std::string sql = std::string("SELECT ") + EventColumns
                            + " FROM events WHERE time_ms >= ?1 AND time_ms < ?2"
                              " AND (?3 = '' OR connection = ?3) ORDER BY time_ms, id";
    sqlite3_stmt *raw = nullptr;
    if (sqlite3_prepare_v2(m_db, sql.c_str(), -1, &raw, nullptr) != SQLITE_OK)
        return failed();
    Stmt stmt(raw);
    sqlite3_bind_int64(raw, 1, fromMs);
    sqlite3_bind_int64(raw, 2, toMs);
    bindText(raw, 3, connection);
    QList<AlarmEvent> events;
    int rc = SQLITE_ROW;
    while ((rc = sqlite3_step(raw)) == SQLITE_ROW) {
        const qint64 row = sqlite3_column_int64(raw, 0);
        // A name this program does not know: the row and the column are named, nothing guessed.
        auto unknown = [&](const char *column, int index) -> ProtocolError {
            return makeError(
                ErrorKind::MalformedResponse,
                msg<MsgId::JournalEventUnknown>(file, row, column, text(columnText(raw, index))));
        };
        AlarmEvent e;
        e.timeMs = sqlite3_column_int64(raw, 1);
        e.utcOffsetS = sqlite3_column_int(raw, 2);
        e.connection = columnText(raw, 3);
        e.alarmId = columnText(raw, 4);
        const auto kind = Alarms::kindFromName(columnText(raw, 5));
        if (!kind)
            return unknown("kind", 5);
        const auto type = Alarms::eventFromName(columnText(raw, 6));
        if (!type)
            return unknown("event", 6);
        const auto state = Alarms::stateFromName(columnText(raw, 7));
        if (!state)
            return unknown("state", 7);
        const auto priority = Alarms::priorityFromName(columnText(raw, 8));
        if (!priority)
            return unknown("priority", 8);
        e.kind = *kind;
        e.type = *type;
        e.state = *state;
        e.priority = *priority;
        e.message = columnText(raw, 9);
        e.group = columnText(raw, 10);
        e.value = columnText(raw, 11);
        e.user = columnText(raw, 12);
        e.comment = columnText(raw, 13);
        e.shelvedUntilMs = sqlite3_column_int64(raw, 14);
        events.append(e);
    }
    if (rc != SQLITE_DONE)
        return failed();
    return events;
}

QByteArray AlarmJournal::toCsv(const QList<AlarmEvent> &events)
{
    return csvText(events).toUtf8();
}

QByteArray AlarmJournal::toCsvFile(const QList<AlarmEvent> &events, CsvFile::LineEnd lineEnd)
{
    return CsvFile::bytes(csvText(events), lineEnd);
}

QString AlarmJournal::csvText(const QList<AlarmEvent> &events)
{
    QString out = QStringLiteral("time,connection,alarm,kind,event,state,priority,group,message,"
                                 "value,user,comment,shelved until\n");
    for (const AlarmEvent &e : events) {
        const QString fields[] = {
            localTime(e.timeMs, e.utcOffsetS),
            e.connection,
            e.alarmId,
            Alarms::kindName(e.kind),
            Alarms::eventName(e.type),
            Alarms::stateName(e.state),
            Alarms::priorityName(e.priority),
            e.group,
            e.message,
            e.value,
            e.user,
            e.comment,
            e.shelvedUntilMs ? localTime(e.shelvedUntilMs, e.utcOffsetS) : QString(),
        };
        bool first = true;
        for (const QString &field : fields) {
            if (!first)
                out += QLatin1Char(',');
            first = false;
            out += CsvField::quoted(field);
        }
        out += QLatin1Char('\n');
    }
    return out;
}

} // namespace Fatek
