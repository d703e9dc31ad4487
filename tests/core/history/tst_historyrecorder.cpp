// What the history keeps of a plant connection's items (issue 51): the recorder fed values as a
// link reports them (WatchItemValue, on a fake clock) and, once, through a real plant connection
// to the simulator over loopback TCP. The sink only collects what the recorder hands over: it is
// the recorder's output.
#include "core/history/historyrecorder.h"
#include "core/link/sessionlink.h"
#include "core/plant/plantconnection.h"
#include "core/session/session.h"
#include "core/sim/simserver.h"
#include "core/sim/simulatedplc.h"
#include "core/watch/watchlist.h"
#include "testutil.h"

#include <QTest>

#include <cmath>
#include <memory>

using namespace Fatek;
using TestUtil::addr;
using TestUtil::floatBits;

namespace {

constexpr qint64 T0 = 1'700'000'000'000; // ms since the epoch, UTC

// What the recorder handed over, in order.
struct Collector : HistorySink
{
    QList<HistorySeries> added;
    QHash<QString, qint64> ids;
    std::vector<std::vector<HistoryRecord>> batches;

    qint64 addSeries(const HistorySeries &series) override
    {
        added.append(series);
        auto it = ids.constFind(series.item);
        if (it == ids.cend())
            it = ids.insert(series.item, ids.size() + 1);
        return *it;
    }
    void record(std::vector<HistoryRecord> records) override
    {
        batches.push_back(std::move(records));
    }
    std::vector<HistorySample> samples(const QString &item) const
    {
        std::vector<HistorySample> list;
        for (const auto &batch : batches) {
            for (const HistoryRecord &r : batch) {
                if (r.series == ids.value(item))
                    list.push_back(r.sample);
            }
        }
        return list;
    }
    std::vector<HistoryQuality> qualities(const QString &item) const
    {
        std::vector<HistoryQuality> list;
        for (const HistorySample &s : samples(item))
            list.push_back(s.quality);
        return list;
    }
    std::vector<std::uint64_t> raws(const QString &item) const
    {
        std::vector<std::uint64_t> list;
        for (const HistorySample &s : samples(item))
            list.push_back(s.raw);
        return list;
    }
};

WatchedItem item(const char *address, std::optional<HistorySetting> history,
                 DisplayFormat format = DisplayFormat::Signed, quint8 station = 1)
{
    WatchedItem w;
    w.spec.address = addr(address);
    w.spec.station = station;
    w.spec.format = format;
    w.spec.history = history;
    w.intervalMs = 100;
    return w;
}

HistorySetting setting(double deadband = 0, int heartbeatS = 600)
{
    return HistorySetting{deadband, heartbeatS};
}

// A value as a link reports it, read at `timeMs`.
WatchItemValue valueOf(std::uint64_t key, std::uint64_t raw, qint64 timeMs,
                       ValueQuality quality = ValueQuality::Good, bool hasValue = true)
{
    WatchItemValue v;
    v.key = key;
    v.words = {static_cast<std::uint32_t>(raw & 0xFFFF),
               static_cast<std::uint32_t>((raw >> 16) & 0xFFFF)};
    v.raw = raw;
    v.hasValue = hasValue;
    v.quality = quality;
    v.time = QDateTime::fromMSecsSinceEpoch(timeMs, Qt::UTC);
    return v;
}

// The recorder on a fake clock, fed as a link feeds it.
struct Rig
{
    Collector sink;
    qint64 now = T0;
    HistoryRecorder recorder{QStringLiteral("line1"), &sink};
    std::uint64_t firstKey = 0;

