#include "core/protocol/faconcodec.h"
#include "testutil.h"

#include <QTest>

#include <random>

using namespace Fatek;
using TestUtil::toFacon;

namespace {

Address addr(ElementType type, std::uint32_t number)
{
    return Address{type, number};
}

Bytes ascii(std::string_view text)
{
    return Bytes(text.begin(), text.end());
}

// A frame with a correct LRC around `body` ("0146010A5"), built independently of the codec.
Bytes frame(std::string_view body)
{
    Bytes out{0x02};
    unsigned sum = 0x02;
    for (char c : body) {
        out.push_back(static_cast<std::uint8_t>(c));
        sum += static_cast<unsigned char>(c);
    }
    static const char digits[] = "0123456789ABCDEF";
    out.push_back(static_cast<std::uint8_t>(digits[(sum >> 4) & 0xF]));
    out.push_back(static_cast<std::uint8_t>(digits[sum & 0xF]));
    out.push_back(0x03);
    return out;
}

QString qs(const std::string &s)
{
    return QString::fromStdString(s);
}

struct VectorCase
{
    std::string_view query; // FACON body of the vector's query, to find the vector
    Request request;
    std::optional<Response> response; // decoded answer; nullopt when the vector answers an error
    int plcError = 0;
};

Response answer(const Request &r, std::vector<std::uint32_t> values = {}, Bytes data = {})
{
    Response resp;
    resp.station = r.station;
    resp.command = r.command;
    resp.values = std::move(values);
    resp.data = std::move(data);
    return resp;
}

std::vector<VectorCase> vectorCases()
{
    using E = ElementType;
    std::vector<VectorCase> cases;
    auto add = [&cases](std::string_view q, Request r, std::optional<Response> resp, int err = 0) {
        cases.push_back({q, std::move(r), std::move(resp), err});
    };
    Request r = Request::briefStatus(1);
    add("0140", r, answer(r, {}, {0x29, 0x00, 0x00}));
    r = Request::runStop(1, true);
    add("01411", r, answer(r));
    r = Request::discreteControl(1, DiscreteOp::Disable, addr(E::X, 16));
    add("01421X0016", r, answer(r));
    r = Request::readEnableFlags(1, addr(E::Y, 10), 7);
    add("014307Y0010", r, answer(r, {1, 0, 1, 0, 0, 0, 1}));
    r = Request::readDiscretes(1, addr(E::X, 50), 6);
    add("014406X0050", r, answer(r, {0, 1, 0, 1, 1, 0}));
    r = Request::writeDiscretes(1, addr(E::Y, 0), {1, 0, 0, 1});
    add("014504Y00001001", r, answer(r));
    r = Request::readRegisters(1, addr(E::R, 12), 3);
    add("014603R00012", r, answer(r, {0x10A5, 0x7FC4, 0x0001}));
    r = Request::writeRegisters(1, addr(E::WY, 8), {0xAAAA, 0x5555});
    add("014702WY0008AAAA5555", r, answer(r));
    r = Request::mixedRead(1, {addr(E::R, 1), addr(E::Y, 9), addr(E::DWM, 0)});
    add("014803R00001Y0009DWM0000", r, answer(r, {0x5C34, 1, 0x003547BA}));
    r = Request::mixedWrite(1, {addr(E::Y, 0), addr(E::Y, 1), addr(E::WM, 8), addr(E::DR, 2)},
                            {1, 0, 0x5555, 0xFF});
    add("014904Y00001Y00010WM00085555DR00002000000FF", r, answer(r));
    r = Request::loopback(1, ascii("ABCDEFG"));
    add("014EABCDEFG", r, answer(r, {}, ascii("ABCDEFG")));
    r = Request::readRegisters(1, addr(E::R, 0), 1);
    add("014601R00000", r, std::nullopt, 0xA);
    r = Request::detailStatus(1);
    add("0153", r, answer(r));
    return cases;
}

Bytes bodyOf(const Bytes &f)
{
    return Bytes(f.begin() + 1, f.end() - 3);
}

} // namespace

class TestFaconCodec : public QObject
{
    Q_OBJECT

private slots:
    void vectors();
    void lrcExample();
    void roundTripEveryElement();
    void roundTripEveryCommand();
    void detailStatusLenient();
    void limits();
    void notInFacon();
    void responseErrors();
    void programPageAnswerForms();
    void plcErrors();
    void lowerCaseHex();
    void decodeRequestErrors();
    void decodeRequestNeverCrashes();
    void errorResponseAndHeader();
    void summarize();

private:
    FaconCodec m_codec;
};

