// SimServer over real loopback sockets (TCP, UDP) and a socat pty pair (serial), spoken to with
// the project's codecs: every command of both protocols, error codes, station filter, broadcast
// silence, bad checksums and each fault knob.

#include "core/protocol/binarycodec.h"
#include "core/protocol/binarydeframer.h"
#include "core/protocol/faconcodec.h"
#include "core/protocol/facondeframer.h"
#include "core/sim/simserver.h"
#include "core/sim/simulatedplc.h"
#include "testutil.h"

#include <QElapsedTimer>
#include <QFileInfo>
#include <QNetworkDatagram>
#include <QNetworkProxy>
#include <QProcess>
#include <QSerialPort>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTcpSocket>
#include <QTemporaryDir>
#include <QTest>
#include <QUdpSocket>

#include <algorithm>
#include <cstring>
#include <memory>

using namespace Fatek;

namespace {

constexpr int answerTimeoutMs = 3000;
// Long enough for a loopback answer to arrive many times over: silence after it means none was
// sent.
constexpr int silenceMs = 300;

Address addr(const char *text)
{
    auto a = Address::parse(text);
    if (!a)
        qFatal("bad address in test: %s", text);
    return *a;
}

const Codec &codecFor(Protocol p)
{
    static const FaconCodec facon;
    static const BinaryCodec binary;
    return p == Protocol::Facon ? static_cast<const Codec &>(facon)
                                : static_cast<const Codec &>(binary);
}

Bytes ascii(const char *text)
{
    return Bytes(text, text + std::strlen(text));
}

enum class Transport { Tcp, Udp, Serial };

// The master side of one link: collects what the simulator sends.
class Master : public QObject
{
public:
    static std::unique_ptr<Master> tcp(quint16 port)
    {
        auto m = std::make_unique<Master>();
        m->m_tcp = std::make_unique<QTcpSocket>();
        m->m_tcp->setProxy(QNetworkProxy::NoProxy);
        QObject::connect(m->m_tcp.get(), &QTcpSocket::readyRead, m.get(), [p = m.get()] {
            p->rx += p->m_tcp->readAll();
            ++p->packets;
        });
        QObject::connect(m->m_tcp.get(), &QTcpSocket::disconnected, m.get(),
                         [p = m.get()] { p->closed = true; });
        m->m_tcp->connectToHost(QHostAddress::LocalHost, port);
        return m;
    }

    static std::unique_ptr<Master> udp(quint16 port)
    {
        auto m = std::make_unique<Master>();
        m->m_udp = std::make_unique<QUdpSocket>();
        // Test masters never go through a desktop proxy, as the transports don't (that also
        // keeps libproxy's thread out of ThreadSanitizer runs).
        m->m_udp->setProxy(QNetworkProxy::NoProxy);
        m->m_udp->bind(QHostAddress::LocalHost, 0);
        m->m_port = port;
        QObject::connect(m->m_udp.get(), &QUdpSocket::readyRead, m.get(), [p = m.get()] {
            while (p->m_udp->hasPendingDatagrams()) {
                p->rx += p->m_udp->receiveDatagram().data();
                ++p->packets;
            }
        });
        return m;
    }

    static std::unique_ptr<Master> serial(const QString &device)
    {
        auto m = std::make_unique<Master>();
        m->m_serial = std::make_unique<QSerialPort>(device);
        m->m_serial->setBaudRate(9600);
        m->m_serial->setDataBits(QSerialPort::Data8);
        if (!m->m_serial->open(QIODevice::ReadWrite))
            return nullptr;
        QObject::connect(m->m_serial.get(), &QSerialPort::readyRead, m.get(), [p = m.get()] {
            p->rx += p->m_serial->readAll();
            ++p->packets;
        });
        return m;
    }

    bool waitConnected()
    {
        if (!m_tcp)
            return true;
        return QTest::qWaitFor([this] { return m_tcp->state() == QAbstractSocket::ConnectedState; },
                               answerTimeoutMs);
    }

    void write(const Bytes &bytes)
    {
        const QByteArray data(reinterpret_cast<const char *>(bytes.data()),
                              static_cast<qsizetype>(bytes.size()));
        if (m_tcp)
            m_tcp->write(data);
        else if (m_udp)
            m_udp->writeDatagram(data, QHostAddress::LocalHost, m_port);
        else
            m_serial->write(data);
    }

    // The next frame (or rejected bytes) of `protocol` in what arrived, waiting up to `timeoutMs`.
    std::optional<DeframedItem> waitFrame(Protocol protocol, int timeoutMs = answerTimeoutMs)
    {
        QElapsedTimer clock;
        clock.start();
        for (;;) {
            Deframer &d = protocol == Protocol::Facon ? static_cast<Deframer &>(m_facon)
                                                      : static_cast<Deframer &>(m_binary);
            if (m_fed < rx.size()) {
                const auto *p = reinterpret_cast<const std::uint8_t *>(rx.constData()) + m_fed;
                d.feed(
                    std::span<const std::uint8_t>(p, static_cast<std::size_t>(rx.size() - m_fed)),
                    m_items);
                m_fed = rx.size();
            }
            if (!m_items.empty()) {
                std::optional<DeframedItem> item = m_items.front();
                m_items.erase(m_items.begin());
                return item;
            }
            if (clock.elapsed() >= timeoutMs)
                return std::nullopt;
            QTest::qWait(2);
        }
    }

