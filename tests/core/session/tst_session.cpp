// Sessions against the in-process simulator over TCP, UDP and a socat pty pair, in both protocols.
#include "core/protocol/binarycodec.h"
#include "core/protocol/faconcodec.h"
#include "core/session/session.h"
#include "core/session/stationscanner.h"
#include "core/sim/simserver.h"
#include "core/sim/simulatedplc.h"
#include "testutil.h"

#include <QElapsedTimer>
#include <QEventLoop>
#include <QFile>
#include <QProcess>
#include <QSerialPort>
#include <QSet>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTcpServer>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>

#include <algorithm>
#include <memory>
#include <thread>

using namespace Fatek;

namespace {

Address addr(const char *text)
{
    return Address::parse(text).value();
}

Bytes bytes(const char *text)
{
    const std::string s(text);
    return Bytes(s.begin(), s.end());
}

using TestUtil::startPtyPair;

// Collects every finished() of a session, in arrival order.
class Results : public QObject
{
public:
    explicit Results(Session *session)
    {
        connect(session, &Session::finished, this, [this](quint64 id, const SessionResult &result) {
            map.insert(id, result);
            order.append(id);
        });
    }
    bool waitFor(quint64 id, int ms = 10000)
    {
        QDeadlineTimer deadline(ms);
        while (!map.contains(id) && !deadline.hasExpired())
            QTest::qWait(2);
        return map.contains(id);
    }
    QHash<quint64, SessionResult> map;
    QList<quint64> order;
};

} // namespace

// The session under test, so that a failed check can show its last traffic.
static Session *g_session = nullptr;
static void dumpLog()
{
    if (!g_session)
        return;
    const quint64 last = g_session->trafficLog()->lastSequence();
    const auto entries = g_session->trafficLog()->entries(last > 8 ? last - 8 : 0);
    for (const TrafficEntry &e : entries)
        qDebug() << int(e.direction) << e.bytes << englishText(e.summary) << englishText(e.error);
}

class TestSession : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void init();
    void cleanup();

    void everyCommand_data();
    void everyCommand();
    void largeAnswers_data();
    void largeAnswers();
    void refusedWhenNotOpen();
    void invalidRequestNeverSent();
    void timeoutAndRetries();
    void damagedAnswersAreRetried();
    void otherStationIgnored();
    void broadcastGetsNoAnswer();
    void userActionsGoFirst();
    void readOnlyMode();
    void rawFrames_data();
    void rawFrames();
    void autoDetect();
    void autoDetectNobody();
    void reconnectAfterSimulatorRestart();
    void reconnectsAreSpread();
    void closeCancelsPending();
    void statistics();
    void trafficLogBounded();
    void trafficLogWakesOnlyListeners();
    void polling();
    void pollingIsolatesBadAddress();
    void pollingSeveralStations();
    void pollingTrickyWatchList_data();
    void pollingTrickyWatchList();
    void lateAnswerDiscarded();
    void stationScan();
    void destroyWhileBusy();
    void serialMultiDrop_data();
    void serialMultiDrop();
    void broadcastOnTheWireBeforeClose();
    void broadcastHeldWhenLinkLost();
    void closeSendsQueuedWrites();
    void destroySendsQueuedWrites_data();
    void destroySendsQueuedWrites();
    void closeDrainIsBounded();
    void retriedWriteReportedOnce();
    void rawUnderAutoNeedsNoProbe();
    void broadcastUnderAuto();

private:
    // Opens the simulator endpoint for `transport` and fills `settings`; false (with QSKIP) if
    // impossible.
    bool makeLink(const QString &transport, LinkSettings::ProtocolChoice protocol,
                  LinkSettings &settings);
    std::unique_ptr<Session> openSession(const LinkSettings &settings);
    // A serial line to the PLC side of a pty pair (`plcSide`), in software flow control so that
    // XOFF holds the session's output; false when socat is not available.
    bool startXoffLine(LinkSettings &settings, QString *plcSide);
    SessionResult run(Session &session, Results &results, const Request &request,
                      Priority priority = Priority::User);

    std::unique_ptr<SimulatedPlc> m_plc;
    std::unique_ptr<SimServer> m_server;
    std::shared_ptr<QProcess> m_socat;
    std::unique_ptr<QTemporaryDir> m_dir;
};

void TestSession::init()
{
    m_plc = std::make_unique<SimulatedPlc>(ModelProfile::fbs());
    m_server = std::make_unique<SimServer>(m_plc.get());
}

void TestSession::cleanup()
{
    g_session = nullptr;
    m_server.reset();
    m_plc.reset();
    m_socat.reset(); // stops socat
    m_dir.reset();
}

bool TestSession::makeLink(const QString &transport, LinkSettings::ProtocolChoice protocol,
                           LinkSettings &settings)
{
    QString error;
    if (transport == QLatin1String("tcp")) {
        if (!m_server->listenTcp(0, &error))
            qWarning() << error;
        settings = LinkSettings::tcp(QStringLiteral("127.0.0.1"), m_server->tcpPort(), protocol);
    } else if (transport == QLatin1String("udp")) {
        if (!m_server->listenUdp(0, &error))
            qWarning() << error;
        settings = LinkSettings::udp(QStringLiteral("127.0.0.1"), m_server->udpPort(), protocol);
    } else {
        m_dir = std::make_unique<QTemporaryDir>();
        const QString plcSide = m_dir->filePath(QStringLiteral("plc"));
        const QString appSide = m_dir->filePath(QStringLiteral("app"));
        m_socat = startPtyPair(plcSide, appSide);
        if (!m_socat)
            return false;
        SerialSettings serial;
        serial.portName = plcSide;
        if (!m_server->openSerial(serial, &error)) {
            qWarning() << error;
            return false;
        }
        settings = LinkSettings::serial(appSide, 9600, protocol);
        settings.interFrameMs = 2;
    }
    settings.timeoutMs = 1000;
    settings.retries = 1;
    return true;
}

std::unique_ptr<Session> TestSession::openSession(const LinkSettings &settings)
{
    auto session = std::make_unique<Session>(settings);
    g_session = session.get();
    QSignalSpy states(session.get(), &Session::linkStateChanged);
    session->open();
    QDeadlineTimer deadline(10000);
    while (session->linkState() != LinkState::Connected && !deadline.hasExpired())
        QTest::qWait(5);
    return session;
}

SessionResult TestSession::run(Session &session, Results &results, const Request &request,
                               Priority priority)
{
    const quint64 id = session.submit(request, priority);
    if (!results.waitFor(id))
        return SessionResult::fromError(
            makeError(ErrorKind::Timeout, "test: no finished() signal"));
    return results.map.value(id);
}

// Evaluates `expr` once (QVERIFY2 evaluates its message even on success).
#define CHECK_OK(expr)                                                                             \
    do {                                                                                           \
        const SessionResult checked_ = (expr);                                                     \
        if (!checked_.ok())                                                                        \
            dumpLog();                                                                             \
        QVERIFY2(checked_.ok(), qPrintable(checked_.errorText()));                                 \
    } while (false)

void TestSession::everyCommand_data()
{
    QTest::addColumn<QString>("transport");
    QTest::addColumn<int>("protocol");
    for (const char *transport : {"tcp", "udp", "serial"}) {
        QTest::addRow("%s facon", transport)
            << QString::fromLatin1(transport) << int(Protocol::Facon);
        QTest::addRow("%s binary", transport)
            << QString::fromLatin1(transport) << int(Protocol::Binary);
    }
}

