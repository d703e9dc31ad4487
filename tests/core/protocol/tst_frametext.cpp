// FrameText (hex and ASCII views of frames, parsing typed bytes) and RawFrame (framing of typed
// bodies, the lenient header peek) on the frames of tests/data/vectors.json and on broken input.
#include "core/protocol/binarycodec.h"
#include "core/protocol/faconcodec.h"
#include "core/protocol/frametext.h"
#include "core/protocol/rawframe.h"
#include "testutil.h"

#include <QTest>

Q_DECLARE_METATYPE(Fatek::Bytes)

using namespace Fatek;

namespace {

Bytes bytes(std::string_view s)
{
    return {s.begin(), s.end()};
}

QString text(const std::string &s)
{
    return QString::fromStdString(s);
}

} // namespace

class TestFrameText : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void views();
    void parsing();
    void parseErrors_data();
    void parseErrors();
    void guess_data();
    void guess();
    void roundTrips_data();
    void roundTrips();
    void peekMatchesCodec_data();
    void peekMatchesCodec();
    void peekTruncatedAndGarbage();
    void framing();
    void summarize();
};

void TestFrameText::views()
{
    const Bytes frame = bytes("\x02"
                              "0140C7\x03");
    QCOMPARE(text(FrameText::toAscii(frame)), QStringLiteral("<STX>0140C7<ETX>"));
    QCOMPARE(text(FrameText::toAscii(frame, FrameText::Controls::Hex)),
             QStringLiteral("<02>0140C7<03>"));
    QCOMPARE(text(FrameText::toHex(frame)), QStringLiteral("02 30 31 34 30 43 37 03"));
    QCOMPARE(text(FrameText::toAscii(bytes("\x0d\xff"))), QStringLiteral("<CR><FF>"));
    // Form feed's name is also the hex of FF: the view writes it in hex so it reads back.
    QCOMPARE(text(FrameText::toAscii(bytes("\x0c\x1b"))), QStringLiteral("<0C><ESC>"));
    QCOMPARE(text(FrameText::toAscii(bytes("\x0d\xff"), FrameText::Controls::Hex)),
             QStringLiteral("<0D><FF>"));
    QCOMPARE(text(FrameText::toHex({})), QString());
}

void TestFrameText::parsing()
{
    QCOMPARE(*FrameText::parseAscii("<STX>0140C7<ETX>"), bytes("\x02"
                                                               "0140C7\x03"));
    QCOMPARE(*FrameText::parseAscii("<02>0140C7<03>"), bytes("\x02"
                                                             "0140C7\x03"));
    QCOMPARE(*FrameText::parseAscii("<stx>01<0d>"), bytes("\x02"
                                                          "01\x0d"));
    QCOMPARE(*FrameText::parseAscii("a<b"), bytes("a<b"));
    QCOMPARE(*FrameText::parseAscii("<FF><ff><0c><esc>"), bytes("\xff\xff\x0c\x1b"));
    QCOMPARE(*FrameText::parseAscii("<>"), bytes("<>"));
    QCOMPARE(*FrameText::parseAscii("<XYZ>"), bytes("<XYZ>"));
    QCOMPARE(*FrameText::parseHex("01 46 03 52 00 0C"), TestUtil::fromHex("01460352000C"));
    QCOMPARE(*FrameText::parseHex("0x01,0x46"), TestUtil::fromHex("0146"));
    QCOMPARE(*FrameText::parseHex("014603"), TestUtil::fromHex("014603"));
    QCOMPARE(*FrameText::parseHex("0a-0B:3c;ff"), TestUtil::fromHex("0A0B3CFF"));
}

void TestFrameText::parseErrors_data()
{
    QTest::addColumn<bool>("hex");
    QTest::addColumn<QString>("input");
    QTest::addColumn<QString>("message");
    QTest::newRow("odd") << true << "01 4"
                         << "Odd number of hex digits: each byte needs two (0C, not C).";
    QTest::newRow("not hex") << true << "01 G6"
                             << QStringLiteral("\u201cG\u201d is not a hex digit; type bytes "
                                               "like 01 46 03 52 00 0C.");
    QTest::newRow("not hex, not ASCII")
        << true << QStringLiteral("01 \u00e9")
        << QStringLiteral("\u201c\u00e9\u201d is not a hex digit; type bytes like 01 46 03 52 "
                          "00 0C.");
    QTest::newRow("lone 0x") << true << "0x"
                             << QStringLiteral("\u201cx\u201d is not a hex digit; type bytes "
                                               "like 01 46 03 52 00 0C.");
    QTest::newRow("empty hex") << true << "  "
                               << "Nothing to send: type the frame's bytes in hex.";
    QTest::newRow("non-ascii") << false << QStringLiteral("01\u00e940")
                               << "Only printable ASCII can be typed; write control characters "
                                  "as <STX>, <ETX> or <0D>.";
    QTest::newRow("tab") << false << "01\t40"
                         << "Only printable ASCII can be typed; write control characters as "
                            "<STX>, <ETX> or <0D>.";
    QTest::newRow("empty ascii") << false << ""
                                 << "Nothing to send: type the frame.";
}

