#include "sqlitehistorystore.h"

#include "historymessages.h"
#include "sqliteutil.h"

#include <QDir>
#include <QFileInfo>

#include <sqlite3.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <string>

namespace Fatek {

namespace {

using namespace SqliteUtil;

// Long enough to ride over another connection's commit (the studio and fatek-cli reading the same
// file), short enough that a file held open for writing is reported while the operator waits.
constexpr int BusyTimeoutMs = 1000;
// The WAL is cut back to this after a checkpoint: a burst (a retention pass) leaves no large log.
constexpr int WalLimitBytes = 4 << 20;

// The same tables as PostgresHistoryStore's. A value is NULL when the item has none (NaN); raw is
// the words as read, a uint64 kept bit for bit in SQLite's signed 64-bit integer.
const char *const CreateSql = R"(
CREATE TABLE series (
    id INTEGER PRIMARY KEY,
    source TEXT NOT NULL,
    item TEXT NOT NULL,
    label TEXT NOT NULL,
    format TEXT NOT NULL,
    heartbeat_s INTEGER NOT NULL,
    UNIQUE (source, item)
);
CREATE TABLE samples (
    series INTEGER NOT NULL,
    time_ms INTEGER NOT NULL,
    value REAL,
    raw INTEGER NOT NULL,
    quality INTEGER NOT NULL,
    PRIMARY KEY (series, time_ms)
) WITHOUT ROWID;
)";

// SQLite copies the text at once (SQLITE_TRANSIENT, whose macro is a C cast).
sqlite3_destructor_type transient()
{
    return reinterpret_cast<sqlite3_destructor_type>(static_cast<std::intptr_t>(-1));
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

SqliteHistoryStore::SqliteHistoryStore(const QString &path)
    : m_path(path)
{}

SqliteHistoryStore::~SqliteHistoryStore()
{
    for (sqlite3_stmt *stmt : {m_insertSample, m_findSeries, m_insertSeries, m_updateSeries})
        sqlite3_finalize(stmt);
    // Closing the last connection checkpoints the WAL into the file and removes it.
    sqlite3_close(m_db);
}

Result<std::unique_ptr<HistoryStore>> SqliteHistoryStore::open(const QString &path,
                                                               HistoryStore::Mode mode)
{
    const bool readOnly = mode == Mode::ReadOnly;
    const std::string file = fileOf(path);
    const QFileInfo info(path);
    if (readOnly && !info.exists())
        return makeError(ErrorKind::InvalidRequest, msg<MsgId::HistoryMissing>(file));
    if (!readOnly && !QDir().mkpath(info.absolutePath()))
        return makeError(ErrorKind::InvalidRequest,
                         msg<MsgId::HistoryNoFolder>(file, fileOf(info.absolutePath())));
    std::unique_ptr<SqliteHistoryStore> store(new SqliteHistoryStore(path));
    const int flags = readOnly ? SQLITE_OPEN_READONLY : SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE;
    const int rc = sqlite3_open_v2(path.toUtf8().constData(), &store->m_db, flags, nullptr);
    if (rc != SQLITE_OK)
        return makeError(
            ErrorKind::InvalidRequest,
            msg<MsgId::HistoryOpenFailed>(
                file, Message::text(store->m_db ? reasonOf(store->m_db) : sqlite3_errstr(rc))));
    sqlite3_extended_result_codes(store->m_db, 1);
    sqlite3_busy_timeout(store->m_db, BusyTimeoutMs);
    if (Status checked = store->checkAndCreate(readOnly); !checked)
        return checked.error();
    if (Status prepared = store->prepareWrites(); !prepared)
        return prepared.error();
    return std::unique_ptr<HistoryStore>(std::move(store));
}

// What the file is, read before anything is written (a file that is not ours stays untouched);
// a new or empty file gets the tables, WAL and our mark in one transaction.
Status SqliteHistoryStore::checkAndCreate(bool readOnly)
{
    const std::string file = fileOf(m_path);
    struct Header
    {
        int applicationId = 0;
        int version = 0;
        int tables = 0;
    };
    auto readHeader = [this, &file]() -> Result<Header> {
        Stmt owner;
        Result<sqlite3_stmt *> stmt
            = prepare(m_db,
                      "SELECT (SELECT application_id FROM pragma_application_id), "
                      "(SELECT user_version FROM pragma_user_version), "
                      "(SELECT count(*) FROM sqlite_schema)",
                      owner);
        int rc = stmt ? sqlite3_step(*stmt) : sqlite3_errcode(m_db);
        if (rc == SQLITE_ROW) {
            return Header{sqlite3_column_int(*stmt, 0), sqlite3_column_int(*stmt, 1),
                          sqlite3_column_int(*stmt, 2)};
        }
        if (isBusy(rc))
            return makeError(ErrorKind::InvalidRequest, msg<MsgId::HistoryLocked>(file));
        return makeError(ErrorKind::InvalidRequest,
                         msg<MsgId::HistoryOpenFailed>(file, Message::text(reasonOf(m_db))));
    };
    auto judge = [&file](const Header &header) -> Status {
        if (header.applicationId != ApplicationId
            && (header.applicationId != 0 || header.tables != 0))
            return makeError(ErrorKind::InvalidRequest, msg<MsgId::HistoryNotHistory>(file));
        if (header.version > FormatVersion)
            return makeError(ErrorKind::InvalidRequest,
                             msg<MsgId::HistoryNewer>(file, header.version, FormatVersion));
        return Ok{};
    };

    Result<Header> header = readHeader();
    if (!header)
        return header.error();
    if (Status fits = judge(*header); !fits)
        return fits;
    if (readOnly) {
        // An empty SQLite file is no history to read (nothing was ever recorded in it).
        if (header->applicationId != ApplicationId)
            return makeError(ErrorKind::InvalidRequest, msg<MsgId::HistoryNotHistory>(file));
        return Ok{};
    }
    // Only before the first table: retention by size gives pages back (incremental_vacuum).
    if (header->tables == 0) {
        if (Status vacuum = exec("PRAGMA auto_vacuum=INCREMENTAL"); !vacuum)
            return vacuum;
    }
    // WAL: a reader (the trend, fatek-cli) never waits for the writer, and a commit is one append
    // to the log. Persistent in the file; a no-op once set.
    if (Status wal = exec("PRAGMA journal_mode=WAL"); !wal)
        return wal;
    // FULL: the log is synced at each commit, so a committed second of values survives a power
    // cut too (NORMAL would survive a kill -9 alike, but not a power cut). The writer commits once
    // a second: one fsync a second costs nothing worth saving.
    if (Status sync = exec("PRAGMA synchronous=FULL"); !sync)
        return sync;
    if (Status limit = exec(("PRAGMA journal_size_limit=" + std::to_string(WalLimitBytes)).c_str());
        !limit)
        return limit;
    // The write lock, taken now: a file another program holds is reported at open, not at the
    // first value. Read again inside it: another process may have created the tables meanwhile.
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

ProtocolError SqliteHistoryStore::writeError(int rc) const
{
    const std::string file = fileOf(m_path);
    if (isBusy(rc))
        return makeError(ErrorKind::InvalidRequest, msg<MsgId::HistoryLocked>(file));
    return makeError(ErrorKind::InvalidRequest,
                     msg<MsgId::HistoryWriteFailed>(file, Message::text(reasonOf(m_db))));
}

ProtocolError SqliteHistoryStore::readError() const
{
    return makeError(ErrorKind::InvalidRequest,
                     msg<MsgId::HistoryReadFailed>(fileOf(m_path), Message::text(reasonOf(m_db))));
}

Status SqliteHistoryStore::exec(const char *sql)
{
    const int rc = sqlite3_exec(m_db, sql, nullptr, nullptr, nullptr);
    if (rc == SQLITE_OK)
        return Ok{};
    return writeError(rc);
}

Status SqliteHistoryStore::prepareWrites()
{
    const bool readOnly = sqlite3_db_readonly(m_db, "main") == 1;
    const std::pair<sqlite3_stmt **, const char *> statements[] = {
        {&m_findSeries,
         "SELECT id, label, format, heartbeat_s FROM series WHERE source = ?1 AND item = ?2"},
        {&m_insertSample, "INSERT OR REPLACE INTO samples (series, time_ms, value, raw, quality) "
                          "VALUES (?1, ?2, ?3, ?4, ?5)"},
        {&m_insertSeries, "INSERT INTO series (source, item, label, format, heartbeat_s) "
                          "VALUES (?1, ?2, ?3, ?4, ?5)"},
        {&m_updateSeries, "UPDATE series SET label = ?2, format = ?3, heartbeat_s = ?4 "
                          "WHERE id = ?1"},
    };
    for (const auto &[stmt, sql] : statements) {
        // Opened to read: the lookup only (m_insertSample stays null: writes are refused).
        if (readOnly && stmt != &m_findSeries)
            continue;
        if (sqlite3_prepare_v3(m_db, sql, -1, SQLITE_PREPARE_PERSISTENT, stmt, nullptr)
            != SQLITE_OK)
            return makeError(
                ErrorKind::InvalidRequest,
                msg<MsgId::HistoryOpenFailed>(fileOf(m_path), Message::text(reasonOf(m_db))));
    }
    return Ok{};
}

Result<qint64> SqliteHistoryStore::seriesId(const HistorySeries &series)
{
    const bool readOnly = !m_insertSeries;
    if (!readOnly) {
        if (Status begun = exec("BEGIN IMMEDIATE"); !begun)
            return begun.error();
    }
    auto lookUp = [&]() -> Result<qint64> {
        std::optional<qint64> id;
        bool changed = false;
        {
            StmtUse use(m_findSeries);
            bindText(m_findSeries, 1, series.source);
            bindText(m_findSeries, 2, series.item);
            const int rc = sqlite3_step(m_findSeries);
            if (rc == SQLITE_ROW) {
                id = sqlite3_column_int64(m_findSeries, 0);
                changed = columnText(m_findSeries, 1) != series.label
                          || columnText(m_findSeries, 2) != series.format
                          || sqlite3_column_int(m_findSeries, 3) != series.heartbeatS;
            } else if (rc != SQLITE_DONE) {
                return readOnly ? readError() : writeError(rc);
            }
        }
        if (readOnly) {
            // Nothing is made or changed: a series not there is unknown.
            if (!id)
                return makeError(
                    ErrorKind::InvalidRequest,
                    msg<MsgId::HistoryUnknownSeries>(fileOf(m_path), series.key().toStdString()));
            return *id;
        }
        if (id && !changed)
            return *id;
        sqlite3_stmt *s = id ? m_updateSeries : m_insertSeries;
        StmtUse use(s);
        if (id) {
            sqlite3_bind_int64(s, 1, *id);
            bindText(s, 2, series.label);
            bindText(s, 3, series.format);
            sqlite3_bind_int(s, 4, series.heartbeatS);
        } else {
            bindText(s, 1, series.source);
            bindText(s, 2, series.item);
            bindText(s, 3, series.label);
            bindText(s, 4, series.format);
            sqlite3_bind_int(s, 5, series.heartbeatS);
        }
        if (const int rc = sqlite3_step(s); rc != SQLITE_DONE)
            return writeError(rc);
        return id ? *id : sqlite3_last_insert_rowid(m_db);
    };
    Result<qint64> id = lookUp();
    if (readOnly)
        return id;
    Status done = id ? exec("COMMIT") : Status(id.error());
    if (!done) {
        sqlite3_exec(m_db, "ROLLBACK", nullptr, nullptr, nullptr);
        return done.error();
    }
    return id;
}

Result<QList<HistorySeries>> SqliteHistoryStore::series() const
{
    Stmt owner;
    Result<sqlite3_stmt *> stmt = prepare(m_db,
                                          "SELECT id, source, item, label, format, heartbeat_s "
                                          "FROM series ORDER BY source, item",
                                          owner);
    if (!stmt)
        return readError();
    QList<HistorySeries> list;
    int rc = SQLITE_ROW;
    while ((rc = sqlite3_step(*stmt)) == SQLITE_ROW) {
        HistorySeries s;
        s.id = sqlite3_column_int64(*stmt, 0);
        s.source = columnText(*stmt, 1);
        s.item = columnText(*stmt, 2);
        s.label = columnText(*stmt, 3);
        s.format = columnText(*stmt, 4);
        s.heartbeatS = sqlite3_column_int(*stmt, 5);
        list.append(s);
    }
    if (rc != SQLITE_DONE)
        return readError();
    return list;
}

Status SqliteHistoryStore::append(const std::vector<HistoryRecord> &records)
{
    if (records.empty())
        return Ok{};
    if (!m_insertSample)
        return makeError(ErrorKind::ReadOnly, msg<MsgId::HistoryReadOnly>(fileOf(m_path)));
    if (Status begun = exec("BEGIN IMMEDIATE"); !begun)
        return begun;
    Status done = Ok{};
    sqlite3_stmt *s = m_insertSample;
    for (const HistoryRecord &r : records) {
        StmtUse use(s);
        sqlite3_bind_int64(s, 1, r.series);
        sqlite3_bind_int64(s, 2, r.sample.timeMs);
        if (std::isnan(r.sample.value))
            sqlite3_bind_null(s, 3);
        else
            sqlite3_bind_double(s, 3, r.sample.value);
        sqlite3_bind_int64(s, 4, std::bit_cast<sqlite3_int64>(r.sample.raw));
        sqlite3_bind_int(s, 5, static_cast<int>(r.sample.quality));
        if (const int rc = sqlite3_step(s); rc != SQLITE_DONE) {
            done = writeError(rc);
            break;
        }
    }
    if (done)
        done = exec("COMMIT");
    if (!done)
        sqlite3_exec(m_db, "ROLLBACK", nullptr, nullptr, nullptr);
    return done;
}

Result<std::vector<HistorySample>> SqliteHistoryStore::samples(qint64 series, qint64 fromMs,
                                                               qint64 toMs, qint64 limit) const
{
    // Both reads in one snapshot: a commit between them cannot slip a sample in twice.
    if (sqlite3_exec(m_db, "BEGIN", nullptr, nullptr, nullptr) != SQLITE_OK)
        return readError();
    struct End
    {
        sqlite3 *db;
        ~End() { sqlite3_exec(db, "COMMIT", nullptr, nullptr, nullptr); }
    } end{m_db};

    std::vector<HistorySample> out;
    auto read = [&](const char *sql, qint64 rows) -> Status {
        Stmt owner;
        Result<sqlite3_stmt *> stmt = prepare(m_db, sql, owner);
        if (!stmt)
            return readError();
        sqlite3_bind_int64(*stmt, 1, series);
        sqlite3_bind_int64(*stmt, 2, fromMs);
        sqlite3_bind_int64(*stmt, 3, toMs);
        sqlite3_bind_int64(*stmt, 4, rows);
        int rc = SQLITE_ROW;
        while ((rc = sqlite3_step(*stmt)) == SQLITE_ROW) {
            HistorySample sample;
            sample.timeMs = sqlite3_column_int64(*stmt, 0);
            if (sqlite3_column_type(*stmt, 1) != SQLITE_NULL)
                sample.value = sqlite3_column_double(*stmt, 1);
            sample.raw = std::bit_cast<std::uint64_t>(
                static_cast<sqlite3_int64>(sqlite3_column_int64(*stmt, 2)));
            const int quality = sqlite3_column_int(*stmt, 3);
            // Written by a program of this format: another number is damage, not guessed at.
            if (quality < 0 || quality > static_cast<int>(HistoryQuality::Off))
                return makeError(ErrorKind::MalformedResponse,
                                 msg<MsgId::HistoryQualityUnknown>(fileOf(m_path), series,
                                                                   sample.timeMs, quality));
            sample.quality = static_cast<HistoryQuality>(quality);
            out.push_back(sample);
        }
        return rc == SQLITE_DONE ? Status(Ok{}) : Status(readError());
    };
    // ?3 (toMs) has no use in the first: a numbered parameter left out is simply never read.
    Status got = read("SELECT time_ms, value, raw, quality FROM samples "
                      "WHERE series = ?1 AND time_ms < ?2 ORDER BY time_ms DESC LIMIT ?4",
                      1);
    if (!got)
        return got.error();
    // The sample before the range counts toward the limit: `limit` is what the caller gets.
    const qint64 rest = limit > 0 ? limit - qint64(out.size()) : -1;
    if (rest != 0) {
        got = read("SELECT time_ms, value, raw, quality FROM samples "
                   "WHERE series = ?1 AND time_ms >= ?2 AND time_ms < ?3 "
                   "ORDER BY time_ms LIMIT ?4",
                   rest);
        if (!got)
            return got.error();
    }
    return out;
}

Result<qint64> SqliteHistoryStore::sizeBytes() const
{
    return QFileInfo(m_path).size() + QFileInfo(m_path + QLatin1String("-wal")).size();
}

Result<qint64> SqliteHistoryStore::sampleCount() const
{
    Stmt owner;
    Result<sqlite3_stmt *> stmt = prepare(m_db, "SELECT count(*) FROM samples", owner);
    if (!stmt || sqlite3_step(*stmt) != SQLITE_ROW)
        return readError();
    return qint64(sqlite3_column_int64(*stmt, 0));
}

} // namespace Fatek