    Rig()
    {
        recorder.setClock([this] { return now; });
    }
    // The recorder's keys: the block it takes next (WatchedItem::newKeys).
    void setItems(const QList<WatchedItem> &items)
    {
        firstKey = WatchedItem::newKey() + 1;
        recorder.setItems(items);
    }
    void setRecordAll(std::optional<HistorySetting> all)
    {
        firstKey = WatchedItem::newKey() + 1;
        recorder.setRecordAll(all);
    }
    // A value of the recorder's item `index`, read now.
    WatchItemValue value(int index, std::uint64_t raw, ValueQuality quality = ValueQuality::Good,
                         bool hasValue = true) const
    {
        return valueOf(firstKey + static_cast<std::uint64_t>(index), raw, now, quality, hasValue);
    }
    // One value of item 0 per second.
    void feed(std::initializer_list<std::uint64_t> raws)
    {
        for (const std::uint64_t raw : raws) {
            now += 1000;
            recorder.plantValues({value(0, raw)});
        }
    }
};

} // namespace

class TestHistoryRecorder : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase() { registerSessionMetaTypes(); }
    void seriesDescribeTheItems();
    void deadbandFromTheLastKeptValue();
    void deadbandZeroKeepsEveryChange();
    void deadbandOnFloats();
    void bitsAndTextKeepEveryChange();
    void heartbeatOfAFlatLine();
    void qualityGapsBeginAndEnd();
    void linkDownEndsEveryLineOnce();
    void itemsThatLeaveEnd();
    void sameStationAndAddressRecordedOnce();
    void recordAll();
    void clockSteppingBack();
    void destructionEndsTheLines();
    void throughThePlantConnection();
};

void TestHistoryRecorder::seriesDescribeTheItems()
{
    Rig rig;
    WatchedItem level = item("R100", setting(0, 30), DisplayFormat::Unsigned, 3);
    level.spec.name = QStringLiteral("Tank level");
    rig.setItems({level, item("R200", std::nullopt)}); // no setting: not recorded
    QCOMPARE(rig.recorder.seriesCount(), 1);
    QCOMPARE(rig.sink.added.size(), 1);
    const HistorySeries s = rig.sink.added.at(0);
    QCOMPARE(s.source, QStringLiteral("line1"));
    QCOMPARE(s.item, QStringLiteral("3-R100"));
    QCOMPARE(s.item, WatchList::itemId(level.spec));
    QCOMPARE(s.label, QStringLiteral("Tank level"));
    QCOMPARE(s.format, QStringLiteral("unsigned"));
    QCOMPARE(s.heartbeatS, 30);
    // The same items again: nothing new to describe.
    rig.setItems({level});
    QCOMPARE(rig.sink.added.size(), 1);
    // A new name or heartbeat is passed on (the same series).
    level.spec.name = QStringLiteral("Tank 1 level");
    rig.setItems({level});
    QCOMPARE(rig.sink.added.size(), 2);
    QCOMPARE(rig.sink.added.at(1).label, QStringLiteral("Tank 1 level"));
    level.spec.history->heartbeatS = 60;
    rig.setItems({level});
    QCOMPARE(rig.sink.added.size(), 3);
    QCOMPARE(rig.sink.added.at(2).heartbeatS, 60);
    QCOMPARE(rig.sink.ids.size(), 1);
}

void TestHistoryRecorder::deadbandFromTheLastKeptValue()
{
    Rig rig;
    rig.setItems({item("R100", setting(2))});
    // Creeping up by 1 a second: each step is inside the deadband of the value before, but not
    // always of the last value kept.
    rig.feed({10, 11, 12, 13, 14, 12, 11, 10, 10});
    QCOMPARE(rig.sink.raws(QStringLiteral("1-R100")), (std::vector<std::uint64_t>{10, 13, 10}));
    const std::vector<HistorySample> samples = rig.sink.samples(QStringLiteral("1-R100"));
    QCOMPARE(samples[0].timeMs, T0 + 1000);
    QCOMPARE(samples[0].value, 10.0);
    QCOMPARE(samples[0].quality, HistoryQuality::Good);
    QCOMPARE(samples[1].timeMs, T0 + 4000);
    QCOMPARE(samples[2].timeMs, T0 + 8000);
    // Negative numbers are numbers too (signed: 0xFFF6 is -10).
    rig.feed({0xFFF6});
    QCOMPARE(rig.sink.samples(QStringLiteral("1-R100")).back().value, -10.0);
    // One batch per call that kept something.
    QCOMPARE(rig.sink.batches.size(), std::size_t(4));
}