void TestSession::everyCommand()
{
    QFETCH(QString, transport);
    QFETCH(int, protocol);
    const auto proto = static_cast<Protocol>(protocol);
    LinkSettings settings;
    if (!makeLink(transport,
                  proto == Protocol::Facon ? LinkSettings::ProtocolChoice::Facon
                                           : LinkSettings::ProtocolChoice::Binary,
                  settings))
        QSKIP("socat is not available for a serial pty pair");
    auto session = openSession(settings);
    QCOMPARE(session->linkState(), LinkState::Connected);
    QCOMPARE(session->protocol(), proto);
    Results results(session.get());
    m_plc->setRunning(false);

    // 40 brief status
    SessionResult r = run(*session, results, Request::briefStatus(1));
    CHECK_OK(r);
    QVERIFY(!r.response().data.empty());
    QVERIFY(!PlcStatus::fromStatus1(r.response().data.front()).running);

    // 41 RUN / STOP
    CHECK_OK(run(*session, results, Request::runStop(1, true)));
    QVERIFY(m_plc->isRunning());
    r = run(*session, results, Request::briefStatus(1));
    CHECK_OK(r);
    QVERIFY(PlcStatus::fromStatus1(r.response().data.front()).running);
    CHECK_OK(run(*session, results, Request::runStop(1, false)));
    QVERIFY(!m_plc->isRunning());

    // 42 single discrete control, 43 enable flags
    CHECK_OK(run(*session, results, Request::discreteControl(1, DiscreteOp::Set, addr("Y5"))));
    QCOMPARE(m_plc->value(addr("Y5")), std::optional<std::uint32_t>(1));
    CHECK_OK(run(*session, results, Request::discreteControl(1, DiscreteOp::Disable, addr("M3"))));
    r = run(*session, results, Request::readEnableFlags(1, addr("M0"), 8));
    CHECK_OK(r);
    QCOMPARE(r.response().values, (std::vector<std::uint32_t>{0, 0, 0, 1, 0, 0, 0, 0}));

    // 45 / 44 discretes
    CHECK_OK(run(*session, results, Request::writeDiscretes(1, addr("Y8"), {1, 0, 1, 1})));
    r = run(*session, results, Request::readDiscretes(1, addr("Y8"), 4));
    CHECK_OK(r);
    QCOMPARE(r.response().values, (std::vector<std::uint32_t>{1, 0, 1, 1}));

    // 47 / 46 registers, 16 and 32 bit
    CHECK_OK(run(*session, results, Request::writeRegisters(1, addr("R10"), {1, 2, 65535})));
    r = run(*session, results, Request::readRegisters(1, addr("R10"), 3));
    CHECK_OK(r);
    QCOMPARE(r.response().values, (std::vector<std::uint32_t>{1, 2, 65535}));
    CHECK_OK(run(*session, results, Request::writeRegisters(1, addr("DR20"), {0x12345678})));
    r = run(*session, results, Request::readRegisters(1, addr("DR20"), 1));
    CHECK_OK(r);
    QCOMPARE(r.response().values, (std::vector<std::uint32_t>{0x12345678}));

    // 49 / 48 mixed
    CHECK_OK(
        run(*session, results,
            Request::mixedWrite(1, {addr("R100"), addr("Y20"), addr("DR30")}, {7, 1, 100000})));
    r = run(*session, results, Request::mixedRead(1, {addr("R100"), addr("Y20"), addr("DR30")}));
    CHECK_OK(r);
    QCOMPARE(r.response().values, (std::vector<std::uint32_t>{7, 1, 100000}));

    // 4E loopback
    r = run(*session, results, Request::loopback(1, bytes("ABC123")));
    CHECK_OK(r);
    QCOMPARE(r.response().data, bytes("ABC123"));

    // 4F / 50 program pages: FACON only
    std::vector<std::uint32_t> page(64);
    for (std::size_t i = 0; i < page.size(); ++i)
        page[i] = static_cast<std::uint32_t>(i * 3 + 1);
    r = run(*session, results, Request::writeProgram(1, 1, page));
    if (proto == Protocol::Facon) {
        CHECK_OK(r);
        r = run(*session, results, Request::readProgram(1, 1));
        CHECK_OK(r);
        QCOMPARE(r.response().values, page);
    } else {
        QVERIFY(!r.ok());
        QCOMPARE(r.errorKind(), ErrorKind::Unsupported);
        QCOMPARE(r.attempts(), 0); // refused before the wire
    }

    // 53 detail status
    r = run(*session, results, Request::detailStatus(1));
    CHECK_OK(r);
    QVERIFY(!r.response().data.empty());

    // A PLC error comes back typed, naming the address, and is not retried.
    r = run(*session, results, Request::readRegisters(1, addr("R3900"), 1));
    QVERIFY(!r.ok());
    QCOMPARE(r.errorKind(), ErrorKind::PlcError);
    QCOMPARE(r.error().plcCode, 0xA);
    QVERIFY2(r.errorText().contains(QStringLiteral("R3900")), qPrintable(r.errorText()));
    QCOMPARE(r.attempts(), 1);
    QCOMPARE(session->statistics().total.plcErrors, quint64(1));
}

void TestSession::largeAnswers_data()
{
    QTest::addColumn<int>("protocol");
    QTest::newRow("udp facon") << int(Protocol::Facon);
    QTest::newRow("udp binary") << int(Protocol::Binary);
}

void TestSession::largeAnswers()
{
    QFETCH(int, protocol);
    LinkSettings settings;
    QVERIFY(makeLink(QStringLiteral("udp"),
                     protocol == int(Protocol::Facon) ? LinkSettings::ProtocolChoice::Facon
                                                      : LinkSettings::ProtocolChoice::Binary,
                     settings));
    auto session = openSession(settings);
    Results results(session.get());

    // 256 discretes, 64 registers, 32 DR, a 64-word mixed read, 256 bytes of loopback: the
    // largest answers of each kind, each in one datagram.
    for (std::uint32_t i = 0; i < 256; ++i)
        m_plc->setValue({ElementType::M, i}, i % 3 == 0 ? 1 : 0);
    SessionResult r = run(*session, results, Request::readDiscretes(1, addr("M0"), 256));
    CHECK_OK(r);
    QCOMPARE(r.response().values.size(), std::size_t(256));
    for (std::uint32_t i = 0; i < 256; ++i)
        QCOMPARE(r.response().values[i], i % 3 == 0 ? 1u : 0u);

    std::vector<std::uint32_t> words;
    for (std::uint32_t i = 0; i < 64; ++i)
        words.push_back(0xA000 + i);
    CHECK_OK(run(*session, results, Request::writeRegisters(1, addr("R200"), words)));
    r = run(*session, results, Request::readRegisters(1, addr("R200"), 64));
    CHECK_OK(r);
    QCOMPARE(r.response().values, words);

    std::vector<std::uint32_t> doubles;
    for (std::uint32_t i = 0; i < 32; ++i)
        doubles.push_back(0x80000000u + i * 77777u);
    CHECK_OK(run(*session, results, Request::writeRegisters(1, addr("DR400"), doubles)));
    r = run(*session, results, Request::readRegisters(1, addr("DR400"), 32));
    CHECK_OK(r);
    QCOMPARE(r.response().values, doubles);

    std::vector<Address> mixed;
    for (std::uint32_t i = 0; i < 64; ++i)
        mixed.push_back({ElementType::R, 200 + i});
    r = run(*session, results, Request::mixedRead(1, mixed));
    CHECK_OK(r);
    QCOMPARE(r.response().values, words);

    Bytes data;
    for (int i = 0; i < 256; ++i)
        data.push_back(static_cast<std::uint8_t>('A' + i % 26));
    r = run(*session, results, Request::loopback(1, data));
    CHECK_OK(r);
    QCOMPARE(r.response().data, data);
}

void TestSession::refusedWhenNotOpen()
{
    Session session(LinkSettings::tcp(QStringLiteral("127.0.0.1"), 1));
    Results results(&session);
    const quint64 id = session.submit(Request::briefStatus(1));
    QVERIFY(id != 0);
    QVERIFY(results.waitFor(id));
    QCOMPARE(results.map.value(id).errorKind(), ErrorKind::LinkError);
    QVERIFY(results.map.value(id).errorText().contains(QStringLiteral("not open")));

    // Unusable settings: open() stays closed and says why.
    Session serial(LinkSettings::serial(QString()));
    QSignalSpy states(&serial, &Session::linkStateChanged);
    serial.open();
    QVERIFY(states.wait(5000));
    QCOMPARE(states.last().at(0).value<LinkState>(), LinkState::Closed);
    QCOMPARE(englishText(states.last().at(1).value<Message>()),
             QStringLiteral("Choose a serial port."));
}

void TestSession::invalidRequestNeverSent()
{
    LinkSettings settings;
    QVERIFY(makeLink(QStringLiteral("tcp"), LinkSettings::ProtocolChoice::Facon, settings));
    auto session = openSession(settings);
    Results results(session.get());
    SessionResult r = run(*session, results, Request::readRegisters(1, addr("R0"), 65));
    QVERIFY(!r.ok());
    QCOMPARE(r.errorKind(), ErrorKind::LimitExceeded);
    r = run(*session, results, Request::readRegisters(255, addr("R0"), 1));
    QVERIFY(!r.ok());
    QCOMPARE(session->statistics().total.bytesOut, quint64(0));
    QCOMPARE(m_server->counters().frames, quint64(0));
}

void TestSession::timeoutAndRetries()
{
    LinkSettings settings;
    QVERIFY(makeLink(QStringLiteral("tcp"), LinkSettings::ProtocolChoice::Facon, settings));
    settings.timeoutMs = 100;
    settings.retries = 2;
    FaultConfig faults;
    faults.dropRate = 1.0;
    m_server->setFaults(faults);
    auto session = openSession(settings);
    Results results(session.get());

    SessionResult r = run(*session, results, Request::briefStatus(1));
    QVERIFY(!r.ok());
    QCOMPARE(r.errorKind(), ErrorKind::Timeout);
    QCOMPARE(r.attempts(), 3);
    QVERIFY2(r.errorText().contains(QStringLiteral("station 1")), qPrintable(r.errorText()));
    SessionStatistics stats = session->statistics();
    QCOMPARE(stats.total.timeouts, quint64(3));
    QCOMPARE(stats.total.retries, quint64(2));
    QCOMPARE(stats.total.requests, quint64(1));
    QCOMPARE(stats.total.answers, quint64(0));
    QCOMPARE(stats.stations.value(1).timeouts, quint64(3));
    QCOMPARE(m_server->counters().frames, quint64(3));

    // A per-request override: no retries.
    RequestOptions once;
    once.retries = 0;
    const quint64 id = session->submit(Request::briefStatus(1), Priority::User, once);
    QVERIFY(results.waitFor(id));
    QCOMPARE(results.map.value(id).attempts(), 1);

    // The PLC comes back: the session works without reconnecting.
    m_server->setFaults(FaultConfig());
    CHECK_OK(run(*session, results, Request::briefStatus(1)));
}