    // Nothing at all arrives within `ms`.
    bool silentFor(int ms)
    {
        const qsizetype before = rx.size();
        QTest::qWait(ms);
        return rx.size() == before;
    }

    Result<Response> ask(const Request &request, Protocol protocol)
    {
        const Codec &codec = codecFor(protocol);
        auto frame = codec.encodeRequest(request);
        if (!frame)
            return frame.error();
        write(*frame);
        auto answer = waitFrame(protocol);
        if (!answer)
            return makeError(ErrorKind::Timeout, "no answer to " + request.describe());
        if (answer->error)
            return *answer->error;
        return codec.decodeResponse(answer->frame, request);
    }

    // Sends a raw body wrapped by the codec; returns the answer frame, empty on silence.
    Bytes askRaw(const Bytes &body, Protocol protocol)
    {
        write(codecFor(protocol).wrap(body));
        auto answer = waitFrame(protocol);
        if (!answer || answer->error)
            return {};
        return answer->frame;
    }

    std::size_t discarded(Protocol p) const
    {
        return p == Protocol::Facon ? m_facon.discardedBytes() : m_binary.discardedBytes();
    }

    QByteArray rx;
    int packets = 0;
    bool closed = false;

private:
    std::unique_ptr<QTcpSocket> m_tcp;
    std::unique_ptr<QUdpSocket> m_udp;
    std::unique_ptr<QSerialPort> m_serial;
    quint16 m_port = 0;
    FaconDeframer m_facon;
    BinaryDeframer m_binary{BinaryDeframer::Direction::Response};
    qsizetype m_fed = 0;
    std::vector<DeframedItem> m_items;
};

// PLC error code carried by an answer frame of either protocol.
int errorCodeOf(const Bytes &frame, Protocol protocol)
{
    if (protocol == Protocol::Binary)
        return frame.size() > 6 ? frame[6] : -1;
    if (frame.size() < 7)
        return -1;
    const char c = static_cast<char>(frame[5]);
    return c >= 'A' ? c - 'A' + 10 : c - '0';
}

// A PLC with a server on every socket transport.
struct Rig
{
    SimulatedPlc plc;
    SimServer server{&plc};

    Rig()
    {
        QString error;
        if (!server.listenTcp(0, &error) || !server.listenUdp(0, &error))
            qFatal("%s", qPrintable(error));
    }