void TestHistoryRecorder::deadbandZeroKeepsEveryChange()
{
    Rig rig;
    rig.setItems({item("R100", setting()), item("R101", setting())});
    rig.now += 1000;
    rig.recorder.plantValues({rig.value(0, 5), rig.value(1, 7)});
    QCOMPARE(rig.sink.batches.size(), std::size_t(1)); // both in one batch
    QCOMPARE(rig.sink.batches[0].size(), std::size_t(2));
    rig.feed({5, 5, 6, 6, 5});
    QCOMPARE(rig.sink.raws(QStringLiteral("1-R100")), (std::vector<std::uint64_t>{5, 6, 5}));
    QCOMPARE(rig.sink.raws(QStringLiteral("1-R101")), (std::vector<std::uint64_t>{7}));
}

void TestHistoryRecorder::deadbandOnFloats()
{
    Rig rig;
    rig.setItems({item("R100", setting(0.5), DisplayFormat::Float32)});
    rig.feed({floatBits(1.0F), floatBits(1.4F), floatBits(1.6F), floatBits(1.2F), floatBits(1.15F),
              floatBits(0.9F)});
    std::vector<HistorySample> samples = rig.sink.samples(QStringLiteral("1-R100"));
    QCOMPARE(samples.size(), std::size_t(3));
    QCOMPARE(samples[0].value, double(1.0F));
    QCOMPARE(samples[1].value, double(1.6F));
    QCOMPARE(samples[2].value, double(0.9F));
    QCOMPARE(samples[1].raw, std::uint64_t(floatBits(1.6F)));
    // A NaN has no number to measure a deadband in: a change of its bits is kept.
    rig.feed({floatBits(std::nanf("")), floatBits(std::nanf(""))});
    samples = rig.sink.samples(QStringLiteral("1-R100"));
    QCOMPARE(samples.size(), std::size_t(4));
    QVERIFY(std::isnan(samples[3].value));
    QCOMPARE(samples[3].quality, HistoryQuality::Good);
}

void TestHistoryRecorder::bitsAndTextKeepEveryChange()
{
    Rig rig;
    // A deadband given to every item (recordAll) does not apply to a bit or to text.
    rig.setItems({item("X0", std::nullopt, DisplayFormat::Bit),
                  item("R10", std::nullopt, DisplayFormat::Ascii)});
    rig.setRecordAll(setting(5));
    QCOMPARE(rig.recorder.seriesCount(), 2);
    rig.feed({0, 0, 1, 1, 0});
    QCOMPARE(rig.sink.raws(QStringLiteral("1-X0")), (std::vector<std::uint64_t>{0, 1, 0}));
    QCOMPARE(rig.sink.samples(QStringLiteral("1-X0"))[1].value, 1.0);
    for (const std::uint64_t raw : {0x4142U, 0x4142U, 0x4143U}) {
        rig.now += 1000;
        rig.recorder.plantValues({rig.value(1, raw)});
    }
    const std::vector<HistorySample> text = rig.sink.samples(QStringLiteral("1-R10"));
    QCOMPARE(text.size(), std::size_t(2));
    QVERIFY(std::isnan(text[0].value)); // text has no height
    QCOMPARE(text[1].raw, std::uint64_t(0x4143));
}