void TestFrameText::parseErrors()
{
    QFETCH(bool, hex);
    QFETCH(QString, input);
    QFETCH(QString, message);
    const std::string utf8 = input.toStdString();
    const Result<Bytes> r = hex ? FrameText::parseHex(utf8) : FrameText::parseAscii(utf8);
    QVERIFY(!r);
    QCOMPARE(text(r.error().text()), message);
    QCOMPARE(r.error().kind, ErrorKind::InvalidRequest);
}

void TestFrameText::guess_data()
{
    QTest::addColumn<QString>("input");
    QTest::addColumn<bool>("hex");
    QTest::addColumn<QString>("bytesHex");
    QTest::newRow("spaced pairs") << "01 40" << true << "0140";
    QTest::newRow("no blanks: characters") << "0140" << false << "30313430";
    QTest::newRow("0x prefix") << "0x0140" << true << "0140";
    QTest::newRow("hex: prefix") << "HEX:01 40 ff" << true << "0140FF";
    QTest::newRow("one pair: a character pair") << "01" << false << "3031";
    QTest::newRow("escapes") << " <02>0140C7<03> " << false << "0230313430433703";
    QTest::newRow("words") << "ab cd ef" << true << "ABCDEF";
    QTest::newRow("not pairs") << "abc de" << false << "616263206465";
}

void TestFrameText::guess()
{
    QFETCH(QString, input);
    QFETCH(bool, hex);
    QFETCH(QString, bytesHex);
    bool wasHex = !hex;
    const Result<Bytes> r = FrameText::parse(input.toStdString(), FrameText::Typed::Guess, &wasHex);
    QVERIFY2(r.ok(), r.ok() ? "" : r.error().text().c_str());
    QCOMPARE(wasHex, hex);
    QCOMPARE(*r, TestUtil::fromHex(bytesHex));
}

void TestFrameText::roundTrips_data()
{
    QTest::addColumn<Bytes>("frame");
    for (const QString &protocol : {QStringLiteral("facon"), QStringLiteral("binary")}) {
        int i = 0;
        for (const TestUtil::Vector &v : TestUtil::loadVectors(protocol)) {
            QTest::addRow("%s %d query", qPrintable(protocol), i) << v.query;
            QTest::addRow("%s %d answer", qPrintable(protocol), i) << v.response;
            ++i;
        }
    }
}

void TestFrameText::roundTrips()
{
    QFETCH(Bytes, frame);
    QVERIFY(!frame.empty());
    QCOMPARE(*FrameText::parseHex(FrameText::toHex(frame)), frame);
    QCOMPARE(*FrameText::parseAscii(FrameText::toAscii(frame)), frame);
    const std::string hexStyle = FrameText::toAscii(frame, FrameText::Controls::Hex);
    QCOMPARE(*FrameText::parseAscii(hexStyle), frame);
    // What fatek-cli prints can be typed back to it.
    bool wasHex = false;
    QCOMPARE(*FrameText::parse(FrameText::toHex(frame), FrameText::Typed::Guess, &wasHex), frame);
    QVERIFY(wasHex);
    QCOMPARE(*FrameText::parse(hexStyle, FrameText::Typed::Guess, &wasHex), frame);
    QVERIFY(!wasHex);
    if (frame.front() == FaconCodec::STX)
        QCOMPARE(text(FrameText::toAscii(frame)), TestUtil::toFacon(frame));
}

void TestFrameText::peekMatchesCodec_data()
{
    roundTrips_data();
}

