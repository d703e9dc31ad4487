// PlcTarget, what the commissioning tools act on: one station behind a link. Against the
// simulator through a direct link (SessionLink), a gateway's link (GatewayWatch, not opened) and
// none; a closed link leaves the target without a link, never dangling.
#include "core/link/gatewaywatch.h"
#include "core/plant/plctarget.h"
#include "core/session/requesttracker.h"
#include "core/session/trafficlog.h"
#include "tst_tools_fixture.h"

#include <QSignalSpy>
#include <QTest>

using namespace Fatek;
using ToolsTest::Rig;

class TestPlcTarget : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void noTarget();
    void directLink();
    void protocolFound();
    void closedLink();
    void gatewayLink();
};

void TestPlcTarget::noTarget()
{
    const PlcTarget none;
    QVERIFY(!none.link());
    QVERIFY(!none.isDirect());
    QVERIFY(!none.session());
    QVERIFY(!none.isReadOnly());
    QCOMPARE(none.station(), quint8(1));
    QCOMPARE(none.timeoutMs(), 0);
    QVERIFY(!none.protocol());
    QCOMPARE(none.framing(), Protocol::Facon);
    QVERIFY(!none.trafficLog());
    QVERIFY(none.confirmedNow().deadline.isForever());
    QObject context;
    QVERIFY(!none.onProtocolDetected(&context, [] {}));
    RequestTracker tracker;
    none.aim(&tracker);
    QVERIFY(!tracker.session());
}

void TestPlcTarget::directLink()
{
    Rig rig;
    QVERIFY(rig.start(LinkSettings::ProtocolChoice::Binary, 700));
    const PlcTarget target = rig.target(3);
    QCOMPARE(target.link(), rig.link.get());
    QVERIFY(target.isDirect());
    QCOMPARE(target.session(), rig.session());
    QCOMPARE(target.station(), quint8(3));
    QCOMPARE(target.connectionName(), Rig::connectionName());
    QCOMPARE(target.timeoutMs(), 700);
    QCOMPARE(target.framing(), Protocol::Binary); // the link's choice, before any answer
    QCOMPARE(target.trafficLog(), rig.session()->trafficLog());
    const qint64 left = target.confirmedNow().deadline.remainingTime();
    QVERIFY2(left > 0 && left <= 700, qPrintable(QString::number(left)));

    // Operator mode is the link's.
    QVERIFY(!target.isReadOnly());
    rig.link->setReadOnly(true);
    QVERIFY(target.isReadOnly());
    rig.link->setReadOnly(false);

    // The engines run on the target's session: a tracker aimed at it is answered by the PLC.
    RequestTracker tracker;
    target.aim(&tracker);
    QCOMPARE(tracker.session(), rig.session());
    bool answered = false;
    tracker.submit(Request::briefStatus(1),
                   [&answered](const SessionResult &r) { answered = r.ok(); });
    QTRY_VERIFY_WITH_TIMEOUT(answered, 10000);

    QVERIFY(target.isSamePlc(rig.target(3)));
    QVERIFY(!target.isSamePlc(rig.target(4)));
}

void TestPlcTarget::protocolFound()
{
    Rig rig;
    QVERIFY(rig.start(LinkSettings::ProtocolChoice::Auto));
    const PlcTarget target = rig.target();
    int detected = 0;
    QObject context;
    const bool connected = target.onProtocolDetected(&context, [&detected] { ++detected; });
    QVERIFY(connected);
    // Found with the first request (its station asked in FACON, then binary).
    QVERIFY(!target.protocol());
    QCOMPARE(target.framing(), Protocol::Facon); // Auto frames as FACON until it knows
    RequestTracker tracker;
    target.aim(&tracker);
    tracker.submit(Request::briefStatus(1), [](const SessionResult &) {});
    QTRY_VERIFY_WITH_TIMEOUT(target.protocol().has_value(), 10000);
    QTRY_COMPARE(detected, 1);
    QCOMPARE(target.protocol(), std::optional(Protocol::Facon)); // the simulator's first answer
    QCOMPARE(target.framing(), Protocol::Facon);
}

void TestPlcTarget::closedLink()
{
    Rig rig;
    QVERIFY(rig.start());
    const PlcTarget target = rig.target(2);
    RequestTracker tracker;
    target.aim(&tracker);
    QSignalSpy gone(&tracker, &RequestTracker::sessionDestroyed);
    rig.link.reset(); // the connection is closed
    QCOMPARE(gone.size(), 1);
    QVERIFY(!target.link());
    QVERIFY(!target.isDirect());
    QVERIFY(!target.session());
    QVERIFY(!target.trafficLog());
    QCOMPARE(target.timeoutMs(), 0);
    QCOMPARE(target.station(), quint8(2)); // still says which PLC it was
    QCOMPARE(target.connectionName(), Rig::connectionName());
}

void TestPlcTarget::gatewayLink()
{
    // Another program owns the PLC's link: the tools cannot talk to it through this one.
    GatewayWatch gateway(GatewayWatchSettings{});
    const PlcTarget target(&gateway, 1, QStringLiteral("Plant (gateway)"));
    QCOMPARE(target.link(), &gateway);
    QVERIFY(!target.isDirect());
    QVERIFY(!target.session());
    QVERIFY(!target.trafficLog());
    gateway.setReadOnly(true);
    QVERIFY(target.isReadOnly());
}

QTEST_GUILESS_MAIN(TestPlcTarget)
#include "tst_plctarget.moc"
