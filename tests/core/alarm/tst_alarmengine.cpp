// The alarms of one plant connection (issue 50), against the simulator over loopback TCP: values
// the PLC really holds raise, return and are acknowledged; a station that stops answering raises
// the quality alarm; a restart brings the states back without raising them twice; definitions
// edited while running keep their alarm's state.
#include "core/alarm/alarmengine.h"
#include "core/link/sessionlink.h"
#include "core/plant/plantconnection.h"
#include "core/session/session.h"
#include "core/sim/simserver.h"
#include "core/sim/simulatedplc.h"
#include "testutil.h"

#include <QSignalSpy>
#include <QTest>

using namespace Fatek;
using TestUtil::addr;

namespace {

constexpr int timeoutMs = 10000;

WatchedItem item(const char *address, QList<AlarmDefinition> alarms,
                 DisplayFormat format = DisplayFormat::Signed)
{
    WatchedItem w;
    w.spec.address = addr(address);
    w.spec.format = format;
    w.spec.alarms = std::move(alarms);
    w.intervalMs = 100;
    return w;
}

AlarmDefinition limit(AlarmKind kind, double value, double deadband = 0)
{
    AlarmDefinition d;
    d.kind = kind;
    d.limit = value;
    d.deadband = deadband;
    d.priority = AlarmPriority::High;
    d.group = QStringLiteral("Tank farm");
    return d;
}

struct Events
{
    QList<AlarmEvent> list;
    QList<AlarmRecord> records;
    explicit Events(AlarmEngine *engine)
    {
        QObject::connect(engine, &AlarmEngine::alarmEvent, engine,
                         [this](const AlarmEvent &e, const AlarmRecord &r) {
                             list << e;
                             records << r;
                         });
    }
    bool waitFor(AlarmEventType type, const QString &id, int count = 1)
    {
        return QTest::qWaitFor(
            [&] {
                int n = 0;
                for (const AlarmEvent &e : list)
                    n += e.type == type && e.alarmId == id ? 1 : 0;
                return n >= count;
            },
            timeoutMs);
    }
};

struct Rig
{
    SimulatedPlc plc{ModelProfile::fbs()};
    SimServer server{&plc};
    PlantConnection *plant = nullptr;

    bool start()
    {
        QString error;
        if (!server.listenTcp(0, &error))
            return false;
        LinkSettings settings = LinkSettings::tcp(QStringLiteral("127.0.0.1"), server.tcpPort());
        settings.timeoutMs = 300;
        settings.retries = 0;
        plant = new PlantConnection(new SessionLink(settings));
        plant->open();
        return true;
    }
    ~Rig() { delete plant; }
};

} // namespace

class TestAlarmEngine : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase() { registerSessionMetaTypes(); }
    void raisedAcknowledgedReturned();
    void qualityAlarmWhenThePlcStopsAnswering();
    void restoreDoesNotRaiseTwice();
    void editedDefinitionsKeepTheState();
    void refusalsAreMessages();
};

void TestAlarmEngine::raisedAcknowledgedReturned()
{
    Rig rig;
    QVERIFY(rig.start());
    QVERIFY(rig.plc.setValue(addr("R100"), 10));
    AlarmEngine engine(QStringLiteral("line1"));
    Events events(&engine);
    engine.setItems({item("R100", {limit(AlarmKind::High, 50, 5)}),
                     item("R200", {})}); // no alarms: not watched
    QCOMPARE(engine.alarmCount(), 1);
    engine.attach(rig.plant);
    QCOMPARE(rig.plant->itemCount(), 1);
    const QString id = QStringLiteral("1-R100-high");

    QTest::qWait(300);
    QVERIFY(events.list.isEmpty());
    QVERIFY(rig.plc.setValue(addr("R100"), 60));
    QVERIFY(events.waitFor(AlarmEventType::Raised, id));
    const AlarmEvent raised = events.list.first();
    QCOMPARE(raised.connection, QStringLiteral("line1"));
    QCOMPARE(raised.value, QStringLiteral("60"));
    QCOMPARE(raised.state, AlarmState::ActiveUnacked);
    QCOMPARE(raised.priority, AlarmPriority::High);
    QCOMPARE(raised.message, QStringLiteral("R100 high"));
    QCOMPARE(raised.group, QStringLiteral("Tank farm"));
    QCOMPARE(engine.unackedCount(), 1);

    QVERIFY(engine.acknowledge(id, QStringLiteral("anna"), QStringLiteral("pump 2 started")));
    const AlarmEvent acked = events.list.last();
    QCOMPARE(acked.type, AlarmEventType::Acknowledged);
    QCOMPARE(acked.user, QStringLiteral("anna"));
    QCOMPARE(acked.comment, QStringLiteral("pump 2 started"));
    QCOMPARE(engine.status(id)->state, AlarmState::ActiveAcked);
    QCOMPARE(engine.unackedCount(), 0);

    QVERIFY(rig.plc.setValue(addr("R100"), 47)); // within the deadband: still active
    QTest::qWait(400);
    QCOMPARE(engine.status(id)->state, AlarmState::ActiveAcked);
    QVERIFY(rig.plc.setValue(addr("R100"), 44));
    QVERIFY(events.waitFor(AlarmEventType::Returned, id));
    QCOMPARE(engine.status(id)->state, AlarmState::Normal);
    QCOMPARE(events.list.last().value, QStringLiteral("44"));
    QCOMPARE(events.records.last().state, AlarmState::Normal);
    QCOMPARE(events.list.size(), 3);
}