void TestHistoryRecorder::heartbeatOfAFlatLine()
{
    Rig rig;
    rig.setItems({item("R100", setting(0, 10))});
    rig.feed({7, 7, 7, 7, 7, 7, 7, 7, 7, 7}); // T0+1 s .. T0+10 s
    QCOMPARE(rig.sink.samples(QStringLiteral("1-R100")).size(), std::size_t(1));
    rig.feed({7}); // T0+11 s: the heartbeat is due, the value that arrives is kept
    QCOMPARE(rig.sink.samples(QStringLiteral("1-R100")).size(), std::size_t(2));
    QCOMPARE(rig.sink.samples(QStringLiteral("1-R100")).back().timeMs, T0 + 11000);

    // Values stop coming, the last one late; the timer's tick keeps it, at its time and with
    // its quality.
    rig.now += 1000;
    rig.recorder.plantValues({rig.value(0, 7, ValueQuality::Late)}); // T0+12 s
    rig.now = T0 + 20000;
    rig.recorder.tick();
    QCOMPARE(rig.sink.samples(QStringLiteral("1-R100")).size(), std::size_t(2));
    rig.now = T0 + 21000;
    rig.recorder.tick();
    const std::vector<HistorySample> samples = rig.sink.samples(QStringLiteral("1-R100"));
    QCOMPARE(samples.size(), std::size_t(3));
    QCOMPARE(samples.back().timeMs, T0 + 12000);
    QCOMPARE(samples.back().quality, HistoryQuality::Late);
    QCOMPARE(samples.back().value, 7.0);
    // Nothing read since: nothing to keep (the silence is a gap, not a flat line).
    rig.now = T0 + 100000;
    rig.recorder.tick();
    QCOMPARE(rig.sink.samples(QStringLiteral("1-R100")).size(), std::size_t(3));
}

void TestHistoryRecorder::qualityGapsBeginAndEnd()
{
    Rig rig;
    rig.setItems({item("R100", setting(50)), item("R200", setting())});
    rig.now += 1000;
    // Not read yet: no value of the PLC's, nothing kept; an item that cannot be read is kept
    // as such.
    rig.recorder.plantValues(
        {rig.value(0, 0, ValueQuality::Good, false), rig.value(1, 0, ValueQuality::Error, false)});
    QVERIFY(rig.sink.samples(QStringLiteral("1-R100")).empty());
    QCOMPARE(rig.sink.qualities(QStringLiteral("1-R200")),
             std::vector<HistoryQuality>{HistoryQuality::Error});
    QVERIFY(std::isnan(rig.sink.samples(QStringLiteral("1-R200"))[0].value));

    rig.feed({40});
    const qint64 lastGood = rig.now;
    // Not read in this cycle: the poller reports the last good value, at its time.
    const WatchItemValue stale = valueOf(rig.firstKey, 40, lastGood, ValueQuality::Stale);
    rig.now += 1000;
    rig.recorder.plantValues({stale});
    rig.now += 1000;
    rig.recorder.plantValues({stale});
    rig.now += 1000;
    rig.recorder.plantValues({rig.value(0, 40, ValueQuality::Error)}); // still no value
    rig.feed({41});                                                    // back, inside the deadband
    rig.now += 1000;
    rig.recorder.plantValues({rig.value(0, 41, ValueQuality::Late)}); // late is no change
    rig.feed({41});
    const std::vector<HistorySample> samples = rig.sink.samples(QStringLiteral("1-R100"));
    QCOMPARE(rig.sink.qualities(QStringLiteral("1-R100")),
             (std::vector<HistoryQuality>{HistoryQuality::Good, HistoryQuality::Stale,
                                          HistoryQuality::Good}));
    // The gap begins right after the last good reading (a store keeps one sample per time).
    QCOMPARE(samples[0].timeMs, lastGood);
    QCOMPARE(samples[1].timeMs, lastGood + 1);
    QVERIFY(std::isnan(samples[1].value));
    QCOMPARE(samples[1].raw, std::uint64_t(40));
    QCOMPARE(samples[2].timeMs, T0 + 6000);
    QCOMPARE(samples[2].value, 41.0);
}

