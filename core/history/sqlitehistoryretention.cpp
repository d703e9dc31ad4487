#include "sqlitehistorystore.h"

// Retention of the SQLite store: what is too old or beyond the size goes, oldest first, in bounded
// steps, and the pages it took are given back to the file system.

#include "historymessages.h"
#include "sqliteutil.h"

#include <QFileInfo>

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

namespace Fatek {

using namespace SqliteUtil;

namespace {

// Steps of one size pass (each a cut, a vacuum and a checkpoint, then measured again).
constexpr int MaxSizeSteps = 16;
// A size step cuts a little more than the excess: pages are freed whole, the tables' inner pages
// stay, and a pass that only just fits would run again at the next minute.
constexpr double SizeMargin = 0.02;
constexpr double MinSizeShare = 0.01;

} // namespace

Result<QList<qint64>> SqliteHistoryStore::seriesIds() const
{
    Stmt owner;
    Result<sqlite3_stmt *> stmt = prepare(m_db, "SELECT id FROM series ORDER BY id", owner);
    if (!stmt)
        return readError();
    QList<qint64> ids;
    int rc = SQLITE_ROW;
    while ((rc = sqlite3_step(*stmt)) == SQLITE_ROW)
        ids.append(sqlite3_column_int64(*stmt, 0));
    if (rc != SQLITE_DONE)
        return readError();
    return ids;
}

// The samples of `series` older than beforeMs, at most maxRows, each series' oldest first, one
// transaction per RetentionChunkRows. Every statement walks the key (series, time_ms): no scan of
// the table, and no index on time alone for the writes to keep up.
Result<qint64> SqliteHistoryStore::removeBefore(const QList<qint64> &series, qint64 beforeMs,
                                                qint64 maxRows)
{
    Stmt findOwner;
    Stmt removeOwner;
    // Where the first `?3` rows of a series before ?2 end (none: fewer than that).
    Result<sqlite3_stmt *> find = prepare(m_db,
                                          "SELECT time_ms FROM samples WHERE series = ?1 "
                                          "AND time_ms < ?2 ORDER BY time_ms LIMIT 1 OFFSET ?3",
                                          findOwner);
    Result<sqlite3_stmt *> remove
        = prepare(m_db, "DELETE FROM samples WHERE series = ?1 AND time_ms < ?2", removeOwner);
    if (!find || !remove)
        return writeError(sqlite3_errcode(m_db));
    qint64 removed = 0;
    qsizetype next = 0;
    while (next < series.size() && removed < maxRows) {
        if (Status begun = exec("BEGIN IMMEDIATE"); !begun)
            return begun.error();
        qint64 inTransaction = 0;
        Status done = Ok{};
        while (done && next < series.size() && inTransaction < RetentionChunkRows
               && removed + inTransaction < maxRows) {
            const qint64 room
                = std::min(RetentionChunkRows - inTransaction, maxRows - removed - inTransaction);
            qint64 until = beforeMs;
            bool whole = true;
            {
                StmtUse use(*find);
                sqlite3_bind_int64(*find, 1, series.at(next));
                sqlite3_bind_int64(*find, 2, beforeMs);
                sqlite3_bind_int64(*find, 3, room);
                const int rc = sqlite3_step(*find);
                if (rc == SQLITE_ROW) {
                    // Times are unique per series: exactly `room` rows lie before this one.
                    until = sqlite3_column_int64(*find, 0);
                    whole = false;
                } else if (rc != SQLITE_DONE) {
                    done = writeError(rc);
                    break;
                }
            }
            StmtUse use(*remove);
            sqlite3_bind_int64(*remove, 1, series.at(next));
            sqlite3_bind_int64(*remove, 2, until);
            if (const int rc = sqlite3_step(*remove); rc != SQLITE_DONE) {
                done = writeError(rc);
                break;
            }
            inTransaction += sqlite3_changes(m_db);
            if (whole)
                ++next;
        }
        if (done)
            done = exec("COMMIT");
        if (!done) {
            sqlite3_exec(m_db, "ROLLBACK", nullptr, nullptr, nullptr);
            return done.error();
        }
        removed += inTransaction;
    }
    return removed;
}

// The bytes the file will take once its log is checkpointed: what a size pass measures, so that a
// reader holding the log (the trend, fatek-cli) cannot make it cut more than the excess.
Result<qint64> SqliteHistoryStore::pageBytes() const
{
    Stmt owner;
    Result<sqlite3_stmt *> stmt = prepare(m_db,
                                          "SELECT (SELECT page_count FROM pragma_page_count) * "
                                          "(SELECT page_size FROM pragma_page_size)",
                                          owner);
    if (!stmt || sqlite3_step(*stmt) != SQLITE_ROW)
        return readError();
    return qint64(sqlite3_column_int64(*stmt, 0));
}

// Freed pages back to the file system: moved to the end and cut off (incremental_vacuum), then the
// log copied into the file and truncated, so that the file itself shrinks. Either may find a
// reader in the way (SQLITE_BUSY): the next pass finishes it; nothing is lost meanwhile.
void SqliteHistoryStore::giveBack()
{
    sqlite3_exec(m_db, "PRAGMA incremental_vacuum", nullptr, nullptr, nullptr);
    sqlite3_exec(m_db, "PRAGMA wal_checkpoint(TRUNCATE)", nullptr, nullptr, nullptr);
}

Result<HistoryRetentionOutcome>
SqliteHistoryStore::applyRetention(const HistoryRetention &retention, qint64 nowMs)
{
    if (!m_insertSample)
        return makeError(ErrorKind::ReadOnly, msg<MsgId::HistoryReadOnly>(fileOf(m_path)));
    HistoryRetentionOutcome outcome;
    outcome.bytesBefore = *sizeBytes();
    if (retention.maxAgeS <= 0 && retention.maxBytes <= 0) {
        outcome.bytesAfter = outcome.bytesBefore;
        return outcome;
    }
    const Result<QList<qint64>> ids = seriesIds();
    if (!ids)
        return ids.error();
    qint64 budget = RetentionMaxRows;
    bool given = false;
    if (retention.maxAgeS > 0) {
        const Result<qint64> removed = removeBefore(*ids, nowMs - retention.maxAgeS * 1000, budget);
        if (!removed)
            return removed.error();
        outcome.samplesRemoved += *removed;
        budget -= *removed;
        if (*removed > 0) {
            giveBack();
            given = true;
        }
    }
    if (retention.maxBytes > 0 && *sizeBytes() > retention.maxBytes) {
        // The log may be all of the excess.
        if (!given)
            giveBack();
        for (int step = 0; step < MaxSizeSteps && budget > 0; ++step) {
            const Result<qint64> bytes = pageBytes();
            if (!bytes)
                return bytes.error();
            if (*bytes <= retention.maxBytes)
                break;
            const Result<std::optional<std::pair<qint64, qint64>>> span = timeSpan(*ids);
            if (!span)
                return span.error();
            if (!*span)
                break; // nothing left to cut: the tables' own pages are the size
            const auto [first, last] = **span;
            // The share of the time span to cut, as if the samples were spread evenly over it;
            // the next step measures again.
            const double excess = double(*bytes - retention.maxBytes) / double(*bytes);
            const double share = std::clamp(excess + SizeMargin, MinSizeShare, 1.0);
            const qint64 cut = std::max<qint64>(
                1, static_cast<qint64>(std::ceil(double(last - first + 1) * share)));
            const Result<qint64> removed = removeBefore(*ids, first + cut, budget);
            if (!removed)
                return removed.error();
            outcome.samplesRemoved += *removed;
            budget -= *removed;
            giveBack();
        }
    }
    outcome.bytesAfter = *sizeBytes();
    return outcome;
}

// The oldest and the newest time of any sample (none: no sample at all).
Result<std::optional<std::pair<qint64, qint64>>>
SqliteHistoryStore::timeSpan(const QList<qint64> &series) const
{
    Stmt owner;
    Result<sqlite3_stmt *> stmt = prepare(
        m_db,
        "SELECT (SELECT time_ms FROM samples WHERE series = ?1 ORDER BY time_ms LIMIT 1), "
        "(SELECT time_ms FROM samples WHERE series = ?1 ORDER BY time_ms DESC LIMIT 1)",
        owner);
    if (!stmt)
        return readError();
    std::optional<std::pair<qint64, qint64>> span;
    for (const qint64 id : series) {
        StmtUse use(*stmt);
        sqlite3_bind_int64(*stmt, 1, id);
        if (sqlite3_step(*stmt) != SQLITE_ROW)
            return readError();
        if (sqlite3_column_type(*stmt, 0) == SQLITE_NULL)
            continue;
        const qint64 first = sqlite3_column_int64(*stmt, 0);
        const qint64 last = sqlite3_column_int64(*stmt, 1);
        span = span ? std::pair{std::min(span->first, first), std::max(span->second, last)}
                    : std::pair{first, last};
    }
    return span;
}

} // namespace Fatek