    std::unique_ptr<Master> connect(Transport t)
    {
        auto m
            = t == Transport::Tcp ? Master::tcp(server.tcpPort()) : Master::udp(server.udpPort());
        if (!m->waitConnected())
            return nullptr;
        return m;
    }
};

// Every command once, checked against the PLC memory. Returns false after a failed check.
bool commandSuite(Master &m, SimulatedPlc &plc, Protocol p)
{
    using V = std::vector<std::uint32_t>;
    const std::uint8_t s = 1;
    bool ok = true;
    auto check = [&](bool condition, const char *what) {
        if (!condition) {
            qWarning("%s: %s", protocolName(p).data(), what);
            ok = false;
        }
    };
    auto askOk = [&](const Request &r) -> Response {
        auto result = m.ask(r, p);
        if (!result) {
            qWarning("%s: %s failed: %s", protocolName(p).data(), r.describe().c_str(),
                     result.error().text().c_str());
            ok = false;
            return {};
        }
        return result.value();
    };

    check(askOk(Request::briefStatus(s)).data == plc.briefStatusBytes(), "40 status bytes");
    askOk(Request::runStop(s, false));
    check(!plc.isRunning(), "41 STOP");
    check(askOk(Request::briefStatus(s)).data.at(0) == 0x00, "40 after STOP");
    askOk(Request::runStop(s, true));
    check(plc.isRunning(), "41 RUN");

    askOk(Request::discreteControl(s, DiscreteOp::Disable, addr("Y3")));
    askOk(Request::discreteControl(s, DiscreteOp::Set, addr("Y3")));
    check(plc.isDisabled(addr("Y3")) == std::optional<bool>{true}, "42 disable");
    check(plc.value(addr("Y3")) == std::optional<std::uint32_t>{1}, "42 set");
    check(askOk(Request::readEnableFlags(s, addr("Y0"), 8)).values == V{0, 0, 0, 1, 0, 0, 0, 0},
          "43 flags");

    askOk(Request::writeDiscretes(s, addr("M10"), {1, 0, 1, 1}));
    check(plc.value(addr("M13")) == std::optional<std::uint32_t>{1}, "45 write");
    check(askOk(Request::readDiscretes(s, addr("M10"), 4)).values == V{1, 0, 1, 1}, "44 read");
    check(askOk(Request::readDiscretes(s, addr("M0"), 256)).values.size() == 256, "44 256 points");

    askOk(Request::writeRegisters(s, addr("R100"), {1, 0xFFFF, 0x1234}));
    check(plc.value(addr("R101")) == std::optional<std::uint32_t>{0xFFFF}, "47 write");
    check(askOk(Request::readRegisters(s, addr("R100"), 3)).values == V{1, 0xFFFF, 0x1234},
          "46 read");
    askOk(Request::writeRegisters(s, addr("DR200"), {0x12345678}));
    check(plc.value(addr("R201")) == std::optional<std::uint32_t>{0x1234}, "47 DR write");
    check(askOk(Request::readRegisters(s, addr("DR200"), 1)).values == V{0x12345678}, "46 DR read");
    check(askOk(Request::readRegisters(s, addr("WM0"), 1)).values == V{0x3400}, "46 WM view");
    check(askOk(Request::readRegisters(s, addr("R0"), 64)).values.size() == 64, "46 64 words");

    askOk(Request::mixedWrite(s, {addr("Y5"), addr("R7"), addr("DD4")}, {1, 0x55AA, 0x01020304}));
    check(plc.value(addr("D5")) == std::optional<std::uint32_t>{0x0102}, "49 write");
    check(askOk(Request::mixedRead(s, {addr("Y5"), addr("R7"), addr("DD4"), addr("WY0")})).values
              == V{1, 0x55AA, 0x01020304, 0x0028},
          "48 read");

    const Bytes test = ascii("Loop 123");
    check(askOk(Request::loopback(s, test)).data == test, "4E loopback");
    check(askOk(Request::detailStatus(s)).data == plc.detailStatusBytes(), "53 detail status");

    if (p == Protocol::Facon) {
        V page(64);
        for (std::uint32_t i = 0; i < 64; ++i)
            page[i] = i * 3;
        // 50 cannot execute in RUN (error 4): the program is written in STOP.
        const auto refused = m.ask(Request::writeProgram(s, 3, page), p);
        check(!refused.ok() && refused.error().plcCode == 4 && plc.programPage(3) != page,
              "50 refused in RUN");
        askOk(Request::runStop(s, false));
        askOk(Request::writeProgram(s, 3, page));
        check(plc.programPage(3) == page, "50 write page");
        check(askOk(Request::readProgram(s, 3)).values == page, "4F read page");
    } else {
        // FACON-only commands in binary: error 4.
        check(errorCodeOf(m.askRaw({s, 0x4F, 0x00, 0x03}, p), p) == 4, "4F in binary answers 4");
    }
    return ok;
}

} // namespace

class TestSimServer : public QObject
{
    Q_OBJECT

private slots:
    void everyCommand_data();
    void everyCommand();
    void everyCommandSerial();
    void referenceVectors_data();
    void referenceVectors();
    void errorCodes_data();
    void errorCodes();
    void stationFilterAndBroadcast_data();
    void stationFilterAndBroadcast();
    void badChecksumGetsNoAnswer();
    void bothProtocolsOnOneConnection();
    void manyTcpClients();
    void demoLadderMovesInRunOnly();
    void verboseLog();
    void bindAddress();
    void faultDrop();
    void faultDropIsSeeded();
    void faultCorrupt();
    void faultGarbage_data();
    void faultGarbage();
    void faultChunks();
    void faultCloseEvery();
    void faultWrongStation();
    void faultDelays_data();
    void faultDelays();
    void faultJitter();
    void faultLineTimeCountsQuery();
};

void TestSimServer::everyCommand_data()
{
    QTest::addColumn<int>("transport");
    QTest::addColumn<int>("protocol");
    QTest::newRow("tcp facon") << int(Transport::Tcp) << int(Protocol::Facon);
    QTest::newRow("tcp binary") << int(Transport::Tcp) << int(Protocol::Binary);
    QTest::newRow("udp facon") << int(Transport::Udp) << int(Protocol::Facon);
    QTest::newRow("udp binary") << int(Transport::Udp) << int(Protocol::Binary);
}

void TestSimServer::everyCommand()
{
    QFETCH(int, transport);
    QFETCH(int, protocol);
    Rig rig;
    auto m = rig.connect(static_cast<Transport>(transport));
    QVERIFY(m);
    QVERIFY(commandSuite(*m, rig.plc, static_cast<Protocol>(protocol)));
}