void TestHistoryRecorder::linkDownEndsEveryLineOnce()
{
    Rig rig;
    rig.setItems({item("R100", setting()), item("R101", setting()), item("R102", setting())});
    rig.now += 1000;
    rig.recorder.plantValues({rig.value(0, 1), rig.value(1, 2)}); // R102: nothing yet
    rig.now += 5000;
    const qint64 down = rig.now;
    rig.recorder.plantLinkState(LinkState::Lost, {});
    QCOMPARE(rig.sink.batches.size(), std::size_t(2));
    QCOMPARE(rig.sink.batches[1].size(), std::size_t(2)); // one batch, no Off for R102
    for (const HistoryRecord &r : rig.sink.batches[1]) {
        QCOMPARE(r.sample.quality, HistoryQuality::Off);
        QCOMPARE(r.sample.timeMs, down);
        QVERIFY(std::isnan(r.sample.value));
    }
    // Once: the states that follow, the stale values the link reports, the ticks add nothing.
    rig.now += 1000;
    rig.recorder.plantLinkState(LinkState::Reconnecting, {});
    rig.recorder.plantValues(
        {rig.value(0, 1, ValueQuality::Stale), rig.value(2, 0, ValueQuality::Stale, false)});
    rig.recorder.plantLinkState(LinkState::Connecting, {});
    rig.now += 3600 * 1000;
    rig.recorder.tick();
    QCOMPARE(rig.sink.batches.size(), std::size_t(2));
    // Up again: the first value is kept, changed or not.
    rig.recorder.plantLinkState(LinkState::Connected, {});
    rig.now += 1000;
    rig.recorder.plantValues({rig.value(0, 1), rig.value(1, 2)});
    QCOMPARE(rig.sink.qualities(QStringLiteral("1-R100")),
             (std::vector<HistoryQuality>{HistoryQuality::Good, HistoryQuality::Off,
                                          HistoryQuality::Good}));
    QCOMPARE(rig.sink.raws(QStringLiteral("1-R101")), (std::vector<std::uint64_t>{2, 0, 2}));
    QVERIFY(rig.sink.samples(QStringLiteral("1-R102")).empty());
}

void TestHistoryRecorder::itemsThatLeaveEnd()
{
    Rig rig;
    rig.setItems({item("R100", setting()), item("R101", setting())});
    rig.now += 1000;
    rig.recorder.plantValues({rig.value(0, 1), rig.value(1, 2)});
    rig.now += 1000;
    rig.setItems({item("R101", setting())});
    QCOMPARE(rig.recorder.seriesCount(), 1);
    QCOMPARE(rig.sink.qualities(QStringLiteral("1-R100")),
             (std::vector<HistoryQuality>{HistoryQuality::Good, HistoryQuality::Off}));
    QCOMPARE(rig.sink.samples(QStringLiteral("1-R100")).back().timeMs, T0 + 2000);
    // The item that stays goes on from its last kept value: unchanged, nothing new.
    rig.now += 1000;
    rig.recorder.plantValues({rig.value(0, 2)});
    QCOMPARE(rig.sink.raws(QStringLiteral("1-R101")), std::vector<std::uint64_t>{2});
    // A value of an item list replaced since goes nowhere.
    rig.recorder.plantValues({valueOf(rig.firstKey - 1, 9, rig.now)});
    QCOMPARE(rig.sink.batches.size(), std::size_t(2));
    // A new format: the same words are another number, the line starts again.
    rig.setItems({item("R101", setting(), DisplayFormat::Unsigned)});
    rig.now += 1000;
    rig.recorder.plantValues({rig.value(0, 2)});
    QCOMPARE(rig.sink.raws(QStringLiteral("1-R101")), (std::vector<std::uint64_t>{2, 2}));
    QCOMPARE(rig.sink.added.back().format, QStringLiteral("unsigned"));
}