void TestFaconCodec::vectors()
{
    const auto vectors = TestUtil::loadVectors(QStringLiteral("facon"));
    const auto cases = vectorCases();
    QCOMPARE(qsizetype(cases.size()), vectors.size());
    for (const TestUtil::Vector &v : vectors) {
        const Bytes body = bodyOf(v.query);
        const std::string_view bodyText(reinterpret_cast<const char *>(body.data()), body.size());
        const auto it = std::find_if(cases.begin(), cases.end(),
                                     [&](const VectorCase &c) { return c.query == bodyText; });
        QVERIFY2(it != cases.end(), qPrintable(QStringLiteral("no case for vector ") + v.what));
        const VectorCase &c = *it;
        const QByteArray what = v.what.toUtf8();

        // encodeRequest gives the vector's bytes exactly.
        const auto encoded = m_codec.encodeRequest(c.request);
        QVERIFY2(encoded.ok(), what.constData());
        QVERIFY2(*encoded == v.query,
                 qPrintable(v.what + QStringLiteral(": ") + toFacon(*encoded)));

        // The simulator side reads the query back into the same typed request.
        const auto decodedQuery = m_codec.decodeRequest(v.query);
        QVERIFY2(decodedQuery.ok(),
                 qPrintable(v.what + QStringLiteral(": ")
                            + (decodedQuery.ok() ? QString() : qs(decodedQuery.error().text()))));
        QVERIFY2(*decodedQuery == c.request, what.constData());

        const auto decoded = m_codec.decodeResponse(v.response, c.request);
        if (c.response) {
            QVERIFY2(decoded.ok(),
                     qPrintable(v.what + QStringLiteral(": ")
                                + (decoded.ok() ? QString() : qs(decoded.error().text()))));
            QCOMPARE(decoded->station, c.response->station);
            QCOMPARE(decoded->command, c.response->command);
            QCOMPARE(decoded->errorCode, std::uint8_t(0));
            QCOMPARE(decoded->values, c.response->values);
            QCOMPARE(decoded->data, c.response->data);
            // The simulator reproduces the vector's answer.
            const Bytes answerBytes = m_codec.encodeResponse(c.request, *c.response);
            QVERIFY2(answerBytes == v.response,
                     qPrintable(v.what + QStringLiteral(": ") + toFacon(answerBytes)));
        } else {
            QVERIFY(!decoded.ok());
            QCOMPARE(decoded.error().kind, ErrorKind::PlcError);
            QCOMPARE(decoded.error().plcCode, c.plcError);
            Response err = answer(c.request);
            err.errorCode = static_cast<std::uint8_t>(c.plcError);
            QCOMPARE(m_codec.encodeResponse(c.request, err), v.response);
        }
    }
}

void TestFaconCodec::lrcExample()
{
    // Reference: STX 0 1 4 0 = 02+30+31+34+30 = C7.
    QCOMPARE(FaconCodec::lrc(Bytes{0x02, 0x30, 0x31, 0x34, 0x30}), std::uint8_t(0xC7));
    QCOMPARE(FaconCodec::lrc(Bytes{0xFF, 0x02}), std::uint8_t(0x01));
    QCOMPARE(m_codec.wrap(ascii("0140")), TestUtil::fromFacon(QStringLiteral("<STX>0140C7<ETX>")));
    // Station in upper-case hex.
    const auto enc = m_codec.encodeRequest(Request::briefStatus(0xFE));
    QVERIFY(enc.ok());
    QCOMPARE(*enc, frame("FE40"));
}

void TestFaconCodec::roundTripEveryElement()
{
    int checked = 0;
    for (const ElementInfo &info : allElements()) {
        if (info.faconDigits == 0)
            continue;
        // Highest start that still leaves room for two elements.
        const Address first{info.type, 0};
        const Address last{info.type, info.maxNumber - info.step};
        for (const Address &a : {first, last}) {
            std::vector<Request> requests;
            std::vector<std::vector<std::uint32_t>> answers;
            if (info.width == ElementWidth::Bit) {
                for (auto op : {DiscreteOp::Disable, DiscreteOp::Enable, DiscreteOp::Set,
                                DiscreteOp::Reset}) {
                    requests.push_back(Request::discreteControl(3, op, a));
                    answers.push_back({});
                }
                requests.push_back(Request::readEnableFlags(3, a, 2));
                answers.push_back({1, 0});
                requests.push_back(Request::readDiscretes(3, a, 2));
                answers.push_back({0, 1});
                requests.push_back(Request::writeDiscretes(3, a, {1, 0}));
                answers.push_back({});
                requests.push_back(Request::mixedRead(3, {a}));
                answers.push_back({1});
                requests.push_back(Request::mixedWrite(3, {a}, {1}));
                answers.push_back({});
            } else {
                const bool dw = info.width == ElementWidth::DoubleWord;
                const std::uint32_t big = dw ? 0xFFFFFFFFu : 0xFFFFu;
                const std::uint32_t mid = dw ? 0x89ABCDEFu : 0x1234u;
                requests.push_back(Request::readRegisters(3, a, 2));
                answers.push_back({big, mid});
                requests.push_back(Request::writeRegisters(3, a, {big, mid}));
                answers.push_back({});
                requests.push_back(Request::mixedRead(3, {a}));
                answers.push_back({mid});
                requests.push_back(Request::mixedWrite(3, {a}, {big}));
                answers.push_back({});
            }
            for (std::size_t i = 0; i < requests.size(); ++i) {
                const Request &r = requests[i];
                const QByteArray what = qs(r.describe()).toUtf8();
                const auto enc = m_codec.encodeRequest(r);
                QVERIFY2(enc.ok(), qPrintable(qs(r.describe()) + QStringLiteral(": ")
                                              + (enc.ok() ? QString() : qs(enc.error().text()))));
                // The fixed-width FACON address is in the frame.
                const std::string text(enc->begin(), enc->end());
                QVERIFY2(text.find(a.toFaconString()) != std::string::npos, what.constData());
                const auto back = m_codec.decodeRequest(*enc);
                QVERIFY2(back.ok(), what.constData());
                QVERIFY2(*back == r, what.constData());

                const Response resp = answer(r, answers[i]);
                const auto decoded = m_codec.decodeResponse(m_codec.encodeResponse(r, resp), r);
                QVERIFY2(decoded.ok(), what.constData());
                QVERIFY2(*decoded == resp, what.constData());
                ++checked;
            }
        }
    }
    QVERIFY(checked > 100);
}

