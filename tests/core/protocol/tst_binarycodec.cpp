#include "core/protocol/binarycodec.h"
#include "testutil.h"

#include <QTest>

#include <random>

Q_DECLARE_METATYPE(Fatek::Request)
Q_DECLARE_METATYPE(Fatek::Bytes)

using namespace Fatek;
using TestUtil::fromHex;
using TestUtil::toHex;

namespace {

using E = ElementType;

Address addr(ElementType type, std::uint32_t number)
{
    return Address{type, number};
}

QString qs(const std::string &s)
{
    return QString::fromStdString(s);
}

// A frame with a correct CRC around `payload`, built independently of the codec.
Bytes frame(std::uint8_t header, const Bytes &payload)
{
    Bytes out{header, 0x10, static_cast<std::uint8_t>(payload.size() >> 8),
              static_cast<std::uint8_t>(payload.size())};
    out.insert(out.end(), payload.begin(), payload.end());
    std::uint16_t crc = 0xFFFF;
    for (std::size_t i = 2; i < out.size(); ++i) {
        crc = static_cast<std::uint16_t>(crc ^ out[i]);
        for (int b = 0; b < 8; ++b)
            crc = static_cast<std::uint16_t>((crc & 1u) ? (crc >> 1) ^ 0xA001u : crc >> 1);
    }
    out.push_back(static_cast<std::uint8_t>(crc & 0xFF));
    out.push_back(static_cast<std::uint8_t>(crc >> 8));
    out.push_back(0x55);
    out.push_back(0xAA);
    return out;
}

Bytes query(const Bytes &payload)
{
    return frame(0x51, payload);
}
Bytes answerFrame(const Bytes &payload)
{
    return frame(0x52, payload);
}

Response answer(const Request &r, std::vector<std::uint32_t> values = {}, Bytes data = {})
{
    Response resp;
    resp.station = r.station;
    resp.command = r.command;
    resp.values = std::move(values);
    resp.data = std::move(data);
    return resp;
}

struct VectorCase
{
    Request request;
    std::optional<Response> response; // nullopt: the vector answers a PLC error
    int plcError = 0;
    QString inMessage; // for PLC errors: text the message must contain
};

// Typed meaning of each binary vector, in the order of vectors.json (the test checks the query
// bytes, so a reordered file fails loudly instead of comparing the wrong frames).
std::vector<VectorCase> vectorCases()
{
    std::vector<VectorCase> c;
    auto ok = [&c](Request r, std::vector<std::uint32_t> values = {}, Bytes data = {}) {
        Response resp = answer(r, std::move(values), std::move(data));
        c.push_back({std::move(r), std::move(resp), 0, {}});
    };
    auto fail = [&c](Request r, int code, QString text) {
        c.push_back({std::move(r), std::nullopt, code, text});
    };

    ok(Request::briefStatus(1), {}, {0x29, 0x00, 0x00});
    ok(Request::briefStatus(1), {}, {0x01, 0x00, 0x00});
    ok(Request::runStop(1, false));
    ok(Request::runStop(1, true));
    ok(Request::discreteControl(1, DiscreteOp::Disable, addr(E::X, 16)));
    ok(Request::readEnableFlags(1, addr(E::Y, 10), 7), {1, 0, 1, 0, 0, 0, 1});
    ok(Request::readEnableFlags(1, addr(E::X, 0), 4), {1, 1, 1, 1});
    ok(Request::readDiscretes(1, addr(E::X, 50), 6), {0, 1, 0, 1, 1, 0});
    ok(Request::readDiscretes(1, addr(E::Y, 0), 15), std::vector<std::uint32_t>(15, 0));
    ok(Request::writeDiscretes(1, addr(E::Y, 0), {1, 0, 0, 1}));
    ok(Request::writeDiscretes(1, addr(E::Y, 0), {0, 1, 0}));
    ok(Request::readRegisters(1, addr(E::R, 12), 3), {0x10A5, 0x7FC4, 0x0001});
    ok(Request::readRegisters(1, addr(E::R, 0), 2), {0xFF55, 0xFF4B});
    ok(Request::writeRegisters(1, addr(E::WY, 16), {0xAAAA, 0x5555}));
    ok(Request::writeRegisters(1, addr(E::R, 0), {0xFF55, 0xFF4B, 0xFF41}));
    ok(Request::mixedRead(1, {addr(E::R, 1), addr(E::Y, 9), addr(E::DWM, 0)}),
       {0x5C34, 1, 0x003547BA});
    ok(Request::mixedRead(1, {addr(E::DR, 15), addr(E::D, 1)}), {0x99990000u, 0x0000});
    ok(Request::mixedWrite(1, {addr(E::Y, 0), addr(E::Y, 1), addr(E::WM, 8), addr(E::DR, 2)},
                           {1, 0, 0x5555, 0xFF}));
    ok(Request::mixedWrite(1, {addr(E::DR, 0), addr(E::R, 15)}, {0, 0xFF}));
    ok(Request::loopback(1, {'A', 'B', 'C', 'D', 'E', 'F', 'G'}), {},
       {'A', 'B', 'C', 'D', 'E', 'F', 'G'});
    ok(Request::loopback(1, {0xFF, 0xFF}), {}, {0xFF, 0xFF});
    fail(Request::readRegisters(1, addr(E::R, 0), 1), 0xA,
         QStringLiteral("PLC error A: illegal address R0"));
    fail(Request::runStop(1, true), 5, QStringLiteral("PLC error 5"));
    return c;
}

// One request of every command the binary protocol has, with an answer a PLC could give.
struct RoundTrip
{
    const char *name;
    Request request;
    Response response;
};

std::vector<RoundTrip> everyCommand()
{
    std::vector<RoundTrip> t;
    auto add = [&t](const char *name, Request r, std::vector<std::uint32_t> values = {},
                    Bytes data = {}) {
        Response resp = answer(r, std::move(values), std::move(data));
        t.push_back({name, std::move(r), std::move(resp)});
    };
    add("40", Request::briefStatus(7), {}, {0x01, 0x00, 0x00});
    add("41 run", Request::runStop(254, true));
    add("41 stop", Request::runStop(3, false));
    add("42 enable", Request::discreteControl(1, DiscreteOp::Enable, addr(E::M, 9999)));
    add("42 set", Request::discreteControl(1, DiscreteOp::Set, addr(E::S, 5)));
    add("42 reset", Request::discreteControl(1, DiscreteOp::Reset, addr(E::T, 300)));
    add("43 256", Request::readEnableFlags(1, addr(E::C, 0), 256),
        std::vector<std::uint32_t>(256, 1));
    add("44 1", Request::readDiscretes(2, addr(E::M, 1000), 1), {1});
    add("44 256", Request::readDiscretes(2, addr(E::X, 100), 256),
        std::vector<std::uint32_t>(256, 0));
    add("45 256", Request::writeDiscretes(1, addr(E::Y, 0), std::vector<std::uint32_t>(256, 1)));
    add("46 RT", Request::readRegisters(1, addr(E::RT, 5), 4), {1, 2, 3, 0xFFFF});
    add("46 64 D", Request::readRegisters(1, addr(E::D, 100), 64),
        std::vector<std::uint32_t>(64, 0x1234));
    add("46 32 DD", Request::readRegisters(1, addr(E::DD, 0), 32),
        std::vector<std::uint32_t>(32, 0x89ABCDEFu));
    add("46 DWY", Request::readRegisters(1, addr(E::DWY, 32), 2), {0xFFFFFFFFu, 0});
    add("47 F", Request::writeRegisters(1, addr(E::F, 65535), {0xBEEF}));
    add("47 DRC", Request::writeRegisters(1, addr(E::DRC, 10), {0x01020304, 0xA0B0C0D0u}));
    add("47 64 WM",
        Request::writeRegisters(1, addr(E::WM, 0), std::vector<std::uint32_t>(64, 0x5A5A)));
    add("48 all kinds",
        Request::mixedRead(1, {addr(E::X, 1), addr(E::WC, 16), addr(E::DF, 4), addr(E::RC, 7)}),
        {1, 0x1111, 0x22223333, 0x4444});
    add("49 all kinds",
        Request::mixedWrite(1, {addr(E::C, 2), addr(E::WT, 8), addr(E::DRT, 0), addr(E::F, 1)},
                            {0, 0x1111, 0x22223333, 0x4444}));
    add("4E empty", Request::loopback(1, {}), {}, {});
    Bytes all(256);
    for (std::size_t i = 0; i < all.size(); ++i)
        all[i] = static_cast<std::uint8_t>(i);
    add("4E 256", Request::loopback(1, all), {}, all);
    add("53", Request::detailStatus(1), {}, {0x01, 0x00, 0x02, 0x31, 0x33, 0x80});
    add("53 empty", Request::detailStatus(1), {}, {});
    add("broadcast 47", Request::writeRegisters(0, addr(E::R, 1), {5}));
    return t;
}

} // namespace

