#include "core/protocol/binarycodec.h"
#include "core/protocol/binarydeframer.h"
#include "testutil.h"

#include <QTest>

#include <random>

using namespace Fatek;
using TestUtil::fromHex;
using TestUtil::toHex;

namespace {

using Dir = BinaryDeframer::Direction;

std::vector<DeframedItem> feedAll(BinaryDeframer &d, const Bytes &bytes)
{
    std::vector<DeframedItem> out;
    d.feed(bytes, out);
    return out;
}

std::vector<DeframedItem> feedByteByByte(BinaryDeframer &d, const Bytes &bytes)
{
    std::vector<DeframedItem> out;
    for (std::uint8_t b : bytes)
        d.feed(std::span<const std::uint8_t>(&b, 1), out);
    return out;
}

Bytes concat(std::initializer_list<Bytes> parts)
{
    Bytes out;
    for (const Bytes &p : parts)
        out.insert(out.end(), p.begin(), p.end());
    return out;
}

QList<Bytes> responses()
{
    QList<Bytes> out;
    for (const auto &v : TestUtil::loadVectors(QStringLiteral("binary")))
        out.append(v.response);
    return out;
}

QList<Bytes> queries()
{
    QList<Bytes> out;
    for (const auto &v : TestUtil::loadVectors(QStringLiteral("binary")))
        out.append(v.query);
    return out;
}

// Frames out of `items` that were accepted, asserting nothing was rejected when `clean`.
QList<Bytes> goodFrames(const std::vector<DeframedItem> &items)
{
    QList<Bytes> out;
    for (const DeframedItem &i : items) {
        if (!i.error)
            out.append(i.frame);
    }
    return out;
}

} // namespace

class TestBinaryDeframer : public QObject
{
    Q_OBJECT

private slots:
    void vectorsWhole();
    void queriesForTheSlave();
    void byteByByte();
    void splitAtEveryBoundary();
    void manyFramesInOneChunk();
    void garbageInterleaved();
    void echoOfOurQueryIsIgnored();
    void corruptedThenGood();
    void garbageLengthDoesNotSwallowTheNextFrame();
    void largestLegalFrame();
    void endlessGarbageStaysBounded();
    void resetDropsPartialFrame();
};

void TestBinaryDeframer::vectorsWhole()
{
    for (const Bytes &r : responses()) {
        BinaryDeframer d;
        const auto items = feedAll(d, r);
        QCOMPARE(items.size(), std::size_t(1));
        QVERIFY(!items[0].error);
        QCOMPARE(toHex(items[0].frame), toHex(r));
        QCOMPARE(d.bufferedBytes(), std::size_t(0));
        QCOMPARE(d.discardedBytes(), std::size_t(0));
    }
    QCOMPARE(BinaryDeframer().maxFrameSize(), BinaryCodec::maxFrameSize);
}

void TestBinaryDeframer::queriesForTheSlave()
{
    BinaryDeframer slave(Dir::Query);
    Bytes stream;
    for (const Bytes &q : queries())
        stream.insert(stream.end(), q.begin(), q.end());
    const auto items = feedAll(slave, stream);
    QCOMPARE(goodFrames(items), queries());
    QCOMPARE(items.size(), std::size_t(queries().size()));
    QCOMPARE(slave.discardedBytes(), std::size_t(0));

    // A slave takes answers of another slave on the bus for garbage.
    BinaryDeframer other(Dir::Query);
    const Bytes answer = responses().at(11);
    QVERIFY(feedAll(other, answer).empty());
    QCOMPARE(other.discardedBytes(), answer.size());
    QCOMPARE(other.bufferedBytes(), std::size_t(0));
}

void TestBinaryDeframer::byteByByte()
{
    BinaryDeframer d;
    Bytes stream;
    for (const Bytes &r : responses())
        stream.insert(stream.end(), r.begin(), r.end());
    const auto items = feedByteByByte(d, stream);
    QCOMPARE(items.size(), std::size_t(responses().size()));
    QCOMPARE(goodFrames(items), responses());
    QCOMPARE(d.bufferedBytes(), std::size_t(0));
}

void TestBinaryDeframer::splitAtEveryBoundary()
{
    for (const Bytes &r : responses()) {
        for (std::size_t cut = 0; cut <= r.size(); ++cut) {
            BinaryDeframer d;
            std::vector<DeframedItem> out;
            d.feed(std::span<const std::uint8_t>(r).first(cut), out);
            if (cut < r.size()) {
                QVERIFY(out.empty());
                QCOMPARE(d.bufferedBytes(), cut);
            }
            d.feed(std::span<const std::uint8_t>(r).subspan(cut), out);
            QCOMPARE(out.size(), std::size_t(1));
            QVERIFY(!out[0].error);
            QCOMPARE(toHex(out[0].frame), toHex(r));
        }
    }
}

void TestBinaryDeframer::manyFramesInOneChunk()
{
    BinaryDeframer d;
    Bytes stream;
    QList<Bytes> expected;
    for (int round = 0; round < 5; ++round) {
        for (const Bytes &r : responses()) {
            stream.insert(stream.end(), r.begin(), r.end());
            expected.append(r);
        }
    }
    const auto items = feedAll(d, stream);
    QCOMPARE(goodFrames(items), expected);
    QCOMPARE(items.size(), std::size_t(expected.size()));
}