void TestFaconCodec::roundTripEveryCommand()
{
    std::vector<std::uint32_t> page(64);
    for (std::uint32_t i = 0; i < 64; ++i)
        page[i] = (i * 0x0409u) & 0xFFFFu;
    Bytes longData;
    for (int i = 0; i < 256; ++i)
        longData.push_back(static_cast<std::uint8_t>(0x20 + i % 95));

    struct Case
    {
        Request request;
        Response response;
    };
    std::vector<Case> cases;
    auto add = [&cases](Request r, std::vector<std::uint32_t> v = {}, Bytes d = {}) {
        Response resp = answer(r, std::move(v), std::move(d));
        cases.push_back({std::move(r), std::move(resp)});
    };
    add(Request::briefStatus(1), {}, {0x01, 0xFF, 0x00});
    add(Request::runStop(1, false));
    add(Request::runStop(254, true));
    add(Request::discreteControl(1, DiscreteOp::Reset, addr(ElementType::M, 1234)));
    add(Request::readEnableFlags(1, addr(ElementType::S, 0), 256),
        std::vector<std::uint32_t>(256, 1));
    add(Request::readDiscretes(1, addr(ElementType::T, 100), 256),
        std::vector<std::uint32_t>(256, 0));
    add(Request::writeDiscretes(1, addr(ElementType::C, 0), std::vector<std::uint32_t>(256, 1)));
    add(Request::readRegisters(1, addr(ElementType::D, 0), 64),
        std::vector<std::uint32_t>(64, 0xBEEF));
    add(Request::readRegisters(1, addr(ElementType::DD, 0), 32),
        std::vector<std::uint32_t>(32, 0xDEADBEEF));
    add(Request::writeRegisters(1, addr(ElementType::RT, 0), std::vector<std::uint32_t>(64, 7)));
    add(Request::writeRegisters(1, addr(ElementType::DRC, 0),
                                std::vector<std::uint32_t>(32, 0x12345678)));
    add(Request::mixedRead(1, std::vector<Address>(32, addr(ElementType::DR, 10))),
        std::vector<std::uint32_t>(32, 0xCAFEF00D));
    add(Request::mixedWrite(1, std::vector<Address>(16, addr(ElementType::DWY, 8)),
                            std::vector<std::uint32_t>(16, 0x80000001)));
    add(Request::loopback(1, {}), {}, {});
    add(Request::loopback(1, longData), {}, longData);
    add(Request::readProgram(1, 0x1234), page);
    add(Request::writeProgram(1, 206, page));
    add(Request::detailStatus(1), {}, Bytes(64, 0x5A));

    for (const Case &c : cases) {
        const QByteArray what = qs(c.request.describe()).toUtf8();
        const auto enc = m_codec.encodeRequest(c.request);
        QVERIFY2(enc.ok(), qPrintable(qs(c.request.describe()) + QStringLiteral(": ")
                                      + (enc.ok() ? QString() : qs(enc.error().text()))));
        QVERIFY2(enc->size() <= FaconCodec::maxFrameSize, what.constData());
        const auto back = m_codec.decodeRequest(*enc);
        QVERIFY2(back.ok(), what.constData());
        QVERIFY2(*back == c.request, what.constData());
        const Bytes answerBytes = m_codec.encodeResponse(c.request, c.response);
        QVERIFY2(answerBytes.size() <= FaconCodec::maxFrameSize, what.constData());
        const auto decoded = m_codec.decodeResponse(answerBytes, c.request);
        QVERIFY2(decoded.ok(),
                 qPrintable(qs(c.request.describe()) + QStringLiteral(": ")
                            + (decoded.ok() ? QString() : qs(decoded.error().text()))));
        QVERIFY2(*decoded == c.response, what.constData());
    }

    // Layouts the vectors do not cover: N = 00 for 256 points, page as 4 hex, program words.
    QCOMPARE(*m_codec.encodeRequest(Request::readDiscretes(1, addr(ElementType::Y, 0), 256)),
             frame("014400Y0000"));
    QCOMPARE(*m_codec.encodeRequest(Request::readProgram(1, 0x00CE)), frame("014F00CE"));
    QCOMPARE(*m_codec.encodeRequest(Request::runStop(1, false)), frame("01410"));
    QCOMPARE(*m_codec.encodeRequest(
                 Request::discreteControl(1, DiscreteOp::Set, addr(ElementType::Y, 7))),
             frame("01423Y0007"));
    QCOMPARE(*m_codec.encodeRequest(Request::readRegisters(1, addr(ElementType::DRT, 4), 2)),
             frame("014602DRT0004"));
    QCOMPARE(
        *m_codec.encodeRequest(Request::writeRegisters(1, addr(ElementType::DD, 2), {0x1A2B3C4D})),
        frame("014701DD000021A2B3C4D"));
    std::string writePage = "01500003";
    for (int i = 0; i < 64; ++i)
        writePage += "00FF";
    QCOMPARE(
        *m_codec.encodeRequest(Request::writeProgram(1, 3, std::vector<std::uint32_t>(64, 0xFF))),
        frame(writePage));
}

