// The ISA-18.2 state machine of one alarm (issue 50): a table of every transition, then the
// timings (deadband, on- and off-delay, shelve expiry, quality delays, chattering) on a fake
// clock: every input carries its time, so nothing here waits.
#include "core/alarm/alarmstatemachine.h"

#include <QTest>

using namespace Fatek;

Q_DECLARE_METATYPE(Fatek::AlarmState)

namespace {

using Events = AlarmStateMachine::Events;
using E = AlarmEventType;
using S = AlarmState;

AlarmDefinition high(double limit, double deadband = 0, int onDelay = 0, int offDelay = 0)
{
    AlarmDefinition d;
    d.kind = AlarmKind::High;
    d.limit = limit;
    d.deadband = deadband;
    d.onDelayMs = onDelay;
    d.offDelayMs = offDelay;
    return d;
}

// A machine brought into `state` the way an operator and the process would.
AlarmStateMachine in(S state, qint64 &now)
{
    AlarmStateMachine m(high(10));
    Events ev;
    switch (state) {
    case S::Normal: break;
    case S::ActiveUnacked: m.valueRead(11, ++now, ev); break;
    case S::ActiveAcked:
        m.valueRead(11, ++now, ev);
        m.acknowledge(++now, ev);
        break;
    case S::ReturnedUnacked:
        m.valueRead(11, ++now, ev);
        m.valueRead(5, ++now, ev);
        break;
    case S::Shelved:
        ++now;
        m.shelve(now + 100000, now, ev);
        break;
    case S::OutOfService: {
        AlarmDefinition d = high(10);
        d.enabled = false;
        m.setDefinition(d, ++now, ev);
        break;
    }
    }
    return m;
}

enum class Input { Above, Below, Ack, Shelve, Unshelve, Disable, Enable, ShelveExpires };

} // namespace

Q_DECLARE_METATYPE(Input)

class TestAlarmStateMachine : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void transitions_data();
    void transitions();
    void deadbandHoldsTheCondition();
    void lowAlarmsMirrorHighOnes();
    void onDelayNeedsAValueReadAfterIt();
    void offDelay();
    void shelveExpiresAndAnnouncesWhatIsActive();
    void shelvedAlarmFollowsTheConditionSilently();
    void qualityAlarmOnTimeAlone();
    void bitAlarms();
    void chatteringWithinAMinute();
    void restoreBringsBackTheState();
    void refusalsChangeNothing();
};

