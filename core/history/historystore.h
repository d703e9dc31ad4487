#pragma once

#include "historytypes.h"

#include "core/protocol/result.h"

#include <QList>
#include <QString>

#include <memory>
#include <vector>

namespace Fatek {

// A history store: where recorded values are kept and read back. Two kinds, one schema: an
// SQLite file (SqliteHistoryStore, the default: the studio's data folder, the gateway's state
// directory) and a PostgreSQL database (PostgresHistoryStore, "postgresql://..." locations:
// several gateways write into one, studios read it). Synchronous and single-threaded: the
// studio and the gateway use a store through HistoryWriter (its own thread); fatek-cli and the
// benchmarks use it directly.
class HistoryStore
{
public:
    enum class Mode {
        ReadWrite, // opened or created (its folder too), its tables made when new
        ReadOnly,  // must exist; nothing is ever changed
    };

    HistoryStore() = default;
    HistoryStore(const HistoryStore &) = delete;
    HistoryStore &operator=(const HistoryStore &) = delete;
    virtual ~HistoryStore() = default;

    // "postgresql://" or "postgres://" URLs (libpq's URI form) open PostgreSQL; anything else is
    // an SQLite file's path. A location that is not a history store (another program's file or
    // tables), a damaged or locked file, a newer format, a refused login: refused with the
    // reason, and nothing is changed.
    static Result<std::unique_ptr<HistoryStore>> open(const QString &location, Mode mode);
    // Whether this build can open PostgreSQL locations (the Windows build has no libpq).
    static bool hasPostgres();

    // The location as given, without a password ("postgresql://fatek@db/plant").
    virtual QString location() const = 0;

    // The series' id (series.id is ignored), made when the store has no such (source, item);
    // its label, format and heartbeat are updated when they changed. Several writers (gateways
    // on one PostgreSQL store) may ask for the same series at once: they get the same id.
    virtual Result<qint64> seriesId(const HistorySeries &series) = 0;
    // Every series, ordered by source and item (with their ids).
    virtual Result<QList<HistorySeries>> series() const = 0;

    // One transaction. A sample whose series and time are already stored replaces it.
    virtual Status append(const std::vector<HistoryRecord> &records) = 0;

    // The samples of one series with fromMs <= time < toMs, oldest first, plus the last one
    // before fromMs when there is one (the value the line enters the range with). `limit` > 0
    // stops after that many (the CLI's --limit).
    virtual Result<std::vector<HistorySample>> samples(qint64 series, qint64 fromMs, qint64 toMs,
                                                       qint64 limit = 0) const = 0;

    // Removes what `retention` no longer keeps, as of nowMs.
    virtual Result<HistoryRetentionOutcome> applyRetention(const HistoryRetention &retention,
                                                           qint64 nowMs)
        = 0;
    // Bytes the store takes (the file with its WAL; PostgreSQL: the tables' total relation size).
    virtual Result<qint64> sizeBytes() const = 0;
    // How many samples it holds (every series).
    virtual Result<qint64> sampleCount() const = 0;

    // The store's format (SQLite PRAGMA user_version; PostgreSQL: the fatek_history_meta row)
    // and, for SQLite, its mark (PRAGMA application_id, "FAHS"), which tells a history file
    // from another program's SQLite file.
    static constexpr int FormatVersion = 1;
    static constexpr int ApplicationId = 0x46414853;
};

} // namespace Fatek