void TestSession::damagedAnswersAreRetried()
{
    LinkSettings settings;
    QVERIFY(makeLink(QStringLiteral("tcp"), LinkSettings::ProtocolChoice::Binary, settings));
    settings.timeoutMs = 150;
    settings.retries = 10;
    FaultConfig faults;
    faults.corruptRate = 0.03;
    faults.seed = 7;
    m_server->setFaults(faults);
    m_plc->setValue(addr("R7"), 4242);
    auto session = openSession(settings);
    Results results(session.get());
    for (int i = 0; i < 30; ++i) {
        const SessionResult r = run(*session, results, Request::readRegisters(1, addr("R7"), 1));
        CHECK_OK(r);
        QCOMPARE(r.response().values.front(), 4242u);
    }
    const SessionStatistics stats = session->statistics();
    QVERIFY(stats.total.retries > 0);
    QVERIFY(stats.total.checksumErrors + stats.total.timeouts > 0);
    // Every damaged answer shows up in the traffic log with its reason.
    int flagged = 0;
    for (const TrafficEntry &entry : session->trafficLog()->entries())
        flagged += entry.error.empty() ? 0 : 1;
    QVERIFY(flagged > 0);
}

void TestSession::otherStationIgnored()
{
    LinkSettings settings;
    QVERIFY(makeLink(QStringLiteral("tcp"), LinkSettings::ProtocolChoice::Facon, settings));
    settings.timeoutMs = 150;
    settings.retries = 0;
    FaultConfig faults;
    faults.wrongStationRate = 1.0;
    m_server->setFaults(faults);
    auto session = openSession(settings);
    Results results(session.get());
    SessionResult r = run(*session, results, Request::briefStatus(1));
    QVERIFY(!r.ok());
    QCOMPARE(r.errorKind(), ErrorKind::Timeout);
    bool logged = false;
    for (const TrafficEntry &entry : session->trafficLog()->entries()) {
        if (entry.direction == TrafficEntry::Direction::In
            && englishText(entry.error).contains(QStringLiteral("station")))
            logged = true;
    }
    QVERIFY(logged);
}

void TestSession::broadcastGetsNoAnswer()
{
    LinkSettings settings;
    QVERIFY(makeLink(QStringLiteral("udp"), LinkSettings::ProtocolChoice::Facon, settings));
    auto session = openSession(settings);
    Results results(session.get());
    CHECK_OK(run(*session, results, Request::writeRegisters(0, addr("R50"), {321})));
    QTRY_COMPARE_WITH_TIMEOUT(m_plc->value(addr("R50")), std::optional<std::uint32_t>(321), 5000);
    QCOMPARE(session->statistics().total.timeouts, quint64(0));
}

void TestSession::userActionsGoFirst()
{
    LinkSettings settings;
    QVERIFY(makeLink(QStringLiteral("tcp"), LinkSettings::ProtocolChoice::Facon, settings));
    FaultConfig faults;
    faults.latencyMs = 10;
    m_server->setFaults(faults);
    auto session = openSession(settings);
    Results results(session.get());
    QList<quint64> polls;
    for (int i = 0; i < 15; ++i)
        polls.append(session->submit(Request::readRegisters(1, addr("R0"), 4), Priority::Poll));
    // The order among the two below is the priorities' only if both wait when the worker picks its
    // next job. So they are submitted while the worker waits for an answer that cannot come yet:
    // the simulator has just taken a query, and its answer's latency timer needs this thread's
    // event loop, which is not running while they are submitted. (Submitted at any other time,
    // the worker could take the background job before the user's arrived.)
    m_server->setVerbose(true);
    QEventLoop queryTaken;
    bool taken = false;
    connect(m_server.get(), &SimServer::logLine, &queryTaken, [&] {
        taken = true;
        queryTaken.quit();
    });
    QTimer::singleShot(10000, &queryTaken, &QEventLoop::quit);
    queryTaken.exec();
    QVERIFY(taken);
    const quint64 background = session->submit(Request::briefStatus(1), Priority::Background);
    const quint64 user
        = session->submit(Request::writeRegisters(1, addr("R60"), {5}), Priority::User);
    QVERIFY(results.waitFor(polls.last()));
    QVERIFY(results.map.value(user).ok());
    const auto position = [&results](quint64 id) {
        return results.order.indexOf(id);
    };
    // At most the poll already on the wire goes before the user's write.
    QVERIFY2(position(user) <= 1, qPrintable(QString::number(position(user))));
    QVERIFY(position(user) < position(background));
    QVERIFY(position(background) < position(polls.last()));
}

void TestSession::readOnlyMode()
{
    LinkSettings settings;
    QVERIFY(makeLink(QStringLiteral("tcp"), LinkSettings::ProtocolChoice::Facon, settings));
    m_plc->setRunning(false);
    auto session = openSession(settings);
    Results results(session.get());
    session->setReadOnly(true);
    QVERIFY(session->isReadOnly());

    const QList<Request> writes = {
        Request::runStop(1, true),
        Request::discreteControl(1, DiscreteOp::Set, addr("Y0")),
        Request::writeDiscretes(1, addr("Y0"), {1}),
        Request::writeRegisters(1, addr("R0"), {9}),
        Request::mixedWrite(1, {addr("R1")}, {9}),
        Request::writeProgram(1, 0, std::vector<std::uint32_t>(64, 0)),
    };
    for (const Request &write : writes) {
        const SessionResult r = run(*session, results, write);
        QVERIFY(!r.ok());
        QCOMPARE(r.errorKind(), ErrorKind::ReadOnly);
        QVERIFY2(r.errorText().contains(QStringLiteral("Read-only")), qPrintable(r.errorText()));
    }
    const quint64 raw = session->sendRaw("0141 1", true);
    QVERIFY(results.waitFor(raw));
    QCOMPARE(results.map.value(raw).errorKind(), ErrorKind::ReadOnly);

    // Nothing reached the wire ...
    QCOMPARE(session->statistics().total.bytesOut, quint64(0));
    QCOMPARE(m_server->counters().frames, quint64(0));
    for (const TrafficEntry &entry : session->trafficLog()->entries())
        QVERIFY(entry.direction != TrafficEntry::Direction::Out);
    QVERIFY(!m_plc->isRunning());
    // ... but reads still work, and leaving the mode allows writes again.
    CHECK_OK(run(*session, results, Request::readRegisters(1, addr("R0"), 1)));
    session->setReadOnly(false);
    CHECK_OK(run(*session, results, Request::writeRegisters(1, addr("R0"), {9})));
    QCOMPARE(m_plc->value(addr("R0")), std::optional<std::uint32_t>(9));
}

void TestSession::rawFrames_data()
{
    QTest::addColumn<int>("protocol");
    QTest::newRow("facon") << int(Protocol::Facon);
    QTest::newRow("binary") << int(Protocol::Binary);
}

void TestSession::rawFrames()
{
    QFETCH(int, protocol);
    const bool facon = protocol == int(Protocol::Facon);
    LinkSettings settings;
    QVERIFY(
        makeLink(QStringLiteral("tcp"),
                 facon ? LinkSettings::ProtocolChoice::Facon : LinkSettings::ProtocolChoice::Binary,
                 settings));
    settings.timeoutMs = 300;
    auto session = openSession(settings);
    Results results(session.get());

    // Body only, framing and checksum added by the session.
    const QByteArray body = facon ? QByteArray("0140") : QByteArray("\x01\x40", 2);
    quint64 id = session->sendRaw(body, true);
    QVERIFY(results.waitFor(id));
    SessionResult r = results.map.value(id);
    CHECK_OK(r);
    QVERIFY(r.isRaw());
    if (facon)
        QVERIFY2(r.rawAnswer().startsWith("\x02"
                                          "0140"),
                 r.rawAnswer().toHex(' ').constData());
    else
        QVERIFY2(r.rawAnswer().startsWith(QByteArray("\x52\x10", 2)),
                 r.rawAnswer().toHex(' ').constData());

    // A complete frame as typed.
    const QByteArray frame = facon ? QByteArray("\x02"
                                                "0140C7\x03")
                                   : QByteArray::fromHex("51 10 00 02 01 40 A1 84 55 AA");
    id = session->sendRaw(frame, false);
    QVERIFY(results.waitFor(id));
    r = results.map.value(id);
    CHECK_OK(r);
    QVERIFY(!r.rawAnswer().isEmpty());

    // Something the PLC ignores (bad checksum): the timeout says nothing came back.
    const QByteArray broken = facon ? QByteArray("\x02"
                                                 "0140FF\x03")
                                    : QByteArray::fromHex("51 10 00 02 01 40 00 00 55 AA");
    id = session->sendRaw(broken, false);
    QVERIFY(results.waitFor(id));
    r = results.map.value(id);
    QVERIFY(!r.ok());
    QCOMPARE(r.errorKind(), ErrorKind::Timeout);
}

