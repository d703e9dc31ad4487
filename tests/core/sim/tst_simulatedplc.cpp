// SimulatedPlc, PlcMemory and ModelProfile without any wire: typed requests in, typed answers out.

#include "core/sim/modelprofile.h"
#include "core/sim/plcmemory.h"
#include "core/sim/simulatedplc.h"

#include <QTest>

#include <array>

using namespace Fatek;

Q_DECLARE_METATYPE(Fatek::Request)

namespace {

Address addr(const char *text)
{
    auto a = Address::parse(text);
    if (!a)
        qFatal("bad address in test: %s", text);
    return *a;
}

constexpr std::uint8_t S = 1;

} // namespace

class TestSimulatedPlc : public QObject
{
    Q_OBJECT

private slots:
    void profiles_data();
    void profiles();
    void profileByName();
    void rangesAnswerA_data();
    void rangesAnswerA();
    void wordViewsOverBits();
    void doubleRegisterPairs();
    void illegalValuesAnswer2();
    void refusedWriteChangesNothing();
    void malformedAnswer4_data();
    void malformedAnswer4();
    void runStopAndStatus();
    void runRefusalCodes_data();
    void runRefusalCodes();
    void detailStatus();
    void forcing();
    void readEnableFlags();
    void demoLadder();
    void ladderStopsInStop();
    void programPages();
    void loopback();
    void mixedReadWrite();
    void clearBackToPowerOn_data();
    void clearBackToPowerOn();
};

void TestSimulatedPlc::profiles_data()
{
    QTest::addColumn<QString>("profile");
    QTest::addColumn<QString>("last");   // highest valid element
    QTest::addColumn<QString>("beyond"); // the next one, missing on this model
    QTest::newRow("fbs X") << "fbs"
                           << "X255"
                           << "X256";
    QTest::newRow("fbs Y") << "fbs"
                           << "Y255"
                           << "Y256";
    QTest::newRow("fbs M") << "fbs"
                           << "M2001"
                           << "M2002";
    QTest::newRow("fbs S") << "fbs"
                           << "S999"
                           << "S1000";
    QTest::newRow("fbs R") << "fbs"
                           << "R3839"
                           << "R3840";
    QTest::newRow("fbs D") << "fbs"
                           << "D2999"
                           << "D3000";
    QTest::newRow("fbs WY") << "fbs"
                            << "WY240"
                            << "WY248";
    QTest::newRow("fbs DWX") << "fbs"
                             << "DWX224"
                             << "DWX232";
    QTest::newRow("fbs DR") << "fbs"
                            << "DR3838"
                            << "DR3839";
    QTest::newRow("m X") << "m"
                         << "X9999"
                         << "";
    QTest::newRow("m R") << "m"
                         << "R65535"
                         << "";
    QTest::newRow("m F") << "m"
                         << "F65535"
                         << "";
    QTest::newRow("m DR") << "m"
                          << "DR65534"
                          << "";
    QTest::newRow("m DWC") << "m"
                           << "DWC9968"
                           << "";
    QTest::newRow("m RT") << "m"
                          << "RT9999"
                          << "";
}

void TestSimulatedPlc::profiles()
{
    QFETCH(QString, profile);
    QFETCH(QString, last);
    QFETCH(QString, beyond);
    const auto p = ModelProfile::byName(profile.toStdString());
    QVERIFY(p);
    QVERIFY(p->contains(addr(last.toLatin1().constData())));
    if (!beyond.isEmpty())
        QVERIFY(!p->contains(addr(beyond.toLatin1().constData())));
}

void TestSimulatedPlc::profileByName()
{
    QVERIFY(ModelProfile::byName("FBS"));
    QVERIFY(ModelProfile::byName("m"));
    QVERIFY(!ModelProfile::byName("fx"));
    QCOMPARE(ModelProfile::names().size(), std::size_t{2});
    // FBs has no file registers at all.
    QVERIFY(!ModelProfile::fbs().contains(Address{ElementType::F, 0}));
    // Misaligned views never exist.
    QVERIFY(!ModelProfile::mSeries().contains(Address{ElementType::WY, 4}));
    QVERIFY(!ModelProfile::mSeries().contains(Address{ElementType::DWM, 12}));
}