void TestAlarmStateMachine::transitions_data()
{
    QTest::addColumn<S>("from");
    QTest::addColumn<Input>("input");
    QTest::addColumn<S>("to");
    QTest::addColumn<QList<int>>("events");
    const auto ev = [](std::initializer_list<E> list) {
        QList<int> l;
        for (E e : list)
            l << static_cast<int>(e);
        return l;
    };
    // Normal
    QTest::newRow("normal, above: raised")
        << S::Normal << Input::Above << S::ActiveUnacked << ev({E::Raised});
    QTest::newRow("normal, below: nothing") << S::Normal << Input::Below << S::Normal << ev({});
    QTest::newRow("normal, ack: refused") << S::Normal << Input::Ack << S::Normal << ev({});
    QTest::newRow("normal, shelve") << S::Normal << Input::Shelve << S::Shelved << ev({E::Shelved});
    QTest::newRow("normal, disable")
        << S::Normal << Input::Disable << S::OutOfService << ev({E::OutOfService});
    // Active, unacknowledged
    QTest::newRow("unacked, below: returned")
        << S::ActiveUnacked << Input::Below << S::ReturnedUnacked << ev({E::Returned});
    QTest::newRow("unacked, above: nothing")
        << S::ActiveUnacked << Input::Above << S::ActiveUnacked << ev({});
    QTest::newRow("unacked, ack") << S::ActiveUnacked << Input::Ack << S::ActiveAcked
                                  << ev({E::Acknowledged});
    QTest::newRow("unacked, shelve")
        << S::ActiveUnacked << Input::Shelve << S::Shelved << ev({E::Shelved});
    QTest::newRow("unacked, disable")
        << S::ActiveUnacked << Input::Disable << S::OutOfService << ev({E::OutOfService});
    // Active, acknowledged
    QTest::newRow("acked, below: normal")
        << S::ActiveAcked << Input::Below << S::Normal << ev({E::Returned});
    QTest::newRow("acked, ack: refused")
        << S::ActiveAcked << Input::Ack << S::ActiveAcked << ev({});
    QTest::newRow("acked, shelve")
        << S::ActiveAcked << Input::Shelve << S::Shelved << ev({E::Shelved});
    // Returned, unacknowledged
    QTest::newRow("returned, ack: normal")
        << S::ReturnedUnacked << Input::Ack << S::Normal << ev({E::Acknowledged});
    QTest::newRow("returned, above: raised again")
        << S::ReturnedUnacked << Input::Above << S::ActiveUnacked << ev({E::Raised});
    QTest::newRow("returned, shelve")
        << S::ReturnedUnacked << Input::Shelve << S::Shelved << ev({E::Shelved});
    // Shelved
    QTest::newRow("shelved, above: silent") << S::Shelved << Input::Above << S::Shelved << ev({});
    QTest::newRow("shelved, ack: refused") << S::Shelved << Input::Ack << S::Shelved << ev({});
    QTest::newRow("shelved, unshelve: normal")
        << S::Shelved << Input::Unshelve << S::Normal << ev({E::Unshelved});
    QTest::newRow("shelved, expiry: normal")
        << S::Shelved << Input::ShelveExpires << S::Normal << ev({E::Unshelved});
    QTest::newRow("shelved, shelve again")
        << S::Shelved << Input::Shelve << S::Shelved << ev({E::Shelved});
    QTest::newRow("shelved, disable")
        << S::Shelved << Input::Disable << S::OutOfService << ev({E::OutOfService});
    // Out of service
    QTest::newRow("out of service, above: silent")
        << S::OutOfService << Input::Above << S::OutOfService << ev({});
    QTest::newRow("out of service, ack: refused")
        << S::OutOfService << Input::Ack << S::OutOfService << ev({});
    QTest::newRow("out of service, shelve: refused")
        << S::OutOfService << Input::Shelve << S::OutOfService << ev({});
    QTest::newRow("out of service, enable: normal")
        << S::OutOfService << Input::Enable << S::Normal << ev({E::InService});
    QTest::newRow("normal, unshelve: refused")
        << S::Normal << Input::Unshelve << S::Normal << ev({});
}

void TestAlarmStateMachine::transitions()
{
    QFETCH(S, from);
    QFETCH(Input, input);
    QFETCH(S, to);
    QFETCH(QList<int>, events);
    qint64 now = 1000;
    AlarmStateMachine m = in(from, now);
    QCOMPARE(m.state(), from);
    Events ev;
    now += 10;
    switch (input) {
    case Input::Above: m.valueRead(12, now, ev); break;
    case Input::Below: m.valueRead(3, now, ev); break;
    case Input::Ack: m.acknowledge(now, ev); break;
    case Input::Shelve: m.shelve(now + 60000, now, ev); break;
    case Input::Unshelve: m.unshelve(now, ev); break;
    case Input::ShelveExpires: m.tick(now + 200000, ev); break;
    case Input::Disable: {
        AlarmDefinition d = m.definition();
        d.enabled = false;
        m.setDefinition(d, now, ev);
        break;
    }
    case Input::Enable: {
        AlarmDefinition d = m.definition();
        d.enabled = true;
        m.setDefinition(d, now, ev);
        break;
    }
    }
    QCOMPARE(m.state(), to);
    QList<int> got;
    for (E e : ev)
        got << static_cast<int>(e);
    QCOMPARE(got, events);
    if (from != to && input != Input::ShelveExpires)
        QCOMPARE(m.sinceMs(), now);
}

void TestAlarmStateMachine::deadbandHoldsTheCondition()
{
    AlarmStateMachine m(high(80, 2));
    Events ev;
    m.valueRead(79.9, 1, ev);
    QCOMPARE(m.state(), S::Normal);
    m.valueRead(80, 2, ev); // at the limit: raised
    QCOMPARE(m.state(), S::ActiveUnacked);
    m.valueRead(78.5, 3, ev); // below the limit, within the deadband: still active
    QCOMPARE(m.state(), S::ActiveUnacked);
    m.valueRead(78, 4, ev); // limit - deadband: still active
    QCOMPARE(m.state(), S::ActiveUnacked);
    m.valueRead(77.9, 5, ev); // past it: returned
    QCOMPARE(m.state(), S::ReturnedUnacked);
    m.valueRead(79, 6, ev); // raising again needs the limit itself
    QCOMPARE(m.state(), S::ReturnedUnacked);
    QCOMPARE(ev, (Events{E::Raised, E::Returned}));
}

