#include "core/protocol/address.h"
#include "core/protocol/request.h"

#include <QTest>

using namespace Fatek;

class TestAddress : public QObject
{
    Q_OBJECT

private slots:
    void parse_data();
    void parse();
    void rejects_data();
    void rejects();
    void everyElementRoundTrips();
    void faconWidths();
    void spans();
    void validateLimits_data();
    void validateLimits();
    void validateAccepts();
    void describeAndTarget();
};

void TestAddress::parse_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<int>("type");
    QTest::addColumn<uint>("number");
    QTest::addColumn<QString>("canonical");

    QTest::newRow("R12") << "R12" << int(ElementType::R) << 12u << "R12";
    QTest::newRow("lower r12") << "r12" << int(ElementType::R) << 12u << "R12";
    QTest::newRow("DWM0") << "DWM0" << int(ElementType::DWM) << 0u << "DWM0";
    QTest::newRow("X16") << "X16" << int(ElementType::X) << 16u << "X16";
    QTest::newRow("D00012 leading zeros") << "D00012" << int(ElementType::D) << 12u << "D12";
    QTest::newRow("spaces") << "  wy8 " << int(ElementType::WY) << 8u << "WY8";
    QTest::newRow("DD vs D") << "DD4" << int(ElementType::DD) << 4u << "DD4";
    QTest::newRow("DR odd allowed") << "DR15" << int(ElementType::DR) << 15u << "DR15";
    QTest::newRow("RT") << "RT5" << int(ElementType::RT) << 5u << "RT5";
    QTest::newRow("DRC max") << "DRC9998" << int(ElementType::DRC) << 9998u << "DRC9998";
    QTest::newRow("R max") << "R65535" << int(ElementType::R) << 65535u << "R65535";
    QTest::newRow("WC max") << "WC9984" << int(ElementType::WC) << 9984u << "WC9984";
    QTest::newRow("DWX max") << "DWX9968" << int(ElementType::DWX) << 9968u << "DWX9968";
    QTest::newRow("F") << "F100" << int(ElementType::F) << 100u << "F100";
}

void TestAddress::parse()
{
    QFETCH(QString, text);
    QFETCH(int, type);
    QFETCH(uint, number);
    QFETCH(QString, canonical);
    const auto r = Address::parse(text.toStdString());
    QVERIFY2(r.ok(), r.ok() ? "" : r.error().text().c_str());
    QCOMPARE(int(r->type), type);
    QCOMPARE(r->number, number);
    QCOMPARE(QString::fromStdString(r->toString()), canonical);
}

void TestAddress::rejects_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("messagePart");

    QTest::newRow("empty") << ""
                           << "Empty address";
    QTest::newRow("no type") << "12"
                             << "must start with an element type";
    QTest::newRow("unknown type") << "Q12"
                                  << "unknown element type \"Q\"";
    QTest::newRow("no number") << "R"
                               << "number is missing";
    QTest::newRow("letters after") << "R12A"
                                   << "not a decimal element number";
    QTest::newRow("negative") << "R-1"
                              << "not a decimal element number";
    QTest::newRow("R out of range") << "R70000"
                                    << "R70000 is out of range";
    QTest::newRow("X out of range") << "X10000"
                                    << "0 to 9999";
    QTest::newRow("WY misaligned") << "WY4"
                                   << "multiple of 8";
    QTest::newRow("DWM misaligned") << "DWM12"
                                    << "e.g. DWM8";
    QTest::newRow("WX past end") << "WX9992"
                                 << "out of range";
    QTest::newRow("DR past end") << "DR65535"
                                 << "out of range";
    QTest::newRow("huge") << "R99999999999999"
                          << "too large";
}

void TestAddress::rejects()
{
    QFETCH(QString, text);
    QFETCH(QString, messagePart);
    const auto r = Address::parse(text.toStdString());
    QVERIFY(!r.ok());
    QCOMPARE(r.error().kind, ErrorKind::InvalidAddress);
    const QString message = QString::fromStdString(r.error().text());
    QVERIFY2(message.contains(messagePart), qPrintable(message));
}

void TestAddress::everyElementRoundTrips()
{
    QCOMPARE(allElements().size(), std::size_t(28));
    for (const ElementInfo &info : allElements()) {
        for (std::uint32_t n : {0u, info.alignment * 3, info.maxNumber}) {
            const Address a{info.type, n};
            const auto parsed = Address::parse(a.toString());
            QVERIFY2(parsed.ok(), a.toString().c_str());
            QCOMPARE(*parsed, a);
            const std::string facon = a.toFaconString();
            if (info.faconDigits == 0) {
                QVERIFY(facon.empty());
                continue;
            }
            const auto fromFacon = Address::parse(facon);
            QVERIFY(fromFacon.ok());
            QCOMPARE(*fromFacon, a);
        }
    }
}

