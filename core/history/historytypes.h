#pragma once

#include <QList>
#include <QMetaType>
#include <QString>

#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

namespace Fatek {

// The quality a history sample was read with. Only Good and Late carry a value worth drawing;
// Stale, Error and Off end the line (a gap) until the next Good or Late sample.
enum class HistoryQuality : std::uint8_t {
    Good = 0,  // read in its cycle
    Late = 1,  // good when read, the line is behind (ValueQuality::Late)
    Stale = 2, // not read (timeout, link down): no value
    Error = 3, // refused by the PLC or cannot be polled: no value
    Off = 4,   // not recorded from here on (the recorder stopped, the item left the list)
};

namespace History {
// "good", "late", "stale", "error", "off": the CLI's, the CSV's and the JSON's words.
QString qualityName(HistoryQuality quality);
std::optional<HistoryQuality> qualityFromName(const QString &name);
// Whether a sample of this quality has a value to draw.
inline bool hasValue(HistoryQuality q)
{
    return q == HistoryQuality::Good || q == HistoryQuality::Late;
}
inline constexpr int DefaultHeartbeatS = 600;
} // namespace History

// One recorded item (a time series) of a store. Its key is (source, item): the source is the
// plant connection's name (the studio's connection, the gateway's "connections" name: several
// gateways sharing one PostgreSQL store keep their names apart), the item "1-R100" (station and
// address, as alarm ids). The rest describes it and is updated when it changes.
struct HistorySeries
{
    qint64 id = 0; // the store's own; 0 until the store gave one
    QString source;
    QString item;   // "1-R100"
    QString label;  // the item's name in the watch list ("Tank level"); may be empty
    QString format; // the watch list's format name ("signed", "float", ...)
    int heartbeatS = History::DefaultHeartbeatS; // a value is stored at least this often

    // "line1/1-R100": how the CLI and the trend name a series.
    QString key() const { return source + QLatin1Char('/') + item; }
    bool operator==(const HistorySeries &) const = default;
};

// One value kept: when the PLC was read (ms since the epoch, UTC), the number in the item's
// format (NaN when the item has none: ASCII, or no value at this quality), its words joined as
// read (ItemValues::join) and the quality.
struct HistorySample
{
    qint64 timeMs = 0;
    double value = std::numeric_limits<double>::quiet_NaN();
    std::uint64_t raw = 0;
    HistoryQuality quality = HistoryQuality::Good;

    bool operator==(const HistorySample &o) const
    {
        return timeMs == o.timeMs && raw == o.raw && quality == o.quality
               && (value == o.value || (std::isnan(value) && std::isnan(o.value)));
    }
};

// A sample on its way into a store: which series (HistorySeries::id of that store) and the
// sample.
struct HistoryRecord
{
    qint64 series = 0;
    HistorySample sample;
};

// What a trend draws of a range, reduced (HistoryReducer): points in time order, each a value
// or a gap (the line ends there). Per time bucket at most the first, minimum, maximum and last
// value, so a week of 1 s values keeps its peaks in 1,000 pixel columns.
struct HistoryPoint
{
    qint64 timeMs = 0;
    double value = 0;
    bool gap = false;

    bool operator==(const HistoryPoint &) const = default;
};

// How long a store keeps values, applied while running (HistoryWriter, every minute) and by
// fatek-cli: samples older than maxAgeS go; beyond maxBytes the oldest go until it fits (the
// file or database never grows past it by more than one minute of values). 0: no limit.
struct HistoryRetention
{
    qint64 maxAgeS = 0;
    qint64 maxBytes = 0;

    bool operator==(const HistoryRetention &) const = default;
};

// What one retention pass did.
struct HistoryRetentionOutcome
{
    qint64 samplesRemoved = 0;
    qint64 bytesBefore = 0;
    qint64 bytesAfter = 0;
};

} // namespace Fatek

Q_DECLARE_METATYPE(Fatek::HistorySample)
Q_DECLARE_METATYPE(Fatek::HistorySeries)