class TestBinaryCodec : public QObject
{
    Q_OBJECT

private slots:
    void crcReference();
    void vectors_data();
    void vectors();
    void dAndDrOverlap();
    void everyElementRoundTrips();
    void everyCommandRoundTrips_data();
    void everyCommandRoundTrips();
    void limitsRejectedBeforeSending_data();
    void limitsRejectedBeforeSending();
    void limitsAtTheBoundaryAccepted_data();
    void limitsAtTheBoundaryAccepted();
    void mismatchesAreNeverValues();
    void brokenFrames_data();
    void brokenFrames();
    void malformedAnswers_data();
    void malformedAnswers();
    void plcErrorsNameWhatWasAsked_data();
    void plcErrorsNameWhatWasAsked();
    void slaveDecodeErrors_data();
    void slaveDecodeErrors();
    void wrapHeaderAndErrorAnswer();
    void summaries();
    void fuzzNeverCrashesAndReencodes();
};

void TestBinaryCodec::crcReference()
{
    const Bytes covered = fromHex(QStringLiteral("00 02 01 40"));
    QCOMPARE(BinaryCodec::crc16(covered), std::uint16_t(0x84A1));
    // CRC-16/MODBUS catalogue check value.
    const Bytes check = {'1', '2', '3', '4', '5', '6', '7', '8', '9'};
    QCOMPARE(BinaryCodec::crc16(check), std::uint16_t(0x4B37));
    const auto encoded = BinaryCodec().encodeRequest(Request::briefStatus(1));
    QVERIFY(encoded.ok());
    QCOMPARE(toHex(*encoded), QStringLiteral("51 10 00 02 01 40 A1 84 55 AA"));
}

void TestBinaryCodec::vectors_data()
{
    QTest::addColumn<int>("index");
    const auto vectors = TestUtil::loadVectors(QStringLiteral("binary"));
    const auto cases = vectorCases();
    QCOMPARE(std::size_t(vectors.size()), cases.size());
    for (int i = 0; i < vectors.size(); ++i)
        QTest::newRow(qPrintable(vectors[i].what)) << i;
}