void TestSimulatedPlc::rangesAnswerA_data()
{
    QTest::addColumn<Request>("request");
    QTest::addColumn<int>("protocol");
    const int facon = static_cast<int>(Protocol::Facon);
    const int binary = static_cast<int>(Protocol::Binary);
    QTest::newRow("read R3840") << Request::readRegisters(S, addr("R3840"), 1) << facon;
    QTest::newRow("read R3838..R3841") << Request::readRegisters(S, addr("R3838"), 4) << facon;
    QTest::newRow("read X250..X259") << Request::readDiscretes(S, addr("X250"), 10) << facon;
    QTest::newRow("write D3000") << Request::writeRegisters(S, addr("D3000"), {1}) << facon;
    QTest::newRow("set M2002") << Request::discreteControl(S, DiscreteOp::Set, addr("M2002"))
                               << facon;
    QTest::newRow("flags S999..S1000") << Request::readEnableFlags(S, addr("S999"), 2) << facon;
    QTest::newRow("misaligned WY4")
        << Request::readRegisters(S, Address{ElementType::WY, 4}, 1) << facon;
    QTest::newRow("WY240 x2") << Request::readRegisters(S, addr("WY240"), 2) << facon;
    QTest::newRow("DR3839 needs R3840") << Request::readRegisters(S, addr("DR3839"), 1) << facon;
    QTest::newRow("F0 on FBs") << Request::readRegisters(S, addr("F0"), 1) << binary;
    QTest::newRow("mixed with R9999")
        << Request::mixedRead(S, {addr("R0"), addr("R9999")}) << facon;
    QTest::newRow("mixed write Y300")
        << Request::mixedWrite(S, {addr("R0"), addr("Y300")}, {5, 1}) << facon;
    QTest::newRow("program page 207") << Request::readProgram(S, 207) << facon;
}

void TestSimulatedPlc::rangesAnswerA()
{
    QFETCH(Request, request);
    QFETCH(int, protocol);
    SimulatedPlc plc;
    const Response r = plc.execute(request, static_cast<Protocol>(protocol));
    QCOMPARE(r.errorCode, std::uint8_t{0xA});
    QVERIFY(r.values.empty());
    QCOMPARE(r.command, request.command);
}

void TestSimulatedPlc::wordViewsOverBits()
{
    SimulatedPlc plc;
    // Y16 and Y31 on: WY16 = 0x8001; bit 0 is the lowest point.
    QCOMPARE(plc.execute(Request::writeDiscretes(S, addr("Y16"), {1})).errorCode, std::uint8_t{0});
    QCOMPARE(plc.execute(Request::writeDiscretes(S, addr("Y31"), {1})).errorCode, std::uint8_t{0});
    Response r = plc.execute(Request::readRegisters(S, addr("WY16"), 1));
    QCOMPARE(r.values, std::vector<std::uint32_t>{0x8001});
    // WY8 overlaps Y8..Y23: only Y16 is on, bit 8.
    r = plc.execute(Request::readRegisters(S, addr("WY8"), 1));
    QCOMPARE(r.values, std::vector<std::uint32_t>{0x0100});

    // Writing a DW view sets the 32 points.
    QCOMPARE(plc.execute(Request::writeRegisters(S, addr("DWM64"), {0x80000003})).errorCode,
             std::uint8_t{0});
    r = plc.execute(Request::readDiscretes(S, addr("M64"), 32));
    std::vector<std::uint32_t> expected(32, 0);
    expected[0] = expected[1] = expected[31] = 1;
    QCOMPARE(r.values, expected);
    r = plc.execute(Request::readRegisters(S, addr("WM64"), 2)); // WM64, WM80
    QCOMPARE(r.values, (std::vector<std::uint32_t>{0x0003, 0x8000}));
}

void TestSimulatedPlc::doubleRegisterPairs()
{
    SimulatedPlc plc;
    plc.execute(Request::writeRegisters(S, addr("R10"), {0x1234, 0xABCD}));
    Response r = plc.execute(Request::readRegisters(S, addr("DR10"), 1));
    QCOMPARE(r.values, std::vector<std::uint32_t>{0xABCD1234});
    // Consecutive DR elements step two registers: DR20, DR22.
    plc.execute(Request::writeRegisters(S, addr("DR20"), {0x00020001, 0x00040003}));
    r = plc.execute(Request::readRegisters(S, addr("R20"), 4));
    QCOMPARE(r.values, (std::vector<std::uint32_t>{1, 2, 3, 4}));
    // Odd start is fine: DR21 = R22:R21.
    r = plc.execute(Request::readRegisters(S, addr("DR21"), 1));
    QCOMPARE(r.values, std::vector<std::uint32_t>{0x00030002});
    QCOMPARE(plc.value(addr("DD0")), std::optional<std::uint32_t>{0});
}