void TestFaconCodec::detailStatusLenient()
{
    const Request r = Request::detailStatus(1);
    for (int n : {0, 21, 28, 64}) {
        std::string body = "01530";
        Bytes expected;
        for (int i = 0; i < n; ++i) {
            body += "1F";
            expected.push_back(0x1F);
        }
        const auto decoded = m_codec.decodeResponse(frame(body), r);
        QVERIFY2(decoded.ok(), qPrintable(QString::number(n)));
        QCOMPARE(decoded->data, expected);
    }
    // The seed's FBE-28MC example, first bytes.
    const auto seed = m_codec.decodeResponse(frame("015302101023133800100"), r);
    QVERIFY(seed.ok());
    QCOMPARE(seed->data, (Bytes{0x21, 0x01, 0x02, 0x31, 0x33, 0x80, 0x01, 0x00}));
    const auto odd = m_codec.decodeResponse(frame("015301F1"), r);
    QVERIFY(!odd.ok());
    QCOMPARE(odd.error().kind, ErrorKind::MalformedResponse);
}

void TestFaconCodec::limits()
{
    using E = ElementType;
    struct Case
    {
        Request request;
        ErrorKind kind;
        const char *mention;
    };
    std::vector<Address> r65(65, addr(E::R, 0));
    std::vector<Address> dr33(33, addr(E::DR, 0));
    std::vector<Address> r63dr1(63, addr(E::R, 0));
    r63dr1.push_back(addr(E::DR, 0));
    std::vector<Address> r33(33, addr(E::R, 0));
    std::vector<Address> dr17(17, addr(E::DR, 0));
    const std::vector<Case> cases = {
        {Request::readEnableFlags(1, addr(E::X, 0), 257), ErrorKind::LimitExceeded, "256"},
        {Request::readDiscretes(1, addr(E::X, 0), 257), ErrorKind::LimitExceeded, "256"},
        {Request::readDiscretes(1, addr(E::X, 0), 0), ErrorKind::LimitExceeded, "256"},
        {Request::writeDiscretes(1, addr(E::Y, 0), std::vector<std::uint32_t>(257, 0)),
         ErrorKind::LimitExceeded, "256"},
        {Request::readRegisters(1, addr(E::R, 0), 65), ErrorKind::LimitExceeded, "64"},
        {Request::readRegisters(1, addr(E::DR, 0), 33), ErrorKind::LimitExceeded, "32"},
        {Request::writeRegisters(1, addr(E::R, 0), std::vector<std::uint32_t>(65, 0)),
         ErrorKind::LimitExceeded, "64"},
        {Request::writeRegisters(1, addr(E::DWM, 0), std::vector<std::uint32_t>(33, 0)),
         ErrorKind::LimitExceeded, "32"},
        {Request::mixedRead(1, r65), ErrorKind::LimitExceeded, "64"},
        {Request::mixedRead(1, dr33), ErrorKind::LimitExceeded, "66"},
        {Request::mixedRead(1, r63dr1), ErrorKind::LimitExceeded, "65"},
        {Request::mixedWrite(1, r33, std::vector<std::uint32_t>(33, 0)), ErrorKind::LimitExceeded,
         "32"},
        {Request::mixedWrite(1, dr17, std::vector<std::uint32_t>(17, 0)), ErrorKind::LimitExceeded,
         "34"},
        {Request::loopback(1, Bytes(257, 'A')), ErrorKind::LimitExceeded, "256"},
        {Request::readRegisters(1, addr(E::R, 65535), 2), ErrorKind::InvalidAddress, "R65535"},
        {Request::readRegisters(1, addr(E::WY, 4), 1), ErrorKind::InvalidAddress, "WY4"},
        {Request::readRegisters(1, addr(E::X, 0), 1), ErrorKind::InvalidRequest, "X0"},
        {Request::writeDiscretes(1, addr(E::Y, 0), {2}), ErrorKind::InvalidRequest, "Y0"},
        {Request::writeRegisters(1, addr(E::R, 0), {0x10000}), ErrorKind::InvalidRequest, "R0"},
        {Request::loopback(1, Bytes{'A', 0x03, 'B'}), ErrorKind::InvalidRequest, "ASCII"},
        {Request::writeProgram(1, 0, std::vector<std::uint32_t>(63, 0)), ErrorKind::InvalidRequest,
         "64"},
        {Request::briefStatus(255), ErrorKind::InvalidRequest, "255"},
    };
    for (const Case &c : cases) {
        const auto enc = m_codec.encodeRequest(c.request);
        QVERIFY2(!enc.ok(), qPrintable(qs(c.request.describe())));
        QCOMPARE(enc.error().kind, c.kind);
        QVERIFY2(enc.error().text().find(c.mention) != std::string::npos,
                 qPrintable(qs(enc.error().text())));
    }

    // The largest legal requests pass.
    std::vector<Address> r62dr1(62, addr(E::R, 0));
    r62dr1.push_back(addr(E::DR, 0));
    const std::vector<Request> fits = {
        Request::readDiscretes(1, addr(E::X, 0), 256),
        Request::writeDiscretes(1, addr(E::Y, 0), std::vector<std::uint32_t>(256, 1)),
        Request::readRegisters(1, addr(E::R, 0), 64),
        Request::readRegisters(1, addr(E::DR, 0), 32),
        Request::mixedRead(1, r62dr1),
        Request::mixedRead(1, std::vector<Address>(32, addr(E::DR, 0))),
        Request::mixedWrite(1, std::vector<Address>(16, addr(E::DR, 0)),
                            std::vector<std::uint32_t>(16, 1)),
        Request::mixedWrite(1, std::vector<Address>(32, addr(E::Y, 0)),
                            std::vector<std::uint32_t>(32, 1)),
        Request::loopback(1, Bytes(256, 'Z')),
    };
    for (const Request &r : fits)
        QVERIFY2(m_codec.encodeRequest(r).ok(), qPrintable(qs(r.describe())));
}

