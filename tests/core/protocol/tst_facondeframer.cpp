#include "core/protocol/faconcodec.h"
#include "core/protocol/facondeframer.h"
#include "testutil.h"

#include <QTest>

using namespace Fatek;
using TestUtil::toFacon;

namespace {

Bytes wrapped(std::string_view body)
{
    return FaconCodec().wrap(Bytes(body.begin(), body.end()));
}

// Every vector frame, queries and answers, in file order.
std::vector<Bytes> vectorFrames()
{
    std::vector<Bytes> frames;
    for (const TestUtil::Vector &v : TestUtil::loadVectors(QStringLiteral("facon"))) {
        frames.push_back(v.query);
        frames.push_back(v.response);
    }
    return frames;
}

Bytes concat(const std::vector<Bytes> &frames)
{
    Bytes all;
    for (const Bytes &f : frames)
        all.insert(all.end(), f.begin(), f.end());
    return all;
}

void append(Bytes &to, const Bytes &what)
{
    to.insert(to.end(), what.begin(), what.end());
}

} // namespace

class TestFaconDeframer : public QObject
{
    Q_OBJECT

private slots:
    void wholeStream();
    void byteByByte();
    void everySplit();
    void garbageBetweenFrames();
    void strayStxRestartsFrame();
    void corruptedThenGood();
    void badHeaderAndShortFrames();
    void endlessStream();
    void largestFrame();
    void resetDropsPartial();

private:
    void expectFrames(const std::vector<DeframedItem> &items, const std::vector<Bytes> &frames);
};

void TestFaconDeframer::expectFrames(const std::vector<DeframedItem> &items,
                                     const std::vector<Bytes> &frames)
{
    QCOMPARE(items.size(), frames.size());
    for (std::size_t i = 0; i < items.size(); ++i) {
        QVERIFY2(!items[i].error.has_value(),
                 qPrintable(toFacon(items[i].frame) + QStringLiteral(": ")
                            + QString::fromStdString(items[i].error ? items[i].error->text()
                                                                    : std::string())));
        QVERIFY2(items[i].frame == frames[i], qPrintable(toFacon(items[i].frame)));
    }
}

void TestFaconDeframer::wholeStream()
{
    const auto frames = vectorFrames();
    FaconDeframer d;
    std::vector<DeframedItem> items;
    d.feed(concat(frames), items);
    expectFrames(items, frames);
    QCOMPARE(d.bufferedBytes(), std::size_t(0));
    QCOMPARE(d.discardedBytes(), std::size_t(0));
    QCOMPARE(d.maxFrameSize(), FaconCodec::maxFrameSize);
}

void TestFaconDeframer::byteByByte()
{
    const auto frames = vectorFrames();
    const Bytes all = concat(frames);
    FaconDeframer d;
    std::vector<DeframedItem> items;
    for (std::uint8_t b : all) {
        d.feed(std::span(&b, 1), items);
        QVERIFY(d.bufferedBytes() <= d.maxFrameSize());
    }
    expectFrames(items, frames);
    QCOMPARE(d.bufferedBytes(), std::size_t(0));
}

void TestFaconDeframer::everySplit()
{
    const auto frames = vectorFrames();
    const Bytes all = concat(frames);
    for (std::size_t k = 0; k <= all.size(); ++k) {
        FaconDeframer d;
        std::vector<DeframedItem> items;
        d.feed(std::span(all).first(k), items);
        d.feed(std::span(all).subspan(k), items);
        expectFrames(items, frames);
        QCOMPARE(d.discardedBytes(), std::size_t(0));
    }
}