void TestSession::autoDetect()
{
    LinkSettings settings;
    QVERIFY(makeLink(QStringLiteral("tcp"), LinkSettings::ProtocolChoice::Auto, settings));
    auto session = openSession(settings);
    QVERIFY(!session->isProtocolKnown());
    QSignalSpy detected(session.get(), &Session::protocolDetected);
    Results results(session.get());
    m_plc->setValue(addr("R3"), 77);
    SessionResult r = run(*session, results, Request::readRegisters(1, addr("R3"), 1));
    CHECK_OK(r);
    QCOMPARE(r.response().values.front(), 77u);
    QVERIFY(session->isProtocolKnown());
    QCOMPARE(session->protocol(),
             Protocol::Facon); // the simulator speaks both; FACON is probed first
    QTRY_COMPARE_WITH_TIMEOUT(detected.count(), 1, 5000);
    // Remembered: the next request probes nothing.
    const quint64 before = m_server->counters().frames;
    CHECK_OK(run(*session, results, Request::readRegisters(1, addr("R3"), 1)));
    QCOMPARE(m_server->counters().frames, before + 1);
}

void TestSession::autoDetectNobody()
{
    LinkSettings settings;
    QVERIFY(makeLink(QStringLiteral("udp"), LinkSettings::ProtocolChoice::Auto, settings));
    settings.timeoutMs = 100;
    m_server->setStation(9); // nobody answers station 1
    auto session = openSession(settings);
    Results results(session.get());
    const SessionResult r = run(*session, results, Request::briefStatus(1));
    QVERIFY(!r.ok());
    QCOMPARE(r.errorKind(), ErrorKind::Timeout);
    QVERIFY2(r.errorText().contains(QStringLiteral("neither in FACON nor in binary")),
             qPrintable(r.errorText()));
    QVERIFY(!session->isProtocolKnown());
}

void TestSession::reconnectAfterSimulatorRestart()
{
    LinkSettings settings;
    QVERIFY(makeLink(QStringLiteral("tcp"), LinkSettings::ProtocolChoice::Binary, settings));
    settings.reconnectMinMs = 50;
    settings.reconnectMaxMs = 200;
    const quint16 port = m_server->tcpPort();
    auto session = openSession(settings);
    QList<LinkState> states;
    QStringList reasons;
    connect(session.get(), &Session::linkStateChanged, this,
            [&](LinkState state, const Message &reason) {
                states.append(state);
                reasons.append(englishText(reason));
            });
    Results results(session.get());
    CHECK_OK(run(*session, results, Request::briefStatus(1)));

    m_server->close(); // the simulator goes away
    QTRY_VERIFY_WITH_TIMEOUT(states.contains(LinkState::Reconnecting), 5000);
    QVERIFY(states.contains(LinkState::Lost));
    QVERIFY(!reasons.at(states.indexOf(LinkState::Lost)).isEmpty());
    // While down, requests fail at once with a link error.
    QTRY_VERIFY_WITH_TIMEOUT(session->linkState() == LinkState::Reconnecting, 5000);
    SessionResult r = run(*session, results, Request::briefStatus(1));
    QVERIFY(!r.ok());
    QCOMPARE(r.errorKind(), ErrorKind::LinkError);

    QString error;
    QVERIFY2(m_server->listenTcp(port, &error), qPrintable(error)); // ... and comes back
    QTRY_VERIFY_WITH_TIMEOUT(session->linkState() == LinkState::Connected, 10000);
    CHECK_OK(run(*session, results, Request::briefStatus(1)));
}

// Issue 33: links that lost their PLCs together do not all try again in the same instant: each
// waits its backoff and up to a quarter more, at random.
void TestSession::reconnectsAreSpread()
{
    QTcpServer probe; // a port nobody listens on: every attempt is refused at once
    QVERIFY(probe.listen(QHostAddress::LocalHost));
    const quint16 port = probe.serverPort();
    probe.close();
    LinkSettings settings = LinkSettings::tcp(QStringLiteral("127.0.0.1"), port);
    settings.reconnectMinMs = 2000;
    settings.reconnectMaxMs = 2000;
    QStringList delays; // "2.0" .. "2.5"
    std::vector<std::unique_ptr<Session>> sessions;
    for (int i = 0; i < 8; ++i) {
        sessions.push_back(std::make_unique<Session>(settings));
        connect(sessions.back().get(), &Session::linkStateChanged, this,
                [&delays](LinkState state, const Message &reason) {
                    if (state == LinkState::Reconnecting && reason.id == MsgId::LinkNextAttempt)
                        delays << QString::fromStdString(reason.args.at(1).text);
                });
        sessions.back()->open();
    }
    QTRY_COMPARE_WITH_TIMEOUT(delays.size(), 8, 10000);
    qInfo("first reconnect delays of 8 links: %s", qPrintable(delays.join(QLatin1Char(' '))));
    for (const QString &delay : std::as_const(delays)) {
        const double seconds = delay.toDouble();
        QVERIFY2(seconds >= 2.0 && seconds <= 2.5, qPrintable(delay)); // never sooner
    }
    QVERIFY2(QSet<QString>(delays.cbegin(), delays.cend()).size() > 1,
             qPrintable(delays.join(QLatin1Char(' '))));
}

void TestSession::closeCancelsPending()
{
    LinkSettings settings;
    QVERIFY(makeLink(QStringLiteral("tcp"), LinkSettings::ProtocolChoice::Facon, settings));
    FaultConfig faults;
    faults.latencyMs = 50;
    m_server->setFaults(faults);
    auto session = openSession(settings);
    Results results(session.get());
    QList<quint64> ids;
    for (int i = 0; i < 5; ++i)
        ids.append(session->submit(Request::briefStatus(1)));
    session->close();
    for (quint64 id : ids) {
        QVERIFY(results.waitFor(id));
        QCOMPARE(results.map.value(id).errorKind(), ErrorKind::Cancelled);
    }
    QTRY_COMPARE_WITH_TIMEOUT(session->linkState(), LinkState::Closed, 5000);
    QCOMPARE(results.map.size(), 5); // exactly one result each
}

void TestSession::statistics()
{
    LinkSettings settings;
    QVERIFY(makeLink(QStringLiteral("udp"), LinkSettings::ProtocolChoice::Binary, settings));
    auto session = openSession(settings);
    QSignalSpy changed(session.get(), &Session::statisticsChanged);
    Results results(session.get());
    for (int i = 0; i < 10; ++i)
        CHECK_OK(run(*session, results, Request::readRegisters(1, addr("R0"), 2)));
    const SessionStatistics stats = session->statistics();
    QCOMPARE(stats.total.requests, quint64(10));
    QCOMPARE(stats.total.answers, quint64(10));
    QCOMPARE(stats.total.timeouts, quint64(0));
    QCOMPARE(stats.total.retries, quint64(0));
    const BinaryCodec codec;
    const Request read = Request::readRegisters(1, addr("R0"), 2);
    Response response;
    response.station = 1;
    response.command = read.command;
    response.values = {0, 0};
    const std::size_t query = codec.encodeRequest(read).value().size();
    const std::size_t answer = codec.encodeResponse(read, response).size();
    QCOMPARE(stats.total.bytesOut, quint64(10 * query));
    QCOMPARE(stats.total.bytesIn, quint64(10 * answer));
    QCOMPARE(stats.stations.value(1).requests, quint64(10));
    QVERIFY(stats.total.rttMeanMs > 0);
    QVERIFY(stats.total.rttP50Ms <= stats.total.rttP99Ms);
    QVERIFY(changed.count() > 0 || changed.wait(2000));
    session->resetStatistics();
    QTRY_COMPARE_WITH_TIMEOUT(session->statistics().total.requests, quint64(0), 5000);
}

void TestSession::trafficLogBounded()
{
    TrafficLog log(10);
    QSignalSpy added(&log, &TrafficLog::entriesAdded);
    for (int i = 0; i < 25; ++i)
        log.append(TrafficEntry::Direction::Out, QByteArray::number(i),
                   Message::text(QStringLiteral("frame %1").arg(i).toStdString()));
    QCOMPARE(log.size(), 10);
    QCOMPARE(added.count(), 25);
    QCOMPARE(log.lastSequence(), quint64(25));
    const QList<TrafficEntry> all = log.entries();
    QCOMPARE(all.size(), 10);
    QCOMPARE(all.first().sequence, quint64(16));
    QCOMPARE(all.last().bytes, QByteArray("24"));
    const QList<TrafficEntry> since = log.entries(22);
    QCOMPARE(since.size(), 3);
    QCOMPARE(englishText(since.first().summary), QStringLiteral("frame 22"));
    QVERIFY(log.entries(25).isEmpty());
    log.clear();
    QCOMPARE(log.size(), 0);

    // A session logs both directions with decoded summaries.
    LinkSettings settings;
    QVERIFY(makeLink(QStringLiteral("tcp"), LinkSettings::ProtocolChoice::Facon, settings));
    auto session = openSession(settings);
    Results results(session.get());
    CHECK_OK(run(*session, results, Request::readRegisters(1, addr("R12"), 3)));
    const QList<TrafficEntry> entries = session->trafficLog()->entries();
    QCOMPARE(entries.size(), 2);
    QCOMPARE(entries.at(0).direction, TrafficEntry::Direction::Out);
    QCOMPARE(entries.at(1).direction, TrafficEntry::Direction::In);
    QVERIFY(entries.at(0).bytes.startsWith("\x02"
                                           "0146"));
    QVERIFY(!entries.at(0).summary.empty());
    QVERIFY(entries.at(1).error.empty());
}

namespace {

// Counts the events delivered to an object (a post from another thread is one).
class EventCounter : public QObject
{
public:
    int count = 0;
    bool eventFilter(QObject *, QEvent *) override
    {
        ++count;
        return false;
    }
};

} // namespace