void TestAddress::faconWidths()
{
    // The reference's fixed widths: discrete 5, 16-bit 6, 32-bit 7 characters.
    for (const ElementInfo &info : allElements()) {
        if (info.faconDigits == 0)
            continue;
        const std::size_t expected = info.width == ElementWidth::Bit    ? 5
                                     : info.width == ElementWidth::Word ? 6
                                                                        : 7;
        QCOMPARE((Address{info.type, 0}.toFaconString().size()), expected);
    }
    QCOMPARE(Address({ElementType::X, 16}).toFaconString(), std::string("X0016"));
    QCOMPARE(Address({ElementType::R, 12}).toFaconString(), std::string("R00012"));
    QCOMPARE(Address({ElementType::WY, 8}).toFaconString(), std::string("WY0008"));
    QCOMPARE(Address({ElementType::DR, 2}).toFaconString(), std::string("DR00002"));
    QCOMPARE(Address({ElementType::DWM, 0}).toFaconString(), std::string("DWM0000"));
    QCOMPARE(Address({ElementType::DRT, 4}).toFaconString(), std::string("DRT0004"));
}

void TestAddress::spans()
{
    QCOMPARE(Address({ElementType::WY, 0}).advanced(2), Address({ElementType::WY, 32}));
    QCOMPARE(Address({ElementType::DWX, 8}).advanced(1), Address({ElementType::DWX, 40}));
    QCOMPARE(Address({ElementType::DR, 0}).advanced(3), Address({ElementType::DR, 6}));
    QCOMPARE(Address({ElementType::R, 5}).advanced(3), Address({ElementType::R, 8}));
    QVERIFY(validateSpan({ElementType::R, 65535 - 63}, 64).ok());
    QVERIFY(!validateSpan({ElementType::R, 65535 - 62}, 64).ok());
    QVERIFY(validateSpan({ElementType::WY, 9984 - 16 * 3}, 4).ok());
    QVERIFY(!validateSpan({ElementType::WY, 9984 - 16 * 3}, 5).ok());
    const auto e = validateSpan({ElementType::X, 9990}, 20);
    QVERIFY(!e.ok());
    QVERIFY(QString::fromStdString(e.error().text()).contains("X9999"));
}

void TestAddress::validateLimits_data()
{
    QTest::addColumn<int>("protocol");
    QTest::addColumn<int>("kind");
    QTest::addColumn<QString>("messagePart");
    QTest::addColumn<int>("which");

    for (int p : {int(Protocol::Facon), int(Protocol::Binary)}) {
        const QByteArray tag = p == int(Protocol::Facon) ? "facon " : "binary ";
        QTest::newRow(tag + "257 points")
            << p << int(ErrorKind::LimitExceeded) << "1 to 256 points" << 0;
        QTest::newRow(tag + "0 points")
            << p << int(ErrorKind::LimitExceeded) << "1 to 256 points" << 1;
        QTest::newRow(tag + "65 words") << p << int(ErrorKind::LimitExceeded) << "1 to 64" << 2;
        QTest::newRow(tag + "33 DR")
            << p << int(ErrorKind::LimitExceeded) << "count as two words" << 3;
        QTest::newRow(tag + "mixed read 65 words")
            << p << int(ErrorKind::LimitExceeded) << "at most 64" << 4;
        QTest::newRow(tag + "mixed write 33 words")
            << p << int(ErrorKind::LimitExceeded) << "at most 32" << 5;
        QTest::newRow(tag + "loopback 257")
            << p << int(ErrorKind::LimitExceeded) << "at most 256" << 6;
        QTest::newRow(tag + "46 on discrete")
            << p << int(ErrorKind::InvalidRequest) << "needs a register" << 7;
        QTest::newRow(tag + "44 on register")
            << p << int(ErrorKind::InvalidRequest) << "needs a discrete" << 8;
        QTest::newRow(tag + "discrete value 2")
            << p << int(ErrorKind::InvalidRequest) << "0 (OFF) or 1 (ON)" << 9;
        QTest::newRow(tag + "word value 70000")
            << p << int(ErrorKind::InvalidRequest) << "16-bit" << 10;
        QTest::newRow(tag + "station 255")
            << p << int(ErrorKind::InvalidRequest) << "1 to 254" << 11;
        QTest::newRow(tag + "span past end")
            << p << int(ErrorKind::InvalidAddress) << "run past" << 12;
        QTest::newRow(tag + "mixed write count mismatch")
            << p << int(ErrorKind::InvalidRequest) << "values" << 13;
    }
    QTest::newRow("facon F") << int(Protocol::Facon) << int(ErrorKind::Unsupported)
                             << "binary protocol only" << 14;
    QTest::newRow("binary 4F") << int(Protocol::Binary) << int(ErrorKind::Unsupported) << "FACON"
                               << 15;
    QTest::newRow("facon loopback control char")
        << int(Protocol::Facon) << int(ErrorKind::InvalidRequest) << "printable" << 16;
}

