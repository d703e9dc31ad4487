// The one rule for changes to a PLC (ChangeVerifier, docs/reliability.md "Changes to a PLC"):
// done, refused (nothing sent, or the PLC said no) or unknown (sent, not answered); a change is
// sent once and never after its deadline; an unknown one is read back as soon as the PLC answers.
// Against the simulator over loopback TCP; what reached the PLC is counted on the simulator.
#include "core/protocol/changecheck.h"
#include "core/session/changeverifier.h"
#include "core/session/session.h"
#include "core/sim/simserver.h"
#include "core/sim/simulatedplc.h"
#include "loopbacksession.h"

#include <QTest>

#include <memory>
#include <optional>

using namespace Fatek;

namespace {

Address addr(const char *text)
{
    return Address::parse(text).value();
}

template<typename Predicate>
bool waitUntil(Predicate done, int ms = 10000)
{
    QDeadlineTimer deadline(ms);
    while (!done() && !deadline.hasExpired())
        QTest::qWait(2);
    return done();
}

// Every report of one change, in order.
struct Reports
{
    QList<ChangeReport> list;
    ChangeVerifier::Callback callback()
    {
        return [this](const ChangeReport &r) {
            list.append(r);
        };
    }
    bool hasFinal() const { return !list.isEmpty() && list.last().final; }
};

FaultConfig dropAll()
{
    FaultConfig f;
    f.dropRate = 1.0; // the PLC acts on every frame and answers none
    return f;
}

} // namespace

class TestChangeOutcome : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void init();
    void cleanup();

    void readBackTable_data();
    void readBackTable();
    void outcomeOfResults();
    void writeSentOnceOnTimeout();
    void expiredWriteNotSent();
    void retryNotSentPastDeadline();
    void unknownWriteReadBackDone();
    void unknownWriteReadBackNotDone();
    void lateAnswerNotTakenForTheReadBack();
    void unknownWaitsForTheLink();
    void unknownStillUnknownWhenClosed();
    void runStopReadBack();
    void plcRefusalIsRefused();

private:
    std::unique_ptr<Session> openSession(int timeoutMs = 300, int retries = 2);

    std::unique_ptr<SimulatedPlc> m_plc;
    std::unique_ptr<SimServer> m_server;
};

void TestChangeOutcome::init()
{
    m_plc = std::make_unique<SimulatedPlc>(ModelProfile::fbs());
    m_server = std::make_unique<SimServer>(m_plc.get());
    QString error;
    QVERIFY2(m_server->listenTcp(0, &error), qPrintable(error));
}

void TestChangeOutcome::cleanup()
{
    m_server.reset();
    m_plc.reset();
}

std::unique_ptr<Session> TestChangeOutcome::openSession(int timeoutMs, int retries)
{
    return TestUtil::openLoopbackSession(m_server->tcpPort(), timeoutMs, retries);
}

// What is read back for each kind of change, and which answers show it in place.
void TestChangeOutcome::readBackTable_data()
{
    QTest::addColumn<Request>("change");
    QTest::addColumn<std::optional<Request>>("read");
    QTest::addColumn<Response>("shows");
    QTest::addColumn<Response>("differs");
    const auto answer = [](std::vector<std::uint32_t> values, Bytes data = {}) {
        Response r;
        r.values = std::move(values);
        r.data = std::move(data);
        return r;
    };
    QTest::newRow("registers") << Request::writeRegisters(2, addr("R50"), {3333, 7})
                               << std::optional(Request::readRegisters(2, addr("R50"), 2))
                               << answer({3333, 7}) << answer({3333, 8});
    QTest::newRow("32-bit") << Request::writeRegisters(1, addr("DR10"), {0x12345678})
                            << std::optional(Request::readRegisters(1, addr("DR10"), 1))
                            << answer({0x12345678}) << answer({0x5678});
    QTest::newRow("discretes") << Request::writeDiscretes(1, addr("M10"), {1, 0, 1})
                               << std::optional(Request::readDiscretes(1, addr("M10"), 3))
                               << answer({1, 0, 1}) << answer({1, 1, 1});
    QTest::newRow("mixed") << Request::mixedWrite(1, {addr("R1"), addr("Y2")}, {5, 1})
                           << std::optional(Request::mixedRead(1, {addr("R1"), addr("Y2")}))
                           << answer({5, 1}) << answer({5, 0});
    QTest::newRow("set") << Request::discreteControl(1, DiscreteOp::Set, addr("Y4"))
                         << std::optional(Request::readDiscretes(1, addr("Y4"), 1)) << answer({1})
                         << answer({0});
    QTest::newRow("reset") << Request::discreteControl(1, DiscreteOp::Reset, addr("Y4"))
                           << std::optional(Request::readDiscretes(1, addr("Y4"), 1)) << answer({0})
                           << answer({1});
    QTest::newRow("disable") << Request::discreteControl(1, DiscreteOp::Disable, addr("Y4"))
                             << std::optional(Request::readEnableFlags(1, addr("Y4"), 1))
                             << answer({1}) << answer({0});
    QTest::newRow("enable") << Request::discreteControl(1, DiscreteOp::Enable, addr("Y4"))
                            << std::optional(Request::readEnableFlags(1, addr("Y4"), 1))
                            << answer({0}) << answer({1});
    QTest::newRow("run") << Request::runStop(1, true) << std::optional(Request::briefStatus(1))
                         << answer({}, {0x01, 0, 0}) << answer({}, {0x00, 0, 0});
    QTest::newRow("stop") << Request::runStop(1, false) << std::optional(Request::briefStatus(1))
                          << answer({}, {0x00, 0, 0}) << answer({}, {0x01, 0, 0});
    QTest::newRow("program page") << Request::writeProgram(1, 0, std::vector<std::uint32_t>(64))
                                  << std::optional<Request>() << Response{} << Response{};
    QTest::newRow("broadcast") << Request::writeRegisters(0, addr("R1"), {1})
                               << std::optional<Request>() << Response{} << Response{};
}