void TestSimulatedPlc::illegalValuesAnswer2()
{
    SimulatedPlc plc;
    QCOMPARE(plc.execute(Request::writeDiscretes(S, addr("Y0"), {1, 2})).errorCode,
             std::uint8_t{2});
    QCOMPARE(plc.execute(Request::writeRegisters(S, addr("R0"), {0x10000})).errorCode,
             std::uint8_t{2});
    QCOMPARE(plc.execute(Request::mixedWrite(S, {addr("M0")}, {7})).errorCode, std::uint8_t{2});
    std::vector<std::uint32_t> page(64, 0);
    page[63] = 0x12345;
    plc.setRunning(false); // 50 is refused in RUN first (error 4)
    QCOMPARE(plc.execute(Request::writeProgram(S, 1, page)).errorCode, std::uint8_t{2});
    Request op = Request::discreteControl(S, DiscreteOp::Set, addr("Y0"));
    op.op = static_cast<DiscreteOp>(9);
    QCOMPARE(plc.execute(op).errorCode, std::uint8_t{2});
}

void TestSimulatedPlc::refusedWriteChangesNothing()
{
    SimulatedPlc plc;
    // The last value is bad: none of the values may be written.
    QCOMPARE(plc.execute(Request::writeRegisters(S, addr("R0"), {1, 2, 0x10000})).errorCode,
             std::uint8_t{2});
    QCOMPARE(plc.value(addr("R0")), std::optional<std::uint32_t>{0});
    QCOMPARE(plc.execute(Request::mixedWrite(S, {addr("R5"), addr("R4000")}, {9, 9})).errorCode,
             std::uint8_t{0xA});
    QCOMPARE(plc.value(addr("R5")), std::optional<std::uint32_t>{0});
}

void TestSimulatedPlc::malformedAnswer4_data()
{
    QTest::addColumn<Request>("request");
    QTest::addColumn<int>("protocol");
    const int facon = static_cast<int>(Protocol::Facon);
    const int binary = static_cast<int>(Protocol::Binary);
    QTest::newRow("44 count 0") << Request::readDiscretes(S, addr("X0"), 0) << facon;
    QTest::newRow("44 count 257") << Request::readDiscretes(S, addr("M0"), 257) << facon;
    QTest::newRow("44 on a register") << Request::readDiscretes(S, addr("R0"), 1) << facon;
    QTest::newRow("42 on a register")
        << Request::discreteControl(S, DiscreteOp::Set, addr("R0")) << facon;
    QTest::newRow("46 on a discrete") << Request::readRegisters(S, addr("Y0"), 1) << facon;
    QTest::newRow("46 65 words") << Request::readRegisters(S, addr("R0"), 65) << facon;
    QTest::newRow("46 33 DR") << Request::readRegisters(S, addr("DR0"), 33) << facon;
    QTest::newRow("47 no value") << Request::writeRegisters(S, addr("R0"), {}) << facon;
    std::vector<Address> many(33, addr("DR0"));
    QTest::newRow("48 66 words") << Request::mixedRead(S, many) << facon;
    std::vector<Address> seventeen(17, addr("DR0"));
    QTest::newRow("49 34 words") << Request::mixedWrite(S, seventeen,
                                                        std::vector<std::uint32_t>(17, 0))
                                 << facon;
    QTest::newRow("49 values missing")
        << Request::mixedWrite(S, {addr("R0"), addr("R1")}, {1}) << facon;
    QTest::newRow("48 empty") << Request::mixedRead(S, {}) << facon;
    QTest::newRow("4E 257 bytes") << Request::loopback(S, Bytes(257, 0x41)) << facon;
    QTest::newRow("4F in binary") << Request::readProgram(S, 0) << binary;
    QTest::newRow("50 in binary") << Request::writeProgram(S, 0, std::vector<std::uint32_t>(64, 0))
                                  << binary;
    QTest::newRow("50 short page")
        << Request::writeProgram(S, 0, std::vector<std::uint32_t>(63, 0)) << facon;
    Request unknown = Request::briefStatus(S);
    unknown.command = static_cast<Command>(0x4A);
    QTest::newRow("command 4A") << unknown << facon;
}

