#include "postgreshistorystore.h"

#include "core/qtbridge/secrets.h"
#include "historymessages.h"
#include "postgreshistorystore_p.h"

#include <libpq-fe.h>

#include <QByteArray>
#include <QRegularExpression>
#include <QStringList>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numeric>

namespace Fatek {

namespace {

// PostgreSQL's type oids (pg_type.h): the append statement's array parameters.
constexpr Oid Int2Oid = 21;
constexpr Oid Int8Oid = 20;
constexpr Oid Float8Oid = 701;
constexpr Oid Int8ArrayOid = 1016;
constexpr Oid Float8ArrayOid = 1022;
constexpr Oid Int2ArrayOid = 1005;

constexpr const char *AppendStatement = "fatek_history_append";
// One statement carries at most this many samples (a few MB of parameters); a larger append
// (the writer's backlog after an outage) is several statements in one transaction.
constexpr std::size_t AppendChunk = 50'000;
// The key of the advisory lock the tables are checked and made under: two gateways starting at
// once on a new database would otherwise both create them (one fails on pg_type's unique index).
constexpr qint64 CreateLockKey = HistoryStore::ApplicationId;
constexpr const char *ApplicationName = "fatek-history";

const char *const CreateTablesSql
    = "CREATE TABLE IF NOT EXISTS fatek_history_meta (key text PRIMARY KEY, value text);"
      "CREATE TABLE IF NOT EXISTS fatek_history_series (id bigserial PRIMARY KEY, "
      "source text NOT NULL, item text NOT NULL, label text NOT NULL, format text NOT NULL, "
      "heartbeat_s integer NOT NULL, UNIQUE (source, item));"
      "CREATE TABLE IF NOT EXISTS fatek_history_samples ("
      "series bigint NOT NULL REFERENCES fatek_history_series (id), time_ms bigint NOT NULL, "
      "value double precision, raw bigint NOT NULL, quality smallint NOT NULL, "
      "PRIMARY KEY (series, time_ms))";

// The batch as five arrays in PostgreSQL's binary format, unnested in one statement. Measured
// against COPY into a temporary table and an INSERT ... SELECT from it (10,000 records of 100
// series, PostgreSQL 15, a shared 2-core machine): 197 against 188 ms, 216 against 224 ms, the
// same within the noise; this needs no temporary table per session and one round trip. About
// half of it is the foreign key's check of each row (110 against 103 ms without it).
const char *const AppendSql
    = "INSERT INTO fatek_history_samples (series, time_ms, value, raw, quality) "
      "SELECT * FROM unnest($1::bigint[], $2::bigint[], $3::float8[], $4::bigint[], "
      "$5::smallint[]) "
      "ON CONFLICT (series, time_ms) DO UPDATE SET value = EXCLUDED.value, raw = EXCLUDED.raw, "
      "quality = EXCLUDED.quality";

// The value the line enters the range with, then the range: both from the primary key's index.
const char *const SamplesSql
    = "SELECT time_ms, value, raw, quality FROM ("
      "(SELECT time_ms, value, raw, quality FROM fatek_history_samples "
      "WHERE series = $1 AND time_ms < $2 ORDER BY time_ms DESC LIMIT 1) "
      "UNION ALL "
      "(SELECT time_ms, value, raw, quality FROM fatek_history_samples "
      "WHERE series = $1 AND time_ms >= $2 AND time_ms < $3 ORDER BY time_ms LIMIT $4)) s "
      "ORDER BY time_ms LIMIT $4";

const char *const SizeSql = "SELECT pg_total_relation_size('fatek_history_samples') "
                            "+ pg_total_relation_size('fatek_history_series')";

// PostgreSQL's binary formats are big-endian.
void put16(QByteArray &out, quint16 v)
{
    const char bytes[2] = {char(v >> 8), char(v)};
    out.append(bytes, 2);
}
void put32(QByteArray &out, quint32 v)
{
    const char bytes[4] = {char(v >> 24), char(v >> 16), char(v >> 8), char(v)};
    out.append(bytes, 4);
}
void put64(QByteArray &out, quint64 v)
{
    put32(out, quint32(v >> 32));
    put32(out, quint32(v));
}
quint64 get(const char *data, int bytes)
{
    quint64 v = 0;
    for (int i = 0; i < bytes; ++i)
        v = (v << 8) | static_cast<unsigned char>(data[i]);
    return v;
}

// A one-dimensional array in PostgreSQL's binary format (array_send): its header, then per
// element its length (-1: NULL) and bytes.
QByteArray arrayHeader(Oid element, std::size_t count, std::size_t elementBytes, bool nulls)
{
    QByteArray out;
    out.reserve(qsizetype(20 + count * (4 + elementBytes)));
    put32(out, 1);
    put32(out, nulls ? 1 : 0);
    put32(out, element);
    put32(out, quint32(count));
    put32(out, 1);
    return out;
}

std::string text(const QString &s)
{
    return s.toStdString();
}

} // namespace

PostgresHistoryStore::Reply::Reply(Reply &&other) noexcept
    : m_result(std::exchange(other.m_result, nullptr))
{}

PostgresHistoryStore::Reply &PostgresHistoryStore::Reply::operator=(Reply &&other) noexcept
{
    if (this != &other) {
        PQclear(m_result);
        m_result = std::exchange(other.m_result, nullptr);
    }
    return *this;
}

PostgresHistoryStore::Reply::~Reply()
{
    PQclear(m_result);
}

PostgresHistoryStore::PostgresHistoryStore(QString location, HistoryStore::Mode mode)
    : m_location(std::move(location))
    , m_mode(mode)
{}

PostgresHistoryStore::~PostgresHistoryStore()
{
    PQfinish(m_conn);
}

QString PostgresHistoryStore::withoutPassword(const QString &url)
{
    static const QRegularExpression uri(QStringLiteral("^postgres(ql)?://"),
                                        QRegularExpression::CaseInsensitiveOption);
    const QRegularExpressionMatch match = uri.match(url);
    if (!match.hasMatch()) {
        // key=value: the pair goes, quoted or not.
        static const QRegularExpression pair(
            QStringLiteral("\\s*\\bpassword\\s*=\\s*('(?:[^'\\\\]|\\\\.)*'|\\S*)"));
        return QString(url).remove(pair).trimmed();
    }
    const qsizetype start = match.capturedEnd();
    qsizetype end = url.size();
    for (const QChar c : {QLatin1Char('/'), QLatin1Char('?')}) {
        const qsizetype at = url.indexOf(c, start);
        if (at >= 0)
            end = std::min(end, at);
    }
    QString authority = url.mid(start, end - start);
    if (const qsizetype at = authority.lastIndexOf(QLatin1Char('@')); at >= 0) {
        const qsizetype colon = authority.left(at).indexOf(QLatin1Char(':'));
        if (colon >= 0)
            authority.remove(colon, at - colon);
    }
    QString rest = url.mid(end);
    if (const qsizetype query = rest.indexOf(QLatin1Char('?')); query >= 0) {
        QStringList params = rest.mid(query + 1).split(QLatin1Char('&'));
        params.removeIf([](const QString &p) { return p.startsWith(QLatin1String("password=")); });
        rest = rest.left(query)
               + (params.isEmpty() ? QString() : QLatin1Char('?') + params.join(QLatin1Char('&')));
    }
    // What the authority's end missed (a raw '/' or '?' in the password): masked.
    return Secrets::maskUrl(url.left(start) + authority + rest);
}

Result<std::unique_ptr<HistoryStore>> PostgresHistoryStore::open(const QString &url,
                                                                 HistoryStore::Mode mode)
{
    std::unique_ptr<PostgresHistoryStore> store(
        new PostgresHistoryStore(withoutPassword(url), mode));
    const QByteArray conninfo = url.toUtf8();
    // Before the URL: what it says itself wins. Keepalives tell a dead server from a quiet one
    // within a minute, not the system's two hours.
    const char *const keys[] = {"connect_timeout",
                                "application_name",
                                "keepalives_idle",
                                "keepalives_count",
                                "keepalives_interval",
                                "dbname",
                                nullptr};
    const char *const values[]
        = {"5", ApplicationName, "30", "3", "10", conninfo.constData(), nullptr};
    store->m_conn = PQconnectdbParams(keys, values, 1);
    // Notices (a CREATE ... IF NOT EXISTS that found the table, VACUUM's warnings) are no errors;
    // libpq would print them on the program's standard error.
    if (store->m_conn)
        PQsetNoticeProcessor(
            store->m_conn, [](void *, const char *) {}, nullptr);
    if (!store->m_conn || PQstatus(store->m_conn) != CONNECTION_OK)
        return store->failure(MsgId::HistoryOpenFailed);
    if (Status set = store->setUpSession(MsgId::HistoryOpenFailed); !set)
        return set.error();
    if (Status checked = store->checkAndCreate(); !checked)
        return checked.error();
    return std::unique_ptr<HistoryStore>(std::move(store));
}

ProtocolError PostgresHistoryStore::failure(Failure id, const Reply *reply) const
{
    QString reason;
    ErrorKind kind = ErrorKind::InvalidRequest;
    if (!m_conn || PQstatus(m_conn) == CONNECTION_BAD)
        kind = ErrorKind::LinkError;
    // The server's own sentence when it answered; libpq's when the connection failed.
    const char *primary = reply && reply->get()
                              ? PQresultErrorField(reply->get(), PG_DIAG_MESSAGE_PRIMARY)
                              : nullptr;
    if (primary && *primary) {
        reason = QString::fromUtf8(primary);
        const char *state = PQresultErrorField(reply->get(), PG_DIAG_SQLSTATE);
        if (state && std::strcmp(state, "25006") == 0) // read_only_sql_transaction
            kind = ErrorKind::ReadOnly;
    } else if (m_conn) {
        reason = QString::fromUtf8(PQerrorMessage(m_conn));
    }
    if (reason.trimmed().isEmpty() && reply && reply->get())
        reason = QString::fromUtf8(PQresStatus(PQresultStatus(reply->get())));
    // libpq's messages span lines (one per address tried, a hint): one line in ours.
    return makeError(kind,
                     Message{id, {text(m_location), Message::text(text(reason.simplified()))}});
}

Result<PostgresHistoryStore::Reply> PostgresHistoryStore::exec(const char *sql, Failure id,
                                                               int expected) const
{
    Reply reply(PQexec(m_conn, sql));
    if (!reply.get() || PQresultStatus(reply.get()) != expected)
        return failure(id, &reply);
    return reply;
}

Status PostgresHistoryStore::setUpSession(Failure id) const
{
    m_prepared = false;
    // A series' samples are spread over the table (the series are written interleaved), so the
    // planner prefers a bitmap scan and a sort for a range; reading the primary key's index in
    // order is twice as fast (86,400 samples: 37 instead of 81 ms on the server, no sort on
    // disk). Every other query here is an index or a sequential scan.
    if (auto set = exec("SET enable_bitmapscan = off", id, PGRES_COMMAND_OK); !set)
        return set.error();
    if (m_mode == Mode::ReadOnly) {
        if (auto set
            = exec("SET SESSION CHARACTERISTICS AS TRANSACTION READ ONLY", id, PGRES_COMMAND_OK);
            !set)
            return set.error();
    }
    return Ok{};
}

Status PostgresHistoryStore::connected(Failure id) const
{
    if (PQstatus(m_conn) == CONNECTION_OK)
        return Ok{};
    PQreset(m_conn);
    if (PQstatus(m_conn) != CONNECTION_OK)
        return failure(id);
    return setUpSession(id);
}

// Read before anything is written, under the advisory lock in the transaction that makes the
// tables: a database holding tables of ours without the mark, or another program's meta, is left
// as it is; one with none of them gets them (ReadWrite) or is missing (ReadOnly).
Status PostgresHistoryStore::checkAndCreate()
{
    Failure id = MsgId::HistoryOpenFailed;
    const bool write = m_mode == Mode::ReadWrite;
    const std::string location = text(m_location);
    if (write) {
        if (auto begun = exec("BEGIN", id, PGRES_COMMAND_OK); !begun)
            return begun.error();
        const std::string lock
            = "SELECT pg_advisory_xact_lock(" + std::to_string(CreateLockKey) + ")";
        if (auto locked = exec(lock.c_str(), id, PGRES_TUPLES_OK); !locked)
            return locked.error();
    }
    auto judge = [&]() -> Result<bool> { // whether the tables must be made
        auto found = exec("SELECT to_regclass('fatek_history_meta') IS NOT NULL, "
                          "to_regclass('fatek_history_series') IS NOT NULL, "
                          "to_regclass('fatek_history_samples') IS NOT NULL",
                          id, PGRES_TUPLES_OK);
        if (!found)
            return found.error();
        const PGresult *r = found->get();
        const bool meta = *PQgetvalue(r, 0, 0) == 't';
        const bool tables = *PQgetvalue(r, 0, 1) == 't' && *PQgetvalue(r, 0, 2) == 't';
        const bool any = meta || *PQgetvalue(r, 0, 1) == 't' || *PQgetvalue(r, 0, 2) == 't';
        if (!any) {
            if (!write)
                return makeError(ErrorKind::InvalidRequest, msg<MsgId::HistoryMissing>(location));
            return true;
        }
        if (!meta)
            return makeError(ErrorKind::InvalidRequest, msg<MsgId::HistoryNotHistory>(location));
        Reply marks(PQexec(m_conn, "SELECT key::text, value::text FROM fatek_history_meta "
                                   "WHERE key::text IN ('format', 'application')"));
        if (PQresultStatus(marks.get()) != PGRES_TUPLES_OK) {
            // Another program's meta table, with other columns.
            const char *state = PQresultErrorField(marks.get(), PG_DIAG_SQLSTATE);
            if (state && std::strcmp(state, "42703") == 0)
                return makeError(ErrorKind::InvalidRequest,
                                 msg<MsgId::HistoryNotHistory>(location));
            return failure(id, &marks);
        }
        QString application;
        QString format;
        for (int row = 0; row < PQntuples(marks.get()); ++row) {
            const QString value = QString::fromUtf8(PQgetvalue(marks.get(), row, 1));
            (std::strcmp(PQgetvalue(marks.get(), row, 0), "format") == 0 ? format : application)
                = value;
        }
        bool number = false;
        const int version = format.toInt(&number);
        if (application != QLatin1String(ApplicationName) || !number || version < 1)
            return makeError(ErrorKind::InvalidRequest, msg<MsgId::HistoryNotHistory>(location));
        if (version > FormatVersion)
            return makeError(ErrorKind::InvalidRequest,
                             msg<MsgId::HistoryNewer>(location, version, FormatVersion));
        if (!tables && !write)
            return makeError(ErrorKind::InvalidRequest, msg<MsgId::HistoryMissing>(location));
        return !tables;
    };
    Result<bool> create = judge();
    Status made = create ? Status(Ok{}) : Status(create.error());
    if (made && *create) {
        const std::string sql = std::string(CreateTablesSql)
                                + ";INSERT INTO fatek_history_meta VALUES ('format', '"
                                + std::to_string(FormatVersion) + "'), ('application', '"
                                + ApplicationName + "') ON CONFLICT (key) DO NOTHING";
        if (auto done = exec(sql.c_str(), id, PGRES_COMMAND_OK); !done)
            made = done.error();
    }
    if (write) {
        if (made) {
            if (auto committed = exec("COMMIT", id, PGRES_COMMAND_OK); !committed)
                made = committed.error();
        } else {
            PQclear(PQexec(m_conn, "ROLLBACK"));
        }
    }
    return made;
}

Result<qint64> PostgresHistoryStore::seriesId(const HistorySeries &series)
{
    const QByteArray values[]
        = {series.source.toUtf8(), series.item.toUtf8(), series.label.toUtf8(),
           series.format.toUtf8(), QByteArray::number(series.heartbeatS)};
    return retried<qint64>(MsgId::HistoryWriteFailed, [&]() -> Result<qint64> {
        const char *params[5];
        for (int i = 0; i < 5; ++i)
            params[i] = values[i].constData();
        // Several writers asking at once: the second waits for the first's row and updates it.
        Reply reply(PQexecParams(m_conn,
                                 "INSERT INTO fatek_history_series "
                                 "(source, item, label, format, heartbeat_s) "
                                 "VALUES ($1, $2, $3, $4, $5::integer) "
                                 "ON CONFLICT (source, item) DO UPDATE SET label = EXCLUDED.label, "
                                 "format = EXCLUDED.format, heartbeat_s = EXCLUDED.heartbeat_s "
                                 "RETURNING id",
                                 5, nullptr, params, nullptr, nullptr, 0));
        if (PQresultStatus(reply.get()) != PGRES_TUPLES_OK || PQntuples(reply.get()) != 1)
            return failure(MsgId::HistoryWriteFailed, &reply);
        return QByteArray(PQgetvalue(reply.get(), 0, 0)).toLongLong();
    });
}

Result<QList<HistorySeries>> PostgresHistoryStore::series() const
{
    return retried<QList<HistorySeries>>(
        MsgId::HistoryReadFailed, [&]() -> Result<QList<HistorySeries>> {
            // COLLATE "C": the order of the SQLite store (bytes), whatever the database's locale.
            auto reply = exec("SELECT id, source, item, label, format, heartbeat_s "
                              "FROM fatek_history_series "
                              "ORDER BY source COLLATE \"C\", item COLLATE \"C\"",
                              MsgId::HistoryReadFailed, PGRES_TUPLES_OK);
            if (!reply)
                return reply.error();
            const PGresult *r = reply->get();
            QList<HistorySeries> list;
            list.reserve(PQntuples(r));
            for (int row = 0; row < PQntuples(r); ++row) {
                HistorySeries s;
                s.id = QByteArray(PQgetvalue(r, row, 0)).toLongLong();
                s.source = QString::fromUtf8(PQgetvalue(r, row, 1));
                s.item = QString::fromUtf8(PQgetvalue(r, row, 2));
                s.label = QString::fromUtf8(PQgetvalue(r, row, 3));
                s.format = QString::fromUtf8(PQgetvalue(r, row, 4));
                s.heartbeatS = QByteArray(PQgetvalue(r, row, 5)).toInt();
                list.append(s);
            }
            return list;
        });
}

Status PostgresHistoryStore::append(const std::vector<HistoryRecord> &records)
{
    if (records.empty())
        return Ok{};
    return retried<Ok>(MsgId::HistoryWriteFailed, [&] { return appendOnce(records); });
}

Status PostgresHistoryStore::appendOnce(const std::vector<HistoryRecord> &records)
{
    Failure id = MsgId::HistoryWriteFailed;
    if (!m_prepared) {
        const Oid types[]
            = {Int8ArrayOid, Int8ArrayOid, Float8ArrayOid, Int8ArrayOid, Int2ArrayOid};
        Reply prepared(PQprepare(m_conn, AppendStatement, AppendSql, 5, types));
        if (PQresultStatus(prepared.get()) != PGRES_COMMAND_OK)
            return failure(id, &prepared);
        m_prepared = true;
    }
    // One statement may not change a row twice (ON CONFLICT): the last of a (series, time) wins,
    // as it would in separate statements. In key order, the index is walked forward.
    std::vector<std::size_t> order(records.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        const HistoryRecord &x = records[a];
        const HistoryRecord &y = records[b];
        return x.series != y.series ? x.series < y.series : x.sample.timeMs < y.sample.timeMs;
    });
    std::vector<std::size_t> kept;
    kept.reserve(order.size());
    for (std::size_t i = 0; i < order.size(); ++i) {
        const HistoryRecord &r = records[order[i]];
        if (i + 1 < order.size() && records[order[i + 1]].series == r.series
            && records[order[i + 1]].sample.timeMs == r.sample.timeMs)
            continue;
        kept.push_back(order[i]);
    }