void TestSimServer::everyCommandSerial()
{
    const QString socat = QStandardPaths::findExecutable(QStringLiteral("socat"));
    if (socat.isEmpty())
        QSKIP("socat is not installed: no pty pair for the serial test");
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString simEnd = dir.filePath(QStringLiteral("sim"));
    const QString masterEnd = dir.filePath(QStringLiteral("master"));
    QProcess proc;
    proc.start(socat, {QStringLiteral("-d"), QStringLiteral("-d"),
                       QStringLiteral("pty,raw,echo=0,link=") + simEnd,
                       QStringLiteral("pty,raw,echo=0,link=") + masterEnd});
    QVERIFY(proc.waitForStarted());
    QVERIFY(QTest::qWaitFor(
        [&] { return QFileInfo::exists(simEnd) && QFileInfo::exists(masterEnd); }, 5000));

    SimulatedPlc plc;
    SimServer server(&plc);
    SerialSettings settings;
    settings.portName = QFileInfo(simEnd).canonicalFilePath();
    QString error;
    QVERIFY2(server.openSerial(settings, &error), qPrintable(error));
    QVERIFY(server.isListening());
    auto m = Master::serial(QFileInfo(masterEnd).canonicalFilePath());
    QVERIFY(m);
    QVERIFY(commandSuite(*m, plc, Protocol::Facon));
    QVERIFY(commandSuite(*m, plc, Protocol::Binary));

    // Broadcast on the serial line: executed, silent.
    auto frame
        = codecFor(Protocol::Facon).encodeRequest(Request::writeRegisters(0, addr("R50"), {77}));
    QVERIFY(frame);
    m->write(*frame);
    QVERIFY(m->silentFor(silenceMs));
    QCOMPARE(plc.value(addr("R50")), std::optional<std::uint32_t>{77});

    m.reset();
    server.close();
    proc.terminate();
    QVERIFY(proc.waitForFinished(3000));
}

void TestSimServer::referenceVectors_data()
{
    QTest::addColumn<int>("protocol");
    QTest::addColumn<QByteArray>("query");
    QTest::addColumn<QByteArray>("response");
    auto bytes = [](const Bytes &b) {
        return QByteArray(reinterpret_cast<const char *>(b.data()),
                          static_cast<qsizetype>(b.size()));
    };
    for (const auto &[name, p] : {std::pair{QStringLiteral("facon"), Protocol::Facon},
                                  std::pair{QStringLiteral("binary"), Protocol::Binary}}) {
        for (const TestUtil::Vector &v : TestUtil::loadVectors(name)) {
            if (v.what.contains(QLatin1String("query only")))
                continue; // no complete answer to compare with
            QTest::newRow(qPrintable(name + QLatin1String(": ") + v.what))
                << int(p) << bytes(v.query) << bytes(v.response);
        }
    }
}

// The checked frames of the reference, replayed over TCP: with the PLC state the answer describes,
// the simulator answers byte for byte the same, and writes land in memory.
void TestSimServer::referenceVectors()
{
    QFETCH(int, protocol);
    QFETCH(QByteArray, query);
    QFETCH(QByteArray, response);
    const auto p = static_cast<Protocol>(protocol);
    const Codec &codec = codecFor(p);
    const Bytes q(query.begin(), query.end());
    const Bytes expected(response.begin(), response.end());
    auto request = codec.decodeRequest(q);
    QVERIFY2(request, request ? "" : request.error().text().c_str());
    const Request &r = *request;
    const auto answer = codec.decodeResponse(expected, r);

    // State the answer describes, on the largest model (STATUS2/3 = 00 as in the vectors).
    ModelProfile profile = ModelProfile::mSeries();
    if (!answer && answer.error().plcCode == 0xA) {
        profile.discretes = {};
        profile.registers = {};
    }
    if (answer && r.command == Command::BriefStatus) {
        profile.status2 = answer->data.at(1);
        profile.status3 = answer->data.at(2);
    }
    SimulatedPlc plc(profile);
    if (!answer) {
        QCOMPARE(answer.error().kind, ErrorKind::PlcError);
        if (answer.error().plcCode != 0xA) {
            plc.setRunning(false);
            plc.setRunRefusalCode(static_cast<std::uint8_t>(answer.error().plcCode));
        }
    } else {
        switch (r.command) {
        case Command::BriefStatus: {
            const PlcStatus flags = PlcStatus::fromStatus1(answer->data.at(0));
            plc.setStatusFlags(flags);
            plc.setRunning(flags.running);
            break;
        }
        case Command::ReadEnableFlags:
            for (std::uint32_t i = 0; i < r.count; ++i)
                QVERIFY(plc.setDisabled(r.start.advanced(i), answer->values.at(i) != 0));
            break;
        case Command::ReadDiscretes:
        case Command::ReadRegisters:
            for (std::uint32_t i = 0; i < r.count; ++i)
                QVERIFY(plc.setValue(r.start.advanced(i), answer->values.at(i)));
            break;
        case Command::MixedRead:
            for (std::size_t i = 0; i < r.addresses.size(); ++i)
                QVERIFY(plc.setValue(r.addresses[i], answer->values.at(i)));
            break;
        default: break;
        }
    }

    SimServer server(&plc);
    QVERIFY(server.listenTcp(0));
    auto m = Master::tcp(server.tcpPort());
    QVERIFY(m->waitConnected());
    m->write(q);
    QVERIFY(QTest::qWaitFor([&] { return m->rx.size() >= response.size(); }, answerTimeoutMs));
    QCOMPARE(TestUtil::toHex(Bytes(m->rx.begin(), m->rx.end())), TestUtil::toHex(expected));

    // Writes reached the memory.
    switch (r.command) {
    case Command::WriteDiscretes:
    case Command::WriteRegisters:
        for (std::uint32_t i = 0; i < r.values.size(); ++i)
            QCOMPARE(plc.value(r.start.advanced(i)), std::optional<std::uint32_t>{r.values[i]});
        break;
    case Command::MixedWrite:
        for (std::size_t i = 0; i < r.addresses.size(); ++i)
            QCOMPARE(plc.value(r.addresses[i]), std::optional<std::uint32_t>{r.values[i]});
        break;
    case Command::DiscreteControl:
        if (r.op == DiscreteOp::Disable)
            QCOMPARE(plc.isDisabled(r.start), std::optional<bool>{true});
        break;
    default: break;
    }
}

