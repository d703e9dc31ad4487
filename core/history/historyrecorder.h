#pragma once

#include "historysink.h"
#include "historytypes.h"

#include "core/plant/plantconnection.h"
#include "core/watch/historysetting.h"
#include "core/watch/itemassembler.h"

#include <QHash>
#include <QObject>
#include <QPointer>
#include <QTimer>

#include <functional>
#include <optional>
#include <vector>

namespace Fatek {

// What one plant connection's items did, for the history: a consumer of the items that have a
// history setting (WatchItemSpec::history, or every item with setRecordAll), which decides per
// value what is kept and hands it to a HistorySink (HistoryWriter). The one place where that is
// decided: the studio and the gateway each run one per connection. Kept: the first value, a change
// beyond the deadband from the last value kept (bits and ASCII: any change), a change of quality
// (good/late vs stale/error: a gap begins or ends), and the current value when nothing was kept
// for the heartbeat. A link that goes down, an item that leaves and the recorder's end keep an Off
// sample (the line ends there). Lives in the plant connection's thread.
class HistoryRecorder : public QObject, public PlantConsumer
{
    Q_OBJECT

public:
    using Clock = std::function<qint64()>; // ms since the epoch, UTC

    // `source` names the connection in the store (HistorySeries::source). `sink` outlives this.
    HistoryRecorder(const QString &source, HistorySink *sink, QObject *parent = nullptr);
    // Keeps an Off sample for every item, detaches.
    ~HistoryRecorder() override;

    QString source() const { return m_source; }
    // Tests drive the recorder on a fake clock (and call tick() themselves).
    void setClock(Clock clock);

    // Every item is recorded with `setting` unless it has its own (the gateway's "recordAll");
    // nothing: only items with a setting.
    void setRecordAll(std::optional<HistorySetting> setting);
    // The items to record (keys are the recorder's own). One series per station and address: an
    // item met twice is recorded once, the first. An item that stays keeps its last kept value; a
    // changed setting applies from its next value.
    void setItems(const QList<WatchedItem> &items);
    // Subscribes to `plant` (nullptr: detaches); values then come from its link.
    void attach(PlantConnection *plant);
    PlantConnection *plant() const { return m_plant; }
    int seriesCount() const;

    // Heartbeats (the recorder's timer calls it every second).
    void tick();

    void plantValues(const QList<WatchItemValue> &values) override;
    void plantLinkState(LinkState state, const Message &reason) override;

private:
    struct Item
    {
        WatchedItem watched;
        HistorySetting setting;
        QString id;        // "1-R100" (WatchList::itemId)
        qint64 series = 0; // the sink's handle
        int width = 16;
        bool numeric = false;  // has a number a deadband is measured in (not a bit, not ASCII)
        bool needFirst = true; // the next value is kept (start, attach, link up, new format)
        std::optional<HistorySample> kept; // the last one kept
        qint64 keptAtMs = 0;               // m_clock when it was kept: the heartbeat's start
        std::optional<HistorySample> seen; // the last one read: what a heartbeat keeps
    };
    using Records = std::vector<HistoryRecord>;

    // Applies m_given and m_recordAll: items that stay keep their state, those that go end.
    void rebuild();
    void subscribe();
    HistorySeries seriesOf(const Item &item) const;
    // The sample a value stands for; nothing for a good value not read yet.
    std::optional<HistorySample> sampleOf(const Item &item, const WatchItemValue &value,
                                          qint64 nowMs) const;
    bool worthKeeping(Item &item, const HistorySample &sample, qint64 nowMs) const;
    bool heartbeatDue(Item &item, qint64 nowMs) const;
    void keep(Item &item, HistorySample sample, qint64 nowMs, Records &out) const;
    // An Off sample (the line ends) unless the item's line already ended or never began.
    void keepOff(Item &item, qint64 nowMs, Records &out) const;
    void keepOffAll(qint64 nowMs);
    void flush(Records &out);

    QString m_source;
    HistorySink *m_sink;
    Clock m_clock;
    QPointer<PlantConnection> m_plant;
    std::optional<HistorySetting> m_recordAll;
    QList<WatchedItem> m_given; // as setItems had them (setRecordAll applies to them again)
    std::vector<Item> m_items;  // the key of m_items[i] is m_firstKey + i
    QHash<QString, std::size_t> m_index; // by id
    std::uint64_t m_firstKey = 0;
    bool m_linkDown = false; // Off was kept for the link: no bad values until it is up again
    QTimer m_timer;
};

} // namespace Fatek