void TestSimulatedPlc::malformedAnswer4()
{
    QFETCH(Request, request);
    QFETCH(int, protocol);
    SimulatedPlc plc;
    QCOMPARE(plc.execute(request, static_cast<Protocol>(protocol)).errorCode, std::uint8_t{4});
}

void TestSimulatedPlc::runStopAndStatus()
{
    SimulatedPlc plc;
    QVERIFY(plc.isRunning()); // powers up in RUN
    Response r = plc.execute(Request::briefStatus(S));
    QCOMPARE(r.errorCode, std::uint8_t{0});
    QCOMPARE(r.data, (Bytes{0x01, 0x54, 0x00}));

    QCOMPARE(plc.execute(Request::runStop(S, false)).errorCode, std::uint8_t{0});
    QVERIFY(!plc.isRunning());
    QCOMPARE(plc.execute(Request::briefStatus(S)).data.at(0), std::uint8_t{0x00});

    PlcStatus flags;
    flags.memoryPack = true;
    flags.idSet = true;
    plc.setStatusFlags(flags);
    QCOMPARE(plc.execute(Request::runStop(S, true)).errorCode, std::uint8_t{0});
    QCOMPARE(plc.execute(Request::briefStatus(S)).data.at(0),
             std::uint8_t{0x29}); // the reference example
    QVERIFY(plc.status().running);

    SimulatedPlc m(ModelProfile::mSeries());
    QCOMPARE(m.execute(Request::briefStatus(S), Protocol::Binary).data, (Bytes{0x01, 0x00, 0x00}));
}

void TestSimulatedPlc::runRefusalCodes_data()
{
    QTest::addColumn<int>("code");
    QTest::newRow("5 ladder checksum") << 5;
    QTest::newRow("6 ID mismatch") << 6;
    QTest::newRow("7 syntax") << 7;
    QTest::newRow("9 not supported") << 9;
}

void TestSimulatedPlc::runRefusalCodes()
{
    QFETCH(int, code);
    SimulatedPlc plc;
    plc.setRunning(false);
    plc.setRunRefusalCode(static_cast<std::uint8_t>(code));
    QCOMPARE(plc.execute(Request::runStop(S, true)).errorCode, static_cast<std::uint8_t>(code));
    QVERIFY(!plc.isRunning());
    // STOP is always accepted.
    QCOMPARE(plc.execute(Request::runStop(S, false)).errorCode, std::uint8_t{0});
    plc.setRunRefusalCode(0);
    QCOMPARE(plc.execute(Request::runStop(S, true)).errorCode, std::uint8_t{0});
    QVERIFY(plc.isRunning());
}

void TestSimulatedPlc::detailStatus()
{
    SimulatedPlc plc;
    const Response r = plc.execute(Request::detailStatus(S));
    QCOMPARE(r.errorCode, std::uint8_t{0});
    QCOMPARE(r.data.size(), std::size_t{64});
    const DetailStatus d = DetailStatus::decode(r.data);
    QVERIFY(d.status.running);
    QCOMPARE(d.mainUnitType, std::optional<std::uint8_t>{1});    // MC
    QCOMPARE(d.ioPointsCode, std::optional<std::uint8_t>{2});    // 28 points
    QCOMPARE(d.osVersion, std::optional<std::uint8_t>{0x31});    // V3.1
    QCOMPARE(d.ladderSize, std::optional<std::uint16_t>{13184}); // 13K
    QCOMPARE(d.discreteInputs, std::optional<std::uint16_t>{256});
    QCOMPARE(d.mRelays, std::optional<std::uint16_t>{2002});
    QCOMPARE(d.rRegisters, std::optional<std::uint16_t>{3840});
    QCOMPARE(d.dRegisters, std::optional<std::uint16_t>{3000});
    QCOMPARE(plc.detailStatusBytes(), r.data);
    // One reading of STATUS2..4 for the GUI, the CLI and the summary.
    QCOMPARE(d.ioPoints(), std::optional<int>{28});
    QCOMPARE(d.osVersionText(), std::optional<std::string>{"V3.1"});
    QCOMPARE(d.modelName(), std::optional<std::string>{"FBs-28MC"});
    QCOMPARE(d.summary(), std::string("FBs-28MC, OS V3.1, program 13184 words"));
    DetailStatus odd = d;
    odd.osVersion = 0x4A; // not BCD
    odd.ioPointsCode = 7;
    QCOMPARE(odd.osVersionText(), std::nullopt);
    QCOMPARE(odd.ioPoints(), std::nullopt);
    QCOMPARE(odd.modelName(), std::nullopt);
    QCOMPARE(odd.summary(),
             std::string("main unit MC, I/O code 7, OS code 74, program 13184 words"));
    odd.osVersion = 0x25;
    QCOMPARE(odd.osVersionText(), std::optional<std::string>{"V2.5"});
}