// Issue 35: a log appended to from the worker's thread posts to its own thread only when something
// listens (the console on screen); a listener that comes later still gets the next entries.
void TestSession::trafficLogWakesOnlyListeners()
{
    TrafficLog log(100);
    EventCounter events;
    log.installEventFilter(&events);
    const auto appendFromAnotherThread = [&log](int n) {
        std::thread worker([&log, n] {
            for (int i = 0; i < n; ++i)
                log.append(TrafficEntry::Direction::Out, QByteArray::number(i), {});
        });
        worker.join();
    };
    appendFromAnotherThread(50);
    QTest::qWait(50);
    QCOMPARE(events.count, 0);
    QCOMPARE(log.size(), 50);

    QSignalSpy added(&log, &TrafficLog::entriesAdded);
    appendFromAnotherThread(1);
    QTRY_COMPARE(added.count(), 1);
    QCOMPARE(added.first().at(0).toULongLong(), quint64(51));
    QVERIFY(events.count >= 1);
}

void TestSession::polling()
{
    LinkSettings settings;
    QVERIFY(makeLink(QStringLiteral("tcp"), LinkSettings::ProtocolChoice::Facon, settings));
    m_plc->setValue(addr("R0"), 11);
    m_plc->setValue(addr("R1"), 22);
    m_plc->setValue(addr("DR10"), 123456);
    m_plc->setValue(addr("Y3"), 1);
    auto session = openSession(settings);
    QList<QList<WatchValue>> batches;
    connect(session.get(), &Session::values, this,
            [&batches](const QList<WatchValue> &v) { batches.append(v); });
    session->setWatchList({{1, 1, addr("R0"), 50},
                           {2, 1, addr("R1"), 50},
                           {3, 1, addr("DR10"), 50},
                           {4, 1, addr("Y3"), 50},
                           {5, 1, addr("R0"), 50}});
    QTRY_VERIFY_WITH_TIMEOUT(!batches.isEmpty(), 5000);
    QList<WatchValue> first = batches.first();
    QCOMPARE(first.size(), 5); // one batch per cycle, every item
    QHash<quint64, quint32> seen;
    for (const WatchValue &v : first) {
        QCOMPARE(v.quality, ValueQuality::Good);
        QVERIFY(v.timestamp.isValid());
        seen.insert(v.itemId, v.value);
    }
    QCOMPARE(seen.value(1), 11u);
    QCOMPARE(seen.value(2), 22u);
    QCOMPARE(seen.value(3), 123456u);
    QCOMPARE(seen.value(4), 1u);
    QCOMPARE(seen.value(5), 11u);

    m_plc->setValue(addr("R1"), 99);
    QTRY_VERIFY_WITH_TIMEOUT(
        std::any_of(batches.last().cbegin(), batches.last().cend(),
                    [](const WatchValue &v) { return v.itemId == 2 && v.value == 99; }),
        5000);

    // Re-plan on a new list; an empty list stops polling.
    session->setWatchList({{7, 1, addr("R1"), 30}});
    QTRY_VERIFY_WITH_TIMEOUT(batches.last().size() == 1 && batches.last().first().itemId == 7,
                             5000);
    session->setWatchList({});
    QTest::qWait(100);
    const qsizetype count = batches.size();
    QTest::qWait(200);
    QCOMPARE(batches.size(), count);
    QVERIFY(session->statistics().pollCycles > 0);
}

void TestSession::pollingIsolatesBadAddress()
{
    LinkSettings settings;
    QVERIFY(makeLink(QStringLiteral("udp"), LinkSettings::ProtocolChoice::Binary, settings));
    m_plc->setValue(addr("R0"), 5);
    m_plc->setValue(addr("R3000"), 6);
    m_plc->setValue(addr("M5"), 1);
    m_plc->setValue(addr("DR100"), 70000);
    auto session = openSession(settings);
    QList<QList<WatchValue>> batches;
    connect(session.get(), &Session::values, this,
            [&batches](const QList<WatchValue> &v) { batches.append(v); });
    // D3500 does not exist on this model (D0..D2999): the PLC answers error A for any batch holding
    // it.
    session->setWatchList({{1, 1, addr("R0"), 50},
                           {2, 1, addr("D3500"), 50},
                           {3, 1, addr("R3000"), 50},
                           {4, 1, addr("M5"), 50},
                           {5, 1, addr("DR100"), 50}});
    QTRY_VERIFY_WITH_TIMEOUT(batches.size() >= 3, 10000);
    for (const QList<WatchValue> &batch : std::as_const(batches)) {
        QCOMPARE(batch.size(), 5);
        for (const WatchValue &v : batch) {
            if (v.itemId == 2) {
                QCOMPARE(v.quality, ValueQuality::Error);
                QVERIFY2(englishText(v.error).contains(QStringLiteral("illegal address")),
                         qPrintable(englishText(v.error)));
            } else {
                QCOMPARE(v.quality, ValueQuality::Good);
            }
        }
    }
    const QList<WatchValue> last = batches.last();
    for (const WatchValue &v : last) {
        if (v.itemId == 1)
            QCOMPARE(v.value, 5u);
        if (v.itemId == 3)
            QCOMPARE(v.value, 6u);
        if (v.itemId == 4)
            QCOMPARE(v.value, 1u);
        if (v.itemId == 5)
            QCOMPARE(v.value, 70000u);
    }
}

void TestSession::pollingSeveralStations()
{
    LinkSettings settings;
    QVERIFY(makeLink(QStringLiteral("tcp"), LinkSettings::ProtocolChoice::Facon, settings));
    settings.timeoutMs = 80;
    settings.retries = 0;
    m_plc->setValue(addr("R0"), 17);
    auto session = openSession(settings);
    QList<QList<WatchValue>> batches;
    connect(session.get(), &Session::values, this,
            [&batches](const QList<WatchValue> &v) { batches.append(v); });
    // Station 2 is absent: its items go stale; station 1 keeps being served.
    session->setWatchList({{1, 1, addr("R0"), 50},
                           {2, 2, addr("R0"), 50},
                           {3, 1, addr("R1"), 50},
                           {4, 2, addr("R1"), 50}});
    // Until station 2 is demoted its timeouts hold up the line, and station 1's values may be
    // reported late (a slow machine, Wine): wait for the steady state of every item (each
    // station's group reports in its own batches), then check it.
    auto latest = [&batches] {
        QHash<std::uint64_t, WatchValue> last;
        for (const QList<WatchValue> &batch : std::as_const(batches)) {
            for (const WatchValue &v : batch)
                last.insert(v.itemId, v);
        }
        return last;
    };
    auto servedAsExpected = [&latest] {
        const QHash<std::uint64_t, WatchValue> last = latest();
        if (last.size() != 4)
            return false;
        for (const WatchValue &v : last) {
            const bool stationOne = v.itemId == 1 || v.itemId == 3;
            if (v.quality != (stationOne ? ValueQuality::Good : ValueQuality::Stale))
                return false;
        }
        return true;
    };
    QTRY_VERIFY_WITH_TIMEOUT(servedAsExpected(), 10000);
    // Station 2 rests after its probes went unanswered: its items say so, and name it.
    for (const WatchValue &v : latest()) {
        if (v.itemId == 2 || v.itemId == 4) {
            QCOMPARE(v.error.id, MsgId::SessionStationDemoted);
            QVERIFY2(englishText(v.error).startsWith(QStringLiteral("Station 2 ")),
                     qPrintable(englishText(v.error)));
        }
    }
    const SessionStatistics stats = session->statistics();
    QVERIFY(stats.stations.value(1).answers > 0);
    QCOMPARE(stats.stations.value(2).answers, quint64(0));
    QVERIFY(stats.stations.value(2).timeouts > 0);
}

void TestSession::pollingTrickyWatchList_data()
{
    QTest::addColumn<int>("protocol");
    QTest::newRow("facon") << int(Protocol::Facon);
    QTest::newRow("binary") << int(Protocol::Binary);
}

void TestSession::pollingTrickyWatchList()
{
    // Gaps, spans beyond one request's limits, 16/32-bit and bit elements mixed, W views,
    // duplicates and an element type the protocol may lack: every value must land on its item.
    QFETCH(int, protocol);
    LinkSettings settings;
    QVERIFY(makeLink(QStringLiteral("tcp"),
                     protocol == int(Protocol::Facon) ? LinkSettings::ProtocolChoice::Facon
                                                      : LinkSettings::ProtocolChoice::Binary,
                     settings));
    QList<WatchEntry> watch;
    QHash<quint64, quint32> expected;
    quint64 id = 100;
    const auto add = [&](const Address &address, quint32 value, bool write = true) {
        if (write)
            QVERIFY(m_plc->setValue(address, value));
        watch.append({id, 1, address, 40});
        expected.insert(id, value);
        ++id;
    };
    for (std::uint32_t n = 0; n < 200; n += 3) // 67 registers over 200 words: more than one 46
        add({ElementType::R, n}, 1000 + n);
    for (std::uint32_t n = 0; n < 16; n += 2) // 32-bit, aligned pairs
        add({ElementType::DR, 300 + n}, 0x10000u * n + 7);
    for (std::uint32_t n = 0; n < 600; n += 37) // bits over more than 256 points
        add({ElementType::M, n}, n % 2);
    add({ElementType::D, 10}, 55);
    add({ElementType::D, 2000}, 66); // far away: mixed read or its own request
    add({ElementType::Y, 3}, 1);
    add({ElementType::WY, 0}, 0x0008, false); // Y3 seen through WY0
    add({ElementType::R, 0}, 1000, false);    // duplicate of the first item
    auto session = openSession(settings);
    QList<QList<WatchValue>> batches;
    connect(session.get(), &Session::values, this,
            [&batches](const QList<WatchValue> &v) { batches.append(v); });
    session->setWatchList(watch);
    QTRY_VERIFY_WITH_TIMEOUT(!batches.isEmpty(), 10000);
    const QList<WatchValue> batch = batches.first();
    QCOMPARE(batch.size(), watch.size());
    for (const WatchValue &v : batch) {
        QVERIFY2(v.quality == ValueQuality::Good, qPrintable(englishText(v.error)));
        QCOMPARE(v.value, expected.value(v.itemId));
    }
}