void TestBinaryDeframer::garbageInterleaved()
{
    const Bytes facon
        = TestUtil::fromFacon(QStringLiteral("<STX>014603R00012F1<ETX><STX>01460010A5<ETX>"));
    const QList<Bytes> garbage = {
        {0x00, 0xFF, 0x13},       {0x52}, // stray header
        {0x52, 0x52, 0x52},               // several
        {0x52, 0x10, 0xFF, 0xFF},         // header, ID and a huge length
        {0x52, 0x10, 0x02, 0x01},         // length 513, one past the largest payload
        {0x52, 0x10, 0x00, 0x01},         // too short for station and command
        {0x52, 0x11, 0x00, 0x03},         // wrong ID
        {0x55, 0xAA, 0x10},       facon,
    };
    const QList<Bytes> frames = responses();
    Bytes stream;
    std::size_t garbageBytes = 0;
    for (int i = 0; i < frames.size(); ++i) {
        const Bytes &g = garbage[i % garbage.size()];
        stream.insert(stream.end(), g.begin(), g.end());
        garbageBytes += g.size();
        stream.insert(stream.end(), frames[i].begin(), frames[i].end());
    }
    for (const Bytes &g : garbage) { // every kind at least once, before a frame
        stream.insert(stream.end(), g.begin(), g.end());
        garbageBytes += g.size();
        stream.insert(stream.end(), frames[0].begin(), frames[0].end());
    }
    QList<Bytes> expected = frames;
    for (int i = 0; i < garbage.size(); ++i)
        expected.append(frames[0]);

    for (int mode = 0; mode < 2; ++mode) {
        BinaryDeframer d;
        const auto items = mode == 0 ? feedAll(d, stream) : feedByteByByte(d, stream);
        QCOMPARE(items.size(), std::size_t(expected.size())); // garbage is skipped, not reported
        QCOMPARE(goodFrames(items), expected);
        QCOMPARE(d.discardedBytes(), garbageBytes);
        QCOMPARE(d.bufferedBytes(), std::size_t(0));
    }
}

void TestBinaryDeframer::echoOfOurQueryIsIgnored()
{
    // 2-wire RS-485: our own query comes back before the answer.
    const auto vectors = TestUtil::loadVectors(QStringLiteral("binary"));
    for (const auto &v : vectors) {
        BinaryDeframer d;
        const auto items = feedByteByByte(d, concat({v.query, v.response}));
        QCOMPARE(items.size(), std::size_t(1));
        QVERIFY(!items[0].error);
        QCOMPARE(toHex(items[0].frame), toHex(v.response));
        QCOMPARE(d.discardedBytes(), v.query.size());
    }
}

void TestBinaryDeframer::corruptedThenGood()
{
    const Bytes good = responses().at(11);
    QVERIFY(good.size() > 8);
    Bytes badCrc = good;
    badCrc[badCrc.size() - 4] ^= 0x40;
    // Built rather than patched: GCC 12 -O2 misreports back() on a copied vector (-Warray-bounds).
    Bytes badEnd(good.begin(), good.end() - 1);
    badEnd.push_back(0xAB);
    Bytes badData = good;
    badData[7] ^= 0x01;

    struct Case
    {
        Bytes broken;
        ErrorKind kind;
    };
    const std::vector<Case> cases = {{badCrc, ErrorKind::BadChecksum},
                                     {badEnd, ErrorKind::BadFrame},
                                     {badData, ErrorKind::BadChecksum}};
    for (const Case &c : cases) {
        for (int mode = 0; mode < 2; ++mode) {
            BinaryDeframer d;
            const Bytes stream = concat({c.broken, good});
            const auto items = mode == 0 ? feedAll(d, stream) : feedByteByByte(d, stream);
            QCOMPARE(items.size(), std::size_t(2));
            QVERIFY(items[0].error.has_value());
            QVERIFY(items[0].error->kind == c.kind);
            QVERIFY(!items[0].error->message.empty());
            QCOMPARE(toHex(items[0].frame), toHex(c.broken));
            QVERIFY(!items[1].error);
            QCOMPARE(toHex(items[1].frame), toHex(good));
            QCOMPARE(d.bufferedBytes(), std::size_t(0));
            QCOMPARE(d.discardedBytes(), std::size_t(0)); // rejected frames are not garbage
        }
    }
}