void TestBinaryCodec::vectors()
{
    QFETCH(int, index);
    const auto vector = TestUtil::loadVectors(QStringLiteral("binary")).at(index);
    const VectorCase c = vectorCases().at(std::size_t(index));
    BinaryCodec codec;

    const auto encoded = codec.encodeRequest(c.request);
    QVERIFY2(encoded.ok(), encoded.ok() ? "" : encoded.error().text().c_str());
    QCOMPARE(toHex(*encoded), toHex(vector.query));

    const auto decodedQuery = codec.decodeRequest(vector.query);
    QVERIFY2(decodedQuery.ok(), decodedQuery.ok() ? "" : decodedQuery.error().text().c_str());
    QVERIFY(*decodedQuery == c.request);

    const auto decoded = codec.decodeResponse(vector.response, c.request);
    if (c.response) {
        QVERIFY2(decoded.ok(), decoded.ok() ? "" : decoded.error().text().c_str());
        QCOMPARE(decoded->station, c.response->station);
        QVERIFY(decoded->command == c.response->command);
        QCOMPARE(decoded->values, c.response->values);
        QCOMPARE(decoded->data, c.response->data);
        QCOMPARE(toHex(codec.encodeResponse(c.request, *c.response)), toHex(vector.response));
    } else {
        QVERIFY(!decoded.ok());
        QVERIFY(decoded.error().kind == ErrorKind::PlcError);
        QCOMPARE(decoded.error().plcCode, c.plcError);
        QVERIFY2(qs(decoded.error().text()).contains(c.inMessage), decoded.error().text().c_str());
        Response error = answer(c.request);
        error.errorCode = static_cast<std::uint8_t>(c.plcError);
        QCOMPARE(toHex(codec.encodeResponse(c.request, error)), toHex(vector.response));
    }

    const auto header = codec.frameHeader(vector.query);
    QVERIFY(header.has_value());
    QCOMPARE(header->station, c.request.station);
    QCOMPARE(header->command, static_cast<std::uint8_t>(c.request.command));
}

void TestBinaryCodec::dAndDrOverlap()
{
    BinaryCodec codec;
    // D20992 = D 0x5200: its bytes 44 52 00 begin like DR.
    const std::vector<Request> requests = {
        Request::readRegisters(1, addr(E::D, 0x5200), 1),
        Request::readRegisters(1, addr(E::D, 0x5210), 3),
        Request::writeRegisters(1, addr(E::D, 0x5201), {0x4452, 0x0001}),
        Request::writeRegisters(1, addr(E::DR, 0x5200), {0x44520000}),
        Request::mixedRead(1, {addr(E::D, 0x5200)}),
        Request::mixedRead(1, {addr(E::D, 0x5200), addr(E::R, 5)}),
        Request::mixedRead(1, {addr(E::R, 5), addr(E::D, 0x5200), addr(E::Y, 3)}),
        Request::mixedWrite(1, {addr(E::D, 0x5200), addr(E::DR, 4)}, {0x4452, 2}),
        Request::mixedWrite(1, {addr(E::DD, 0x5200), addr(E::D, 0x5244)}, {0x44524452, 0x4452}),
        Request::readRegisters(1, addr(E::DR, 0x0012), 2),
    };
    for (const Request &r : requests) {
        const auto encoded = codec.encodeRequest(r);
        QVERIFY2(encoded.ok(), encoded.ok() ? "" : encoded.error().text().c_str());
        const auto decoded = codec.decodeRequest(*encoded);
        QVERIFY2(decoded.ok(), qPrintable(toHex(*encoded)));
        QVERIFY2(*decoded == r, qPrintable(qs(r.describe()) + QStringLiteral(" came back as ")
                                           + qs(decoded->describe())));
    }
    // The payload of "D20992" starts with the bytes of "DR": make sure the test above meant it.
    const auto encoded = codec.encodeRequest(requests[0]);
    QCOMPARE(toHex(*encoded).mid(3 * 7, 8), QStringLiteral("44 52 00"));

    // Some mixed lists are truly ambiguous on the wire: D21060, D20992, DR17490 gives the same
    // bytes as DR17476, R68, R17490. The longest symbol wins, as the reference says.
    const auto ambiguous = codec.encodeRequest(
        Request::mixedRead(1, {addr(E::D, 0x5244), addr(E::D, 0x5200), addr(E::DR, 0x4452)}));
    QVERIFY(ambiguous.ok());
    const auto parsed = codec.decodeRequest(*ambiguous);
    QVERIFY(parsed.ok());
    QVERIFY(parsed->addresses
            == (std::vector<Address>{addr(E::DR, 0x4444), addr(E::R, 0x44), addr(E::R, 0x4452)}));
}

void TestBinaryCodec::everyElementRoundTrips()
{
    BinaryCodec codec;
    std::mt19937 random(7);
    for (const ElementInfo &info : allElements()) {
        std::vector<Request> requests;
        const Address first{info.type, 0};
        const Address end{info.type,
                          info.maxNumber / info.alignment * info.alignment}; // highest valid
        const std::uint32_t full = info.width == ElementWidth::DoubleWord ? 0xFFFFFFFFu
                                   : info.width == ElementWidth::Word     ? 0xFFFFu
                                                                          : 1u;
        if (info.width == ElementWidth::Bit) {
            requests.push_back(Request::discreteControl(1, DiscreteOp::Set, end));
            requests.push_back(Request::readEnableFlags(1, first, 3));
            requests.push_back(Request::readDiscretes(1, end, 1));
            requests.push_back(Request::writeDiscretes(1, first, {1, 0, 1}));
        } else {
            requests.push_back(Request::readRegisters(1, first, 2));
            requests.push_back(Request::readRegisters(1, end, 1));
            requests.push_back(Request::writeRegisters(1, first, {full, full / 3}));
        }
        requests.push_back(Request::mixedRead(1, {first, end}));
        requests.push_back(Request::mixedWrite(1, {end, first}, {full, 0}));
        for (const Request &r : requests) {
            const auto encoded = codec.encodeRequest(r);
            QVERIFY2(encoded.ok(), encoded.ok() ? "" : encoded.error().text().c_str());
            const auto decoded = codec.decodeRequest(*encoded);
            QVERIFY2(decoded.ok(), decoded.ok() ? "" : decoded.error().text().c_str());
            QVERIFY2(*decoded == r, r.describe().c_str());

            // Answers carry the element's width.
            std::vector<std::uint32_t> values;
            for (std::uint32_t i = 0; i < r.expectedValueCount(); ++i)
                values.push_back(full == 1 ? random() % 2
                                           : static_cast<std::uint32_t>(random()) & full);
            const Response resp = answer(r, values);
            const auto back = codec.decodeResponse(codec.encodeResponse(r, resp), r);
            QVERIFY2(back.ok(), back.ok() ? "" : back.error().text().c_str());
            QCOMPARE(back->values, values);
        }
    }
}