void TestFrameText::peekMatchesCodec()
{
    QFETCH(Bytes, frame);
    const bool facon = frame.front() == FaconCodec::STX;
    const Codec &codec = RawFrame::codec(facon ? Protocol::Facon : Protocol::Binary);
    const auto strict = codec.frameHeader(frame);
    QVERIFY(strict); // the vectors are valid frames
    const auto peek = RawFrame::peek(frame);
    QVERIFY(peek);
    QCOMPARE(peek->protocol, facon ? Protocol::Facon : Protocol::Binary);
    QCOMPARE(peek->station, strict->station);
    QCOMPARE(peek->command, strict->command);
    QVERIFY(RawFrame::protocolOf(frame) == peek->protocol);

    // A broken checksum: the codec refuses the frame, the peek still names it.
    Bytes broken = frame;
    broken[broken.size() - (facon ? 2 : 3)] ^= 0x01;
    QVERIFY(!codec.frameHeader(broken));
    const auto brokenPeek = RawFrame::peek(broken);
    QVERIFY(brokenPeek);
    QCOMPARE(brokenPeek->command, strict->command);

    // Cut short: the header is there from 5 (FACON) or 6 (binary) bytes on, never before.
    const std::size_t headerEnd = facon ? 5 : 6;
    for (std::size_t n = 0; n <= frame.size(); ++n) {
        const auto cut = RawFrame::peek(std::span(frame).first(n));
        if (n < headerEnd) {
            QVERIFY2(!cut, qPrintable(QStringLiteral("%1 bytes").arg(n)));
        } else {
            QVERIFY2(cut, qPrintable(QStringLiteral("%1 bytes").arg(n)));
            QCOMPARE(cut->station, strict->station);
            QCOMPARE(cut->command, strict->command);
        }
    }
}

void TestFrameText::peekTruncatedAndGarbage()
{
    QVERIFY(!RawFrame::peek({}));
    QVERIFY(!RawFrame::peek(bytes("hello")));
    QVERIFY(!RawFrame::peek(bytes("\x02"
                                  "0")));
    // STX, then no hex header.
    QVERIFY(!RawFrame::peek(bytes("\x02"
                                  "0G40C7\x03")));
    QVERIFY(RawFrame::protocolOf(bytes("\x02"
                                       "0G40C7\x03"))
            == Protocol::Facon);
    // Binary header byte with the wrong ID.
    QVERIFY(!RawFrame::peek(TestUtil::fromHex("51 11 00 02 01 40 A1 84 55 AA")));
    QVERIFY(!RawFrame::protocolOf(bytes("hello")));
    QVERIFY(!RawFrame::protocolOf({}));
    // Every byte pattern of a few bytes: no crash, and a peek only where a protocol starts.
    for (int first = 0; first < 256; ++first) {
        for (int second = 0; second < 256; second += 15) {
            const Bytes b = {std::uint8_t(first), std::uint8_t(second), 0x31, 0x34, 0x30, 0x01};
            const auto peek = RawFrame::peek(b);
            if (peek)
                QVERIFY(RawFrame::protocolOf(b) == peek->protocol);
            if (first != FaconCodec::STX && first != BinaryCodec::queryHeader
                && first != BinaryCodec::responseHeader)
                QVERIFY(!peek);
        }
    }
}

void TestFrameText::framing()
{
    const QList<TestUtil::Vector> facon = TestUtil::loadVectors(QStringLiteral("facon"));
    const QList<TestUtil::Vector> binary = TestUtil::loadVectors(QStringLiteral("binary"));
    QVERIFY(!facon.isEmpty() && !binary.isEmpty());
    // The body of a vector framed again is the vector: FACON between STX and LRC, binary payload.
    for (const TestUtil::Vector &v : facon) {
        const Bytes body(v.query.begin() + 1, v.query.end() - 3);
        QCOMPARE(RawFrame::frame(body, Protocol::Facon), v.query);
        const auto peek = RawFrame::peek(RawFrame::frame(body, Protocol::Facon));
        QVERIFY(peek);
        QCOMPARE(peek->protocol, Protocol::Facon);
    }
    for (const TestUtil::Vector &v : binary) {
        const Bytes payload(v.query.begin() + 4, v.query.end() - 4);
        QCOMPARE(RawFrame::frame(payload, Protocol::Binary), v.query);
    }
    // Without framing, the bytes go as typed.
    const Bytes typed = bytes("anything\x02");
    QCOMPARE(RawFrame::frame(typed, std::nullopt), typed);
    const auto body = RawFrame::peek(RawFrame::frame(bytes("014603R00012"), Protocol::Facon));
    QVERIFY(body);
    QCOMPARE(body->station, std::uint8_t(1));
    QCOMPARE(body->command, std::uint8_t(0x46));
}

void TestFrameText::summarize()
{
    const Bytes facon = TestUtil::fromFacon(QStringLiteral("<STX>0140C7<ETX>"));
    QCOMPARE(RawFrame::summarize(facon), FaconCodec().summarize(facon));
    const Bytes binary = TestUtil::fromHex("51 10 00 02 01 40 A1 84 55 AA");
    QCOMPARE(RawFrame::summarize(binary), BinaryCodec().summarize(binary));
    // Neither: read as binary, whose summary says why it is not a frame.
    const Bytes garbage = bytes("hello");
    QCOMPARE(RawFrame::summarize(garbage), BinaryCodec().summarize(garbage));
}

QTEST_GUILESS_MAIN(TestFrameText)
#include "tst_frametext.moc"