void TestFaconCodec::notInFacon()
{
    using E = ElementType;
    for (const Request &r :
         {Request::readRegisters(1, addr(E::F, 0), 1), Request::readRegisters(1, addr(E::DF, 0), 1),
          Request::writeRegisters(1, addr(E::F, 10), {1}),
          Request::mixedRead(1, {addr(E::R, 0), addr(E::DF, 2)}),
          Request::mixedWrite(1, {addr(E::F, 1)}, {5})}) {
        const auto enc = m_codec.encodeRequest(r);
        QVERIFY(!enc.ok());
        QCOMPARE(enc.error().kind, ErrorKind::Unsupported);
        QVERIFY2(enc.error().text().find("FACON") != std::string::npos,
                 qPrintable(qs(enc.error().text())));
    }
}

void TestFaconCodec::responseErrors()
{
    const Request r46 = Request::readRegisters(1, addr(ElementType::R, 12), 3);
    auto expectError = [this, &r46](const Bytes &f, ErrorKind kind, const char *mention = nullptr,
                                    const Request *req = nullptr) {
        const auto d = m_codec.decodeResponse(f, req ? *req : r46);
        QVERIFY2(!d.ok(), qPrintable(toFacon(f)));
        QVERIFY2(d.error().kind == kind,
                 qPrintable(toFacon(f) + QStringLiteral(": ") + qs(d.error().text())));
        QVERIFY(!d.error().text().empty());
        if (mention)
            QVERIFY2(d.error().text().find(mention) != std::string::npos,
                     qPrintable(qs(d.error().text())));
    };
    // Another station or command is an error, never a value.
    expectError(frame("0246010A57FC40001"), ErrorKind::StationMismatch, "station 2");
    expectError(frame("0147010A57FC40001"), ErrorKind::CommandMismatch, "47");
    // Bad LRC (last hex digit changed), bad framing.
    Bytes bad = frame("0146010A57FC40001");
    bad[bad.size() - 2] = bad[bad.size() - 2] == '0' ? '1' : '0';
    expectError(bad, ErrorKind::BadChecksum, "checksum");
    Bytes noEtx = frame("0146010A57FC40001");
    noEtx.back() = 'X';
    expectError(noEtx, ErrorKind::BadFrame);
    Bytes noStx = frame("0146010A57FC40001");
    noStx.front() = '0';
    expectError(noStx, ErrorKind::BadFrame);
    expectError(Bytes{0x02, 0x03}, ErrorKind::BadFrame);
    expectError(Bytes{}, ErrorKind::BadFrame);
    Bytes hexLrc = frame("0146010A57FC40001");
    hexLrc[hexLrc.size() - 3] = 'G';
    expectError(hexLrc, ErrorKind::BadFrame);
    expectError(frame("0G46010A57FC40001"), ErrorKind::BadFrame);
    // Truncated, too long, non-hex data.
    expectError(frame("0146010A57FC4"), ErrorKind::MalformedResponse, "12");
    expectError(frame("0146010A57FC400010"), ErrorKind::MalformedResponse, "12");
    expectError(frame("0146010A57FC4000Z"), ErrorKind::MalformedResponse, "hex");
    expectError(frame("0146"), ErrorKind::MalformedResponse, "error digit");
    expectError(frame("0146Z"), ErrorKind::MalformedResponse, "error digit");
    // Discretes must be 0/1.
    const Request r44 = Request::readDiscretes(1, addr(ElementType::X, 50), 3);
    expectError(frame("01440120"), ErrorKind::MalformedResponse, "0 or 1", &r44);
    expectError(frame("0144001"), ErrorKind::MalformedResponse, "got 2", &r44);
    expectError(frame("014400101"), ErrorKind::MalformedResponse, "got 4", &r44);
    // Write answers carry nothing after the error digit.
    const Request r41 = Request::runStop(1, true);
    expectError(frame("014100"), ErrorKind::MalformedResponse, nullptr, &r41);
    const Request r40 = Request::briefStatus(1);
    expectError(frame("014002900"), ErrorKind::MalformedResponse, "6", &r40);
    // Mixed read: widths per address.
    const Request r48 = Request::mixedRead(1, {addr(ElementType::R, 1), addr(ElementType::Y, 9)});
    expectError(frame("014805C3410"), ErrorKind::MalformedResponse, "5", &r48);
    // Program page: exactly 64 words.
    const Request r4f = Request::readProgram(1, 1);
    expectError(frame("014F0" + std::string(252, '0')), ErrorKind::MalformedResponse, "256", &r4f);
    // Loopback echo must be identical.
    const Request r4e = Request::loopback(1, ascii("ABCDEFG"));
    expectError(frame("014EABCDEFH"), ErrorKind::MalformedResponse, "oopback data differs", &r4e);
    expectError(frame("014E0ABCDEFG"), ErrorKind::MalformedResponse, "oopback data differs", &r4e);
}