void TestSimServer::errorCodes_data()
{
    QTest::addColumn<int>("protocol");
    QTest::newRow("facon") << int(Protocol::Facon);
    QTest::newRow("binary") << int(Protocol::Binary);
}

void TestSimServer::errorCodes()
{
    QFETCH(int, protocol);
    const auto p = static_cast<Protocol>(protocol);
    Rig rig;
    auto m = rig.connect(Transport::Tcp);
    QVERIFY(m);

    // A: beyond the FBs ranges (valid on the largest model, so the codec sends it).
    auto r = m->ask(Request::readRegisters(1, addr("R3840"), 1), p);
    QVERIFY(!r);
    QCOMPARE(r.error().kind, ErrorKind::PlcError);
    QCOMPARE(r.error().plcCode, 0xA);
    r = m->ask(Request::mixedRead(1, {addr("R0"), addr("M5000")}), p);
    QVERIFY(!r);
    QCOMPARE(r.error().plcCode, 0xA);

    // 2: a discrete value of 2, which no codec would encode.
    const Bytes badValue
        = p == Protocol::Facon ? ascii("014501Y00002") : Bytes{1, 0x45, 1, 'Y', 0, 0, 2};
    QCOMPARE(errorCodeOf(m->askRaw(badValue, p), p), 2);
    QCOMPARE(rig.plc.value(addr("Y0")), std::optional<std::uint32_t>{0});

    // 4: unknown command, malformed data.
    const Bytes unknown = p == Protocol::Facon ? ascii("014A") : Bytes{1, 0x4A};
    QCOMPARE(errorCodeOf(m->askRaw(unknown, p), p), 4);
    const Bytes garbled = p == Protocol::Facon ? ascii("0146ZZQ") : Bytes{1, 0x46, 1, 'R'};
    QCOMPARE(errorCodeOf(m->askRaw(garbled, p), p), 4);

    // RUN refusals.
    for (int code : {5, 6, 7, 9}) {
        rig.plc.setRunning(false);
        rig.plc.setRunRefusalCode(static_cast<std::uint8_t>(code));
        r = m->ask(Request::runStop(1, true), p);
        QVERIFY(!r);
        QCOMPARE(r.error().kind, ErrorKind::PlcError);
        QCOMPARE(r.error().plcCode, code);
        QVERIFY(!rig.plc.isRunning());
    }
    // Still in step: the next request gets its own answer.
    rig.plc.setRunRefusalCode(0);
    QVERIFY(m->ask(Request::runStop(1, true), p));
    QVERIFY(rig.plc.isRunning());
}

void TestSimServer::stationFilterAndBroadcast_data()
{
    errorCodes_data();
}

void TestSimServer::stationFilterAndBroadcast()
{
    QFETCH(int, protocol);
    const auto p = static_cast<Protocol>(protocol);
    Rig rig;
    rig.server.setStation(7);
    auto m = rig.connect(Transport::Tcp);
    QVERIFY(m);

    QVERIFY(m->ask(Request::briefStatus(7), p));
    // Another station: ignored, not executed.
    auto frame = codecFor(p).encodeRequest(Request::writeRegisters(1, addr("R9"), {9}));
    QVERIFY(frame);
    m->write(*frame);
    QVERIFY(m->silentFor(silenceMs));
    QCOMPARE(rig.plc.value(addr("R9")), std::optional<std::uint32_t>{0});
    QCOMPARE(rig.server.counters().otherStation, quint64{1});

    // Broadcast: executed, never answered, even when it fails.
    frame = codecFor(p).encodeRequest(Request::writeDiscretes(0, addr("Y20"), {1}));
    QVERIFY(frame);
    m->write(*frame);
    frame = codecFor(p).encodeRequest(Request::readRegisters(0, addr("R5000"), 1));
    QVERIFY(frame);
    m->write(*frame);
    QVERIFY(m->silentFor(silenceMs));
    QCOMPARE(rig.plc.value(addr("Y20")), std::optional<std::uint32_t>{1});

    auto r = m->ask(Request::readDiscretes(7, addr("Y20"), 1), p);
    QVERIFY(r);
    QCOMPARE(r->values, std::vector<std::uint32_t>{1});
}