void TestBinaryCodec::everyCommandRoundTrips_data()
{
    QTest::addColumn<int>("index");
    const auto all = everyCommand();
    for (std::size_t i = 0; i < all.size(); ++i)
        QTest::newRow(all[i].name) << int(i);
}

void TestBinaryCodec::everyCommandRoundTrips()
{
    QFETCH(int, index);
    const RoundTrip t = everyCommand().at(std::size_t(index));
    BinaryCodec codec;
    const auto encoded = codec.encodeRequest(t.request);
    QVERIFY2(encoded.ok(), encoded.ok() ? "" : encoded.error().text().c_str());
    const auto decoded = codec.decodeRequest(*encoded);
    QVERIFY2(decoded.ok(), decoded.ok() ? "" : decoded.error().text().c_str());
    QVERIFY(*decoded == t.request);

    const Bytes answerBytes = codec.encodeResponse(t.request, t.response);
    const auto back = codec.decodeResponse(answerBytes, t.request);
    QVERIFY2(back.ok(), back.ok() ? "" : back.error().text().c_str());
    QVERIFY(*back == t.response);
    // A 256-point count travels as 0.
    if (t.request.count == 256)
        QCOMPARE((*encoded)[6], std::uint8_t(0));
}

void TestBinaryCodec::limitsRejectedBeforeSending_data()
{
    QTest::addColumn<Request>("request");
    QTest::addColumn<int>("kind");
    const int limit = int(ErrorKind::LimitExceeded);
    const std::vector<Address> r65(65, addr(E::R, 1));
    const std::vector<Address> dr33(33, addr(E::DR, 2));
    const std::vector<Address> r33(33, addr(E::R, 1));
    const std::vector<Address> dr17(17, addr(E::DR, 2));
    std::vector<Address> mixed = std::vector<Address>(62, addr(E::Y, 3));
    mixed.push_back(addr(E::DWM, 8)); // 62 + 2 = 64 words: fine; one more word is too many
    mixed.push_back(addr(E::X, 0));

    QTest::newRow("44 257 points") << Request::readDiscretes(1, addr(E::X, 0), 257) << limit;
    QTest::newRow("44 0 points") << Request::readDiscretes(1, addr(E::X, 0), 0) << limit;
    QTest::newRow("43 257 points") << Request::readEnableFlags(1, addr(E::X, 0), 257) << limit;
    QTest::newRow("45 257 values")
        << Request::writeDiscretes(1, addr(E::Y, 0), std::vector<std::uint32_t>(257, 0)) << limit;
    QTest::newRow("46 65 words") << Request::readRegisters(1, addr(E::R, 0), 65) << limit;
    QTest::newRow("46 33 x 32-bit") << Request::readRegisters(1, addr(E::DR, 0), 33) << limit;
    QTest::newRow("47 65 words") << Request::writeRegisters(1, addr(E::R, 0),
                                                            std::vector<std::uint32_t>(65, 0))
                                 << limit;
    QTest::newRow("47 33 x 32-bit")
        << Request::writeRegisters(1, addr(E::DWY, 0), std::vector<std::uint32_t>(33, 0)) << limit;
    QTest::newRow("48 65 words") << Request::mixedRead(1, r65) << limit;
    QTest::newRow("48 33 x 32-bit") << Request::mixedRead(1, dr33) << limit;
    QTest::newRow("48 65 words mixed") << Request::mixedRead(1, mixed) << limit;
    QTest::newRow("49 33 words") << Request::mixedWrite(1, r33, std::vector<std::uint32_t>(33, 0))
                                 << limit;
    QTest::newRow("49 17 x 32-bit")
        << Request::mixedWrite(1, dr17, std::vector<std::uint32_t>(17, 0)) << limit;
    QTest::newRow("4E 257 bytes") << Request::loopback(1, Bytes(257, 0x41)) << limit;
    QTest::newRow("4F FACON only") << Request::readProgram(1, 0) << int(ErrorKind::Unsupported);
    QTest::newRow("50 FACON only") << Request::writeProgram(1, 0, std::vector<std::uint32_t>(64, 0))
                                   << int(ErrorKind::Unsupported);
    QTest::newRow("station 255") << Request::briefStatus(255) << int(ErrorKind::InvalidRequest);
    QTest::newRow("R past 65535") << Request::readRegisters(1, addr(E::R, 65535), 2)
                                  << int(ErrorKind::InvalidAddress);
    QTest::newRow("X10000") << Request::readDiscretes(1, addr(E::X, 10000), 1)
                            << int(ErrorKind::InvalidAddress);
    QTest::newRow("WY unaligned") << Request::readRegisters(1, addr(E::WY, 4), 1)
                                  << int(ErrorKind::InvalidAddress);
    QTest::newRow("46 on discrete")
        << Request::readRegisters(1, addr(E::X, 0), 1) << int(ErrorKind::InvalidRequest);
    QTest::newRow("45 value 2") << Request::writeDiscretes(1, addr(E::Y, 0), {2})
                                << int(ErrorKind::InvalidRequest);
    QTest::newRow("47 16-bit overflow")
        << Request::writeRegisters(1, addr(E::R, 0), {0x10000}) << int(ErrorKind::InvalidRequest);
    QTest::newRow("49 count mismatch")
        << Request::mixedWrite(1, {addr(E::R, 0)}, {}) << int(ErrorKind::InvalidRequest);
}