void TestChangeOutcome::readBackTable()
{
    QFETCH(Request, change);
    QFETCH(std::optional<Request>, read);
    QFETCH(Response, shows);
    QFETCH(Response, differs);
    QCOMPARE(ChangeCheck::readBack(change), read);
    if (!read)
        return;
    QVERIFY(ChangeCheck::inPlace(change, shows));
    QVERIFY(!ChangeCheck::inPlace(change, differs));
    QVERIFY(!ChangeCheck::inPlace(change, Response{})); // an empty answer shows nothing
}

void TestChangeOutcome::outcomeOfResults()
{
    SessionResult done(Result<Response>(Response{}));
    done.setAttempts(1);
    QCOMPARE(done.outcome(), ChangeOutcome::Done);
    SessionResult notSent = SessionResult::fromError(makeError(ErrorKind::LinkError, "down"));
    QCOMPARE(notSent.outcome(), ChangeOutcome::Refused);
    SessionResult plc = SessionResult::fromError(makePlcError(0xA, "R70000"));
    plc.setAttempts(1);
    QCOMPARE(plc.outcome(), ChangeOutcome::Refused);
    for (ErrorKind kind : {ErrorKind::Timeout, ErrorKind::LinkError, ErrorKind::Cancelled,
                           ErrorKind::BadChecksum, ErrorKind::MalformedResponse}) {
        SessionResult sent = SessionResult::fromError(makeError(kind, "lost"));
        sent.setAttempts(1);
        QCOMPARE(sent.outcome(), ChangeOutcome::Unknown);
    }
}

// A write whose answer is late is not sent again (a copy could land later still): one frame, an
// unknown outcome, and the PLC holds the value. (Reads keep their retries: tst_session.)
void TestChangeOutcome::writeSentOnceOnTimeout()
{
    auto session = openSession(100, 2);
    FaultConfig slow;
    slow.latencyMs = 250;
    m_server->setFaults(slow);
    std::optional<SessionResult> result;
    QObject context;
    session->submit(Request::writeRegisters(1, addr("R300"), {5}), &context,
                    [&](const SessionResult &r) { result = r; });
    QVERIFY(waitUntil([&] { return result.has_value(); }));
    QCOMPARE(result->errorKind(), ErrorKind::Timeout);
    QCOMPARE(result->attempts(), 1);
    QCOMPARE(result->outcome(), ChangeOutcome::Unknown);
    QTest::qWait(400); // a second copy would have arrived by now
    QCOMPARE(m_server->counters().frames, quint64(1));
    QCOMPARE(m_plc->value(addr("R300")), std::optional<std::uint32_t>(5));
}

// A write that waited past its deadline behind a slow request is not sent: refused, and the
// simulator never saw it.
void TestChangeOutcome::expiredWriteNotSent()
{
    auto session = openSession(1000, 0);
    FaultConfig slow;
    slow.latencyMs = 300;
    m_server->setFaults(slow);
    QObject context;
    std::optional<SessionResult> read, write;
    session->submit(Request::readRegisters(1, addr("R0"), 1), &context,
                    [&](const SessionResult &r) { read = r; });
    RequestOptions options;
    options.deadline.setRemainingTime(100);
    session->submit(
        Request::writeRegisters(1, addr("R301"), {77}), &context,
        [&](const SessionResult &r) { write = r; }, Priority::User, options);
    QVERIFY(waitUntil([&] { return read && write; }));
    QVERIFY(read->ok());
    QCOMPARE(write->errorKind(), ErrorKind::Expired);
    QCOMPARE(write->attempts(), 0);
    QCOMPARE(write->outcome(), ChangeOutcome::Refused);
    QVERIFY2(write->errorText().contains(QStringLiteral("deadline")),
             qPrintable(write->errorText()));
    QTest::qWait(100);
    QCOMPARE(m_server->counters().frames, quint64(1));
    QCOMPARE(m_plc->value(addr("R301")), std::optional<std::uint32_t>(0));
}