void TestSimServer::badChecksumGetsNoAnswer()
{
    Rig rig;
    auto m = rig.connect(Transport::Tcp);
    QVERIFY(m);
    for (Protocol p : {Protocol::Facon, Protocol::Binary}) {
        auto frame = codecFor(p).encodeRequest(Request::writeRegisters(1, addr("R3"), {3}));
        QVERIFY(frame);
        Bytes bad = *frame;
        bad[bad.size() - 3] ^= 0x01; // FACON: LRC digit; binary: CRC high byte
        m->write(bad);
        QVERIFY(m->silentFor(silenceMs));
        QCOMPARE(rig.plc.value(addr("R3")), std::optional<std::uint32_t>{0});
        QVERIFY(m->ask(Request::briefStatus(1), p));
    }
    QCOMPARE(rig.server.counters().rejected, quint64{2});
}

void TestSimServer::bothProtocolsOnOneConnection()
{
    Rig rig;
    auto m = rig.connect(Transport::Tcp);
    QVERIFY(m);
    const Request facon = Request::readRegisters(1, addr("R0"), 1);
    const Request binary = Request::loopback(1, ascii("bin"));
    Bytes both = *codecFor(Protocol::Facon).encodeRequest(facon);
    const Bytes second = *codecFor(Protocol::Binary).encodeRequest(binary);
    both.insert(both.end(), {'x', 'y'}); // noise between frames is skipped
    both.insert(both.end(), second.begin(), second.end());
    m->write(both);
    const qsizetype expected
        = 13 + 13; // FACON 46 answer of one register; binary 4E answer of 3 bytes
    QVERIFY(QTest::qWaitFor([&] { return m->rx.size() >= expected; }, answerTimeoutMs));
    QCOMPARE(m->rx.size(), expected);
    const auto *bytes = reinterpret_cast<const std::uint8_t *>(m->rx.constData());
    const std::span<const std::uint8_t> all(bytes, static_cast<std::size_t>(m->rx.size()));
    std::vector<DeframedItem> items;
    FaconDeframer fd;
    fd.feed(all, items);
    BinaryDeframer bd(BinaryDeframer::Direction::Response);
    bd.feed(all, items);
    QCOMPARE(items.size(), std::size_t{2});
    QVERIFY(codecFor(Protocol::Facon).decodeResponse(items[0].frame, facon));
    QVERIFY(codecFor(Protocol::Binary).decodeResponse(items[1].frame, binary));
}

void TestSimServer::manyTcpClients()
{
    Rig rig;
    QSignalSpy clients(&rig.server, &SimServer::clientCountChanged);
    std::vector<std::unique_ptr<Master>> masters;
    for (int i = 0; i < 5; ++i) {
        masters.push_back(rig.connect(Transport::Tcp));
        QVERIFY(masters.back());
    }
    QVERIFY(QTest::qWaitFor([&] { return rig.server.tcpClientCount() == 5; }, answerTimeoutMs));
    // All send before any reads: each gets its own answer.
    for (std::uint32_t i = 0; i < masters.size(); ++i) {
        const auto p = i % 2 ? Protocol::Binary : Protocol::Facon;
        masters[i]->write(*codecFor(p).encodeRequest(
            Request::writeRegisters(1, Address{ElementType::R, i}, {100 + i})));
    }
    for (std::uint32_t i = 0; i < masters.size(); ++i) {
        const auto p = i % 2 ? Protocol::Binary : Protocol::Facon;
        auto answer = masters[i]->waitFrame(p);
        QVERIFY(answer && !answer->error);
        QCOMPARE(rig.plc.value(Address{ElementType::R, i}), std::optional<std::uint32_t>{100 + i});
    }
    masters.pop_back();
    QVERIFY(QTest::qWaitFor([&] { return rig.server.tcpClientCount() == 4; }, answerTimeoutMs));
    QVERIFY(clients.count() >= 6);
}

void TestSimServer::demoLadderMovesInRunOnly()
{
    Rig rig;
    rig.server.setDemoLadder(true);
    QVERIFY(rig.server.demoLadder());
    auto m = rig.connect(Transport::Tcp);
    QVERIFY(m);
    auto readR0 = [&] {
        auto r = m->ask(Request::readRegisters(1, addr("R0"), 1), Protocol::Facon);
        return r ? std::optional<std::uint32_t>(r->values.at(0)) : std::nullopt;
    };
    const auto first = readR0();
    QVERIFY(first);
    QVERIFY(QTest::qWaitFor([&] { return readR0() != first; }, 5000));

    QVERIFY(m->ask(Request::runStop(1, false), Protocol::Facon));
    const auto stopped = readR0();
    QVERIFY(stopped);
    QTest::qWait(100); // ten scan periods
    QCOMPARE(readR0(), stopped);
}