void TestBinaryCodec::limitsRejectedBeforeSending()
{
    QFETCH(Request, request);
    QFETCH(int, kind);
    const auto encoded = BinaryCodec().encodeRequest(request);
    QVERIFY(!encoded.ok());
    QCOMPARE(int(encoded.error().kind), kind);
    QVERIFY(!encoded.error().text().empty());
}

void TestBinaryCodec::limitsAtTheBoundaryAccepted_data()
{
    QTest::addColumn<Request>("request");
    std::vector<Address> mixed = std::vector<Address>(62, addr(E::Y, 3));
    mixed.push_back(addr(E::DWM, 8));
    std::vector<Address> w64;
    for (std::uint32_t i = 0; i < 64; ++i)
        w64.push_back(addr(E::WX, i * 16));
    QTest::newRow("44 256") << Request::readDiscretes(1, addr(E::X, 0), 256);
    QTest::newRow("46 64 words") << Request::readRegisters(1, addr(E::R, 0), 64);
    QTest::newRow("46 32 x 32-bit") << Request::readRegisters(1, addr(E::DR, 0), 32);
    QTest::newRow("48 64 words mixed") << Request::mixedRead(1, mixed);
    QTest::newRow("48 64 WX (largest query)") << Request::mixedRead(1, w64);
    QTest::newRow("49 32 words") << Request::mixedWrite(1, std::vector<Address>(32, addr(E::R, 9)),
                                                        std::vector<std::uint32_t>(32, 1));
    QTest::newRow("49 16 x 32-bit") << Request::mixedWrite(
        1, std::vector<Address>(16, addr(E::DWC, 8)), std::vector<std::uint32_t>(16, 1));
    QTest::newRow("4E 256 bytes") << Request::loopback(1, Bytes(256, 0x52));
}

void TestBinaryCodec::limitsAtTheBoundaryAccepted()
{
    QFETCH(Request, request);
    BinaryCodec codec;
    const auto encoded = codec.encodeRequest(request);
    QVERIFY2(encoded.ok(), encoded.ok() ? "" : encoded.error().text().c_str());
    QVERIFY(encoded->size() <= BinaryCodec::maxFrameSize);
    const auto decoded = codec.decodeRequest(*encoded);
    QVERIFY2(decoded.ok(), decoded.ok() ? "" : decoded.error().text().c_str());
    QVERIFY(*decoded == request);
}

void TestBinaryCodec::mismatchesAreNeverValues()
{
    BinaryCodec codec;
    const Request r = Request::readRegisters(1, addr(E::R, 12), 3);
    const Bytes values = {0x00, 0x10, 0xA5, 0x7F, 0xC4, 0x00, 0x01};

    Bytes p = {0x02, 0x46};
    p.insert(p.end(), values.begin(), values.end());
    auto decoded = codec.decodeResponse(answerFrame(p), r);
    QVERIFY(!decoded.ok());
    QVERIFY(decoded.error().kind == ErrorKind::StationMismatch);
    QVERIFY2(qs(decoded.error().text()).contains(QLatin1String("station 2")),
             decoded.error().text().c_str());

    p = {0x01, 0x44};
    p.insert(p.end(), values.begin(), values.end());
    decoded = codec.decodeResponse(answerFrame(p), r);
    QVERIFY(!decoded.ok());
    QVERIFY(decoded.error().kind == ErrorKind::CommandMismatch);
    QVERIFY2(qs(decoded.error().text()).contains(QLatin1String("44")),
             decoded.error().text().c_str());

    // A PLC error from another station is still a station mismatch, not a PLC error.
    decoded = codec.decodeResponse(answerFrame({0x05, 0x46, 0x0A}), r);
    QVERIFY(!decoded.ok());
    QVERIFY(decoded.error().kind == ErrorKind::StationMismatch);
}

void TestBinaryCodec::brokenFrames_data()
{
    QTest::addColumn<Bytes>("bytes");
    QTest::addColumn<int>("kind");
    const Bytes good
        = fromHex(QStringLiteral("52 10 00 09 01 46 00 10 A5 7F C4 00 01 88 21 55 AA"));
    const int bad = int(ErrorKind::BadFrame);
    Bytes b = good;
    b[13] ^= 0x01;
    QTest::newRow("bad CRC low") << b << int(ErrorKind::BadChecksum);
    b = good;
    b[14] ^= 0x80;
    QTest::newRow("bad CRC high") << b << int(ErrorKind::BadChecksum);
    b = good;
    b[8] ^= 0x04;
    QTest::newRow("payload bit flipped") << b << int(ErrorKind::BadChecksum);
    b = good;
    b[16] = 0xAB;
    QTest::newRow("bad terminator") << b << bad;
    b = good;
    b[15] = 0x00;
    QTest::newRow("bad terminator first") << b << bad;
    QTest::newRow("truncated") << Bytes(good.begin(), good.end() - 3) << bad;
    QTest::newRow("truncated to header") << Bytes(good.begin(), good.begin() + 4) << bad;
    QTest::newRow("empty") << Bytes{} << bad;
    b = good;
    b[0] = 0x53;
    QTest::newRow("bad header") << b << bad;
    b = good;
    b[1] = 0x11;
    QTest::newRow("bad ID") << b << bad;
    b = good;
    b[3] = 0x0A;
    QTest::newRow("length too big") << b << bad;
    b = good;
    b.insert(b.end() - 2, 0x00);
    QTest::newRow("extra byte") << b << bad;
    QTest::newRow("echo of the query") << query({0x01, 0x46, 0x03, 0x52, 0x00, 0x0C}) << bad;
    QTest::newRow("no station/command") << answerFrame({0x01}) << bad;
}

void TestBinaryCodec::brokenFrames()
{
    QFETCH(Bytes, bytes);
    QFETCH(int, kind);
    BinaryCodec codec;
    const auto decoded = codec.decodeResponse(bytes, Request::readRegisters(1, addr(E::R, 12), 3));
    QVERIFY(!decoded.ok());
    QCOMPARE(int(decoded.error().kind), kind);
    QVERIFY(!decoded.error().text().empty());
    QVERIFY(!codec.frameHeader(bytes).has_value() || kind == int(ErrorKind::BadFrame));
    QVERIFY(!codec.summarize(bytes).empty());
}