    auto run = [&](std::size_t from, std::size_t to) -> Status {
        const std::size_t n = to - from;
        bool nulls = false;
        for (std::size_t i = from; i < to; ++i)
            nulls = nulls || std::isnan(records[kept[i]].sample.value);
        QByteArray series = arrayHeader(Int8Oid, n, 8, false);
        QByteArray times = arrayHeader(Int8Oid, n, 8, false);
        QByteArray values = arrayHeader(Float8Oid, n, 8, nulls);
        QByteArray raws = arrayHeader(Int8Oid, n, 8, false);
        QByteArray qualities = arrayHeader(Int2Oid, n, 2, false);
        for (std::size_t i = from; i < to; ++i) {
            const HistoryRecord &r = records[kept[i]];
            put32(series, 8);
            put64(series, quint64(r.series));
            put32(times, 8);
            put64(times, quint64(r.sample.timeMs));
            if (std::isnan(r.sample.value)) {
                put32(values, quint32(-1)); // NULL: a value PostgreSQL would sort and compare
            } else {
                quint64 bits = 0;
                std::memcpy(&bits, &r.sample.value, sizeof bits);
                put32(values, 8);
                put64(values, bits);
            }
            put32(raws, 8);
            put64(raws, r.sample.raw); // bit for bit: the top bit makes it negative
            put32(qualities, 2);
            put16(qualities, static_cast<quint16>(r.sample.quality));
        }
        const char *params[] = {series.constData(), times.constData(), values.constData(),
                                raws.constData(), qualities.constData()};
        const int lengths[] = {int(series.size()), int(times.size()), int(values.size()),
                               int(raws.size()), int(qualities.size())};
        const int formats[] = {1, 1, 1, 1, 1};
        Reply reply(PQexecPrepared(m_conn, AppendStatement, 5, params, lengths, formats, 0));
        if (PQresultStatus(reply.get()) != PGRES_COMMAND_OK)
            return failure(id, &reply);
        return Ok{};
    };