void TestAlarmEngine::qualityAlarmWhenThePlcStopsAnswering()
{
    Rig rig;
    QVERIFY(rig.start());
    AlarmEngine engine(QStringLiteral("line1"));
    Events events(&engine);
    AlarmDefinition quality;
    quality.kind = AlarmKind::Quality;
    quality.onDelayMs = 1000;
    engine.setItems({item("R100", {quality})});
    engine.attach(rig.plant);
    QTest::qWait(600);
    QVERIFY(events.list.isEmpty());
    QElapsedTimer stopped;
    stopped.start();
    rig.server.close();
    const QString id = QStringLiteral("1-R100-quality");
    QVERIFY(events.waitFor(AlarmEventType::Raised, id));
    QVERIFY2(stopped.elapsed() >= 1000, "raised before its on-delay");
    QCOMPARE(engine.status(id)->state, AlarmState::ActiveUnacked);
}

void TestAlarmEngine::restoreDoesNotRaiseTwice()
{
    Rig rig;
    QVERIFY(rig.start());
    QVERIFY(rig.plc.setValue(addr("R100"), 60));
    const QString id = QStringLiteral("1-R100-high");
    AlarmRecord kept;
    kept.connection = QStringLiteral("line1");
    kept.alarmId = id;
    kept.state = AlarmState::ActiveUnacked;
    kept.sinceMs = 1234;
    kept.raisedMs = 1234;
    kept.conditionActive = true;
    AlarmRecord otherConnection = kept;
    otherConnection.connection = QStringLiteral("line2");
    otherConnection.state = AlarmState::ActiveAcked;

    AlarmEngine engine(QStringLiteral("line1"));
    Events events(&engine);
    engine.setItems({item("R100", {limit(AlarmKind::High, 50)})});
    engine.holdForRestore();
    engine.attach(rig.plant);
    QTest::qWait(500); // values arrive, held
    QVERIFY(events.list.isEmpty());
    engine.restore({otherConnection, kept});
    QTest::qWait(300);
    QVERIFY(events.list.isEmpty()); // still active: not raised a second time
    QCOMPARE(engine.status(id)->state, AlarmState::ActiveUnacked);
    QCOMPARE(engine.status(id)->raisedMs, 1234);
    QVERIFY(rig.plc.setValue(addr("R100"), 10));
    QVERIFY(events.waitFor(AlarmEventType::Returned, id));
    QCOMPARE(engine.status(id)->state, AlarmState::ReturnedUnacked);
}

void TestAlarmEngine::editedDefinitionsKeepTheState()
{
    Rig rig;
    QVERIFY(rig.start());
    QVERIFY(rig.plc.setValue(addr("R100"), 60));
    AlarmEngine engine(QStringLiteral("line1"));
    Events events(&engine);
    QSignalSpy reset(&engine, &AlarmEngine::alarmsReset);
    engine.setItems({item("R100", {limit(AlarmKind::High, 50)})});
    engine.attach(rig.plant);
    const QString id = QStringLiteral("1-R100-high");
    QVERIFY(events.waitFor(AlarmEventType::Raised, id));

    // A new limit and message, the same alarm: still active, not raised again. The same item in a
    // second table counts once.
    AlarmDefinition edited = limit(AlarmKind::High, 55);
    edited.message = QStringLiteral("Tank 1 overfill");
    engine.setItems({item("R100", {edited}), item("R100", {edited})});
    QCOMPARE(engine.alarmCount(), 1);
    QCOMPARE(rig.plant->itemCount(), 1);
    QCOMPARE(engine.status(id)->state, AlarmState::ActiveUnacked);
    QCOMPARE(engine.status(id)->message, QStringLiteral("Tank 1 overfill"));
    QVERIFY(reset.count() >= 2);

    edited.enabled = false;
    engine.setItems({item("R100", {edited})});
    QCOMPARE(events.list.last().type, AlarmEventType::OutOfService);
    QCOMPARE(engine.status(id)->state, AlarmState::OutOfService);
    QCOMPARE(engine.unackedCount(), 0);
    edited.enabled = true;
    engine.setItems({item("R100", {edited})});
    // In service again with the value still above: raised again, as new.
    QCOMPARE(events.list.at(events.list.size() - 2).type, AlarmEventType::InService);
    QCOMPARE(events.list.last().type, AlarmEventType::Raised);

    engine.setItems({});
    QCOMPARE(engine.alarmCount(), 0);
    QCOMPARE(rig.plant->itemCount(), 0);
}

void TestAlarmEngine::refusalsAreMessages()
{
    AlarmEngine engine(QStringLiteral("line1"));
    engine.setItems({item("R100", {limit(AlarmKind::High, 50)})});
    const Status unknown = engine.acknowledge(QStringLiteral("1-R9-high"), {}, {});
    QVERIFY(!unknown);
    QCOMPARE(QString::fromStdString(unknown.error().text()),
             QStringLiteral("There is no alarm 1-R9-high."));
    const Status nothing = engine.acknowledge(QStringLiteral("1-R100-high"), {}, {});
    QVERIFY(!nothing);
    QVERIFY(QString::fromStdString(nothing.error().text()).contains(QStringLiteral("nothing")));
    QVERIFY(!engine.unshelve(QStringLiteral("1-R100-high"), {}));
    QVERIFY(!engine.shelve(QStringLiteral("1-R100-high"), 1, {}, {}));
    QVERIFY(engine.shelve(QStringLiteral("1-R100-high"),
                          QDateTime::currentMSecsSinceEpoch() + 60000, {}, {}));
    QCOMPARE(engine.status(QStringLiteral("1-R100-high"))->lastUser, Alarms::currentUser());
}

QTEST_GUILESS_MAIN(TestAlarmEngine)
#include "tst_alarmengine.moc"