void TestHistoryRecorder::sameStationAndAddressRecordedOnce()
{
    Rig rig;
    WatchedItem first = item("R100", setting(0, 60));
    first.spec.name = QStringLiteral("Level");
    WatchedItem again = item("R100", setting(3, 5), DisplayFormat::Hex);
    again.spec.name = QStringLiteral("Level (hex)");
    rig.setItems({first, again, item("R100", setting(), DisplayFormat::Signed, 2)});
    QCOMPARE(rig.recorder.seriesCount(), 2);
    QCOMPARE(rig.sink.added.size(), 2);
    QCOMPARE(rig.sink.added.at(0).label, QStringLiteral("Level"));
    QCOMPARE(rig.sink.added.at(0).heartbeatS, 60);
    QCOMPARE(rig.sink.added.at(1).item, QStringLiteral("2-R100"));
}

void TestHistoryRecorder::recordAll()
{
    Rig rig;
    rig.setItems({item("R100", std::nullopt), item("R101", setting(0, 30))});
    QCOMPARE(rig.recorder.seriesCount(), 1);
    rig.setRecordAll(setting(0, 900));
    QCOMPARE(rig.recorder.seriesCount(), 2);
    QCOMPARE(rig.sink.added.size(), 2); // R101 unchanged: its own setting stays its own
    QCOMPARE(rig.sink.added.at(1).item, QStringLiteral("1-R100"));
    QCOMPARE(rig.sink.added.at(1).heartbeatS, 900);
    rig.now += 1000;
    rig.recorder.plantValues({rig.value(0, 4), rig.value(1, 5)});
    QCOMPARE(rig.sink.batches.back().size(), std::size_t(2));
    // Back to the items' own settings: the others end.
    rig.now += 1000;
    rig.setRecordAll(std::nullopt);
    QCOMPARE(rig.recorder.seriesCount(), 1);
    QCOMPARE(rig.sink.qualities(QStringLiteral("1-R100")),
             (std::vector<HistoryQuality>{HistoryQuality::Good, HistoryQuality::Off}));
    QCOMPARE(rig.sink.qualities(QStringLiteral("1-R101")),
             std::vector<HistoryQuality>{HistoryQuality::Good});
}

void TestHistoryRecorder::clockSteppingBack()
{
    Rig rig;
    rig.setItems({item("R100", setting(0, 10))});
    rig.feed({1, 2}); // T0+1 s, T0+2 s
    // The PC's clock is set back an hour: readings older than the last kept are dropped.
    rig.now -= 3600 * 1000;
    rig.feed({3, 4});
    QCOMPARE(rig.sink.raws(QStringLiteral("1-R100")), (std::vector<std::uint64_t>{1, 2}));
    rig.recorder.tick();
    QCOMPARE(rig.sink.batches.size(), std::size_t(2));
    // Once the readings pass the last kept time again, the line goes on.
    rig.now = T0 + 2500;
    rig.feed({5});
    rig.feed({5, 5, 5, 5, 5, 5, 5, 5, 5, 5}); // the heartbeat, 10 s on
    std::vector<HistorySample> samples = rig.sink.samples(QStringLiteral("1-R100"));
    QCOMPARE(samples.size(), std::size_t(4));
    QCOMPARE(samples[2].timeMs, T0 + 3500);
    QCOMPARE(samples[3].timeMs, T0 + 13500);

    // Only the recorder's clock steps back (a gateway's readings carry the gateway's time): the
    // heartbeat counts from the step, not an hour late.
    rig.now -= 3600 * 1000;
    for (int i = 1; i <= 10; ++i) {
        rig.now += 1000;
        rig.recorder.plantValues({valueOf(rig.firstKey, 5, T0 + 13500 + i * 1000)});
    }
    samples = rig.sink.samples(QStringLiteral("1-R100"));
    QCOMPARE(samples.size(), std::size_t(4));
    rig.now += 1000;
    rig.recorder.plantValues({valueOf(rig.firstKey, 5, T0 + 24500)});
    samples = rig.sink.samples(QStringLiteral("1-R100"));
    QCOMPARE(samples.size(), std::size_t(5));
    QCOMPARE(samples[4].timeMs, T0 + 24500);
}