void TestBinaryCodec::malformedAnswers_data()
{
    QTest::addColumn<Request>("request");
    QTest::addColumn<Bytes>("payload");
    QTest::addColumn<QString>("inMessage");
    const Request r46 = Request::readRegisters(1, addr(E::R, 12), 3);
    QTest::newRow("46 one byte short")
        << r46 << Bytes{0x01, 0x46, 0x00, 0x10, 0xA5, 0x7F, 0xC4, 0x00} << "5 data bytes";
    QTest::newRow("46 one byte long")
        << r46 << Bytes{0x01, 0x46, 0x00, 1, 2, 3, 4, 5, 6, 7} << "7 data bytes";
    QTest::newRow("46 32-bit width") << Request::readRegisters(1, addr(E::DR, 0), 2)
                                     << Bytes{0x01, 0x46, 0x00, 1, 2, 3, 4} << "instead of 8";
    QTest::newRow("44 byte 02") << Request::readDiscretes(1, addr(E::X, 50), 2)
                                << Bytes{0x01, 0x44, 0x00, 0x01, 0x02} << "X51";
    QTest::newRow("44 too few") << Request::readDiscretes(1, addr(E::X, 50), 2)
                                << Bytes{0x01, 0x44, 0x00, 0x01} << "1 data bytes";
    QTest::newRow("43 byte FF") << Request::readEnableFlags(1, addr(E::Y, 0), 1)
                                << Bytes{0x01, 0x43, 0x00, 0xFF} << "FF";
    QTest::newRow("40 two status bytes")
        << Request::briefStatus(1) << Bytes{0x01, 0x40, 0x00, 0x01, 0x00} << "3 status";
    QTest::newRow("41 with data") << Request::runStop(1, true) << Bytes{0x01, 0x41, 0x00, 0x00}
                                  << "without data";
    QTest::newRow("no error byte") << r46 << Bytes{0x01, 0x46} << "error byte";
    QTest::newRow("48 widths") << Request::mixedRead(
        1, {addr(E::R, 1), addr(E::Y, 9), addr(E::DWM, 0)})
                               << Bytes{0x01, 0x48, 0x00, 0x5C, 0x34, 0x01, 0x00, 0x35, 0x47}
                               << "6 data bytes";
    QTest::newRow("48 discrete 07")
        << Request::mixedRead(1, {addr(E::Y, 9)}) << Bytes{0x01, 0x48, 0x00, 0x07} << "Y9";
    QTest::newRow("4E other data")
        << Request::loopback(1, {'A', 'B'}) << Bytes{0x01, 0x4E, 'A', 'C'} << "differ";
    QTest::newRow("4E shorter") << Request::loopback(1, {'A', 'B'}) << Bytes{0x01, 0x4E, 'A'}
                                << "differ";
}

void TestBinaryCodec::malformedAnswers()
{
    QFETCH(Request, request);
    QFETCH(Bytes, payload);
    QFETCH(QString, inMessage);
    const auto decoded = BinaryCodec().decodeResponse(answerFrame(payload), request);
    QVERIFY(!decoded.ok());
    QVERIFY(decoded.error().kind == ErrorKind::MalformedResponse);
    QVERIFY2(qs(decoded.error().text()).contains(inMessage), decoded.error().text().c_str());
}

void TestBinaryCodec::plcErrorsNameWhatWasAsked_data()
{
    QTest::addColumn<Request>("request");
    QTest::addColumn<int>("code");
    QTest::addColumn<QString>("message");
    QTest::newRow("A on R0") << Request::readRegisters(1, addr(E::R, 0), 1) << 0xA
                             << "PLC error A: illegal address R0";
    QTest::newRow("A on R100..R102") << Request::readRegisters(1, addr(E::R, 100), 3) << 0xA
                                     << "PLC error A: illegal address R100..R102";
    QTest::newRow("2 on write Y0")
        << Request::writeDiscretes(1, addr(E::Y, 0), {1}) << 2 << "PLC error 2: illegal value Y0";
    QTest::newRow("4 on mixed")
        << Request::mixedRead(1, {addr(E::R, 1), addr(E::DWM, 0)}) << 4
        << "PLC error 4: illegal format, or command cannot execute R1, DWM0";
    QTest::newRow("3 on 42") << Request::discreteControl(1, DiscreteOp::Set, addr(E::M, 7)) << 3
                             << "M7";
    QTest::newRow("6 on RUN") << Request::runStop(1, true) << 6
                              << "PLC error 6: cannot RUN: PLC ID differs";
    QTest::newRow("unknown 0x1F") << Request::briefStatus(1) << 0x1F << "31";
}

void TestBinaryCodec::plcErrorsNameWhatWasAsked()
{
    QFETCH(Request, request);
    QFETCH(int, code);
    QFETCH(QString, message);
    BinaryCodec codec;
    const auto decoded = codec.decodeResponse(
        answerFrame({request.station, static_cast<std::uint8_t>(request.command),
                     static_cast<std::uint8_t>(code)}),
        request);
    QVERIFY(!decoded.ok());
    QVERIFY(decoded.error().kind == ErrorKind::PlcError);
    QCOMPARE(decoded.error().plcCode, code);
    QVERIFY2(qs(decoded.error().text()).contains(message), decoded.error().text().c_str());
}