void TestFaconDeframer::garbageBetweenFrames()
{
    const auto frames = vectorFrames();
    // Binary-protocol bytes, stray ETX, text, high bytes: none is STX, so all is skipped.
    const Bytes garbage = {0x52, 0x10, 0x00, 0x03, 0x01, 0x41, 0x00, 0x45, 0xD4, 0x55, 0xAA,
                           0x03, 'h',  'i',  0x00, 0xFF, 0x80, 0x03, '0',  '1',  '4',  '0'};
    Bytes stream = garbage;
    for (const Bytes &f : frames) {
        append(stream, f);
        append(stream, garbage);
    }
    FaconDeframer d;
    std::vector<DeframedItem> items;
    d.feed(stream, items);
    expectFrames(items, frames);
    QCOMPARE(d.discardedBytes(), garbage.size() * (frames.size() + 1));
    QCOMPARE(d.bufferedBytes(), std::size_t(0));

    // Same stream byte by byte.
    FaconDeframer d2;
    std::vector<DeframedItem> items2;
    for (std::uint8_t b : stream)
        d2.feed(std::span(&b, 1), items2);
    expectFrames(items2, frames);
    QCOMPARE(d2.discardedBytes(), d.discardedBytes());

    // Garbage holding an STX (a binary query: 51 10 00 02 ...) opens a bogus frame that the next
    // real STX abandons: one rejected item, and every real frame still comes out.
    const Bytes withStx = {0x51, 0x10, 0x00, 0x02, 0x01, 0x40, 0xA1, 0x84, 0x55, 0xAA};
    Bytes stream3;
    for (const Bytes &f : frames) {
        append(stream3, withStx);
        append(stream3, f);
    }
    FaconDeframer d3;
    std::vector<DeframedItem> items3;
    d3.feed(stream3, items3);
    QCOMPARE(items3.size(), 2 * frames.size());
    std::vector<DeframedItem> good;
    for (std::size_t i = 0; i < items3.size(); ++i) {
        if (i % 2 == 0) {
            QVERIFY(items3[i].error.has_value());
            QCOMPARE(items3[i].error->kind, ErrorKind::BadFrame);
        } else {
            good.push_back(items3[i]);
        }
    }
    expectFrames(good, frames);
    QCOMPARE(d3.discardedBytes(), 3 * frames.size());
}

void TestFaconDeframer::strayStxRestartsFrame()
{
    const Bytes good = wrapped("014603R00012");
    Bytes stream = {0x02, '0', '1', '4'};
    append(stream, good);
    stream.push_back(0x02); // starts a frame that never ends in this chunk
    FaconDeframer d;
    std::vector<DeframedItem> items;
    d.feed(stream, items);
    QCOMPARE(items.size(), std::size_t(2));
    QVERIFY(items[0].error.has_value());
    QCOMPARE(items[0].error->kind, ErrorKind::BadFrame);
    QCOMPARE(items[0].frame, (Bytes{0x02, '0', '1', '4'}));
    QVERIFY(!items[1].error.has_value());
    QCOMPARE(items[1].frame, good);
    QCOMPARE(d.bufferedBytes(), std::size_t(1));
    QCOMPARE(d.discardedBytes(), std::size_t(0));
    // The pending STX is the start of the next frame.
    items.clear();
    const Bytes rest(good.begin() + 1, good.end());
    d.feed(rest, items);
    QCOMPARE(items.size(), std::size_t(1));
    QVERIFY(!items[0].error.has_value());
    QCOMPARE(items[0].frame, good);
}

void TestFaconDeframer::corruptedThenGood()
{
    const Bytes good = wrapped("0146010A57FC40001");
    Bytes corrupted = good;
    corrupted[corrupted.size() - 2] = corrupted[corrupted.size() - 2] == '0' ? '1' : '0';
    Bytes corruptedData = good;
    corruptedData[7] = '9'; // a data byte hit by noise: LRC no longer matches
    Bytes stream = corrupted;
    append(stream, good);
    append(stream, corruptedData);
    append(stream, good);
    FaconDeframer d;
    std::vector<DeframedItem> items;
    d.feed(stream, items);
    QCOMPARE(items.size(), std::size_t(4));
    QVERIFY(items[0].error.has_value());
    QCOMPARE(items[0].error->kind, ErrorKind::BadChecksum);
    QCOMPARE(items[0].frame, corrupted);
    QVERIFY(!items[1].error.has_value());
    QCOMPARE(items[1].frame, good);
    QVERIFY(items[2].error.has_value());
    QCOMPARE(items[2].error->kind, ErrorKind::BadChecksum);
    QVERIFY(!items[3].error.has_value());
    QCOMPARE(items[3].frame, good);
    QCOMPARE(d.discardedBytes(), std::size_t(0)); // rejected frames are not garbage
}