void TestHistoryRecorder::destructionEndsTheLines()
{
    Collector sink;
    qint64 now = T0;
    {
        HistoryRecorder recorder(QStringLiteral("line1"), &sink);
        recorder.setClock([&now] { return now; });
        const std::uint64_t key = WatchedItem::newKey() + 1;
        recorder.setItems({item("R100", setting()), item("R101", setting())});
        recorder.plantValues({valueOf(key, 3, now)});
        now += 5000;
    }
    QCOMPARE(sink.qualities(QStringLiteral("1-R100")),
             (std::vector<HistoryQuality>{HistoryQuality::Good, HistoryQuality::Off}));
    QCOMPARE(sink.samples(QStringLiteral("1-R100")).back().timeMs, T0 + 5000);
    QVERIFY(sink.samples(QStringLiteral("1-R101")).empty());
}

void TestHistoryRecorder::throughThePlantConnection()
{
    SimulatedPlc plc{ModelProfile::fbs()};
    SimServer server{&plc};
    QString error;
    QVERIFY2(server.listenTcp(0, &error), qPrintable(error));
    LinkSettings settings = LinkSettings::tcp(QStringLiteral("127.0.0.1"), server.tcpPort());
    settings.timeoutMs = 300;
    settings.retries = 0;
    auto plant = std::make_unique<PlantConnection>(new SessionLink(settings));
    QVERIFY(plc.setValue(addr("R100"), 10));
    QVERIFY(plc.setValue(addr("R200"), floatBits(2.5F) & 0xFFFF));
    QVERIFY(plc.setValue(addr("R201"), floatBits(2.5F) >> 16));

    Collector sink;
    HistoryRecorder recorder(QStringLiteral("line1"), &sink);
    recorder.setItems({item("R100", setting(5)), item("R200", setting(), DisplayFormat::Float32),
                       item("R300", std::nullopt)});
    recorder.attach(plant.get());
    QCOMPARE(recorder.plant(), plant.get());
    QCOMPARE(plant->itemCount(), 2);
    plant->open();
    const auto samplesOf = [&sink](const char *id) {
        return sink.samples(QString::fromLatin1(id)).size();
    };
    QTRY_COMPARE_WITH_TIMEOUT(samplesOf("1-R100"), std::size_t(1), 10000);
    QTRY_COMPARE_WITH_TIMEOUT(samplesOf("1-R200"), std::size_t(1), 10000);
    QCOMPARE(sink.samples(QStringLiteral("1-R200"))[0].value, 2.5);
    QCOMPARE(sink.samples(QStringLiteral("1-R100"))[0].value, 10.0);

    QVERIFY(plc.setValue(addr("R100"), 14)); // inside the deadband
    QTest::qWait(500);
    QCOMPARE(samplesOf("1-R100"), std::size_t(1));
    QVERIFY(plc.setValue(addr("R100"), 16));
    QTRY_COMPARE_WITH_TIMEOUT(samplesOf("1-R100"), std::size_t(2), 10000);
    QCOMPARE(sink.samples(QStringLiteral("1-R100"))[1].value, 16.0);
    const qint64 read = sink.samples(QStringLiteral("1-R100"))[1].timeMs;
    QVERIFY(std::abs(read - QDateTime::currentMSecsSinceEpoch()) < 5000);
    QCOMPARE(samplesOf("1-R200"), std::size_t(1));

    // The PLC goes away: the lines end (a gap, then Off when the link is lost).
    server.close();
    QTRY_VERIFY_WITH_TIMEOUT(sink.qualities(QStringLiteral("1-R100")).back() == HistoryQuality::Off,
                             10000);
    QCOMPARE(sink.qualities(QStringLiteral("1-R200")).back(), HistoryQuality::Off);
    recorder.attach(nullptr);
    QCOMPARE(plant->itemCount(), 0);
}

QTEST_GUILESS_MAIN(TestHistoryRecorder)
#include "tst_historyrecorder.moc"