void TestSession::lateAnswerDiscarded()
{
    LinkSettings settings;
    QVERIFY(makeLink(QStringLiteral("tcp"), LinkSettings::ProtocolChoice::Facon, settings));
    settings.timeoutMs = 100;
    settings.retries = 0;
    FaultConfig slow;
    slow.latencyMs = 300;
    m_server->setFaults(slow);
    m_plc->setValue(addr("R0"), 1);
    auto session = openSession(settings);
    Results results(session.get());
    SessionResult r = run(*session, results, Request::readRegisters(1, addr("R0"), 1));
    QCOMPARE(r.errorKind(), ErrorKind::Timeout);

    // The PLC's late answer (R0 = 1) arrives after the timeout; it must never pass for the
    // answer to the next, identical query.
    m_server->setFaults(FaultConfig());
    m_plc->setValue(addr("R0"), 2);
    QTRY_VERIFY_WITH_TIMEOUT(session->statistics().bytesDiscarded > 0, 5000);
    r = run(*session, results, Request::readRegisters(1, addr("R0"), 1));
    CHECK_OK(r);
    QCOMPARE(r.response().values.front(), 2u);
    bool logged = false;
    for (const TrafficEntry &entry : session->trafficLog()->entries())
        logged = logged || englishText(entry.error).contains(QStringLiteral("no query pending"));
    QVERIFY(logged);
}

void TestSession::stationScan()
{
    LinkSettings settings;
    QVERIFY(makeLink(QStringLiteral("udp"), LinkSettings::ProtocolChoice::Facon, settings));
    m_server->setStation(3);
    m_plc->setRunning(true);
    auto session = openSession(settings);
    StationScanner scanner(session.get());
    QSignalSpy done(&scanner, &StationScanner::finished);
    QSignalSpy progress(&scanner, &StationScanner::progress);
    scanner.start(1, 6, 50);
    QVERIFY(scanner.isRunning());
    QVERIFY(done.wait(10000));
    const QList<StationScanner::Hit> hits = scanner.hits();
    QCOMPARE(hits.size(), 1);
    QCOMPARE(hits.first().station, quint8(3));
    QVERIFY(hits.first().status.running);
    QCOMPARE(progress.last().at(0).toInt(), 6);
    QVERIFY(!scanner.isRunning());

    // A cancelled scan ends at once and leaves nothing queued behind.
    Results results(session.get());
    scanner.start(1, 254, 50);
    scanner.cancel();
    QCOMPARE(done.count(), 2);
    QVERIFY(!scanner.isRunning());
    CHECK_OK(run(*session, results, Request::briefStatus(3)));
    QTest::qWait(100);
    QVERIFY2(session->statistics().total.requests < 20,
             qPrintable(QString::number(session->statistics().total.requests)));
}

void TestSession::destroyWhileBusy()
{
    LinkSettings settings;
    QVERIFY(makeLink(QStringLiteral("tcp"), LinkSettings::ProtocolChoice::Facon, settings));
    FaultConfig faults;
    faults.latencyMs = 20;
    m_server->setFaults(faults);
    auto session = openSession(settings);
    Results results(session.get());
    session->setWatchList({{1, 1, addr("R0"), 10}});
    quint64 first = 0;
    for (int i = 0; i < 50; ++i) {
        const quint64 id = session->submit(Request::readRegisters(1, addr("R0"), 1));
        if (i == 0)
            first = id;
    }
    QVERIFY(results.waitFor(first));
    session.reset(); // must return promptly, with requests queued and one on the wire
    QVERIFY(!session);
}

QTEST_GUILESS_MAIN(TestSession)
namespace {

std::unique_ptr<QSerialPort> openRaw(const QString &name)
{
    auto port = std::make_unique<QSerialPort>(name);
    if (!port->open(QIODevice::ReadWrite))
        return nullptr;
    port->setDataBits(QSerialPort::Data8);
    port->setParity(QSerialPort::NoParity);
    return port;
}

} // namespace

void TestSession::serialMultiDrop_data()
{
    QTest::addColumn<int>("protocol");
    QTest::addColumn<bool>("echo");
    QTest::newRow("facon") << int(Protocol::Facon) << false;
    QTest::newRow("binary") << int(Protocol::Binary) << false;
    QTest::newRow("facon, 2-wire echo") << int(Protocol::Facon) << true;
    QTest::newRow("binary, 2-wire echo") << int(Protocol::Binary) << true;
}

// An RS-485 multi-drop line with two PLCs: three socat pty pairs joined by a bus in this test
// that passes every byte from the master to both PLCs and every answer back (with `echo`, the
// master also hears its own query, as on a 2-wire bus). Each PLC sees the other's traffic and
// must ignore it; the session must read and write both stations through one port and never
// take one PLC's values for the other's.
void TestSession::serialMultiDrop()
{
    QFETCH(int, protocol);
    QFETCH(bool, echo);
    m_dir = std::make_unique<QTemporaryDir>();
    auto path = [this](const char *name) {
        return m_dir->filePath(QString::fromLatin1(name));
    };
    auto master = startPtyPair(path("app"), path("bus"));
    auto line1 = startPtyPair(path("drop1"), path("plc1"));
    auto line2 = startPtyPair(path("drop2"), path("plc2"));
    if (!master || !line1 || !line2)
        QSKIP("socat is not available for serial pty pairs");

    SimulatedPlc plc2(ModelProfile::fbs());
    SimServer server2(&plc2);
    m_server->setStation(1);
    server2.setStation(2);
    SerialSettings serial;
    serial.portName = path("plc1");
    QString error;
    QVERIFY2(m_server->openSerial(serial, &error), qPrintable(error));
    serial.portName = path("plc2");
    QVERIFY2(server2.openSerial(serial, &error), qPrintable(error));

    auto bus = openRaw(path("bus"));
    auto drop1 = openRaw(path("drop1"));
    auto drop2 = openRaw(path("drop2"));
    QVERIFY(bus && drop1 && drop2);
    connect(bus.get(), &QSerialPort::readyRead, this, [&] {
        const QByteArray data = bus->readAll();
        drop1->write(data);
        drop2->write(data);
        if (echo)
            bus->write(data);
    });
    for (QSerialPort *drop : {drop1.get(), drop2.get()}) {
        connect(drop, &QSerialPort::readyRead, this, [&, drop] {
            const QByteArray data = drop->readAll();
            bus->write(data);
            // The other PLC hears the answer too.
            (drop == drop1.get() ? drop2 : drop1)->write(data);
        });
    }

    m_plc->setValue(addr("R0"), 1111);
    plc2.setValue(addr("R0"), 2222);
    m_plc->setValue(addr("Y3"), 1);
    plc2.setValue(addr("Y3"), 0);
    LinkSettings settings = LinkSettings::serial(path("app"), 9600,
                                                 static_cast<Protocol>(protocol) == Protocol::Facon
                                                     ? LinkSettings::ProtocolChoice::Facon
                                                     : LinkSettings::ProtocolChoice::Binary);
    settings.interFrameMs = 2;
    settings.timeoutMs = 1000;
    settings.retries = 1;
    auto session = openSession(settings);
    QCOMPARE(session->linkState(), LinkState::Connected);
    Results results(session.get());

    // One-off reads and a write reach the right PLC.
    SessionResult r = run(*session, results, Request::readRegisters(2, addr("R0"), 1));
    CHECK_OK(r);
    QCOMPARE(r.response().values, std::vector<std::uint32_t>{2222});
    CHECK_OK(run(*session, results, Request::writeRegisters(2, addr("R5"), {77})));
    QCOMPARE(plc2.value(addr("R5")), std::optional<std::uint32_t>(77));
    QCOMPARE(m_plc->value(addr("R5")), std::optional<std::uint32_t>(0));

    // Polling both stations through one port (each station's items come in batches of their own).
    std::map<std::uint64_t, WatchValue> latest;
    QList<WatchValue> last;
    connect(session.get(), &Session::values, this, [&latest, &last](const QList<WatchValue> &v) {
        for (const WatchValue &value : v)
            latest[value.itemId] = value;
        last.clear();
        for (const auto &[id, value] : latest)
            last.append(value);
    });
    session->setWatchList({{1, 1, addr("R0"), 50},
                           {2, 2, addr("R0"), 50},
                           {3, 1, addr("Y3"), 50},
                           {4, 2, addr("Y3"), 50}});
    const std::map<std::uint64_t, std::uint32_t> expected{{1, 1111}, {2, 2222}, {3, 1}, {4, 0}};
    QTRY_VERIFY_WITH_TIMEOUT(
        last.size() == 4
            && std::all_of(last.begin(), last.end(),
                           [](const WatchValue &v) { return v.quality == ValueQuality::Good; }),
        10000);
    for (const WatchValue &v : last)
        QCOMPARE(v.value, expected.at(v.itemId));
    session->setWatchList({});

    const SessionStatistics stats = session->statistics();
    QVERIFY(stats.stations.value(1).answers > 0);
    QVERIFY(stats.stations.value(2).answers > 0);
    QCOMPARE(stats.total.timeouts, quint64(0));
    // Both PLCs heard the frames meant for the other one and stayed silent.
    QVERIFY(m_server->counters().otherStation > 0);
    QVERIFY(server2.counters().otherStation > 0);
}