void TestSimServer::verboseLog()
{
    Rig rig;
    rig.server.setVerbose(true);
    QSignalSpy log(&rig.server, &SimServer::logLine);
    auto m = rig.connect(Transport::Tcp);
    QVERIFY(m);
    QVERIFY(m->ask(Request::readRegisters(1, addr("R12"), 3), Protocol::Facon));
    bool found = false;
    for (const QList<QVariant> &args : log)
        found = found || args.at(0).toString().contains(QStringLiteral("read R12..R14"));
    QVERIFY(found);
}

void TestSimServer::bindAddress()
{
    SimulatedPlc plc;
    SimServer server(&plc);
    QCOMPARE(server.bindAddress(), QHostAddress(QHostAddress::LocalHost));
    QVERIFY(!server.isListening());
    QVERIFY(server.listenTcp(0));
    QVERIFY(server.isListening());
    QVERIFY(server.tcpPort() != 0);
    // The port is taken now: a second server reports why it cannot listen.
    SimServer other(&plc);
    QString error;
    QVERIFY(!other.listenTcp(server.tcpPort(), &error));
    QVERIFY(error.contains(QString::number(server.tcpPort())));
    server.close();
    QVERIFY(!server.isListening());
}

void TestSimServer::faultDrop()
{
    Rig rig;
    FaultConfig f;
    f.dropRate = 1.0;
    rig.server.setFaults(f);
    auto m = rig.connect(Transport::Tcp);
    QVERIFY(m);
    m->write(*codecFor(Protocol::Facon).encodeRequest(Request::writeRegisters(1, addr("R0"), {5})));
    QVERIFY(m->silentFor(silenceMs));
    QCOMPARE(rig.plc.value(addr("R0")), std::optional<std::uint32_t>{5}); // executed all the same
    QCOMPARE(rig.server.counters().dropped, quint64{1});
}

void TestSimServer::faultDropIsSeeded()
{
    // Twenty loopbacks, half of the answers dropped: the same ones for the same seed.
    auto run = [](std::uint32_t seed) {
        Rig rig;
        FaultConfig f;
        f.dropRate = 0.5;
        f.seed = seed;
        rig.server.setFaults(f);
        auto m = rig.connect(Transport::Tcp);
        Bytes all;
        for (int i = 0; i < 20; ++i) {
            const Bytes one = *codecFor(Protocol::Facon)
                                   .encodeRequest(Request::loopback(
                                       1, ascii(QByteArray::number(100 + i).constData())));
            all.insert(all.end(), one.begin(), one.end());
        }
        m->write(all);
        if (!QTest::qWaitFor([&] { return rig.server.counters().frames == 20; }, answerTimeoutMs))
            return QStringList{QStringLiteral("timeout")};
        QStringList answered;
        while (auto item = m->waitFrame(Protocol::Facon, 200))
            answered << QString::fromLatin1(reinterpret_cast<const char *>(item->frame.data()) + 5,
                                            3);
        return answered;
    };
    const QStringList first = run(42);
    QVERIFY(!first.isEmpty());
    QVERIFY(first.size() < 20);
    QCOMPARE(run(42), first);
}

void TestSimServer::faultCorrupt()
{
    Rig rig;
    FaultConfig f;
    f.corruptRate = 1.0;
    rig.server.setFaults(f);
    auto m = rig.connect(Transport::Tcp);
    QVERIFY(m);
    const Bytes clean
        = codecFor(Protocol::Facon)
              .encodeResponse(Request::briefStatus(1),
                              Response{1, Command::BriefStatus, 0, {}, rig.plc.briefStatusBytes()});
    m->write(*codecFor(Protocol::Facon).encodeRequest(Request::briefStatus(1)));
    QVERIFY(QTest::qWaitFor([&] { return m->rx.size() >= static_cast<qsizetype>(clean.size()); },
                            answerTimeoutMs));
    QCOMPARE(m->rx.size(), static_cast<qsizetype>(clean.size()));
    // Every byte differs, so no valid answer can be found in it.
    for (qsizetype i = 0; i < m->rx.size(); ++i)
        QVERIFY(static_cast<std::uint8_t>(m->rx[i]) != clean[static_cast<std::size_t>(i)]);
    auto item = m->waitFrame(Protocol::Facon, 50);
    QVERIFY(!item || item->error);
}

void TestSimServer::faultGarbage_data()
{
    errorCodes_data();
}

void TestSimServer::faultGarbage()
{
    QFETCH(int, protocol);
    const auto p = static_cast<Protocol>(protocol);
    Rig rig;
    FaultConfig f;
    f.garbageBytes = 12;
    rig.server.setFaults(f);
    auto m = rig.connect(Transport::Tcp);
    QVERIFY(m);
    QVERIFY(m->ask(Request::briefStatus(1), p));
    QVERIFY(m->ask(Request::readRegisters(1, addr("R0"), 2), p));
    QCOMPARE(m->discarded(p), std::size_t{24});
}

void TestSimServer::faultChunks()
{
    Rig rig;
    FaultConfig f;
    f.chunkSize = 4;
    f.chunkDelayMs = 5;
    rig.server.setFaults(f);
    // Over UDP every piece is its own datagram, so the pieces can be counted.
    auto m = rig.connect(Transport::Udp);
    QVERIFY(m);
    auto r = m->ask(Request::briefStatus(1), Protocol::Facon); // 15-byte answer
    QVERIFY(r);
    QCOMPARE(r->data, rig.plc.briefStatusBytes());
    QCOMPARE(m->packets, 4);
}