// A read's retry is not sent past the request's deadline either.
void TestChangeOutcome::retryNotSentPastDeadline()
{
    auto session = openSession(150, 5);
    m_server->setFaults(dropAll());
    QObject context;
    std::optional<SessionResult> read;
    RequestOptions options;
    options.deadline.setRemainingTime(200);
    session->submit(
        Request::readRegisters(1, addr("R0"), 1), &context,
        [&](const SessionResult &r) { read = r; }, Priority::User, options);
    QVERIFY(waitUntil([&] { return read.has_value(); }));
    QCOMPARE(read->errorKind(), ErrorKind::Timeout);
    QCOMPARE(read->attempts(), 2); // at 0 and 150 ms; the third would go at 300 ms
    QCOMPARE(m_server->counters().frames, quint64(2));
}

// Unknown, then done: the answer was lost, the read-back shows the value in place.
void TestChangeOutcome::unknownWriteReadBackDone()
{
    auto session = openSession(150, 1);
    m_server->setFaults(dropAll());
    QObject context;
    Reports reports;
    ChangeVerifier::submit(session.get(), Request::writeRegisters(1, addr("R50"), {3333}), &context,
                           reports.callback());
    QVERIFY(waitUntil([&] { return !reports.list.isEmpty(); }));
    QCOMPARE(reports.list.first().outcome, ChangeOutcome::Unknown);
    QVERIFY(!reports.list.first().final);
    QVERIFY2(english(reports.list.first().message).find("may have been carried out")
                 != std::string::npos,
             english(reports.list.first().message).c_str());
    // The read-back goes unanswered too, and is asked again until the PLC answers.
    QVERIFY(waitUntil([&] { return m_server->counters().frames >= 3; }));
    QVERIFY(!reports.hasFinal());
    m_server->setFaults({});
    QVERIFY(waitUntil([&] { return reports.hasFinal(); }));
    QCOMPARE(reports.list.size(), 2);
    QCOMPARE(reports.list.last().outcome, ChangeOutcome::Done);
    QVERIFY2(english(reports.list.last().message).find("Done: confirmed by reading it back") == 0,
             english(reports.list.last().message).c_str());
    QCOMPARE(m_plc->value(addr("R50")), std::optional<std::uint32_t>(3333));
}

// Unknown, then not done: the PLC holds something else when it is read back.
void TestChangeOutcome::unknownWriteReadBackNotDone()
{
    auto session = openSession(150, 1);
    m_server->setFaults(dropAll());
    QObject context;
    Reports reports;
    ChangeVerifier::submit(session.get(), Request::writeRegisters(1, addr("R51"), {3333}), &context,
                           reports.callback());
    QVERIFY(waitUntil([&] { return !reports.list.isEmpty(); }));
    m_plc->setValue(addr("R51"), 12); // the PLC's program wrote it since
    m_server->setFaults({});
    QVERIFY(waitUntil([&] { return reports.hasFinal(); }));
    QCOMPARE(reports.list.last().outcome, ChangeOutcome::Refused);
    QVERIFY2(english(reports.list.last().message).find("Not done") == 0,
             english(reports.list.last().message).c_str());
}

// A PLC that answers late (in order, as one that stalled): the answer to a read of the same
// register sent before the write (FACON answers carry no address) must not be taken for the
// read-back's. Found through the gateway with a PLC stopped mid-request: a write that landed was
// reported "not done". The read-back follows a fence (a loopback answered with its own data).
void TestChangeOutcome::lateAnswerNotTakenForTheReadBack()
{
    auto session = openSession(400, 0);
    QVERIFY(m_plc->setValue(addr("R101"), 5));
    FaultConfig slow;
    slow.latencyMs = 1000; // every answer after the session gave up on it
    m_server->setFaults(slow);
    QObject context;
    std::optional<SessionResult> read;
    session->submit(Request::readRegisters(1, addr("R101"), 1), &context,
                    [&read](const SessionResult &r) { read = r; });
    QList<ChangeReport> reports;
    ChangeVerifier::submit(session.get(), Request::writeRegisters(1, addr("R101"), {789}), &context,
                           [&](const ChangeReport &r) {
                               reports.append(r);
                               if (reports.size() == 1) {
                                   // Answers now come within the timeout, behind the late ones.
                                   FaultConfig quicker;
                                   quicker.latencyMs = 300;
                                   m_server->setFaults(quicker);
                               }
                           });
    QVERIFY(waitUntil([&] { return !reports.isEmpty() && reports.last().final; }));
    QVERIFY(read && !read->ok());
    QCOMPARE(reports.first().outcome, ChangeOutcome::Unknown);
    QCOMPARE(m_plc->value(addr("R101")), std::optional<std::uint32_t>(789));
    QVERIFY2(reports.last().outcome == ChangeOutcome::Done,
             english(reports.last().message).c_str());
}