void TestAlarmStateMachine::lowAlarmsMirrorHighOnes()
{
    AlarmDefinition d;
    d.kind = AlarmKind::LowLow;
    d.limit = -5;
    d.deadband = 1;
    AlarmStateMachine m(d);
    Events ev;
    m.valueRead(-4.9, 1, ev);
    m.valueRead(-5, 2, ev);
    m.valueRead(-4.2, 3, ev);
    QCOMPARE(m.state(), S::ActiveUnacked);
    m.valueRead(-3.9, 4, ev);
    QCOMPARE(m.state(), S::ReturnedUnacked);
    QCOMPARE(ev, (Events{E::Raised, E::Returned}));
}

void TestAlarmStateMachine::onDelayNeedsAValueReadAfterIt()
{
    AlarmStateMachine m(high(10, 0, 2000));
    Events ev;
    m.valueRead(11, 1000, ev);
    m.valueRead(11, 2500, ev);
    m.tick(5000, ev); // time alone confirms nothing: no value was read since
    QVERIFY(ev.empty());
    m.valueRead(11, 3000, ev); // 2000 ms after the crossing, confirmed by this reading
    QCOMPARE(ev, (Events{E::Raised}));
    QCOMPARE(m.raisedMs(), 3000);
    // A dip below the limit restarts the delay.
    AlarmStateMachine n(high(10, 0, 2000));
    ev.clear();
    n.valueRead(11, 1000, ev);
    n.valueRead(9, 2000, ev);
    n.valueRead(11, 2500, ev);
    n.valueRead(11, 4000, ev);
    QVERIFY(ev.empty());
    n.valueRead(11, 4500, ev);
    QCOMPARE(ev, (Events{E::Raised}));
}

void TestAlarmStateMachine::offDelay()
{
    AlarmStateMachine m(high(10, 0, 0, 3000));
    Events ev;
    m.valueRead(11, 0, ev);
    m.valueRead(5, 1000, ev);
    m.valueRead(5, 3999, ev);
    QCOMPARE(m.state(), S::ActiveUnacked);
    m.valueRead(5, 4000, ev);
    QCOMPARE(m.state(), S::ReturnedUnacked);
    QCOMPARE(ev, (Events{E::Raised, E::Returned}));
}

void TestAlarmStateMachine::shelveExpiresAndAnnouncesWhatIsActive()
{
    AlarmStateMachine m(high(10));
    Events ev;
    m.valueRead(11, 0, ev);
    m.acknowledge(10, ev);
    QCOMPARE(m.shelve(60000, 20, ev), AlarmStateMachine::Refusal::None);
    QCOMPARE(m.shelvedUntilMs(), 60000);
    ev.clear();
    m.tick(59999, ev);
    QCOMPARE(m.state(), S::Shelved);
    m.tick(60000, ev);
    // Still above the limit: announced as new (unacknowledged), the operator has not seen it.
    QCOMPARE(ev, (Events{E::Unshelved, E::Raised}));
    QCOMPARE(m.state(), S::ActiveUnacked);
    QCOMPARE(m.shelvedUntilMs(), 0);
}

void TestAlarmStateMachine::shelvedAlarmFollowsTheConditionSilently()
{
    AlarmStateMachine m(high(10));
    Events ev;
    m.shelve(100000, 0, ev);
    ev.clear();
    m.valueRead(11, 10, ev);
    m.valueRead(5, 20, ev);
    QVERIFY(ev.empty());
    m.unshelve(30, ev);
    QCOMPARE(ev, (Events{E::Unshelved}));
    QCOMPARE(m.state(), S::Normal);
}

