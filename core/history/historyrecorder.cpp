#include "historyrecorder.h"

// What a plant connection's items did, decided per value: kept or not.

#include "core/watch/valueformat.h"
#include "core/watch/watchlist.h"

#include <QDateTime>

#include <algorithm>
#include <cmath>

namespace Fatek {

namespace {

HistoryQuality qualityOf(ValueQuality quality)
{
    switch (quality) {
    case ValueQuality::Good: return HistoryQuality::Good;
    case ValueQuality::Late: return HistoryQuality::Late;
    case ValueQuality::Stale: return HistoryQuality::Stale;
    case ValueQuality::Error: return HistoryQuality::Error;
    }
    return HistoryQuality::Error;
}

} // namespace

HistoryRecorder::HistoryRecorder(const QString &source, HistorySink *sink, QObject *parent)
    : QObject(parent)
    , m_source(source)
    , m_sink(sink)
    , m_clock([] { return QDateTime::currentMSecsSinceEpoch(); })
{
    // A child, so that it follows the recorder into the plant connection's thread.
    m_timer.setParent(this);
    m_timer.setInterval(1000);
    connect(&m_timer, &QTimer::timeout, this, &HistoryRecorder::tick);
}

HistoryRecorder::~HistoryRecorder()
{
    keepOffAll(m_clock());
    if (m_plant)
        m_plant->unsubscribe(this);
}

void HistoryRecorder::setClock(Clock clock)
{
    m_clock = std::move(clock);
}

void HistoryRecorder::setRecordAll(std::optional<HistorySetting> setting)
{
    if (m_recordAll == setting)
        return;
    m_recordAll = setting;
    rebuild();
}

void HistoryRecorder::setItems(const QList<WatchedItem> &items)
{
    m_given = items;
    rebuild();
}

int HistoryRecorder::seriesCount() const
{
    return static_cast<int>(m_items.size());
}

HistorySeries HistoryRecorder::seriesOf(const Item &item) const
{
    HistorySeries series;
    series.source = m_source;
    series.item = item.id;
    series.label = item.watched.spec.name;
    series.format = ValueFormat::name(item.watched.spec.format);
    series.heartbeatS = item.setting.heartbeatS;
    return series;
}

void HistoryRecorder::rebuild()
{
    const qint64 now = m_clock();
    std::vector<Item> items;
    QHash<QString, std::size_t> index;
    std::vector<bool> stays(m_items.size(), false);
    for (const WatchedItem &watched : std::as_const(m_given)) {
        const WatchItemSpec &spec = watched.spec;
        const std::optional<HistorySetting> setting = spec.history ? spec.history : m_recordAll;
        if (!setting)
            continue;
        const QString id = WatchList::itemId(spec);
        if (index.contains(id))
            continue; // the same station and address in another table: the first one counts
        Item item;
        item.watched = watched;
        item.setting = *setting;
        item.id = id;
        item.width = ValueFormat::valueWidth(spec.address, spec.format);
        item.numeric = item.width > 1 && spec.format != DisplayFormat::Ascii;
        const HistorySeries series = seriesOf(item);
        if (const auto old = m_index.constFind(id); old != m_index.cend()) {
            // The item stays: its line goes on from its last kept value.
            Item &was = m_items[*old];
            stays[*old] = true;
            item.series = was.series;
            item.kept = was.kept;
            item.keptAtMs = was.keptAtMs;
            item.seen = was.seen;
            item.needFirst = was.needFirst;
            const WatchItemSpec &before = was.watched.spec;
            if (before.format != spec.format || before.swapWords != spec.swapWords) {
                // The same words mean another number: the line starts again from the next one.
                item.needFirst = true;
                item.seen.reset();
            }
            if (seriesOf(was) != series)
                item.series = m_sink->addSeries(series);
        } else {
            item.series = m_sink->addSeries(series);
        }
        index.insert(id, items.size());
        items.push_back(std::move(item));
    }
    Records out;
    for (std::size_t i = 0; i < m_items.size(); ++i) {
        if (!stays[i])
            keepOff(m_items[i], now, out);
    }
    // Keys in one run: a value finds its item by key - first, without a look-up.
    m_firstKey = items.empty() ? 0 : WatchedItem::newKeys(items.size());
    for (std::size_t i = 0; i < items.size(); ++i)
        items[i].watched.key = m_firstKey + i;
    m_items = std::move(items);
    m_index = std::move(index);
    flush(out);
    subscribe();
    if (m_items.empty())
        m_timer.stop();
    else if (!m_timer.isActive())
        m_timer.start();
}

void HistoryRecorder::attach(PlantConnection *plant)
{
    if (m_plant == plant)
        return;
    if (m_plant) {
        // Nothing more comes from the old link: its lines end now.
        keepOffAll(m_clock());
        m_plant->unsubscribe(this);
    }
    m_plant = plant;
    m_linkDown = plant && plant->linkState() != LinkState::Connected;
    for (Item &item : m_items)
        item.needFirst = true;
    subscribe();
}

void HistoryRecorder::subscribe()
{
    if (!m_plant)
        return;
    QList<WatchedItem> watched;
    watched.reserve(static_cast<qsizetype>(m_items.size()));
    for (const Item &item : m_items)
        watched.append(item.watched);
    if (watched.isEmpty())
        m_plant->unsubscribe(this);
    else
        m_plant->subscribe(this, watched);
}

std::optional<HistorySample>
HistoryRecorder::sampleOf(const Item &item, const WatchItemValue &value, qint64 nowMs) const
{
    HistorySample sample;
    sample.quality = qualityOf(value.quality);
    const bool good = History::hasValue(sample.quality);
    if (good && !value.hasValue)
        return std::nullopt; // not every element read yet: no value of the PLC's
    sample.timeMs = value.time.isValid() ? value.time.toMSecsSinceEpoch() : nowMs;
    sample.raw = value.raw;
    if (good) {
        const WatchItemSpec &spec = item.watched.spec;
        if (const auto number
            = ValueFormat::number(value.raw, item.width, spec.format, spec.swapWords)) {
            sample.value = *number;
        }
    }
    return sample;
}

bool HistoryRecorder::heartbeatDue(Item &item, qint64 nowMs) const
{
    if (nowMs < item.keptAtMs)
        item.keptAtMs = nowMs; // the clock stepped back: the heartbeat counts from now
    return nowMs - item.keptAtMs >= qint64(item.setting.heartbeatS) * 1000;
}

bool HistoryRecorder::worthKeeping(Item &item, const HistorySample &sample, qint64 nowMs) const
{
    const bool hasValue = History::hasValue(sample.quality);
    if (m_linkDown && !hasValue)
        return false; // the Off kept for the link already ended the line
    if (item.needFirst || !item.kept)
        return true;
    const HistorySample &kept = *item.kept;
    if (hasValue != History::hasValue(kept.quality))
        return true; // a gap begins or ends
    if (hasValue) {
        const double deadband = item.numeric ? item.setting.deadband : 0;
        if (deadband > 0 && std::isfinite(sample.value) && std::isfinite(kept.value)) {
            if (std::abs(sample.value - kept.value) > deadband)
                return true;
        } else if (sample.raw != kept.raw) {
            return true;
        }
    }
    // Unchanged: kept when the heartbeat is due and this is a newer reading.
    return sample.timeMs > kept.timeMs && heartbeatDue(item, nowMs);
}

void HistoryRecorder::keep(Item &item, HistorySample sample, qint64 nowMs, Records &out) const
{
    // A store replaces a sample of the same series and time: a stale value carries the time of
    // its last good reading, so a gap that begins then is kept a millisecond after it.
    if (item.kept && sample.timeMs <= item.kept->timeMs)
        sample.timeMs = item.kept->timeMs + 1;
    item.kept = sample;
    item.keptAtMs = nowMs;
    item.needFirst = false;
    out.push_back({item.series, sample});
}

void HistoryRecorder::keepOff(Item &item, qint64 nowMs, Records &out) const
{
    item.needFirst = true;
    item.seen.reset();
    if (!item.kept || item.kept->quality == HistoryQuality::Off)
        return;
    HistorySample off;
    off.timeMs = std::max(nowMs, item.kept->timeMs + 1);
    off.quality = HistoryQuality::Off;
    item.kept = off;
    item.keptAtMs = nowMs;
    out.push_back({item.series, off});
}

void HistoryRecorder::keepOffAll(qint64 nowMs)
{
    Records out;
    for (Item &item : m_items)
        keepOff(item, nowMs, out);
    flush(out);
}

void HistoryRecorder::flush(Records &out)
{
    if (!out.empty())
        m_sink->record(std::move(out));
    out.clear();
}

void HistoryRecorder::plantValues(const QList<WatchItemValue> &values)
{
    const qint64 now = m_clock();
    Records out;
    for (const WatchItemValue &value : values) {
        const std::uint64_t index = value.key - m_firstKey;
        if (value.key < m_firstKey || index >= m_items.size())
            continue; // of an item list replaced since
        Item &item = m_items[index];
        const std::optional<HistorySample> sample = sampleOf(item, value, now);
        if (!sample)
            continue;
        if (item.kept && sample->timeMs < item.kept->timeMs)
            continue; // older than what is kept (the clock stepped back): the line goes forward
        if (!m_linkDown || History::hasValue(sample->quality))
            item.seen = sample;
        if (worthKeeping(item, *sample, now))
            keep(item, *sample, now, out);
    }
    flush(out);
}

void HistoryRecorder::plantLinkState(LinkState state, const Message &reason)
{
    Q_UNUSED(reason);
    if (state == LinkState::Connected) {
        if (m_linkDown) {
            m_linkDown = false;
            for (Item &item : m_items)
                item.needFirst = true;
        }
        return;
    }
    // Every line ends when the link goes down (once: Lost, Reconnecting and Connecting follow).
    m_linkDown = true;
    keepOffAll(m_clock());
}

void HistoryRecorder::tick()
{
    const qint64 now = m_clock();
    Records out;
    for (Item &item : m_items) {
        if (!item.kept || !item.seen || item.kept->quality == HistoryQuality::Off)
            continue;
        if (item.seen->timeMs > item.kept->timeMs && heartbeatDue(item, now))
            keep(item, *item.seen, now, out);
    }
    flush(out);
}

} // namespace Fatek
