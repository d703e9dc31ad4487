#pragma once

#include "core/protocol/request.h"
#include "core/protocol/result.h"
#include "core/session/watchvalue.h"
#include "watchlist.h"

#include <QList>
#include <QString>

#include <cstdint>
#include <span>
#include <vector>

namespace Fatek {

// The value of one watch item and the elements it is made of. An item (one address and a format)
// may span several elements: a float over R100 is R100 (low word) and R101 (high word), a double
// four registers, a double over DR10 is DR10 and DR12. The session polls and writes elements;
// this class is the one place that splits an item into its elements (poll entries, write
// requests) and joins the elements' words back into the item's raw value, as ValueFormat reads it.
// Every client (watch tables, trends and logs through them, fatek-cli) goes through it.
class ItemValues
{
public:
    // Most elements one item spans: a double over 16-bit registers, R(n)..R(n+3).
    static constexpr int MaxElements = 4;

    ItemValues() = default;
    // Takes fresh poll ids for the item's elements (a counter: cheap, also for a one-off write).
    explicit ItemValues(const WatchItemSpec &item);

    const WatchItemSpec &item() const { return m_item; }
    // Replaces the item. When its elements change (another address, or a format that spans
    // another number of them) it takes fresh poll ids and returns true: the caller polls the new
    // entries, and values still arriving for the old ids match nothing.
    bool setItem(const WatchItemSpec &item);

    // Elements the item spans (address.advanced(0..n-1)); at least 1, so that an item whose
    // format does not fit its address is still polled and shows the element's quality.
    int elementCount() const;
    // Bits of the joined value: the format's width (32 for a float over R100), else the element's
    // own (1, 16 or 32).
    int width() const;
    Address elementAddress(int element) const;

    // One id per element, unique in the process: tables sharing a connection share one session
    // watch list, so their ids must not meet.
    std::span<const std::uint64_t> pollIds() const { return m_pollIds; }
    // The element a poll id stands for (0 = the item's address), or -1 if it is not this item's.
    int elementOf(std::uint64_t pollId) const;
    QList<WatchEntry> pollEntries(int intervalMs) const;

    // The words of the elements, element 0 first, as one raw value: element n fills bits
    // n * (element bits) upwards (R(n+1) is the high word of a float over R(n)). Missing words
    // count as 0; words past elementCount() are ignored.
    std::uint64_t join(std::span<const std::uint32_t> words) const;
    // The reverse: elementCount() words (1 or 0 for a discrete).
    std::vector<std::uint32_t> split(std::uint64_t raw) const;

    // Text of a joined value in the item's format and word order.
    QString text(std::uint64_t raw) const;
    // What a technician typed, in the item's format and word order, as the raw value to write
    // (ValueFormat::parse's grammar and ranges: 12, -5, 0x1A, 1Ah, 0b1010, 1.5 for floats,
    // ON/OFF ...). NaN and infinities only when the item allows them (allowNonFinite). The one
    // check of a typed value before it is written: watch tables, fatek-cli write, the gateway.
    Result<std::uint64_t> parse(const QString &text) const;
    // The raw value to write from the elements' words as given (the gateway's "words"), element 0
    // first, with the checks parse() makes: each word fits its element (0/1 for a discrete,
    // 0..65535 for a register, where join() would cut 70000 to 4464), and a float is finite
    // unless the item allows otherwise. The caller has checked that there are elementCount().
    Result<std::uint64_t> fromWords(std::span<const std::uint32_t> words) const;
    // The request that writes `raw` into every element: 45 for a discrete, 47 over all registers
    // (a float over R100 writes R100 and R101 in one request).
    Request writeRequest(std::uint64_t raw) const;

private:
    void takePollIds();
    Result<std::uint64_t> finite(std::uint64_t raw, const QString &text) const;

    WatchItemSpec m_item;
    std::vector<std::uint64_t> m_pollIds;
};

} // namespace Fatek
