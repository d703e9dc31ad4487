#include "itemassembler.h"

#include "watchmessages.h"

#include <algorithm>
#include <atomic>

namespace Fatek {

namespace {

std::atomic<std::uint64_t> nextItemKey{1};

} // namespace

std::uint64_t WatchedItem::newKey()
{
    return nextItemKey.fetch_add(1);
}

std::uint64_t WatchedItem::newKeys(std::size_t count)
{
    return nextItemKey.fetch_add(count);
}

void ItemAssembler::setItems(const QList<WatchedItem> &items)
{
    QHash<std::uint64_t, std::size_t> old;
    for (std::size_t i = 0; i < m_items.size(); ++i)
        old.insert(m_items[i].key, i);
    std::vector<Item> next;
    next.reserve(static_cast<std::size_t>(items.size()));
    for (const WatchedItem &wanted : items) {
        Item item;
        const auto found = old.constFind(wanted.key);
        if (found != old.cend()) {
            item = m_items[*found];
            const bool otherPlc = item.values.item().station != wanted.spec.station;
            // Other elements, or another PLC's: nothing of the old applies.
            if (item.values.setItem(wanted.spec) || otherPlc)
                item = Item{};
        }
        if (item.words.empty()) {
            item.values = ItemValues(wanted.spec);
            const auto count = static_cast<std::size_t>(item.values.elementCount());
            item.words.assign(count, 0);
            item.read.assign(count, false);
        }
        item.key = wanted.key;
        item.intervalMs = wanted.intervalMs;
        next.push_back(std::move(item));
    }
    m_items = std::move(next);
    rebuildIndex();
}

void ItemAssembler::rebuildIndex()
{
    m_itemOfPollId.clear();
    for (std::size_t i = 0; i < m_items.size(); ++i) {
        for (const std::uint64_t id : m_items[i].values.pollIds())
            m_itemOfPollId.insert(id, i);
    }
}

QList<WatchedItem> ItemAssembler::items() const
{
    QList<WatchedItem> list;
    list.reserve(static_cast<qsizetype>(m_items.size()));
    for (const Item &item : m_items)
        list.append({item.key, item.values.item(), item.intervalMs});
    return list;
}

QList<WatchEntry> ItemAssembler::pollEntries() const
{
    QList<WatchEntry> entries;
    for (const Item &item : m_items)
        entries += item.values.pollEntries(item.intervalMs);
    return entries;
}

QList<WatchItemValue> ItemAssembler::assemble(const QList<WatchValue> &batch)
{
    // Per item of this batch: which of its elements came, and the worst quality among them.
    struct Gathered
    {
        std::size_t item = 0;
        int seen = 0;
        ValueQuality quality = ValueQuality::Good;
        Message error;
        QDateTime time;
    };
    std::vector<Gathered> gathered;
    QHash<std::size_t, std::size_t> gatheredOf;
    for (const WatchValue &v : batch) {
        const auto found = m_itemOfPollId.constFind(v.itemId);
        if (found == m_itemOfPollId.cend())
            continue;
        Item &item = m_items[*found];
        const int element = item.values.elementOf(v.itemId);
        if (element < 0 || element >= static_cast<int>(item.words.size()))
            continue;
        auto slot = gatheredOf.constFind(*found);
        if (slot == gatheredOf.cend()) {
            slot = gatheredOf.insert(*found, gathered.size());
            gathered.push_back({*found, 0, ValueQuality::Good, {}, {}});
        }
        Gathered &g = gathered[*slot];
        ++g.seen;
        const auto e = static_cast<std::size_t>(element);
        // A stale or refused element keeps its last word (the session reports 0 or its last).
        if (v.quality == ValueQuality::Good) {
            item.words[e] = v.value;
            item.read[e] = true;
        }
        if (v.timestamp.isValid() && (!g.time.isValid() || v.timestamp > g.time))
            g.time = v.timestamp;
        if (v.quality == ValueQuality::Error) {
            g.quality = ValueQuality::Error;
            g.error = v.error;
        } else if (v.quality == ValueQuality::Stale && g.quality != ValueQuality::Error) {
            g.quality = ValueQuality::Stale;
            g.error = v.error;
        } else if (v.quality == ValueQuality::Late && g.quality == ValueQuality::Good) {
            g.quality = ValueQuality::Late;
            g.error = v.error;
        }
    }
    std::sort(gathered.begin(), gathered.end(),
              [](const Gathered &a, const Gathered &b) { return a.item < b.item; });
    QList<WatchItemValue> values;
    values.reserve(static_cast<qsizetype>(gathered.size()));
    for (Gathered &g : gathered) {
        Item &item = m_items[g.item];
        if (g.seen < item.values.elementCount() && g.quality == ValueQuality::Good) {
            // Good means every element was read now, not some of them.
            g.quality = ValueQuality::Stale;
            g.error = msg<MsgId::GatewayNoValueThisCycle>();
        }
        item.quality = g.quality;
        item.error = g.quality == ValueQuality::Good ? Message{} : g.error;
        if (g.time.isValid())
            item.time = g.time;
        values.append(valueOf(item));
    }
    return values;
}

QList<WatchItemValue> ItemAssembler::markAll(ValueQuality quality, const Message &reason)
{
    QList<WatchItemValue> values;
    values.reserve(static_cast<qsizetype>(m_items.size()));
    for (Item &item : m_items) {
        item.quality = quality;
        item.error = reason;
        values.append(valueOf(item));
    }
    return values;
}

WatchItemValue ItemAssembler::valueOf(const Item &item) const
{
    WatchItemValue value;
    value.key = item.key;
    value.words = item.words;
    value.raw = item.values.join(item.words);
    value.hasValue = std::all_of(item.read.cbegin(), item.read.cend(), [](bool r) { return r; });
    value.quality = item.quality;
    value.error = item.error;
    value.time = item.time;
    return value;
}

} // namespace Fatek