void TestAlarmStateMachine::qualityAlarmOnTimeAlone()
{
    AlarmDefinition d;
    d.kind = AlarmKind::Quality;
    d.onDelayMs = 5000;
    d.offDelayMs = 1000;
    AlarmStateMachine m(d);
    Events ev;
    m.valueRead(99, 0, ev); // values mean nothing to it
    m.qualitySeen(false, 0, ev);
    m.qualitySeen(true, 1000, ev);
    m.tick(5999, ev);
    QVERIFY(ev.empty());
    m.tick(6000, ev); // stale for 5 s, nothing read since: raised by time alone
    QCOMPARE(ev, (Events{E::Raised}));
    m.qualitySeen(false, 7000, ev);
    m.tick(7999, ev);
    QCOMPARE(m.state(), S::ActiveUnacked);
    m.tick(8000, ev);
    QCOMPARE(m.state(), S::ReturnedUnacked);
}

void TestAlarmStateMachine::bitAlarms()
{
    AlarmDefinition on;
    on.kind = AlarmKind::On;
    AlarmStateMachine m(on);
    Events ev;
    m.valueRead(0, 0, ev);
    QCOMPARE(m.state(), S::Normal);
    m.valueRead(1, 1, ev);
    QCOMPARE(m.state(), S::ActiveUnacked);
    AlarmDefinition off;
    off.kind = AlarmKind::Off;
    AlarmStateMachine n(off);
    n.valueRead(1, 0, ev);
    QCOMPARE(n.state(), S::Normal);
    n.valueRead(0, 1, ev);
    QCOMPARE(n.state(), S::ActiveUnacked);
}

void TestAlarmStateMachine::chatteringWithinAMinute()
{
    AlarmStateMachine m(high(10));
    Events ev;
    qint64 t = 0;
    for (int i = 0; i < 3; ++i) {
        m.valueRead(11, t += 1000, ev);
        m.valueRead(5, t += 1000, ev);
    }
    QCOMPARE(std::count(ev.begin(), ev.end(), E::Raised), 3);
    QVERIFY(m.chattering(t));
    QVERIFY(m.chattering(1000 + Alarms::ChatterWindowMs));
    QVERIFY(!m.chattering(1001 + Alarms::ChatterWindowMs)); // the first raise left the minute
    // Two raises a minute apart are not chattering.
    AlarmStateMachine n(high(10));
    n.valueRead(11, 0, ev);
    n.valueRead(5, 1, ev);
    n.valueRead(11, 70000, ev);
    n.valueRead(5, 70001, ev);
    n.valueRead(11, 140000, ev);
    QVERIFY(!n.chattering(140000));
}

void TestAlarmStateMachine::restoreBringsBackTheState()
{
    AlarmStateMachine before(high(10));
    Events ev;
    before.valueRead(11, 100, ev);
    const AlarmRecord kept = before.record();
    QCOMPARE(kept.state, S::ActiveUnacked);
    QVERIFY(kept.conditionActive);

    AlarmStateMachine after(high(10));
    after.restore(kept);
    QCOMPARE(after.state(), S::ActiveUnacked);
    QCOMPARE(after.raisedMs(), 100);
    ev.clear();
    after.valueRead(12, 200, ev); // still active: nothing new (not raised twice)
    QVERIFY(ev.empty());
    after.valueRead(5, 300, ev); // back in range while nobody acknowledged it
    QCOMPARE(ev, (Events{E::Returned}));
    QCOMPARE(after.state(), S::ReturnedUnacked);

    // A shelve whose expiry passed while the program was stopped ends at the first tick.
    AlarmRecord shelved;
    shelved.state = S::Shelved;
    shelved.shelvedUntilMs = 500;
    AlarmStateMachine s(high(10));
    s.restore(shelved);
    ev.clear();
    s.tick(1000, ev);
    QCOMPARE(ev, (Events{E::Unshelved}));
}

void TestAlarmStateMachine::refusalsChangeNothing()
{
    AlarmStateMachine m(high(10));
    Events ev;
    QCOMPARE(m.acknowledge(1, ev), AlarmStateMachine::Refusal::NothingToAck);
    QCOMPARE(m.unshelve(1, ev), AlarmStateMachine::Refusal::NotShelved);
    QCOMPARE(m.shelve(5, 10, ev), AlarmStateMachine::Refusal::ShelveExpired);
    QVERIFY(ev.empty());
    QCOMPARE(m.state(), S::Normal);
    QCOMPARE(m.sinceMs(), 0);
}

QTEST_GUILESS_MAIN(TestAlarmStateMachine)
#include "tst_alarmstatemachine.moc"