// 4F: the reference answers an error digit and 64 words (257 chars), the seed's drawing shows the
// 64 words alone (256 chars); both decode to the same page. One char is an error digit; any other
// length is refused.
void TestFaconCodec::programPageAnswerForms()
{
    const Request r = Request::readProgram(1, 3);
    std::string words;
    std::vector<std::uint32_t> expected;
    for (std::uint32_t i = 0; i < Limits::programPageWords; ++i) {
        const std::uint32_t w = (i * 0x0101u + 0x1A2Bu) & 0xFFFFu;
        static const char digits[] = "0123456789ABCDEF";
        for (int shift = 12; shift >= 0; shift -= 4)
            words += digits[(w >> shift) & 0xFu];
        expected.push_back(w);
    }
    QCOMPARE(words.size(), std::size_t{256});

    const auto withDigit = m_codec.decodeResponse(frame("014F0" + words), r);
    QVERIFY2(withDigit.ok(), withDigit.ok() ? "" : withDigit.error().text().c_str());
    QCOMPARE(withDigit->values, expected);

    const auto withoutDigit = m_codec.decodeResponse(frame("014F" + words), r);
    QVERIFY2(withoutDigit.ok(), withoutDigit.ok() ? "" : withoutDigit.error().text().c_str());
    QCOMPARE(withoutDigit->values, expected);

    const auto error = m_codec.decodeResponse(frame("014F4"), r);
    QVERIFY(!error.ok());
    QCOMPARE(error.error().kind, ErrorKind::PlcError);
    QCOMPARE(error.error().plcCode, 4);

    // Wrong lengths after an error digit 0: short, long, nothing.
    for (const std::string &wrong :
         {"0" + words.substr(0, 254), "0" + words + "0", "0" + words + "00", std::string("0")}) {
        const auto d = m_codec.decodeResponse(frame("014F" + wrong), r);
        QVERIFY2(!d.ok(), qPrintable(QString::number(wrong.size())));
        QCOMPARE(d.error().kind, ErrorKind::MalformedResponse);
    }
}

void TestFaconCodec::plcErrors()
{
    const Request r = Request::readRegisters(1, addr(ElementType::R, 60000), 3);
    for (int code : {2, 3, 4, 5, 6, 7, 9, 0xA, 0xB}) {
        const char digit = "0123456789ABCDEF"[code];
        const auto d = m_codec.decodeResponse(frame(std::string("0146") + digit), r);
        QVERIFY(!d.ok());
        QCOMPARE(d.error().kind, ErrorKind::PlcError);
        QCOMPARE(d.error().plcCode, code);
        const std::string &msg = d.error().text();
        QVERIFY2(msg.find(std::string("error ") + digit) != std::string::npos, msg.c_str());
        QVERIFY2(msg.find("R60000") != std::string::npos, msg.c_str());
        QVERIFY2(msg.find(plcErrorText(code)) != std::string::npos, msg.c_str());
    }
    const auto a = m_codec.decodeResponse(frame("0146A"), r);
    QVERIFY2(a.error().text().find("illegal address") != std::string::npos,
             a.error().text().c_str());
    // Error answer to a write.
    const Request w = Request::writeDiscretes(1, addr(ElementType::Y, 300), {1});
    const auto e = m_codec.decodeResponse(frame("01453"), w);
    QVERIFY(!e.ok());
    QCOMPARE(e.error().plcCode, 3);
    QVERIFY2(e.error().text().find("Y300") != std::string::npos, e.error().text().c_str());
}