void TestBinaryDeframer::garbageLengthDoesNotSwallowTheNextFrame()
{
    // A plausible fake header whose length reaches into the real frame: once the fake one is
    // rejected, the real frame inside it must still come out.
    const Bytes good = responses().at(2); // 11 bytes
    const Bytes fake = {0x52, 0x10, 0x00, 0x05};
    for (int mode = 0; mode < 2; ++mode) {
        BinaryDeframer d;
        const Bytes stream = concat({fake, good});
        const auto items = mode == 0 ? feedAll(d, stream) : feedByteByByte(d, stream);
        QCOMPARE(items.size(), std::size_t(2));
        QVERIFY(items[0].error.has_value());
        QVERIFY(items[0].error->kind == ErrorKind::BadFrame);
        QVERIFY(!items[1].error);
        QCOMPARE(toHex(items[1].frame), toHex(good));
        QCOMPARE(d.discardedBytes(), std::size_t(0));
        // Garbage after a rejected frame still counts.
        std::vector<DeframedItem> more;
        d.feed(Bytes{0x00, 0x01, 0x02}, more);
        QCOMPARE(d.discardedBytes(), std::size_t(3));
    }
}

void TestBinaryDeframer::largestLegalFrame()
{
    BinaryCodec codec;
    Bytes payload(BinaryCodec::maxPayload, 0x00);
    payload[0] = 0x01;
    payload[1] = 0x53;
    const Bytes biggest = codec.wrap(payload, true);
    QCOMPARE(biggest.size(), BinaryCodec::maxFrameSize);
    BinaryDeframer d;
    auto items = feedByteByByte(d, biggest);
    QCOMPARE(items.size(), std::size_t(1));
    QVERIFY(!items[0].error);

    // One byte more is no frame: the header is dropped and the next frame is found.
    payload.push_back(0x00);
    const Bytes tooBig = codec.wrap(payload, true);
    const Bytes good = responses().at(0);
    items = feedAll(d, concat({tooBig, good}));
    QCOMPARE(goodFrames(items), QList<Bytes>{good});
    QVERIFY(d.discardedBytes() >= tooBig.size());
}

void TestBinaryDeframer::endlessGarbageStaysBounded()
{
    std::mt19937 random(42);
    const std::vector<Bytes> patterns = {
        {0x52, 0x10, 0x01, 0x00}, // fake frames of 264 bytes that never end right
        {0x52, 0x10, 0x02, 0x00}, // and of the largest size
        {0x52},
        {0x52, 0x10},
    };
    for (int mode = 0; mode < 2; ++mode) {
        BinaryDeframer d;
        std::size_t rejectedBytes = 0;
        std::size_t fed = 0;
        while (fed < 200000) {
            Bytes chunk(1 + random() % (mode == 0 ? 2000 : 16));
            for (std::size_t i = 0; i < chunk.size(); ++i) {
                if (random() % 8 == 0) {
                    const Bytes &p = patterns[random() % patterns.size()];
                    chunk.insert(chunk.begin() + std::ptrdiff_t(i), p.begin(), p.end());
                    i += p.size();
                    if (i >= chunk.size())
                        break;
                } else {
                    chunk[i] = static_cast<std::uint8_t>(random());
                }
            }
            std::vector<DeframedItem> out;
            d.feed(chunk, out);
            fed += chunk.size();
            for (const DeframedItem &item : out) {
                QVERIFY(item.error.has_value()); // noise never passes CRC and terminator here
                QVERIFY(item.frame.size() <= d.maxFrameSize());
                rejectedBytes += item.frame.size();
            }
            QVERIFY(d.bufferedBytes() <= d.maxFrameSize());
        }
        // Every byte is held, skipped as garbage or part of a rejected item.
        QVERIFY(d.discardedBytes() > 0);
        QVERIFY(d.discardedBytes() + rejectedBytes + d.bufferedBytes() >= fed);
        // After all that noise real frames still come out: fake frames pending in the buffer
        // end within one largest frame, then every copy is found.
        std::vector<DeframedItem> out;
        const Bytes good = responses().at(0);
        const int copies = 100;
        for (int i = 0; i < copies; ++i)
            d.feed(good, out);
        QVERIFY(!out.empty());
        QVERIFY(!out.back().error);
        QCOMPARE(toHex(out.back().frame), toHex(good));
        QVERIFY(goodFrames(out).size() >= copies - int(d.maxFrameSize() / good.size()) - 1);

        // reset() makes it immediate.
        d.feed(fromHex(QStringLiteral("52 10 02 00 00 00")), out);
        d.reset();
        out.clear();
        d.feed(good, out);
        QCOMPARE(goodFrames(out), QList<Bytes>{good});
    }
}

void TestBinaryDeframer::resetDropsPartialFrame()
{
    const Bytes good = responses().at(11);
    BinaryDeframer d;
    std::vector<DeframedItem> out;
    d.feed(std::span<const std::uint8_t>(good).first(7), out);
    QCOMPARE(d.bufferedBytes(), std::size_t(7));
    d.reset();
    QCOMPARE(d.bufferedBytes(), std::size_t(0));
    // The rest of the old frame is garbage now; the next full frame is found.
    d.feed(std::span<const std::uint8_t>(good).subspan(7), out);
    QVERIFY(out.empty());
    d.feed(good, out);
    QCOMPARE(out.size(), std::size_t(1));
    QVERIFY(!out[0].error);
    QCOMPARE(toHex(out[0].frame), toHex(good));
}

QTEST_APPLESS_MAIN(TestBinaryDeframer)
#include "tst_binarydeframer.moc"
