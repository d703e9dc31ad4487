// The plant (issue 49): consumers of one plant connection against the simulator over loopback TCP.
// A new consumer is a few lines (Recorder below) and receives the same values a watch table does
// (a PlantSubscription, as WatchTableWidget uses), each consumer only its own items; the link
// watches their union; a consumer that leaves, even from inside its own call, gets nothing more;
// a write through the plant is done when the simulator logged it.
#include "core/link/sessionlink.h"
#include "core/plant/plantconnection.h"
#include "core/plant/plantsubscription.h"
#include "core/session/session.h"
#include "core/sim/simserver.h"
#include "core/sim/simulatedplc.h"
#include "latestvalues.h"
#include "testutil.h"

#include <QSignalSpy>
#include <QTest>

#include <bit>
#include <functional>
#include <optional>

using namespace Fatek;
using TestUtil::addr;

namespace {

constexpr int timeoutMs = 10000;

WatchedItem item(const char *address, DisplayFormat format)
{
    WatchItemSpec spec;
    spec.address = addr(address);
    spec.format = format;
    return {WatchedItem::newKey(), spec, 100};
}

// A consumer as the next issues add them (alarms, history, a server): the whole of it.
struct Recorder : PlantConsumer
{
    TestUtil::LatestValues latest;
    QList<LinkState> states;
    std::function<void()> onBatch;

    void plantValues(const QList<WatchItemValue> &values) override
    {
        latest.take(values);
        if (onBatch)
            onBatch();
    }
    void plantLinkState(LinkState state, const Message &) override { states << state; }
};

} // namespace

class TestPlant : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase() { registerSessionMetaTypes(); }
    void consumersGetTheirOwnValues();
};

void TestPlant::consumersGetTheirOwnValues()
{
    SimulatedPlc plc(ModelProfile::fbs());
    SimServer server(&plc);
    server.setVerbose(true); // a write is done when the simulator logged it
    QStringList simLog;
    connect(&server, &SimServer::logLine, this, [&simLog](const QString &l) { simLog << l; });
    QString error;
    QVERIFY2(server.listenTcp(0, &error), qPrintable(error));
    QVERIFY(plc.setValue(addr("R100"), std::bit_cast<std::uint32_t>(12.5f) & 0xFFFFu));
    QVERIFY(plc.setValue(addr("R101"), std::bit_cast<std::uint32_t>(12.5f) >> 16));
    QVERIFY(plc.setValue(addr("R200"), 42));
    QVERIFY(plc.setValue(addr("D10"), 7));

    LinkSettings settings = LinkSettings::tcp(QStringLiteral("127.0.0.1"), server.tcpPort());
    settings.timeoutMs = 500;
    PlantConnection plant(new SessionLink(settings));

    // The table's way: a subscription with a signal.
    PlantSubscription subscription;
    TestUtil::LatestValues table;
    connect(&subscription, &PlantSubscription::itemValues, this,
            [&table](const QList<WatchItemValue> &values) { table.take(values); });
    const WatchedItem flow = item("R100", DisplayFormat::Float32);
    const WatchedItem tableSetpoint = item("R200", DisplayFormat::Signed);
    subscription.setConnection(&plant);
    subscription.setItems({flow, tableSetpoint});

    // The new consumer: the same R200 under its own key, and D10.
    Recorder recorder;
    const WatchedItem setpoint = item("R200", DisplayFormat::Signed);
    const WatchedItem counter = item("D10", DisplayFormat::Unsigned);
    plant.subscribe(&recorder, {setpoint, counter});
    QCOMPARE(plant.consumerCount(), 2);
    QCOMPARE(plant.itemCount(), 4); // the link watches the union

    plant.open();
    QTRY_COMPARE_WITH_TIMEOUT(plant.linkState(), LinkState::Connected, timeoutMs);
    QTRY_VERIFY_WITH_TIMEOUT(recorder.states.contains(LinkState::Connected), timeoutMs);
    QTRY_VERIFY_WITH_TIMEOUT(table.good(flow.key, std::bit_cast<std::uint32_t>(12.5f))
                                 && table.good(tableSetpoint.key, 42),
                             timeoutMs);
    QTRY_VERIFY_WITH_TIMEOUT(
        recorder.latest.good(setpoint.key, 42) && recorder.latest.good(counter.key, 7), timeoutMs);
    // Each its own items only, and the same value of the same register.
    QCOMPARE(table.values.size(), 2);
    QCOMPARE(recorder.latest.values.size(), 2);
    QCOMPARE(recorder.latest.values.value(setpoint.key).words,
             table.values.value(tableSetpoint.key).words);

    // A write through the plant: one result, done on the wire, seen by both consumers.
    std::optional<LinkWriteResult> result;
    QObject context;
    const auto writes = [&simLog] {
        return simLog.filter(QStringLiteral(" write ")).size();
    };
    const qsizetype before = writes();
    plant.write(setpoint.spec, 1234, &context, [&result](const LinkWriteResult &r) { result = r; });
    QTRY_VERIFY_WITH_TIMEOUT(result.has_value() && result->final, timeoutMs);
    QVERIFY2(result->ok, qPrintable(englishText(result->error)));
    QCOMPARE(writes(), before + 1);
    QCOMPARE(plc.value(addr("R200")), std::optional<std::uint32_t>(1234));
    QTRY_VERIFY_WITH_TIMEOUT(
        recorder.latest.good(setpoint.key, 1234) && table.good(tableSetpoint.key, 1234), timeoutMs);

    // A consumer that leaves from inside its own call gets nothing more; the table goes on.
    recorder.onBatch = [&plant, &recorder] {
        plant.unsubscribe(&recorder);
    };
    QTRY_COMPARE_WITH_TIMEOUT(plant.consumerCount(), 1, timeoutMs);
    const int left = recorder.latest.batches;
    QCOMPARE(plant.itemCount(), 2);
    QCOMPARE(plant.watchedStations(), QSet<quint8>{1});
    QVERIFY(plc.setValue(addr("R200"), 99));
    QTRY_VERIFY_WITH_TIMEOUT(table.good(tableSetpoint.key, 99), timeoutMs);
    QCOMPARE(recorder.latest.batches, left);

    // The table moves away: the link watches nothing, and nothing more is read.
    subscription.setConnection(nullptr);
    QCOMPARE(plant.consumerCount(), 0);
    QCOMPARE(plant.itemCount(), 0);
    QTest::qWait(300); // a poll cycle under way ends
    const quint64 requests = plant.statistics().total.requests;
    QTest::qWait(500); // five poll intervals
    QCOMPARE(plant.statistics().total.requests, requests);
    plant.close(CloseMode::Discard);
}

QTEST_GUILESS_MAIN(TestPlant)
#include "tst_plant.moc"
