// The retention of PostgresHistoryStore (postgreshistorystore.h): by age, and by size.
#include "historymessages.h"
#include "postgreshistorystore_p.h"

#include <QByteArray>

#include <algorithm>
#include <string>

namespace Fatek {

namespace {

// Every series' oldest and newest sample, each one index probe.
const char *const SpanSql = "SELECT min(first), max(last) FROM fatek_history_series s, LATERAL "
                            "(SELECT min(time_ms) AS first, max(time_ms) AS last "
                            "FROM fatek_history_samples WHERE series = s.id) x";

// Through the primary key's index, series by series (no index on time alone).
const char *const DeleteOlderSql
    = "DELETE FROM fatek_history_samples "
      "WHERE series = ANY (ARRAY(SELECT id FROM fatek_history_series)) AND time_ms < $1";

} // namespace

Result<qint64> PostgresHistoryStore::deleteOlderThan(qint64 cutoffMs)
{
    const QByteArray cutoff = QByteArray::number(cutoffMs);
    return retried<qint64>(MsgId::HistoryWriteFailed, [&]() -> Result<qint64> {
        const char *params[] = {cutoff.constData()};
        Reply reply(PQexecParams(m_conn, DeleteOlderSql, 1, nullptr, params, nullptr, nullptr, 0));
        if (PQresultStatus(reply.get()) != PGRES_COMMAND_OK)
            return failure(MsgId::HistoryWriteFailed, &reply);
        return QByteArray(PQcmdTuples(reply.get())).toLongLong();
    });
}

Status PostgresHistoryStore::vacuum()
{
    // Outside a transaction (VACUUM cannot run in one). A role that does not own the table gets
    // a warning, not an error: autovacuum does it then.
    return retried<Ok>(MsgId::HistoryWriteFailed, [&]() -> Status {
        auto done
            = exec("VACUUM fatek_history_samples", MsgId::HistoryWriteFailed, PGRES_COMMAND_OK);
        return done ? Status(Ok{}) : Status(done.error());
    });
}

// PostgreSQL keeps the space of deleted rows in its files for new rows (a plain VACUUM makes it
// reusable; only VACUUM FULL gives it back to the disk), so the tables' size does not shrink
// when the oldest samples go: it stops growing. The size limit therefore counts the samples
// kept, each at what a sample takes packed in the table and its index, measured once in a
// temporary copy of the table (the same on every server version and page size).
Result<double> PostgresHistoryStore::bytesPerSample()
{
    if (m_bytesPerSample > 0)
        return m_bytesPerSample;
    constexpr int Series = 10;
    constexpr int Times = 2000;
    const std::string sql
        = "CREATE TEMP TABLE fatek_history_probe (LIKE fatek_history_samples INCLUDING INDEXES);"
          "INSERT INTO fatek_history_probe SELECT s, t, t * 0.5, t, 0 FROM generate_series(1, "
          + std::to_string(Times) + ") t, generate_series(1, " + std::to_string(Series)
          + ") s ORDER BY t, s;"
            "SELECT pg_total_relation_size('pg_temp.fatek_history_probe')";
    auto measured = retried<Reply>(MsgId::HistoryWriteFailed, [&] {
        return exec(sql.c_str(), MsgId::HistoryWriteFailed, PGRES_TUPLES_OK);
    });
    PQclear(PQexec(m_conn, "DROP TABLE IF EXISTS pg_temp.fatek_history_probe"));
    if (!measured)
        return measured.error();
    m_bytesPerSample
        = double(QByteArray(PQgetvalue(measured->get(), 0, 0)).toLongLong()) / (Series * Times);
    return m_bytesPerSample;
}

Result<HistoryRetentionOutcome>
PostgresHistoryStore::applyRetention(const HistoryRetention &retention, qint64 nowMs)
{
    HistoryRetentionOutcome outcome;
    Result<qint64> before = sizeBytes();
    if (!before)
        return before.error();
    outcome.bytesBefore = outcome.bytesAfter = *before;
    if (retention.maxAgeS > 0) {
        Result<qint64> removed = deleteOlderThan(nowMs - retention.maxAgeS * 1000);
        if (!removed)
            return removed.error();
        outcome.samplesRemoved += *removed;
    }
    if (retention.maxBytes > 0 && *before > retention.maxBytes) {
        Result<double> perSample = bytesPerSample();
        Result<qint64> count = perSample ? sampleCount() : Result<qint64>(perSample.error());
        auto seriesBytes = retried<Reply>(MsgId::HistoryReadFailed, [&] {
            return exec("SELECT pg_total_relation_size('fatek_history_series')",
                        MsgId::HistoryReadFailed, PGRES_TUPLES_OK);
        });
        if (!count)
            return count.error();
        if (!seriesBytes)
            return seriesBytes.error();
        const qint64 room
            = retention.maxBytes - QByteArray(PQgetvalue(seriesBytes->get(), 0, 0)).toLongLong();
        const qint64 keep = room > 0 ? qint64(double(room) / *perSample) : 0;
        qint64 left = *count;
        // The oldest go in steps: each step's cutoff assumes the samples are spread evenly in
        // time, the next corrects it; every step removes at least the oldest instant.
        for (int step = 0; left > keep && step < 64; ++step) {
            auto span = retried<Reply>(MsgId::HistoryReadFailed, [&] {
                return exec(SpanSql, MsgId::HistoryReadFailed, PGRES_TUPLES_OK);
            });
            if (!span)
                return span.error();
            if (PQgetisnull(span->get(), 0, 0))
                break;
            const qint64 oldest = QByteArray(PQgetvalue(span->get(), 0, 0)).toLongLong();
            const qint64 newest = QByteArray(PQgetvalue(span->get(), 0, 1)).toLongLong();
            const double share = double(left - keep) / double(left);
            const qint64 cutoff
                = oldest + std::max<qint64>(1, qint64(double(newest - oldest + 1) * share));
            Result<qint64> removed = deleteOlderThan(cutoff);
            if (!removed)
                return removed.error();
            outcome.samplesRemoved += *removed;
            left -= *removed;
        }
    }
    if (outcome.samplesRemoved > 0) {
        if (Status vacuumed = vacuum(); !vacuumed)
            return vacuumed.error();
        Result<qint64> after = sizeBytes();
        if (!after)
            return after.error();
        outcome.bytesAfter = *after;
    }
    return outcome;
}
} // namespace Fatek
