#pragma once

#include "core/session/watchvalue.h"
#include "itemvalues.h"

#include <QHash>
#include <QList>

#include <cstdint>
#include <vector>

namespace Fatek {

// One item a link watches: the caller's key (unique in the process, see newKey(): tables sharing
// a link hand in one union of their items), the item and how often it is read.
struct WatchedItem
{
    std::uint64_t key = 0;
    WatchItemSpec spec;
    int intervalMs = 500;

    // A fresh key from a process-wide counter.
    static std::uint64_t newKey();
    // The first of `count` consecutive fresh keys (a consumer that finds its items by key - first).
    static std::uint64_t newKeys(std::size_t count);
};

// The value of one watch item as a link reports it: its elements' words and their join.
struct WatchItemValue
{
    std::uint64_t key = 0;
    // Element 0 (the item's address) first, one per element; an element not read in this report
    // keeps its last word (0 before its first read).
    std::vector<std::uint32_t> words;
    std::uint64_t raw = 0; // the words joined (ItemValues::join)
    // Every element has been read at least once: before that `raw` is no value of the PLC's.
    bool hasValue = false;
    // The item's quality is its worst element's; Stale ("not read in this cycle") when only some
    // of its elements were reported. `time` is the newest of its elements' times.
    ValueQuality quality = ValueQuality::Error;
    Message error;
    QDateTime time;
    // What the far end calls the item (the name in a gateway's watch list); empty for a direct
    // link, whose names are the window's own.
    QString name;
};

// The one place that turns element values (what a session polls) into item values (what a table,
// the CLI monitor and the gateway show or publish). Holds the items of one link: splits them into
// poll entries, and joins each batch of element values back into the values of the items they
// belong to, keeping each element's last word between batches.
class ItemAssembler
{
public:
    // Replaces the items. An item whose key and elements stay keeps its words (a new format over
    // the same elements shows the same value at once); others start afresh with new poll ids.
    void setItems(const QList<WatchedItem> &items);
    QList<WatchedItem> items() const;
    int itemCount() const { return static_cast<int>(m_items.size()); }
    // What the session polls for these items: one entry per element.
    QList<WatchEntry> pollEntries() const;

    // The values of the items the batch has elements of (in the order of the items), each with
    // its elements' words joined. Values for poll ids of no item (old ones) are ignored.
    QList<WatchItemValue> assemble(const QList<WatchValue> &batch);
    // Every item at once with `quality` and `reason` (the link went away): the last words stay.
    QList<WatchItemValue> markAll(ValueQuality quality, const Message &reason);

private:
    struct Item
    {
        std::uint64_t key = 0;
        ItemValues values;
        int intervalMs = 500;
        std::vector<std::uint32_t> words;
        std::vector<bool> read; // per element: read at least once
        ValueQuality quality = ValueQuality::Error;
        Message error;
        QDateTime time;
    };
    WatchItemValue valueOf(const Item &item) const;
    void rebuildIndex();

    std::vector<Item> m_items;
    QHash<std::uint64_t, std::size_t> m_itemOfPollId;
};

} // namespace Fatek
