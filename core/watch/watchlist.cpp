#include "watchlist.h"

// Validation and range expansion; the JSON file is in watchlistjson.cpp, the CSV import in
// watchlistcsv.cpp.

#include "core/protocol/addressrange.h"
#include "watchlisterrors.h"
#include "watchmessages.h"

namespace Fatek::WatchList {

using namespace Errors;

namespace {

Status validateInterval(int intervalMs)
{
    if (intervalMs < MinIntervalMs || intervalMs > MaxIntervalMs) {
        return fileError(QStringLiteral("poll interval %1 ms is out of range (%2..%3 ms)")
                             .arg(intervalMs)
                             .arg(MinIntervalMs)
                             .arg(MaxIntervalMs));
    }
    return Ok{};
}

} // namespace

Status validateEntry(const WatchItemSpec &entry)
{
    if (entry.station == 0)
        return fileError(
            QStringLiteral("station 0 is broadcast (no PLC answers): use a station number 1..254"));
    if (entry.station > 254)
        return fileError(QStringLiteral("station %1 is not valid: use a station number 1..254")
                             .arg(entry.station));
    if (Status s = validateAddress(entry.address); !s)
        return s;
    const int count = ValueFormat::elementCount(entry.address, entry.format);
    const QString address = QString::fromStdString(entry.address.toString());
    if (count == 0) {
        return fileError(
            QStringLiteral("format \"%1\" does not apply to %2 (%3)")
                .arg(ValueFormat::name(entry.format), address,
                     QString::fromUtf8(entry.address.info().name.data(),
                                       static_cast<qsizetype>(entry.address.info().name.size()))));
    }
    if (count > 1) {
        if (Status s = validateSpan(entry.address, static_cast<std::uint32_t>(count)); !s) {
            return fileError(QStringLiteral("format \"%1\" on %2 needs %3 elements: %4")
                                 .arg(ValueFormat::name(entry.format), address)
                                 .arg(count)
                                 .arg(lowerFirst(QString::fromStdString(s.error().text()))));
        }
    }
    if (Status s = Alarms::validate(entry); !s)
        return s;
    return HistorySettings::validate(entry);
}

QString itemId(const WatchItemSpec &item)
{
    return QStringLiteral("%1-%2")
        .arg(item.station)
        .arg(QString::fromStdString(item.address.toString()));
}

Status validate(const WatchListFile &file)
{
    for (qsizetype t = 0; t < file.tables.size(); ++t) {
        const WatchTableSpec &table = file.tables.at(t);
        if (Status s = validateInterval(table.intervalMs); !s)
            return atPlace(tablePlace(t), s.error());
        if (table.items.size() > MaxTableItems)
            return atPlace(tablePlace(t), tooManyItems(table.items.size()));
        for (qsizetype i = 0; i < table.items.size(); ++i) {
            if (Status s = validateEntry(table.items.at(i)); !s)
                return atPlace(itemPlace(t, i), s.error());
        }
    }
    qsizetype index = 0;
    for (const auto &entry : file.symbols.entries()) {
        if (Status s = validateAddress(entry.first); !s)
            return atPlace(msg<MsgId::PlaceSymbol>(index + 1), s.error());
        ++index;
    }
    return Ok{};
}

Result<QList<Address>> expandRange(const QString &text)
{
    const auto range = AddressRange::parse(text.toStdString());
    if (!range)
        return range.error();
    // One range becomes that many watch rows: the grammar is AddressRange's, the limit ours.
    if (range->count > static_cast<std::uint32_t>(MaxRangeItems)) {
        return makeError(
            ErrorKind::InvalidAddress,
            msg<MsgId::RangeTooMany>(text.trimmed().toStdString(), range->count, MaxRangeItems));
    }
    QList<Address> addresses;
    addresses.reserve(range->count);
    for (std::uint32_t i = 0; i < range->count; ++i)
        addresses.append(range->start.advanced(i));
    return addresses;
}

} // namespace Fatek::WatchList