void TestFaconCodec::lowerCaseHex()
{
    const Request r = Request::readRegisters(0xAB, addr(ElementType::R, 12), 3);
    Bytes f = frame("ab46010a57fc40001");
    const auto d = m_codec.decodeResponse(f, r);
    QVERIFY2(d.ok(), d.ok() ? "" : d.error().text().c_str());
    QCOMPARE(d->values, (std::vector<std::uint32_t>{0x10A5, 0x7FC4, 0x0001}));
    // Lower-case LRC too: <STX>0140 sums to C7.
    Bytes lower = frame("0140");
    QCOMPARE(lower[5], std::uint8_t('C'));
    lower[5] = 'c';
    QVERIFY(m_codec.decodeRequest(lower).ok());
    QVERIFY(m_codec.frameHeader(lower).has_value());
}

void TestFaconCodec::decodeRequestErrors()
{
    auto expectCode = [this](const Bytes &f, int code, const char *mention = nullptr) {
        const auto d = m_codec.decodeRequest(f);
        QVERIFY2(!d.ok(), qPrintable(toFacon(f)));
        QVERIFY2(d.error().plcCode == code,
                 qPrintable(toFacon(f) + QStringLiteral(": code %1, ").arg(d.error().plcCode)
                            + qs(d.error().text())));
        QVERIFY(!d.error().text().empty());
        if (mention)
            QVERIFY2(d.error().text().find(mention) != std::string::npos,
                     qPrintable(qs(d.error().text())));
    };
    Bytes badLrc = frame("014603R00012");
    badLrc[badLrc.size() - 2] ^= 0x01;
    expectCode(badLrc, 0);
    expectCode(Bytes{0x02, '0', '1', 0x03}, 0);
    expectCode(Bytes{'h', 'e', 'l', 'l', 'o', '!', '!', '!'}, 0);
    expectCode(frame("0199"), 4, "99");
    expectCode(frame("0140X"), 4);
    expectCode(frame("014603R000121"), 4, "unexpected");
    expectCode(frame("014603R0001"), 4);
    expectCode(frame("0146"), 4);
    expectCode(frame("014641R00000"), 4, "65"); // 65 registers
    expectCode(frame("014600R00000"), 4);       // 0 registers
    expectCode(frame("014601X0000"), 4, "X0");  // discrete in a register command
    expectCode(frame("014403R00000"), 4, "R0"); // register in a discrete command
    expectCode(frame("0146010R0000"), 4);       // address missing its letters
    expectCode(frame("014601R0A000"), 4, "decimal");
    expectCode(frame("014601R70000"), 0xA, "R70000");
    expectCode(frame("014601WY0003"), 0xA, "WY3");
    expectCode(frame("014601Q00000"), 0xA, "Q");
    expectCode(frame("014601F00000"), 0xA, "F");
    expectCode(frame("014801DF00000"), 0xA, "DF");
    expectCode(frame("014402X9999"), 0xA, "X9999"); // runs past X9999
    expectCode(frame("014502Y000012"), 2, "0 or 1");
    expectCode(frame("014701R00000ZZZZ"), 2, "hex");
    expectCode(frame("014902Y00001R00000GGGG"), 2, "hex");
    expectCode(frame("01415"), 2);
    expectCode(frame("01425X0000"), 2);
    expectCode(frame("01421R00000"), 4);
    expectCode(frame("0150000100FF"), 4); // program page cut short
    expectCode(frame("FF40"), 4, "255");
    // Broadcast is a valid query.
    QVERIFY(m_codec.decodeRequest(frame("00411")).ok());
    QVERIFY(m_codec.decodeRequest(frame("00411"))->station == 0);
}