namespace {

int countEntries(const Session &session, TrafficEntry::Direction direction, const QString &text)
{
    int n = 0;
    for (const TrafficEntry &e : session.trafficLog()->entries())
        n += e.direction == direction
                     && (englishText(e.summary) + englishText(e.error)).contains(text)
                 ? 1
                 : 0;
    return n;
}

} // namespace

// A broadcast gets no answer: it is done when its frame has left, not when it is queued, and a
// frame the line does not take is reported as not sent and never leaves later. The test is the
// PLC side of a pty pair and stops the session's output with XOFF (software flow control).
bool TestSession::startXoffLine(LinkSettings &settings, QString *plcSide)
{
    m_dir = std::make_unique<QTemporaryDir>();
    *plcSide = m_dir->filePath(QStringLiteral("plc"));
    const QString appSide = m_dir->filePath(QStringLiteral("app"));
    m_socat = startPtyPair(*plcSide, appSide);
    if (!m_socat)
        return false;
    settings = LinkSettings::serial(appSide, 9600, LinkSettings::ProtocolChoice::Facon);
    settings.flowControl = LinkSettings::FlowControl::Software;
    settings.interFrameMs = 0;
    settings.reconnectMinMs = 50;
    return true;
}

void TestSession::broadcastOnTheWireBeforeClose()
{
    LinkSettings settings;
    QString plcSide;
    if (!startXoffLine(settings, &plcSide))
        QSKIP("socat is not available for serial pty pairs");
    auto peer = openRaw(plcSide);
    QVERIFY(peer);
    QByteArray received;
    connect(peer.get(), &QSerialPort::readyRead, this, [&] { received += peer->readAll(); });
    auto session = openSession(settings);
    QCOMPARE(session->linkState(), LinkState::Connected);
    Results results(session.get());
    const QString unexpected = QStringLiteral("no query pending");
    // A byte the session logs, then XOFF: once the byte is logged the XOFF took effect. (Qt sets
    // IXANY: any byte restarts the output, so a stop always comes last.)
    peer->write("a\x13");
    QTRY_COMPARE_WITH_TIMEOUT(countEntries(*session, TrafficEntry::Direction::In, unexpected), 1,
                              5000);

    const Request first = Request::writeRegisters(0, addr("R6"), {1});
    const quint64 waiting = session->submit(first);
    QTRY_COMPARE_WITH_TIMEOUT(countEntries(*session, TrafficEntry::Direction::Out, {}), 1, 5000);
    // A byte the session reads after it wrote the frame: a result due by then has been posted.
    peer->write("b\x13");
    QTRY_COMPARE_WITH_TIMEOUT(countEntries(*session, TrafficEntry::Direction::In, unexpected), 2,
                              5000);
    QCoreApplication::processEvents();
    QVERIFY2(!results.map.contains(waiting), "broadcast reported done while its frame was held");
    peer->write("\x11"); // XON: the frame leaves, then the broadcast is done
    QVERIFY(results.waitFor(waiting));
    CHECK_OK(results.map.value(waiting));
    const Bytes firstFrame = FaconCodec().encodeRequest(first).value();
    const QByteArray firstBytes(reinterpret_cast<const char *>(firstFrame.data()),
                                static_cast<qsizetype>(firstFrame.size()));
    QTRY_COMPARE_WITH_TIMEOUT(received, firstBytes, 5000);

    // The line stops again and stays stopped: a bounded wait, then a clear error.
    peer->write("c\x13");
    QTRY_COMPARE_WITH_TIMEOUT(countEntries(*session, TrafficEntry::Direction::In, unexpected), 3,
                              5000);
    RequestOptions quick;
    quick.timeoutMs = 200;
    const quint64 stuck
        = session->submit(Request::writeRegisters(0, addr("R6"), {2}), Priority::User, quick);
    QVERIFY(results.waitFor(stuck));
    const SessionResult notSent = results.map.value(stuck);
    QCOMPARE(notSent.errorKind(), ErrorKind::LinkError);
    QVERIFY2(notSent.errorText().startsWith(QStringLiteral("Not sent:")),
             qPrintable(notSent.errorText()));
    // Never retried (a second copy could follow the first), and it did not leave whole: nothing
    // reached the PLC, so refused, not unknown.
    QCOMPARE(notSent.attempts(), 0);
    QCOMPARE(notSent.outcome(), ChangeOutcome::Refused);

    // Reported as not sent, so it must never arrive: the session reset the link. After the
    // reconnect and an XON, the next broadcast is the only frame the peer gets.
    QTRY_COMPARE_WITH_TIMEOUT(session->linkState(), LinkState::Connected, 5000);
    peer->write("\x11"
                "d");
    QTRY_COMPARE_WITH_TIMEOUT(countEntries(*session, TrafficEntry::Direction::In, unexpected), 4,
                              5000);
    const Request third = Request::writeRegisters(0, addr("R6"), {3});
    CHECK_OK(run(*session, results, third));
    const Bytes thirdFrame = FaconCodec().encodeRequest(third).value();
    const QByteArray thirdBytes(reinterpret_cast<const char *>(thirdFrame.data()),
                                static_cast<qsizetype>(thirdFrame.size()));
    QTRY_COMPARE_WITH_TIMEOUT(received, firstBytes + thirdBytes, 5000);
}

// A broadcast whose frame the line holds when the link is lost: the wait for that frame goes with
// the link. After the reconnect the next request waits for its own answer; it is not taken for
// the broadcast ("done" once its own frame left, or "not sent" at its timeout).
void TestSession::broadcastHeldWhenLinkLost()
{
    LinkSettings settings;
    QString plcSide;
    if (!startXoffLine(settings, &plcSide))
        QSKIP("socat is not available for serial pty pairs");
    settings.reconnectMaxMs = 200;
    auto peer = openRaw(plcSide);
    QVERIFY(peer);
    auto session = openSession(settings);
    QCOMPARE(session->linkState(), LinkState::Connected);
    Results results(session.get());
    // A byte the session logs, then XOFF: once the byte is logged the XOFF took effect.
    peer->write("a\x13");
    QTRY_COMPARE_WITH_TIMEOUT(
        countEntries(*session, TrafficEntry::Direction::In, QStringLiteral("no query pending")), 1,
        5000);
    RequestOptions patient;
    patient.timeoutMs = 20000;
    const quint64 held
        = session->submit(Request::writeRegisters(0, addr("R6"), {1}), Priority::User, patient);
    QTRY_COMPARE_WITH_TIMEOUT(countEntries(*session, TrafficEntry::Direction::Out, {}), 1, 5000);

    // The line goes (the pty pair ends) while the frame is held, and comes back.
    peer.reset();
    m_socat.reset();
    QVERIFY(results.waitFor(held));
    QCOMPARE(results.map.value(held).errorKind(), ErrorKind::LinkError);
    m_socat = startPtyPair(plcSide, m_dir->filePath(QStringLiteral("app")));
    QVERIFY(m_socat);
    peer = openRaw(plcSide);
    QVERIFY(peer);
    QTRY_COMPARE_WITH_TIMEOUT(session->linkState(), LinkState::Connected, 10000);

    // A read nobody answers: its own timeout.
    RequestOptions quick;
    quick.timeoutMs = 300;
    quick.retries = 0;
    const quint64 read
        = session->submit(Request::readRegisters(1, addr("R0"), 1), Priority::User, quick);
    QVERIFY(results.waitFor(read));
    const SessionResult r = results.map.value(read);
    QVERIFY2(!r.ok(), "a read taken for the broadcast held before the link was lost");
    QCOMPARE(r.errorKind(), ErrorKind::Timeout);
}

