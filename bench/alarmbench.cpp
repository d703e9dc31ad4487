// Figure 8 (issue 50): what evaluating alarms costs per item update. 10,000 items, each with a
// high and a low alarm, updated at 10 Hz: batches of WatchItemValue handed to
// AlarmEngine::plantValues as a plant connection hands them, on the engine's fake clock (100 ms per
// batch, no sleeping). The values move on a slow sine per item, so a share of the alarms is raised
// and returns every batch and the events are emitted (to a counter) as in the studio; then the
// same batches with every value still and inside its limits (evaluation without events).
#include "bench.h"

#include "core/alarm/alarmengine.h"

#include <QElapsedTimer>

#include <cmath>
#include <numbers>

namespace Fatek::Bench {

void runAlarmEvaluation(const Options &options, Report &report)
{
    constexpr int Items = 10000;
    constexpr int RegistersPerStation = 3840; // R0..R3839 of an FBs
    const int batches = options.quick ? 20 : 300;

    QList<WatchedItem> items;
    items.reserve(Items);
    for (int i = 0; i < Items; ++i) {
        WatchItemSpec spec;
        spec.address
            = *Address::parse(QStringLiteral("R%1").arg(i % RegistersPerStation).toStdString());
        spec.station = static_cast<quint8>(1 + i / RegistersPerStation);
        spec.format = DisplayFormat::Unsigned;
        AlarmDefinition high;
        high.kind = AlarmKind::High;
        high.limit = 900;
        high.deadband = 5;
        AlarmDefinition low;
        low.kind = AlarmKind::Low;
        low.limit = 100;
        low.deadband = 5;
        spec.alarms = {high, low};
        items.append(WatchedItem{0, spec, 100});
    }
    qint64 now = Q_INT64_C(1796635411000);
    AlarmEngine engine(QStringLiteral("bench"));
    engine.setClock([&now] { return now; });
    // The engine numbers its items from a block of fresh keys (WatchedItem::newKeys): the next
    // key after this one. Checked below with the first and the last item.
    const std::uint64_t firstKey = WatchedItem::newKey() + 1;
    engine.setItems(items);
    quint64 events = 0;
    QObject::connect(&engine, &AlarmEngine::alarmEvent, &engine,
                     [&events](const AlarmEvent &, const AlarmRecord &) { ++events; });

    QList<WatchItemValue> batch(Items);
    for (int i = 0; i < Items; ++i) {
        WatchItemValue &v = batch[i];
        v.key = firstKey + static_cast<std::uint64_t>(i);
        v.words = {0};
        v.hasValue = true;
        v.quality = ValueQuality::Good;
    }
    // The keys checked: the first and the last item raise their high alarm.
    WatchItemValue probe = batch[0];
    probe.raw = probe.words[0] = 1000;
    WatchItemValue lastProbe = probe;
    lastProbe.key = batch[Items - 1].key;
    engine.plantValues({probe, lastProbe});
    const bool keysRight
        = engine.unackedCount() == 2
          && engine.status(Alarms::alarmId(items.first().spec, AlarmKind::High))->state
                 == AlarmState::ActiveUnacked
          && engine.status(Alarms::alarmId(items.last().spec, AlarmKind::High))->state
                 == AlarmState::ActiveUnacked;
    qint64 evaluationNs = 0;
    QElapsedTimer clock;
    for (int b = 0; b < batches; ++b) {
        // A period of 60 batches (6 s), each item a step further along it.
        for (int i = 0; i < Items; ++i) {
            const double phase = 2 * std::numbers::pi * ((b + i) % 60) / 60.0;
            const auto raw = static_cast<std::uint32_t>(std::lround(500 + 450 * std::sin(phase)));
            batch[i].words[0] = raw;
            batch[i].raw = raw;
        }
        now += 100;
        clock.start();
        engine.plantValues(batch);
        evaluationNs += clock.nsecsElapsed();
    }
    // The same with every value inside its limits and still: no event, evaluation alone.
    const quint64 eventsMoving = events;
    qint64 quietNs = 0;
    for (int i = 0; i < Items; ++i) {
        batch[i].words[0] = 500;
        batch[i].raw = 500;
    }
    for (int b = 0; b < batches; ++b) {
        now += 100;
        clock.start();
        engine.plantValues(batch);
        quietNs += clock.nsecsElapsed();
    }
    const qint64 updates = static_cast<qint64>(batches) * Items;
    const double quietNsPerUpdate = static_cast<double>(quietNs) / static_cast<double>(updates);
    const double nsPerUpdate = static_cast<double>(evaluationNs) / static_cast<double>(updates);
    // The values reached the alarms (the keys were right), and the cost at 10 Hz.
    const bool reached = keysRight && engine.alarmCount() == 2 * Items && eventsMoving > 0;
    const double cpuShare = nsPerUpdate * Items * 10 / 1e9 * 100;
    report.row(QStringLiteral("alarm evaluation: 10,000 items (high + low) updated at 10 Hz"),
               QStringLiteral("%1 ns per item update").arg(fmt(nsPerUpdate, 0)),
               QStringLiteral("%1% of one core at 10 Hz (%2 events in %3 batches); values "
                              "still: %4 ns")
                   .arg(fmt(cpuShare, 2))
                   .arg(eventsMoving)
                   .arg(batches)
                   .arg(fmt(quietNsPerUpdate, 0)),
               ratioText(nsPerUpdate, quietNsPerUpdate), QStringLiteral("<= 1000 ns"));
    report.result(QStringLiteral("alarm_evaluation_ns_per_item_update"), nsPerUpdate,
                  QStringLiteral("<=1000"), reached && nsPerUpdate <= 1000);
    if (!reached)
        std::fprintf(stderr, "figure 8: %d alarms, %llu events: the values did not reach them\n",
                     engine.alarmCount(), static_cast<unsigned long long>(eventsMoving));
}

} // namespace Fatek::Bench