void TestFaconCodec::decodeRequestNeverCrashes()
{
    // Every prefix of every vector query and answer, re-wrapped with a valid LRC, plus random
    // bodies from the FACON alphabet: each yields a request or a coded error.
    std::vector<std::string> bodies;
    for (const TestUtil::Vector &v : TestUtil::loadVectors(QStringLiteral("facon"))) {
        for (const Bytes &f : {v.query, v.response}) {
            const Bytes body = bodyOf(f);
            for (std::size_t n = 0; n <= body.size(); ++n)
                bodies.emplace_back(body.begin(), body.begin() + static_cast<std::ptrdiff_t>(n));
        }
    }
    std::mt19937 rng(12345);
    const std::string alphabet = "0123456789ABCDEFXYMSTCWRDabf\x7f\x80 ";
    const std::vector<std::string> heads
        = {"0140", "0141", "0142", "0143", "0144", "0145", "0146", "0147",
           "0148", "0149", "014E", "014F", "0150", "0153", "01FF"};
    for (int i = 0; i < 20000; ++i) {
        std::string body = heads[rng() % heads.size()];
        const std::size_t len = rng() % 80;
        for (std::size_t k = 0; k < len; ++k)
            body += alphabet[rng() % alphabet.size()];
        bodies.push_back(body);
    }
    int accepted = 0;
    for (const std::string &body : bodies) {
        const Bytes f = frame(body);
        const auto d = m_codec.decodeRequest(f);
        if (d.ok()) {
            ++accepted;
            // What the slave accepts, the master could have sent.
            const auto again = m_codec.encodeRequest(*d);
            QVERIFY2(again.ok(), body.c_str());
            QVERIFY2(m_codec.decodeRequest(*again).ok(), body.c_str());
            (void)m_codec.encodeResponse(*d, answer(*d));
        } else {
            const int code = d.error().plcCode;
            QVERIFY2(code == 0 || code == 2 || code == 4 || code == 0xA, body.c_str());
        }
        (void)m_codec.summarize(f);
        (void)m_codec.frameHeader(f);
    }
    QVERIFY(accepted > 0);
}

void TestFaconCodec::errorResponseAndHeader()
{
    QCOMPARE(m_codec.encodeErrorResponse({1, 0x46}, 0xA),
             TestUtil::fromFacon(QStringLiteral("<STX>0146A0E<ETX>")));
    QCOMPARE(m_codec.encodeErrorResponse({0x1F, 0x99}, 4), frame("1F994"));
    const auto h
        = m_codec.frameHeader(TestUtil::fromFacon(QStringLiteral("<STX>014603R0001275<ETX>")));
    QVERIFY(h.has_value());
    QCOMPARE(h->station, std::uint8_t(1));
    QCOMPARE(h->command, std::uint8_t(0x46));
    QVERIFY(!m_codec.frameHeader(TestUtil::fromFacon(QStringLiteral("<STX>014603R0001276<ETX>")))
                 .has_value());
    QVERIFY(!m_codec.frameHeader(Bytes{0x02, 0x03}).has_value());
    // Error answer for a write: error digit only.
    const Request w = Request::writeRegisters(1, addr(ElementType::R, 0), {1});
    Response resp = answer(w);
    resp.errorCode = 3;
    QCOMPARE(m_codec.encodeResponse(w, resp), frame("01473"));
    // Loopback error answer has the digit; a normal loopback answer has none.
    const Request l = Request::loopback(1, ascii("HI"));
    resp = answer(l);
    resp.errorCode = 4;
    QCOMPARE(m_codec.encodeResponse(l, resp), frame("014E4"));
    QCOMPARE(m_codec.encodeResponse(l, answer(l)), frame("014EHI"));
}

void TestFaconCodec::summarize()
{
    using TestUtil::fromFacon;
    QCOMPARE(m_codec.summarize(fromFacon(QStringLiteral("<STX>014603R0001275<ETX>"))),
             std::string("station 1, 46 read consecutive registers: 3 x R00012"));
    QCOMPARE(m_codec.summarize(fromFacon(QStringLiteral("<STX>0146A0E<ETX>"))),
             std::string("station 1, 46 answer: error A (illegal address)"));
    QCOMPARE(m_codec.summarize(fromFacon(QStringLiteral("<STX>0140C7<ETX>"))),
             std::string("station 1, 40 read brief status"));
    QCOMPARE(m_codec.summarize(fromFacon(QStringLiteral("<STX>01421X001619<ETX>"))),
             std::string("station 1, 42 single discrete control: disable X0016"));
    QCOMPARE(m_codec.summarize(fromFacon(QStringLiteral("<STX>014504Y000010010B<ETX>"))),
             std::string("station 1, 45 write consecutive discretes: 4 x Y0000 = 1001"));
    QCOMPARE(m_codec.summarize(fromFacon(QStringLiteral("<STX>0146010A57FC4000189<ETX>"))),
             std::string("station 1, 46 answer: OK, 12 data chars \"10A57FC40001\""));
    QCOMPARE(m_codec.summarize(fromFacon(QStringLiteral("<STX>01420F9<ETX>"))),
             std::string("station 1, 42 answer: OK"));
    const std::string badLrc = m_codec.summarize(fromFacon(QStringLiteral("<STX>0140C8<ETX>")));
    QVERIFY2(badLrc.find("checksum") != std::string::npos, badLrc.c_str());
    const std::string garbage = m_codec.summarize(Bytes{0xFF, 0x00});
    QVERIFY2(garbage.find("invalid") != std::string::npos, garbage.c_str());
}

QTEST_GUILESS_MAIN(TestFaconCodec)
#include "tst_faconcodec.moc"
