#pragma once

#include "historystore.h"

#include <QString>

#include <string>

struct pg_conn;
struct pg_result;

namespace Fatek {

// A history store in a PostgreSQL database, through libpq's C API: the schema of the SQLite
// store in three tables (fatek_history_meta, _series, _samples), shared by several gateways that
// write and studios that read. One connection, synchronous. A connection lost (the server
// restarted, the network) is opened again (PQreset) by the next call, and a call that lost it
// midway is tried once more on the new one: every write is an upsert, so a repeat is harmless.
class PostgresHistoryStore : public HistoryStore
{
public:
    // `url`: a libpq URI ("postgresql://user:password@host/db") or key=value string. Connects
    // with a 5 s connect_timeout and application_name=fatek-history unless the URL says
    // otherwise; ReadWrite makes the tables when the database has none of them.
    static Result<std::unique_ptr<HistoryStore>> open(const QString &url, HistoryStore::Mode mode);
    ~PostgresHistoryStore() override;

    // The URL without its password (for messages): a URI loses ":password" and any
    // "password=" parameter, a key=value string its password pair.
    static QString withoutPassword(const QString &url);

    QString location() const override { return m_location; }
    Result<qint64> seriesId(const HistorySeries &series) override;
    Result<QList<HistorySeries>> series() const override;
    Status append(const std::vector<HistoryRecord> &records) override;
    Result<std::vector<HistorySample>> samples(qint64 series, qint64 fromMs, qint64 toMs,
                                               qint64 limit = 0) const override;
    Result<HistoryRetentionOutcome> applyRetention(const HistoryRetention &retention,
                                                   qint64 nowMs) override;
    Result<qint64> sizeBytes() const override;
    Result<qint64> sampleCount() const override;

private:
    // A query's result, cleared when it goes.
    class Reply
    {
    public:
        explicit Reply(pg_result *result = nullptr)
            : m_result(result)
        {}
        Reply(Reply &&other) noexcept;
        Reply &operator=(Reply &&other) noexcept;
        Reply(const Reply &) = delete;
        Reply &operator=(const Reply &) = delete;
        ~Reply();
        pg_result *get() const { return m_result; }

    private:
        pg_result *m_result;
    };
    // How a failure is reported: the message id of the operation (%1 location, %2 reason).
    using Failure = const MessageDef &;

    PostgresHistoryStore(QString location, HistoryStore::Mode mode);

    // The failure of `reply` (or of the connection when it has none) as `id`, with libpq's or the
    // server's reason; LinkError when the connection is gone, ReadOnly when a read-only session
    // refused a change.
    ProtocolError failure(Failure id, const Reply *reply = nullptr) const;
    // Runs `sql` (no parameters); an error of `id` unless it returned `expected`.
    Result<Reply> exec(const char *sql, Failure id, int expected) const;
    // The connection for the next call: opened again (once) when it was lost.
    Status connected(Failure id) const;
    // Runs `op`; when it failed because the connection was lost, once more on a new one.
    template<typename T, typename Op>
    Result<T> retried(Failure id, Op op) const;
    // What a new session needs: READ ONLY for a reader.
    Status setUpSession(Failure id) const;
    // Tells what the database holds; makes the tables (ReadWrite) when it holds none of them.
    Status checkAndCreate();
    Status appendOnce(const std::vector<HistoryRecord> &records);
    // Bytes a sample takes in the table and its index when packed (measured once, see .cpp).
    Result<double> bytesPerSample();
    Result<qint64> deleteOlderThan(qint64 cutoffMs);
    Status vacuum();

    QString m_location;
    HistoryStore::Mode m_mode;
    pg_conn *m_conn = nullptr;
    mutable bool m_prepared = false; // the append statement, on this session
    double m_bytesPerSample = 0;
};

} // namespace Fatek