    if (kept.size() <= AppendChunk)
        return run(0, kept.size()); // one statement: one transaction
    if (auto begun = exec("BEGIN", id, PGRES_COMMAND_OK); !begun)
        return begun.error();
    Status done = Ok{};
    for (std::size_t from = 0; done && from < kept.size(); from += AppendChunk)
        done = run(from, std::min(kept.size(), from + AppendChunk));
    if (done) {
        if (auto committed = exec("COMMIT", id, PGRES_COMMAND_OK); !committed)
            return committed.error();
        return Ok{};
    }
    if (PQstatus(m_conn) == CONNECTION_OK)
        PQclear(PQexec(m_conn, "ROLLBACK"));
    return done;
}

Result<std::vector<HistorySample>> PostgresHistoryStore::samples(qint64 series, qint64 fromMs,
                                                                 qint64 toMs, qint64 limit) const
{
    const QByteArray values[] = {QByteArray::number(series), QByteArray::number(fromMs),
                                 QByteArray::number(toMs), QByteArray::number(limit)};
    return retried<std::vector<HistorySample>>(
        MsgId::HistoryReadFailed, [&]() -> Result<std::vector<HistorySample>> {
            // LIMIT NULL is no limit.
            const char *params[]
                = {values[0].constData(), values[1].constData(), values[2].constData(),
                   limit > 0 ? values[3].constData() : nullptr};
            // Binary results: the doubles exactly as stored, no text to parse.
            Reply reply(PQexecParams(m_conn, SamplesSql, 4, nullptr, params, nullptr, nullptr, 1));
            if (PQresultStatus(reply.get()) != PGRES_TUPLES_OK)
                return failure(MsgId::HistoryReadFailed, &reply);
            const PGresult *r = reply.get();
            std::vector<HistorySample> list(std::size_t(PQntuples(r)));
            for (int row = 0; row < PQntuples(r); ++row) {
                HistorySample &s = list[std::size_t(row)];
                s.timeMs = qint64(get(PQgetvalue(r, row, 0), 8));
                if (!PQgetisnull(r, row, 1)) {
                    const quint64 bits = get(PQgetvalue(r, row, 1), 8);
                    std::memcpy(&s.value, &bits, sizeof bits);
                }
                s.raw = get(PQgetvalue(r, row, 2), 8);
                s.quality = static_cast<HistoryQuality>(get(PQgetvalue(r, row, 3), 2));
            }
            return list;
        });
}

Result<qint64> PostgresHistoryStore::sizeBytes() const
{
    return retried<qint64>(MsgId::HistoryReadFailed, [&]() -> Result<qint64> {
        auto reply = exec(SizeSql, MsgId::HistoryReadFailed, PGRES_TUPLES_OK);
        if (!reply)
            return reply.error();
        return QByteArray(PQgetvalue(reply->get(), 0, 0)).toLongLong();
    });
}

Result<qint64> PostgresHistoryStore::sampleCount() const
{
    return retried<qint64>(MsgId::HistoryReadFailed, [&]() -> Result<qint64> {
        auto reply = exec("SELECT count(*) FROM fatek_history_samples", MsgId::HistoryReadFailed,
                          PGRES_TUPLES_OK);
        if (!reply)
            return reply.error();
        return QByteArray(PQgetvalue(reply->get(), 0, 0)).toLongLong();
    });
}

} // namespace Fatek