void TestSimulatedPlc::forcing()
{
    SimulatedPlc plc;
    const Address y0 = addr("Y0");
    // Not disabled: the ladder drives Y0 (on during the first half second).
    plc.scan(100);
    QCOMPARE(plc.value(y0), std::optional<std::uint32_t>{1});

    QCOMPARE(plc.execute(Request::discreteControl(S, DiscreteOp::Disable, y0)).errorCode,
             std::uint8_t{0});
    QCOMPARE(plc.isDisabled(y0), std::optional<bool>{true});
    QCOMPARE(plc.execute(Request::discreteControl(S, DiscreteOp::Reset, y0)).errorCode,
             std::uint8_t{0});
    plc.scan(200); // ladder wants 1
    QCOMPARE(plc.value(y0), std::optional<std::uint32_t>{0});
    QCOMPARE(plc.execute(Request::discreteControl(S, DiscreteOp::Set, y0)).errorCode,
             std::uint8_t{0});
    plc.scan(700); // ladder wants 0
    QCOMPARE(plc.value(y0), std::optional<std::uint32_t>{1});

    // A disabled input stays put too, while its neighbours follow the pattern.
    plc.execute(Request::discreteControl(S, DiscreteOp::Disable, addr("X3")));
    plc.execute(Request::discreteControl(S, DiscreteOp::Reset, addr("X3")));
    plc.scan(3 * 250);
    QCOMPARE(plc.value(addr("X3")), std::optional<std::uint32_t>{0});
    plc.scan(2 * 250);
    QCOMPARE(plc.value(addr("X2")), std::optional<std::uint32_t>{1});

    // Enabled again: the ladder takes over at the next scan.
    QCOMPARE(plc.execute(Request::discreteControl(S, DiscreteOp::Enable, y0)).errorCode,
             std::uint8_t{0});
    QCOMPARE(plc.isDisabled(y0), std::optional<bool>{false});
    plc.scan(1700);
    QCOMPARE(plc.value(y0), std::optional<std::uint32_t>{0});
}

void TestSimulatedPlc::readEnableFlags()
{
    SimulatedPlc plc;
    for (const char *a : {"Y10", "Y12", "Y16"})
        plc.execute(Request::discreteControl(S, DiscreteOp::Disable, addr(a)));
    const Response r = plc.execute(Request::readEnableFlags(S, addr("Y10"), 7));
    QCOMPARE(r.errorCode, std::uint8_t{0});
    QCOMPARE(r.values, (std::vector<std::uint32_t>{1, 0, 1, 0, 0, 0, 1}));
    // 256 points in one request (count 256 is sent as 0 on the wire).
    QCOMPARE(plc.execute(Request::readEnableFlags(S, addr("M0"), 256)).values.size(),
             std::size_t{256});
}

void TestSimulatedPlc::demoLadder()
{
    SimulatedPlc plc;
    plc.scan(0);
    plc.scan(10);
    plc.scan(2500); // a quarter of the 10 s sine period
    QCOMPARE(plc.scanCount(), std::uint64_t{3});
    QCOMPARE(plc.value(addr("R0")), std::optional<std::uint32_t>{3});
    QCOMPARE(plc.value(addr("R1")), std::optional<std::uint32_t>{1000});
    plc.scan(7500);
    QCOMPARE(plc.value(addr("R1")),
             std::optional<std::uint32_t>{static_cast<std::uint16_t>(-1000)});
    plc.scan(12345);
    QCOMPARE(plc.value(addr("DR10")), std::optional<std::uint32_t>{1234});
    QCOMPARE(plc.value(addr("Y0")), std::optional<std::uint32_t>{1});
    plc.scan(12845);
    QCOMPARE(plc.value(addr("Y0")), std::optional<std::uint32_t>{0});
    plc.scan(5 * 250);
    QCOMPARE(plc.value(addr("WX0")), std::optional<std::uint32_t>{1u << 5});
}