void TestBinaryCodec::slaveDecodeErrors_data()
{
    QTest::addColumn<Bytes>("bytes");
    QTest::addColumn<int>("plcCode");
    Bytes badCrc = query({0x01, 0x46, 0x01, 0x52, 0x00, 0x00});
    badCrc[10] ^= 0xFF;
    QTest::newRow("bad CRC: no answer") << badCrc << 0;
    Bytes badEnd = query({0x01, 0x40});
    badEnd.back() = 0x00;
    QTest::newRow("bad terminator: no answer") << badEnd << 0;
    Bytes badId = query({0x01, 0x40});
    badId[1] = 0x20;
    QTest::newRow("bad ID: no answer") << badId << 0;
    QTest::newRow("answer frame: no answer") << answerFrame({0x01, 0x40, 0x00}) << 0;
    QTest::newRow("truncated: no answer") << Bytes{0x51, 0x10, 0x00, 0x02, 0x01} << 0;
    QTest::newRow("unknown command 4A") << query({0x01, 0x4A}) << 4;
    QTest::newRow("4F FACON only") << query({0x01, 0x4F, 0x00, 0x00}) << 4;
    QTest::newRow("40 with data") << query({0x01, 0x40, 0x00}) << 4;
    QTest::newRow("41 missing byte") << query({0x01, 0x41}) << 4;
    QTest::newRow("41 control 02") << query({0x01, 0x41, 0x02}) << 2;
    QTest::newRow("42 op 05") << query({0x01, 0x42, 0x05, 'Y', 0x00, 0x00}) << 2;
    QTest::newRow("42 on register") << query({0x01, 0x42, 0x03, 'R', 0x00, 0x00}) << 4;
    QTest::newRow("44 unknown element Z") << query({0x01, 0x44, 0x01, 'Z', 0x00, 0x00}) << 0xA;
    QTest::newRow("44 X10000") << query({0x01, 0x44, 0x01, 'X', 0x27, 0x10}) << 0xA;
    QTest::newRow("44 truncated address") << query({0x01, 0x44, 0x01, 'X', 0x00}) << 4;
    QTest::newRow("44 no count") << query({0x01, 0x44}) << 4;
    QTest::newRow("45 value 02") << query({0x01, 0x45, 0x02, 'Y', 0x00, 0x00, 0x01, 0x02}) << 2;
    QTest::newRow("45 values missing") << query({0x01, 0x45, 0x02, 'Y', 0x00, 0x00, 0x01}) << 4;
    QTest::newRow("46 count 0") << query({0x01, 0x46, 0x00, 'R', 0x00, 0x00}) << 4;
    QTest::newRow("46 count 65") << query({0x01, 0x46, 0x41, 'R', 0x00, 0x00}) << 4;
    QTest::newRow("46 33 DR") << query({0x01, 0x46, 0x21, 'D', 'R', 0x00, 0x00}) << 4;
    QTest::newRow("46 WY unaligned") << query({0x01, 0x46, 0x01, 'W', 'Y', 0x00, 0x04}) << 0xA;
    QTest::newRow("46 discrete") << query({0x01, 0x46, 0x01, 'X', 0x00, 0x00}) << 4;
    QTest::newRow("47 R value missing") << query({0x01, 0x47, 0x01, 'R', 0x00, 0x00, 0x12}) << 4;
    QTest::newRow("48 count 0") << query({0x01, 0x48, 0x00}) << 4;
    QTest::newRow("48 short list") << query({0x01, 0x48, 0x02, 'R', 0x00, 0x01}) << 4;
    QTest::newRow("48 unknown element") << query({0x01, 0x48, 0x01, 'Q', 0x00, 0x01}) << 0xA;
    QTest::newRow("48 65 words") << [] {
        Bytes p{0x01, 0x48, 65};
        for (int i = 0; i < 65; ++i)
            p.insert(p.end(), {'R', 0x00, static_cast<std::uint8_t>(i)});
        return query(p);
    }() << 4;
    QTest::newRow("49 value 02") << query({0x01, 0x49, 0x01, 'Y', 0x00, 0x00, 0x02}) << 2;
    QTest::newRow("49 33 words") << [] {
        Bytes p{0x01, 0x49, 33};
        for (int i = 0; i < 33; ++i)
            p.insert(p.end(), {'R', 0x00, static_cast<std::uint8_t>(i), 0x00, 0x01});
        return query(p);
    }() << 4;
    QTest::newRow("4E 257 bytes") << [] {
        Bytes p{0x01, 0x4E};
        p.insert(p.end(), 257, 0x41);
        return query(p);
    }() << 4;
    QTest::newRow("station 255") << query({0xFF, 0x40}) << 4;
}

void TestBinaryCodec::slaveDecodeErrors()
{
    QFETCH(Bytes, bytes);
    QFETCH(int, plcCode);
    const auto decoded = BinaryCodec().decodeRequest(bytes);
    QVERIFY2(!decoded.ok(), decoded.ok() ? decoded->describe().c_str() : "");
    QCOMPARE(decoded.error().plcCode, plcCode);
    QVERIFY(!decoded.error().text().empty());
}

void TestBinaryCodec::wrapHeaderAndErrorAnswer()
{
    BinaryCodec codec;
    const Bytes body = {0x01, 0x46, 0x03, 0x52, 0x00, 0x0C};
    QCOMPARE(toHex(codec.wrap(body)), QStringLiteral("51 10 00 06 01 46 03 52 00 0C 0F 85 55 AA"));
    QCOMPARE(toHex(codec.wrap(Bytes{0x01, 0x46, 0x0A}, true)),
             QStringLiteral("52 10 00 03 01 46 0A C7 E3 55 AA"));
    QCOMPARE(toHex(codec.encodeErrorResponse(FrameHeader{1, 0x46}, 0x0A)),
             QStringLiteral("52 10 00 03 01 46 0A C7 E3 55 AA"));
    QCOMPARE(toHex(codec.encodeErrorResponse(FrameHeader{1, 0x41}, 0x05)),
             QStringLiteral("52 10 00 03 01 41 05 85 D7 55 AA"));

    const auto header
        = codec.frameHeader(fromHex(QStringLiteral("52 10 00 03 01 46 0A C7 E3 55 AA")));
    QVERIFY(header.has_value());
    QCOMPARE(header->station, std::uint8_t(1));
    QCOMPARE(header->command, std::uint8_t(0x46));
    QVERIFY(!codec.frameHeader(fromHex(QStringLiteral("52 10 00 03 01 46 0A C7 E4 55 AA")))
                 .has_value());
    // Unknown commands still have a header (the simulator answers them with error 4).
    const auto unknown = codec.frameHeader(query({0x09, 0x4A}));
    QVERIFY(unknown.has_value());
    QCOMPARE(unknown->station, std::uint8_t(9));
    QCOMPARE(unknown->command, std::uint8_t(0x4A));
}