void TestSimServer::faultCloseEvery()
{
    Rig rig;
    FaultConfig f;
    f.closeEverySeconds = 1;
    rig.server.setFaults(f);
    auto m = rig.connect(Transport::Tcp);
    QVERIFY(m);
    QVERIFY(m->ask(Request::briefStatus(1), Protocol::Facon));
    QVERIFY(QTest::qWaitFor([&] { return m->closed; }, 5000));
    QCOMPARE(rig.server.counters().closed, quint64{1});
    // A new connection is served again.
    auto again = rig.connect(Transport::Tcp);
    QVERIFY(again);
    QVERIFY(again->ask(Request::briefStatus(1), Protocol::Binary));
}

void TestSimServer::faultWrongStation()
{
    Rig rig;
    FaultConfig f;
    f.wrongStationRate = 1.0;
    rig.server.setFaults(f);
    auto m = rig.connect(Transport::Tcp);
    QVERIFY(m);
    for (Protocol p : {Protocol::Facon, Protocol::Binary}) {
        auto r = m->ask(Request::readRegisters(1, addr("R0"), 1), p);
        QVERIFY(!r);
        QCOMPARE(r.error().kind, ErrorKind::StationMismatch);
    }
}

void TestSimServer::faultDelays_data()
{
    QTest::addColumn<int>("latency");
    QTest::addColumn<int>("turnaround");
    QTest::addColumn<int>("baud");
    QTest::addColumn<int>("minimumMs");
    QTest::newRow("latency 150 ms") << 150 << 0 << 0 << 150;
    QTest::newRow("turnaround 100 ms") << 0 << 100 << 0 << 100;
    // 53 answer: 137 FACON bytes, 1370 bits at 9600 baud.
    QTest::newRow("9600 baud") << 0 << 0 << 9600 << 142;
}

void TestSimServer::faultDelays()
{
    QFETCH(int, latency);
    QFETCH(int, turnaround);
    QFETCH(int, baud);
    QFETCH(int, minimumMs);
    Rig rig;
    FaultConfig f;
    f.latencyMs = latency;
    f.turnaroundMs = turnaround;
    f.baud = baud;
    rig.server.setFaults(f);
    auto m = rig.connect(Transport::Tcp);
    QVERIFY(m);
    QElapsedTimer clock;
    clock.start();
    QVERIFY(m->ask(Request::detailStatus(1), Protocol::Facon));
    // Only a lower bound: a busy machine may always be slower, never faster.
    QVERIFY2(clock.elapsed() >= minimumMs, qPrintable(QString::number(clock.elapsed())));
}

void TestSimServer::faultJitter()
{
    Rig rig;
    FaultConfig f;
    f.jitterMs = 200;
    f.seed = 7;
    rig.server.setFaults(f);
    auto m = rig.connect(Transport::Tcp);
    QVERIFY(m);
    qint64 longest = 0;
    for (int i = 0; i < 6; ++i) {
        QElapsedTimer clock;
        clock.start();
        QVERIFY(m->ask(Request::briefStatus(1), Protocol::Facon));
        longest = std::max(longest, clock.elapsed());
    }
    // Six draws of 0..200 ms from a fixed seed: at least one is well above zero.
    QVERIFY2(longest >= 20, qPrintable(QString::number(longest)));
}

void TestSimServer::faultLineTimeCountsQuery()
{
    // Line-speed emulation is half duplex: a long query (a 32-register write) occupies the line
    // before its short answer does, so the answer waits for both.
    Rig rig;
    FaultConfig f;
    f.baud = 9600;
    rig.server.setFaults(f);
    auto m = rig.connect(Transport::Tcp);
    QVERIFY(m);
    const Request write
        = Request::writeRegisters(1, addr("R0"), std::vector<std::uint32_t>(32, 0x1234));
    FaconCodec codec;
    const std::size_t queryBytes = codec.encodeRequest(write).value().size();
    Response ok;
    ok.station = 1;
    ok.command = Command::WriteRegisters;
    const std::size_t answerBytes = codec.encodeResponse(write, ok).size();
    const auto minimumMs = static_cast<qint64>((queryBytes + answerBytes) * 10 * 1000 / 9600);
    QVERIFY(minimumMs > 150); // the query alone is ~140 bytes: ~150 ms
    QElapsedTimer clock;
    clock.start();
    QVERIFY(m->ask(write, Protocol::Facon));
    // Only a lower bound: a busy machine may always be slower, never faster.
    QVERIFY2(clock.elapsed() >= minimumMs,
             qPrintable(QStringLiteral("%1 < %2").arg(clock.elapsed()).arg(minimumMs)));
}

QTEST_GUILESS_MAIN(TestSimServer)
#include "tst_simserver.moc"