void TestSimulatedPlc::ladderStopsInStop()
{
    SimulatedPlc plc;
    plc.scan(100);
    QCOMPARE(plc.execute(Request::runStop(S, false)).errorCode, std::uint8_t{0});
    const auto r0 = plc.value(addr("R0"));
    plc.scan(110);
    plc.scan(900);
    QCOMPARE(plc.value(addr("R0")), r0);
    QCOMPARE(plc.value(addr("Y0")), std::optional<std::uint32_t>{1});
    QCOMPARE(plc.scanCount(), std::uint64_t{1});
}

void TestSimulatedPlc::programPages()
{
    SimulatedPlc plc;
    std::vector<std::uint32_t> page(64);
    for (std::uint32_t i = 0; i < 64; ++i)
        page[i] = 0xF000 + i;
    // Power-on: page 0 is the FBs header ("FB13", 13184 words, 0xFF to the end), page 1 is not
    // empty, the pages after the demo ladder are.
    const std::vector<std::uint32_t> header = plc.programPage(0);
    QCOMPARE(header.size(), std::size_t{64});
    QCOMPARE(header[0], std::uint32_t{0x4642});
    QCOMPARE(header[1], std::uint32_t{0x3133});
    QCOMPARE(header[2], std::uint32_t{0x3380});
    QCOMPARE(header[63], std::uint32_t{0xFFFF});
    QVERIFY(plc.programPage(1) != std::vector<std::uint32_t>(64, 0));
    QCOMPARE(SimulatedPlc(ModelProfile::mSeries()).programPage(0)[0], std::uint32_t{0x464D});
    // 50 cannot execute in RUN (error 4), and changes nothing.
    QVERIFY(plc.isRunning());
    QCOMPARE(plc.execute(Request::writeProgram(S, 206, page)).errorCode, std::uint8_t{4});
    QCOMPARE(plc.programPage(206), std::vector<std::uint32_t>(64, 0));
    plc.setRunning(false);
    QCOMPARE(plc.execute(Request::writeProgram(S, 206, page)).errorCode, std::uint8_t{0});
    const Response r = plc.execute(Request::readProgram(S, 206));
    QCOMPARE(r.errorCode, std::uint8_t{0});
    QCOMPARE(r.values, page);
    QCOMPARE(plc.execute(Request::readProgram(S, 205)).values, std::vector<std::uint32_t>(64, 0));
    QCOMPARE(plc.programPage(206), page);
    QVERIFY(plc.programPage(207).empty());
    QCOMPARE(plc.execute(Request::writeProgram(S, 207, page)).errorCode, std::uint8_t{0xA});
}

void TestSimulatedPlc::loopback()
{
    SimulatedPlc plc;
    const Bytes data = {'H', 'e', 'l', 'l', 'o'};
    const Response r = plc.execute(Request::loopback(S, data));
    QCOMPARE(r.errorCode, std::uint8_t{0});
    QCOMPARE(r.data, data);
    QCOMPARE(plc.execute(Request::loopback(S, {})).data, Bytes{});
}

void TestSimulatedPlc::mixedReadWrite()
{
    SimulatedPlc plc(ModelProfile::mSeries());
    const std::vector<Address> list
        = {addr("Y9"), addr("R70"), addr("DWM16"), addr("F100"), addr("DF2")};
    QCOMPARE(plc.execute(Request::mixedWrite(S, list, {1, 0xBEEF, 0x00010002, 7, 0xCAFEF00D}),
                         Protocol::Binary)
                 .errorCode,
             std::uint8_t{0});
    const Response r = plc.execute(Request::mixedRead(S, list), Protocol::Binary);
    QCOMPARE(r.values, (std::vector<std::uint32_t>{1, 0xBEEF, 0x00010002, 7, 0xCAFEF00D}));
    QCOMPARE(plc.value(addr("M17")), std::optional<std::uint32_t>{1});
    QCOMPARE(plc.value(addr("M32")), std::optional<std::uint32_t>{1});
    QCOMPARE(plc.value(addr("F3")), std::optional<std::uint32_t>{0xCAFE});
    // F is binary only: the same request in FACON names an element FACON cannot address.
    QCOMPARE(plc.execute(Request::mixedRead(S, list), Protocol::Facon).errorCode,
             std::uint8_t{0xA});
    // 64 words: the largest mixed read.
    QCOMPARE(
        plc.execute(Request::mixedRead(S, std::vector<Address>(32, addr("DR0")))).values.size(),
        std::size_t{32});
}

