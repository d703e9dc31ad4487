#pragma once

#include "historystore.h"

#include <optional>
#include <utility>

struct sqlite3;
struct sqlite3_stmt;

namespace Fatek {

// The history in one SQLite file (WAL): the table `series` (id, source, item, label, format,
// heartbeat_s; unique by source and item) and the table `samples` (series, time_ms, value, raw,
// quality; keyed by series and time, without a rowid: a range of one series is one walk of the
// key). The schema is PostgresHistoryStore's, in SQLite's types. Opened through
// HistoryStore::open(); see HistoryStore for what each call does.
class SqliteHistoryStore final : public HistoryStore
{
public:
    ~SqliteHistoryStore() override;

    // Opens or creates the file (its folder too) and its tables; refuses a file that is not a
    // history store (left untouched), damaged, newer, locked by another program, or missing
    // when ReadOnly.
    static Result<std::unique_ptr<HistoryStore>> open(const QString &path, HistoryStore::Mode mode);

    QString location() const override { return m_path; }
    Result<qint64> seriesId(const HistorySeries &series) override;
    Result<QList<HistorySeries>> series() const override;
    Status append(const std::vector<HistoryRecord> &records) override;
    Result<std::vector<HistorySample>> samples(qint64 series, qint64 fromMs, qint64 toMs,
                                               qint64 limit = 0) const override;
    Result<HistoryRetentionOutcome> applyRetention(const HistoryRetention &retention,
                                                   qint64 nowMs) override;
    Result<qint64> sizeBytes() const override;
    Result<qint64> sampleCount() const override;

    // Rows one retention pass removes at most (the rest at the next pass: the writer's thread is
    // never held for long), and per transaction.
    static constexpr qint64 RetentionMaxRows = 1'000'000;
    static constexpr qint64 RetentionChunkRows = 100'000;

private:
    explicit SqliteHistoryStore(const QString &path);
    Status checkAndCreate(bool readOnly);
    Status exec(const char *sql);
    Status prepareWrites();
    ProtocolError writeError(int rc) const;
    ProtocolError readError() const;
    Result<QList<qint64>> seriesIds() const;
    Result<qint64> removeBefore(const QList<qint64> &series, qint64 beforeMs, qint64 maxRows);
    Result<std::optional<std::pair<qint64, qint64>>> timeSpan(const QList<qint64> &series) const;
    Result<qint64> pageBytes() const;
    void giveBack();

    QString m_path;
    sqlite3 *m_db = nullptr;
    // Prepared once (append runs every second, the rest as often as series come and go).
    sqlite3_stmt *m_insertSample = nullptr;
    sqlite3_stmt *m_findSeries = nullptr;
    sqlite3_stmt *m_insertSeries = nullptr;
    sqlite3_stmt *m_updateSeries = nullptr;
};

} // namespace Fatek