// The link is lost after the write: the read-back waits for it and goes once it is back.
void TestChangeOutcome::unknownWaitsForTheLink()
{
    LinkSettings settings = LinkSettings::tcp(QStringLiteral("127.0.0.1"), m_server->tcpPort(),
                                              LinkSettings::ProtocolChoice::Facon);
    settings.timeoutMs = 150;
    settings.retries = 0;
    settings.autoReconnect = true;
    Session session(settings);
    session.open();
    QVERIFY(waitUntil([&] { return session.linkState() == LinkState::Connected; }));
    const quint16 port = m_server->tcpPort();
    m_server->setFaults(dropAll());
    QObject context;
    Reports reports;
    ChangeVerifier::submit(&session, Request::writeRegisters(1, addr("R52"), {9}), &context,
                           reports.callback());
    QVERIFY(waitUntil([&] { return !reports.list.isEmpty(); }));
    QCOMPARE(reports.list.first().outcome, ChangeOutcome::Unknown);
    m_server->close(); // the PLC goes away
    QVERIFY(waitUntil([&] { return session.linkState() != LinkState::Connected; }));
    QTest::qWait(300);
    QVERIFY(!reports.hasFinal());
    m_server->setFaults({});
    QString error;
    QVERIFY2(m_server->listenTcp(port, &error), qPrintable(error));
    QVERIFY(waitUntil([&] { return reports.hasFinal(); }, 20000));
    QCOMPARE(reports.list.last().outcome, ChangeOutcome::Done);
}

// Closed before the read-back could tell: still unknown, said as such (never "failed").
void TestChangeOutcome::unknownStillUnknownWhenClosed()
{
    auto session = openSession(150, 0);
    m_server->setFaults(dropAll());
    QObject context;
    Reports reports;
    ChangeVerifier::submit(session.get(), Request::writeRegisters(1, addr("R53"), {1}), &context,
                           reports.callback());
    QVERIFY(waitUntil([&] { return !reports.list.isEmpty(); }));
    session->close(CloseMode::Discard);
    QVERIFY(waitUntil([&] { return reports.hasFinal(); }));
    QCOMPARE(reports.list.size(), 2);
    QCOMPARE(reports.list.last().outcome, ChangeOutcome::Unknown);
    QVERIFY2(english(reports.list.last().message).find("still unknown") != std::string::npos,
             english(reports.list.last().message).c_str());
}

void TestChangeOutcome::runStopReadBack()
{
    auto session = openSession(150, 0);
    QVERIFY(m_plc->isRunning());
    m_server->setFaults(dropAll());
    QObject context;
    Reports reports;
    ChangeVerifier::submit(session.get(), Request::runStop(1, false), &context, reports.callback());
    QVERIFY(waitUntil([&] { return !reports.list.isEmpty(); }));
    QCOMPARE(reports.list.first().outcome, ChangeOutcome::Unknown);
    m_server->setFaults({});
    QVERIFY(waitUntil([&] { return reports.hasFinal(); }));
    QCOMPARE(reports.list.last().outcome, ChangeOutcome::Done);
    QVERIFY(!m_plc->isRunning());
}

// The PLC answered with an error: refused, one report, nothing read back.
void TestChangeOutcome::plcRefusalIsRefused()
{
    auto session = openSession(300, 0);
    QObject context;
    Reports reports;
    ChangeVerifier::submit(session.get(), Request::writeRegisters(1, addr("R4000"), {1}), &context,
                           reports.callback());
    QVERIFY(waitUntil([&] { return !reports.list.isEmpty(); }));
    QTest::qWait(200);
    QCOMPARE(reports.list.size(), 1);
    QCOMPARE(reports.list.first().outcome, ChangeOutcome::Refused);
    QVERIFY(reports.list.first().final);
    QCOMPARE(m_server->counters().frames, quint64(1));
}

QTEST_GUILESS_MAIN(TestChangeOutcome)
#include "tst_changeoutcome.moc"