void TestSimulatedPlc::clearBackToPowerOn_data()
{
    QTest::addColumn<QString>("profile");
    QTest::newRow("fbs") << "fbs";
    QTest::newRow("m") << "m";
}

// clear() (the fuzzer calls it before every input) zeroes only the kinds written since the last
// clear() and copies the program back only when it was written: after any mix of writes, every
// element, flag and program word must read as on a PLC just powered on, the second time too.
void TestSimulatedPlc::clearBackToPowerOn()
{
    QFETCH(QString, profile);
    const ModelProfile p = *ModelProfile::byName(profile.toStdString());
    const SimulatedPlc fresh(p);
    SimulatedPlc plc(p);
    constexpr std::array<ElementType, 6> discretes
        = {ElementType::X, ElementType::Y, ElementType::M,
           ElementType::S, ElementType::T, ElementType::C};
    constexpr std::array<ElementType, 5> registers
        = {ElementType::RT, ElementType::RC, ElementType::R, ElementType::D, ElementType::F};
    auto samePowerOn = [&] {
        for (ElementType t : discretes) {
            for (std::uint32_t n = 0; n < p.size(t); ++n) {
                const Address a{t, n};
                if (plc.value(a) != std::optional<std::uint32_t>{0}
                    || plc.isDisabled(a) != std::optional<bool>{false})
                    return false;
            }
        }
        for (ElementType t : registers) {
            for (std::uint32_t n = 0; n < p.size(t); ++n) {
                if (plc.value(Address{t, n}) != std::optional<std::uint32_t>{0})
                    return false;
            }
        }
        for (std::uint16_t page = 0; page < p.programPages(); ++page) {
            if (plc.programPage(page) != fresh.programPage(page))
                return false;
        }
        return plc.scanCount() == 0;
    };
    QVERIFY(samePowerOn());

    // Every kind at both ends, flags, the ladder, a program page by 50 and one set directly.
    for (ElementType t : discretes) {
        QVERIFY(plc.setValue(Address{t, 0}, 1));
        QVERIFY(plc.setValue(Address{t, p.size(t) - 1}, 1));
        QVERIFY(plc.setDisabled(Address{t, p.size(t) - 1}, true));
    }
    for (ElementType t : registers) {
        if (p.size(t) == 0)
            continue;
        QVERIFY(plc.setValue(Address{t, 0}, 0xFFFF));
        QVERIFY(plc.setValue(Address{t, p.size(t) - 1}, 0x1234));
    }
    plc.scan(123);
    plc.setRunning(false);
    QCOMPARE(
        plc.execute(Request::writeProgram(S, 1, std::vector<std::uint32_t>(64, 0xABCD))).errorCode,
        std::uint8_t{0});
    QVERIFY(plc.setProgramPage(2, std::vector<std::uint32_t>(64, 0x5555)));
    QVERIFY(!samePowerOn());
    plc.clear();
    QVERIFY(samePowerOn());
    QVERIFY(!plc.isRunning()); // STOP stays as it is

    // Written again after a clear(): the next clear() must zero it again.
    QVERIFY(plc.setValue(addr("DR100"), 0xDEADBEEF));
    QVERIFY(plc.setValue(addr("WY16"), 0x8001));
    QVERIFY(plc.setDisabled(addr("M7"), true));
    QCOMPARE(plc.execute(Request::discreteControl(S, DiscreteOp::Set, addr("S3"))).errorCode,
             std::uint8_t{0});
    std::vector<std::uint16_t> program(std::size_t{p.programPages()} * 64, 0x7777);
    QVERIFY(plc.setProgram(program));
    QVERIFY(!samePowerOn());
    plc.clear();
    QVERIFY(samePowerOn());
    plc.clear(); // nothing written: still power-on
    QVERIFY(samePowerOn());
}

QTEST_APPLESS_MAIN(TestSimulatedPlc)
#include "tst_simulatedplc.moc"