// Writes accepted before close() reach the PLC; reads queued with them are cancelled.
void TestSession::closeSendsQueuedWrites()
{
    LinkSettings settings;
    QVERIFY(makeLink(QStringLiteral("tcp"), LinkSettings::ProtocolChoice::Facon, settings));
    auto session = openSession(settings);
    Results results(session.get());
    QList<quint64> writes;
    for (int i = 0; i < 20; ++i)
        writes.append(session->submit(
            Request::writeRegisters(1, addr("R100").advanced(static_cast<std::uint32_t>(i)),
                                    {static_cast<std::uint32_t>(i + 1)})));
    const quint64 read = session->submit(Request::readRegisters(1, addr("R0"), 1));
    session->close();
    for (quint64 id : writes) {
        QVERIFY(results.waitFor(id));
        CHECK_OK(results.map.value(id));
    }
    QVERIFY(results.waitFor(read));
    QCOMPARE(results.map.value(read).errorKind(), ErrorKind::Cancelled);
    for (int i = 0; i < 20; ++i)
        QCOMPARE(m_plc->value(addr("R100").advanced(static_cast<std::uint32_t>(i))),
                 std::optional<std::uint32_t>(i + 1));
    QTRY_COMPARE_WITH_TIMEOUT(session->linkState(), LinkState::Closed, 5000);
    QCOMPARE(session->pendingWrites(), 0);
    QCOMPARE(results.map.size(), 21); // exactly one result each
    // Nothing new is taken once closed.
    const SessionResult late = run(*session, results, Request::writeRegisters(1, addr("R0"), {1}));
    QCOMPARE(late.errorKind(), ErrorKind::LinkError);
}

void TestSession::destroySendsQueuedWrites_data()
{
    QTest::addColumn<QString>("transport");
    QTest::newRow("tcp") << QStringLiteral("tcp");
    QTest::newRow("serial") << QStringLiteral("serial");
}

// Destroying a session (the CLI's exit, the GUI's quit) sends what it accepted first. Broadcasts,
// as the simulator lives on this thread and cannot answer while the destructor waits.
void TestSession::destroySendsQueuedWrites()
{
    QFETCH(QString, transport);
    LinkSettings settings;
    if (!makeLink(transport, LinkSettings::ProtocolChoice::Facon, settings))
        QSKIP("socat is not available for serial pty pairs");
    settings.interFrameMs = 0;
    auto session = openSession(settings);
    QCOMPARE(session->linkState(), LinkState::Connected);
    for (int i = 0; i < 20; ++i)
        session->submit(
            Request::writeRegisters(0, addr("R200").advanced(static_cast<std::uint32_t>(i)),
                                    {static_cast<std::uint32_t>(i + 1)}));
    session.reset();
    g_session = nullptr;
    QTRY_COMPARE_WITH_TIMEOUT(m_server->counters().frames, quint64(20), 5000);
    for (int i = 0; i < 20; ++i)
        QCOMPARE(m_plc->value(addr("R200").advanced(static_cast<std::uint32_t>(i))),
                 std::optional<std::uint32_t>(i + 1));
}

// A PLC that stops answering cannot hold a close for longer than the drain bound.
void TestSession::closeDrainIsBounded()
{
    LinkSettings settings;
    QVERIFY(makeLink(QStringLiteral("tcp"), LinkSettings::ProtocolChoice::Facon, settings));
    settings.timeoutMs = 2000;
    settings.retries = 0;
    FaultConfig faults;
    faults.dropRate = 1.0;
    m_server->setFaults(faults);
    auto session = openSession(settings);
    session->setCloseDrainMs(300);
    QCOMPARE(session->closeDrainMs(), 300);
    Results results(session.get());
    QList<quint64> ids;
    for (int i = 0; i < 3; ++i)
        ids.append(session->submit(Request::writeRegisters(1, addr("R10"), {7})));
    QElapsedTimer clock;
    clock.start();
    session->close();
    // The first write went out and waits for its answer; the bound ends the wait.
    QTRY_COMPARE_WITH_TIMEOUT(m_server->counters().frames, quint64(1), 5000);
    QTRY_COMPARE_WITH_TIMEOUT(session->linkState(), LinkState::Closed, 5000);
    QVERIFY2(clock.elapsed() < 1500, qPrintable(QString::number(clock.elapsed())));
    for (quint64 id : ids) {
        QVERIFY(results.waitFor(id));
        QCOMPARE(results.map.value(id).errorKind(), ErrorKind::Cancelled);
        QVERIFY2(results.map.value(id).errorText().contains(QStringLiteral("300 ms")),
                 qPrintable(results.map.value(id).errorText()));
    }
    QCOMPARE(results.map.size(), 3);
    QCOMPARE(m_server->counters().frames, quint64(1));
}

// A write whose answer comes late is not sent again (docs/reliability.md, "Changes to a PLC"):
// one frame, one result (a timeout whose outcome is unknown), and the late answer is logged as
// unexpected, not taken as a second result.
void TestSession::retriedWriteReportedOnce()
{
    LinkSettings settings;
    QVERIFY(makeLink(QStringLiteral("tcp"), LinkSettings::ProtocolChoice::Facon, settings));
    settings.timeoutMs = 100;
    settings.retries = 2;
    FaultConfig slow;
    slow.latencyMs = 150;
    m_server->setFaults(slow);
    auto session = openSession(settings);
    Results results(session.get());
    const quint64 id = session->submit(Request::writeRegisters(1, addr("R300"), {5}));
    QVERIFY(results.waitFor(id));
    QCOMPARE(results.map.value(id).errorKind(), ErrorKind::Timeout);
    QCOMPARE(results.map.value(id).attempts(), 1);
    QCOMPARE(results.map.value(id).outcome(), ChangeOutcome::Unknown);
    QTRY_COMPARE_WITH_TIMEOUT(
        countEntries(*session, TrafficEntry::Direction::In, QStringLiteral("no query pending")), 1,
        5000);
    QCoreApplication::processEvents();
    QCOMPARE(results.order.count(id), 1);
    QCOMPARE(results.map.size(), 1);
    QCOMPARE(countEntries(*session, TrafficEntry::Direction::Out, {}), 1);
    QCOMPARE(
        countEntries(*session, TrafficEntry::Direction::Event, QStringLiteral("(attempt 1 of 1)")),
        1);
    QCOMPARE(m_server->counters().frames, quint64(1));
    QCOMPARE(m_plc->value(addr("R300")), std::optional<std::uint32_t>(5));
    QCOMPARE(session->statistics().total.requests, quint64(1));
}

// Raw frames under auto-detect: one sent as typed needs no probe; one the session frames is
// preceded by a probe of the station it is for, not station 1.
void TestSession::rawUnderAutoNeedsNoProbe()
{
    LinkSettings settings;
    QVERIFY(makeLink(QStringLiteral("tcp"), LinkSettings::ProtocolChoice::Auto, settings));
    m_server->setStation(9);
    auto session = openSession(settings);
    Results results(session.get());
    const QByteArray status("\x02"
                            "0940CF\x03");
    quint64 id = session->sendRaw(status, false);
    QVERIFY(results.waitFor(id));
    CHECK_OK(results.map.value(id));
    QVERIFY2(results.map.value(id).rawAnswer().startsWith("\x02"
                                                          "0940"),
             results.map.value(id).rawAnswer().constData());
    QCOMPARE(m_server->counters().frames, quint64(1));
    QVERIFY(!session->isProtocolKnown());

    RequestOptions station9;
    station9.station = 9;
    id = session->sendRaw("0940", true, station9);
    QVERIFY(results.waitFor(id));
    CHECK_OK(results.map.value(id));
    QVERIFY(session->isProtocolKnown());
    QCOMPARE(session->protocol(), Protocol::Facon);
    QCOMPARE(m_server->counters().frames, quint64(3)); // the probe of station 9, then the frame
    QCOMPARE(m_server->counters().otherStation, quint64(0));
}

// A broadcast has no station to detect the protocol with: before the protocol is known it is
// refused with nothing on the wire (not a probe of station 1); once a request detected it, a
// broadcast goes out alone, without a probe in front.
void TestSession::broadcastUnderAuto()
{
    LinkSettings settings;
    QVERIFY(makeLink(QStringLiteral("tcp"), LinkSettings::ProtocolChoice::Auto, settings));
    m_server->setStation(9);
    auto session = openSession(settings);
    Results results(session.get());
    m_plc->setValue(addr("R6"), 1);

    SessionResult r = run(*session, results, Request::writeRegisters(0, addr("R6"), {4321}));
    QVERIFY(!r.ok());
    QCOMPARE(r.errorKind(), ErrorKind::InvalidRequest);
    QVERIFY2(r.errorText().contains(QStringLiteral("give --protocol for a broadcast")),
             qPrintable(r.errorText()));
    // The console's broadcast with framing to add: refused the same way.
    RequestOptions broadcast;
    broadcast.station = 0;
    const quint64 id = session->sendRaw("0041", true, broadcast);
    QVERIFY(results.waitFor(id));
    QCOMPARE(results.map.value(id).errorKind(), ErrorKind::InvalidRequest);
    QTest::qWait(200); // anything sent would have arrived by now
    QCOMPARE(m_server->counters().bytesIn, quint64(0));
    QCOMPARE(m_plc->value(addr("R6")), std::optional<std::uint32_t>(1));
    QVERIFY(!session->isProtocolKnown());

    // A request to a station detects the protocol (the probe, then the request) ...
    CHECK_OK(run(*session, results, Request::readRegisters(9, addr("R6"), 1)));
    QVERIFY(session->isProtocolKnown());
    QCOMPARE(m_server->counters().frames, quint64(2));
    // ... and the broadcast then goes out in it, alone.
    CHECK_OK(run(*session, results, Request::writeRegisters(0, addr("R6"), {4321})));
    QTRY_COMPARE_WITH_TIMEOUT(m_plc->value(addr("R6")), std::optional<std::uint32_t>(4321), 5000);
    QTest::qWait(100);
    QCOMPARE(m_server->counters().frames, quint64(3));
}

#include "tst_session.moc"