void TestAddress::validateLimits()
{
    QFETCH(int, protocol);
    QFETCH(int, kind);
    QFETCH(QString, messagePart);
    QFETCH(int, which);

    const Address r0{ElementType::R, 0};
    const Address y0{ElementType::Y, 0};
    const Address dr0{ElementType::DR, 0};
    Request req;
    switch (which) {
    case 0: req = Request::readDiscretes(1, y0, 257); break;
    case 1: req = Request::readEnableFlags(1, y0, 0); break;
    case 2: req = Request::readRegisters(1, r0, 65); break;
    case 3: req = Request::writeRegisters(1, dr0, std::vector<std::uint32_t>(33, 1)); break;
    case 4: {
        std::vector<Address> list(31, dr0); // 62 words
        list.push_back(r0);
        list.push_back(y0);
        list.push_back(r0); // 65
        req = Request::mixedRead(1, list);
        break;
    }
    case 5: {
        std::vector<Address> list(16, dr0); // 32 words
        list.push_back(y0);
        req = Request::mixedWrite(1, list, std::vector<std::uint32_t>(list.size(), 1));
        break;
    }
    case 6: req = Request::loopback(1, Bytes(257, 'A')); break;
    case 7: req = Request::readRegisters(1, y0, 1); break;
    case 8: req = Request::readDiscretes(1, r0, 1); break;
    case 9: req = Request::writeDiscretes(1, y0, {1, 2}); break;
    case 10: req = Request::writeRegisters(1, r0, {70000}); break;
    case 11: req = Request::briefStatus(255); break;
    case 12: req = Request::readRegisters(1, {ElementType::R, 65535}, 2); break;
    case 13: req = Request::mixedWrite(1, {r0, y0}, {1}); break;
    case 14: req = Request::readRegisters(1, {ElementType::F, 0}, 1); break;
    case 15: req = Request::readProgram(1, 0); break;
    case 16: req = Request::loopback(1, Bytes{'A', 0x03}); break;
    }
    const Status s = validateRequest(req, Protocol(protocol));
    QVERIFY(!s.ok());
    QCOMPARE(int(s.error().kind), kind);
    const QString message = QString::fromStdString(s.error().text());
    QVERIFY2(message.contains(messagePart), qPrintable(message));
}

void TestAddress::validateAccepts()
{
    const Address dr0{ElementType::DR, 0};
    for (Protocol p : {Protocol::Facon, Protocol::Binary}) {
        QVERIFY(validateRequest(Request::readDiscretes(1, {ElementType::X, 0}, 256), p).ok());
        QVERIFY(validateRequest(Request::readRegisters(1, {ElementType::R, 0}, 64), p).ok());
        QVERIFY(validateRequest(Request::readRegisters(1, dr0, 32), p).ok());
        QVERIFY(validateRequest(Request::mixedRead(1, std::vector<Address>(32, dr0)), p).ok());
        QVERIFY(validateRequest(Request::mixedWrite(1, std::vector<Address>(16, dr0),
                                                    std::vector<std::uint32_t>(16, 0xFFFFFFFF)),
                                p)
                    .ok());
        QVERIFY(validateRequest(Request::loopback(1, Bytes(256, 'Z')), p).ok());
        QVERIFY(validateRequest(Request::loopback(1, {}), p).ok());
        QVERIFY(validateRequest(Request::runStop(0, true), p).ok()); // broadcast
    }
    QVERIFY(
        validateRequest(Request::readRegisters(1, {ElementType::DF, 0}, 1), Protocol::Binary).ok());
    QVERIFY(validateRequest(Request::writeProgram(1, 3, std::vector<std::uint32_t>(64, 0xFFFF)),
                            Protocol::Facon)
                .ok());
    QVERIFY(!validateRequest(Request::writeProgram(1, 3, std::vector<std::uint32_t>(63, 0)),
                             Protocol::Facon)
                 .ok());
}

void TestAddress::describeAndTarget()
{
    const Request read = Request::readRegisters(1, {ElementType::R, 12}, 3);
    QCOMPARE(read.target(), std::string("R12..R14"));
    QCOMPARE(read.describe(), std::string("read R12..R14 (station 1)"));
    const Request wy = Request::writeRegisters(2, {ElementType::WY, 16}, {0xAAAA, 0x5555});
    QCOMPARE(wy.target(), std::string("WY16..WY32"));
    QCOMPARE(wy.describe(), std::string("write WY16..WY32 = 0xAAAA 0x5555 (station 2)"));
    const Request mixed
        = Request::mixedWrite(1, {{ElementType::Y, 0}, {ElementType::DR, 2}}, {1, 255});
    QCOMPARE(mixed.describe(), std::string("write Y0=1, DR2=0x000000FF (station 1)"));
    QCOMPARE(Request::runStop(0, false).describe(), std::string("STOP (broadcast)"));
    const ProtocolError e
        = makePlcError(0xA, Request::readRegisters(1, {ElementType::R, 65535}, 1).target());
    QCOMPARE(e.text(), std::string("PLC error A: illegal address R65535"));
    QCOMPARE(e.plcCode, 0xA);
    QCOMPARE(e.kind, ErrorKind::PlcError);
    QVERIFY(isWriteCommand(Command::MixedWrite));
    QVERIFY(!isWriteCommand(Command::MixedRead));
}

QTEST_APPLESS_MAIN(TestAddress)
#include "tst_address.moc"