void TestFaconDeframer::badHeaderAndShortFrames()
{
    struct Case
    {
        Bytes frame;
        ErrorKind kind;
    };
    Bytes badStation = wrapped("0G40");
    Bytes badLrc = wrapped("0140");
    badLrc[5] = 'Z';
    const std::vector<Case> cases = {
        {Bytes{0x02, 0x03}, ErrorKind::BadFrame},
        {Bytes{0x02, '0', '1', '4', '0', 0x03}, ErrorKind::BadFrame},
        {Bytes{0x02, '0', '1', '4', '0', 'C', 0x03}, ErrorKind::BadFrame},
        {badStation, ErrorKind::BadFrame},
        {badLrc, ErrorKind::BadFrame},
    };
    const Bytes good = wrapped("0140");
    for (const Case &c : cases) {
        FaconDeframer d;
        std::vector<DeframedItem> items;
        Bytes stream = c.frame;
        append(stream, good);
        d.feed(stream, items);
        QCOMPARE(items.size(), std::size_t(2));
        QVERIFY2(items[0].error.has_value(), qPrintable(toFacon(c.frame)));
        QCOMPARE(items[0].error->kind, c.kind);
        QVERIFY(!items[0].error->message.empty());
        QCOMPARE(items[0].frame, c.frame);
        QVERIFY(!items[1].error.has_value());
    }
    // Lower-case hex is accepted (the codec is lenient about it too).
    Bytes lower = wrapped("ab40");
    FaconDeframer d;
    std::vector<DeframedItem> items;
    d.feed(lower, items);
    QCOMPARE(items.size(), std::size_t(1));
    QVERIFY(!items[0].error.has_value());
}

void TestFaconDeframer::endlessStream()
{
    FaconDeframer d;
    std::vector<DeframedItem> items;
    const std::size_t noise = 10000;
    Bytes stream{0x02};
    stream.insert(stream.end(), noise, 'A');
    for (std::uint8_t b : stream) {
        d.feed(std::span(&b, 1), items);
        QVERIFY(d.bufferedBytes() <= d.maxFrameSize());
    }
    QCOMPARE(items.size(), std::size_t(1));
    QVERIFY(items[0].error.has_value());
    QCOMPARE(items[0].error->kind, ErrorKind::FrameTooLong);
    QCOMPARE(items[0].frame.size(), d.maxFrameSize());
    // After the rejection, bytes up to the next STX are garbage.
    QCOMPARE(d.discardedBytes(), stream.size() - d.maxFrameSize());
    QCOMPARE(d.bufferedBytes(), std::size_t(0));

    // Resynchronises on the next frame, also when fed as one big chunk.
    items.clear();
    Bytes chunk(3000, 'B');
    chunk.insert(chunk.begin(), 0x02);
    const Bytes good = wrapped("014EABCDEFG");
    append(chunk, good);
    d.feed(chunk, items);
    QVERIFY(d.bufferedBytes() <= d.maxFrameSize());
    QCOMPARE(items.size(), std::size_t(2));
    QCOMPARE(items[0].error->kind, ErrorKind::FrameTooLong);
    QVERIFY(!items[1].error.has_value());
    QCOMPARE(items[1].frame, good);
}

void TestFaconDeframer::largestFrame()
{
    // 500 data characters: exactly maxFrameSize bytes, still legal.
    const std::string body = "014E" + std::string(FaconCodec::maxDataChars, 'Q');
    const Bytes big = wrapped(body);
    QCOMPARE(big.size(), FaconCodec::maxFrameSize);
    FaconDeframer d;
    std::vector<DeframedItem> items;
    for (std::uint8_t b : big)
        d.feed(std::span(&b, 1), items);
    QCOMPARE(items.size(), std::size_t(1));
    QVERIFY(!items[0].error.has_value());
    QCOMPARE(items[0].frame, big);

    // One data character more no longer fits.
    items.clear();
    const Bytes tooBig = wrapped(body + "Q");
    d.feed(tooBig, items);
    QVERIFY(!items.empty());
    QCOMPARE(items[0].error->kind, ErrorKind::FrameTooLong);
    QCOMPARE(d.bufferedBytes(), std::size_t(0));
}

void TestFaconDeframer::resetDropsPartial()
{
    FaconDeframer d;
    std::vector<DeframedItem> items;
    const Bytes good = wrapped("0140");
    d.feed(std::span(good).first(4), items);
    QCOMPARE(d.bufferedBytes(), std::size_t(4));
    d.reset();
    QCOMPARE(d.bufferedBytes(), std::size_t(0));
    // The stale tail is garbage now, not part of the next frame.
    d.feed(std::span(good).subspan(4), items);
    QVERIFY(items.empty());
    QCOMPARE(d.discardedBytes(), good.size() - 4);
    d.feed(good, items);
    QCOMPARE(items.size(), std::size_t(1));
    QVERIFY(!items[0].error.has_value());
    QCOMPARE(items[0].frame, good);
}

QTEST_GUILESS_MAIN(TestFaconDeframer)
#include "tst_facondeframer.moc"