void TestBinaryCodec::summaries()
{
    BinaryCodec codec;
    auto summary = [&codec](const QString &hex) {
        return qs(codec.summarize(fromHex(hex)));
    };
    QCOMPARE(summary(QStringLiteral("51 10 00 06 01 46 03 52 00 0C 0F 85 55 AA")),
             QStringLiteral("station 1, 46 read consecutive registers: 3 x R12"));
    QCOMPARE(summary(QStringLiteral("52 10 00 03 01 46 0A C7 E3 55 AA")),
             QStringLiteral("station 1, 46 answer: error A (illegal address)"));
    QCOMPARE(summary(QStringLiteral(
                 "51 10 00 0E 01 48 03 52 00 01 59 00 09 44 57 4D 00 00 67 33 55 AA")),
             QStringLiteral("station 1, 48 mixed read: R1, Y9, DWM0"));
    QCOMPARE(summary(QStringLiteral("51 10 00 03 01 41 01 84 14 55 AA")),
             QStringLiteral("station 1, 41 RUN/STOP control: RUN"));
    QCOMPARE(summary(QStringLiteral("52 10 00 09 01 46 00 10 A5 7F C4 00 01 88 21 55 AA")),
             QStringLiteral("station 1, 46 answer: OK, 6 data bytes: 10 A5 7F C4 00 01"));
    QCOMPARE(summary(QStringLiteral("52 10 00 09 01 4E 41 42 43 44 45 46 47 32 79 55 AA")),
             QStringLiteral("station 1, 4E answer: echo of 7 bytes"));
    QVERIFY(summary(QStringLiteral("52 10 00 03 01 46 0A C7 E4 55 AA"))
                .startsWith(QLatin1String("bad binary frame")));
    QVERIFY(qs(codec.summarize(query({0x01, 0x4A}))).contains(QLatin1String("4A unknown command")));
    QVERIFY(qs(codec.summarize(query({0x01, 0x44, 0x01, 'Z', 0, 0})))
                .contains(QLatin1String("Unknown element")));
}

void TestBinaryCodec::fuzzNeverCrashesAndReencodes()
{
    BinaryCodec codec;
    std::mt19937 random(20261123);
    const auto vectors = TestUtil::loadVectors(QStringLiteral("binary"));
    const Request anyRequest = Request::readRegisters(1, addr(E::R, 12), 3);
    int decodedQueries = 0;
    for (int round = 0; round < 20000; ++round) {
        const auto &v = vectors[round % vectors.size()];
        // Mutate the payload and give it a correct CRC so the content parsers are reached.
        Bytes payload(v.query.begin() + 4, v.query.end() - 4);
        const int edits = 1 + int(random() % 3);
        for (int e = 0; e < edits; ++e) {
            const auto kind = random() % 4;
            const auto pos = payload.empty() ? 0 : random() % payload.size();
            const auto byte = static_cast<std::uint8_t>(random());
            if (kind == 0 && !payload.empty())
                payload[pos] = byte;
            else if (kind == 1)
                payload.insert(payload.begin() + std::ptrdiff_t(pos), byte);
            else if (kind == 2 && !payload.empty())
                payload.erase(payload.begin() + std::ptrdiff_t(pos));
            else if (payload.size() > 2)
                payload[2 + random() % (payload.size() - 2)]
                    = static_cast<std::uint8_t>("XYMSTCRDFW"[random() % 10]);
        }
        const Bytes q = query(payload);
        const auto decoded = codec.decodeRequest(q);
        if (decoded.ok()) {
            ++decodedQueries;
            // Whatever parses must be exactly what the codec would send for it.
            const auto again = codec.encodeRequest(*decoded);
            QVERIFY2(again.ok(), again.ok() ? "" : again.error().text().c_str());
            QVERIFY2(*again == q, qPrintable(toHex(q) + QStringLiteral(" -> ") + toHex(*again)));
        } else {
            QVERIFY(!decoded.error().text().empty());
            // Checksum and framing are fine here: only a payload without command goes unanswered.
            QVERIFY2(decoded.error().plcCode != 0 || payload.size() < 2,
                     decoded.error().text().c_str());
        }
        QVERIFY(!codec.summarize(q).empty());

        const Bytes a = answerFrame(payload);
        const auto response = codec.decodeResponse(a, decoded.ok() ? *decoded : anyRequest);
        QVERIFY(response.ok() || !response.error().text().empty());
        QVERIFY(!codec.summarize(a).empty());

        // Raw noise.
        Bytes noise(random() % 40);
        for (auto &b : noise)
            b = static_cast<std::uint8_t>(random());
        if (noise.size() > 1 && random() % 2) {
            noise[0] = 0x51;
            noise[1] = 0x10;
        }
        QVERIFY(!codec.decodeRequest(noise).ok() || noise.size() >= 10);
        (void)codec.decodeResponse(noise, anyRequest);
        (void)codec.frameHeader(noise);
        QVERIFY(!codec.summarize(noise).empty());
    }
    QVERIFY(decodedQueries > 100); // the mutations did reach the successful paths
}

QTEST_APPLESS_MAIN(TestBinaryCodec)
#include "tst_binarycodec.moc"
