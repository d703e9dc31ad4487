// ItemValues: a watch item split into poll entries and write requests, and the polled words joined
// back into the item's value, for every kind of item (discretes, 16/32-bit registers, floats and
// doubles over several registers, swapped word order).
#include "core/watch/itemassembler.h"
#include "core/watch/itemvalues.h"
#include "core/watch/watchmessages.h"

#include <QTest>

#include <bit>
#include <cmath>
#include <set>

using namespace Fatek;

Q_DECLARE_METATYPE(Fatek::WatchItemSpec)

namespace {

WatchItemSpec item(const char *address, DisplayFormat format, bool swapWords = false,
                   quint8 station = 1)
{
    WatchItemSpec spec;
    spec.address = *Address::parse(address);
    spec.format = format;
    spec.swapWords = swapWords;
    spec.station = station;
    return spec;
}

QStringList addressesOf(const QList<WatchEntry> &entries)
{
    QStringList list;
    for (const WatchEntry &e : entries)
        list << QString::fromStdString(e.address.toString());
    return list;
}

std::vector<std::uint32_t> words(std::initializer_list<std::uint32_t> list)
{
    return list;
}

} // namespace

class TestItemValues : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void elementsOfEachKind_data();
    void elementsOfEachKind();
    void pollIdsAreUniqueAndMapBack();
    void joinPlacesWordsByElement();
    void splitJoinRoundTrip_data();
    void splitJoinRoundTrip();
    void typedValuesBecomeWrites_data();
    void typedValuesBecomeWrites();
    void typingErrors_data();
    void typingErrors();
    void nonFiniteOnlyWhereAllowed();
    void wordsMustFitTheirElements();
    void setItemRenewsIdsOnlyWhenElementsChange();
    void assemblerJoinsElementsIntoItems();
    void assemblerKeepsWordsAcrossBatchesAndFormats();
};

void TestItemValues::elementsOfEachKind_data()
{
    QTest::addColumn<WatchItemSpec>("spec");
    QTest::addColumn<QStringList>("elements");
    QTest::addColumn<int>("width");
    QTest::newRow("discrete") << item("Y3", DisplayFormat::Bit) << QStringList{"Y3"} << 1;
    QTest::newRow("register") << item("R7", DisplayFormat::Signed) << QStringList{"R7"} << 16;
    QTest::newRow("32-bit register")
        << item("DR10", DisplayFormat::Unsigned) << QStringList{"DR10"} << 32;
    QTest::newRow("float over registers")
        << item("R100", DisplayFormat::Float32) << QStringList{"R100", "R101"} << 32;
    QTest::newRow("swapped float")
        << item("D4", DisplayFormat::Float32, true) << QStringList{"D4", "D5"} << 32;
    QTest::newRow("double over registers")
        << item("R0", DisplayFormat::Double64) << QStringList{"R0", "R1", "R2", "R3"} << 64;
    // 32-bit registers step by two: the second element of DR10 is DR12.
    QTest::newRow("double over 32-bit registers")
        << item("DR10", DisplayFormat::Double64) << QStringList{"DR10", "DR12"} << 64;
    // A format that does not fit the element still polls the element itself.
    QTest::newRow("float on a discrete")
        << item("X0", DisplayFormat::Float32) << QStringList{"X0"} << 1;
}

void TestItemValues::elementsOfEachKind()
{
    QFETCH(WatchItemSpec, spec);
    QFETCH(QStringList, elements);
    QFETCH(int, width);
    spec.station = 7;
    const ItemValues values(spec);
    QCOMPARE(values.elementCount(), static_cast<int>(elements.size()));
    QCOMPARE(values.width(), width);
    const QList<WatchEntry> entries = values.pollEntries(250);
    QCOMPARE(addressesOf(entries), elements);
    for (qsizetype i = 0; i < entries.size(); ++i) {
        QCOMPARE(entries.at(i).station, std::uint8_t(7));
        QCOMPARE(entries.at(i).intervalMs, 250);
        QCOMPARE(entries.at(i).id, values.pollIds()[static_cast<std::size_t>(i)]);
        QCOMPARE(QString::fromStdString(values.elementAddress(static_cast<int>(i)).toString()),
                 elements.at(i));
    }
}

void TestItemValues::pollIdsAreUniqueAndMapBack()
{
    const ItemValues a(item("R0", DisplayFormat::Double64));
    const ItemValues b(item("R0", DisplayFormat::Double64));
    const ItemValues c(item("Y0", DisplayFormat::Bit));
    std::set<std::uint64_t> seen;
    for (const ItemValues *v : {&a, &b, &c}) {
        for (std::size_t i = 0; i < v->pollIds().size(); ++i) {
            const std::uint64_t id = v->pollIds()[i];
            QVERIFY2(seen.insert(id).second, "a poll id was handed out twice");
            QCOMPARE(v->elementOf(id), static_cast<int>(i));
        }
    }
    QCOMPARE(seen.size(), std::size_t(4 + 4 + 1));
    // Another item's ids are not this one's.
    QCOMPARE(a.elementOf(b.pollIds().front()), -1);
    QCOMPARE(b.elementOf(c.pollIds().front()), -1);
    QCOMPARE(c.elementOf(0), -1);
}

void TestItemValues::joinPlacesWordsByElement()
{
    // R(n) is the low word, R(n+1) the high word: 1.5f = 0x3FC00000.
    const ItemValues f(item("R100", DisplayFormat::Float32));
    QCOMPARE(f.join(words({0x0000, 0x3FC0})), 0x3FC00000ull);
    QCOMPARE(f.text(f.join(words({0x0000, 0x3FC0}))), QStringLiteral("1.5"));
    // A PLC that stores the high word first: shown swapped, the same words read as 1.5.
    const ItemValues swapped(item("R100", DisplayFormat::Float32, true));
    QCOMPARE(swapped.join(words({0x3FC0, 0x0000})), 0x00003FC0ull);
    QCOMPARE(swapped.text(swapped.join(words({0x3FC0, 0x0000}))), QStringLiteral("1.5"));
    // 32-bit elements fill 32 bits each.
    const ItemValues d(item("DR10", DisplayFormat::Double64));
    const auto bits = std::bit_cast<std::uint64_t>(-2.25);
    QCOMPARE(
        d.join(words({static_cast<std::uint32_t>(bits), static_cast<std::uint32_t>(bits >> 32)})),
        bits);
    QCOMPARE(d.text(bits), QStringLiteral("-2.25"));
    const ItemValues q(item("R0", DisplayFormat::Double64));
    QCOMPARE(q.join(words({0x4444, 0x3333, 0x2222, 0x1111})), 0x1111222233334444ull);
    // A 32-bit register alone.
    const ItemValues dr(item("DR0", DisplayFormat::Signed));
    QCOMPARE(dr.join(words({0xFFFE7960})), 0xFFFE7960ull);
    QCOMPARE(dr.text(0xFFFE7960), QStringLiteral("-100000"));
    // Discretes: one bit.
    const ItemValues y(item("Y0", DisplayFormat::Bit));
    QCOMPARE(y.join(words({1})), 1ull);
    QCOMPARE(y.text(1), QStringLiteral("ON"));
    // Missing words count as 0, extra words and bits above an element's width are ignored.
    QCOMPARE(q.join(words({0x4444, 0x3333})), 0x0000000033334444ull);
    QCOMPARE(f.join(words({0x1, 0x2, 0x3})), 0x00020001ull);
    const ItemValues r(item("R5", DisplayFormat::Unsigned));
    QCOMPARE(r.join(words({0x12345})), 0x2345ull);
    QCOMPARE(y.join(words({2})), 0ull);
    QCOMPARE(r.join({}), 0ull);
}

void TestItemValues::splitJoinRoundTrip_data()
{
    QTest::addColumn<WatchItemSpec>("spec");
    QTest::addColumn<quint64>("raw");
    QTest::addColumn<std::vector<std::uint32_t>>("expected");
    QTest::newRow("bit on") << item("M9", DisplayFormat::Bit) << quint64(1) << words({1});
    QTest::newRow("bit off") << item("M9", DisplayFormat::Bit) << quint64(0) << words({0});
    QTest::newRow("16-bit") << item("R1", DisplayFormat::Hex) << quint64(0xBEEF) << words({0xBEEF});
    QTest::newRow("32-bit") << item("DR2", DisplayFormat::Unsigned) << quint64(0x12345678)
                            << words({0x12345678});
    QTest::newRow("float") << item("R10", DisplayFormat::Float32) << quint64(0x3FC00000)
                           << words({0x0000, 0x3FC0});
    QTest::newRow("swapped float") << item("R10", DisplayFormat::Float32, true)
                                   << quint64(0x00003FC0) << words({0x3FC0, 0x0000});
    QTest::newRow("double") << item("R10", DisplayFormat::Double64) << quint64(0x0123456789ABCDEF)
                            << words({0xCDEF, 0x89AB, 0x4567, 0x0123});
    QTest::newRow("double over DR")
        << item("DR10", DisplayFormat::Double64) << quint64(0x0123456789ABCDEF)
        << words({0x89ABCDEF, 0x01234567});
}

void TestItemValues::splitJoinRoundTrip()
{
    QFETCH(WatchItemSpec, spec);
    QFETCH(quint64, raw);
    QFETCH(std::vector<std::uint32_t>, expected);
    const ItemValues values(spec);
    QCOMPARE(values.split(raw), expected);
    QCOMPARE(values.join(expected), raw);
    QCOMPARE(values.join(values.split(raw)), raw);
}

void TestItemValues::typedValuesBecomeWrites_data()
{
    QTest::addColumn<WatchItemSpec>("spec");
    QTest::addColumn<QString>("text");
    QTest::addColumn<int>("command");
    QTest::addColumn<std::vector<std::uint32_t>>("written");
    const int registers = static_cast<int>(Command::WriteRegisters);
    const int discretes = static_cast<int>(Command::WriteDiscretes);
    QTest::newRow("decimal") << item("R0", DisplayFormat::Signed) << "1234" << registers
                             << words({1234});
    QTest::newRow("negative") << item("R0", DisplayFormat::Signed) << "-2" << registers
                              << words({0xFFFE});
    QTest::newRow("0x hex") << item("R0", DisplayFormat::Signed) << "0xBEEF" << registers
                            << words({0xBEEF});
    QTest::newRow("h suffix") << item("R0", DisplayFormat::Signed) << "1Ah" << registers
                              << words({0x1A});
    QTest::newRow("0b binary") << item("R0", DisplayFormat::Signed) << "0b101" << registers
                               << words({5});
    QTest::newRow("bare hex in hex format")
        << item("R0", DisplayFormat::Hex) << "1A" << registers << words({0x1A});
    QTest::newRow("bcd") << item("R0", DisplayFormat::Bcd) << "1234" << registers
                         << words({0x1234});
    QTest::newRow("32-bit negative")
        << item("DR200", DisplayFormat::Signed) << "-100000" << registers << words({0xFFFE7960});
    QTest::newRow("float") << item("R20", DisplayFormat::Float32) << "1.5" << registers
                           << words({0x0000, 0x3FC0});
    QTest::newRow("swapped float") << item("R20", DisplayFormat::Float32, true) << "1.5"
                                   << registers << words({0x3FC0, 0x0000});
    QTest::newRow("float raw bits") << item("R20", DisplayFormat::Float32) << "0x3FC00000"
                                    << registers << words({0x0000, 0x3FC0});
    QTest::newRow("double") << item("R20", DisplayFormat::Double64) << "1" << registers
                            << words({0, 0, 0, 0x3FF0});
    QTest::newRow("ascii") << item("R20", DisplayFormat::Ascii) << "AB" << registers
                           << words({0x4142});
    QTest::newRow("discrete on") << item("Y1", DisplayFormat::Bit) << "on" << discretes
                                 << words({1});
    QTest::newRow("discrete 0") << item("Y1", DisplayFormat::Bit) << "0" << discretes << words({0});
}

void TestItemValues::typedValuesBecomeWrites()
{
    QFETCH(WatchItemSpec, spec);
    QFETCH(QString, text);
    QFETCH(int, command);
    QFETCH(std::vector<std::uint32_t>, written);
    spec.station = 3;
    const ItemValues values(spec);
    const auto raw = values.parse(text);
    QVERIFY2(raw.ok(), raw.ok() ? "" : raw.error().text().c_str());
    QCOMPARE(values.split(*raw), written);
    const Request r = values.writeRequest(*raw);
    QCOMPARE(static_cast<int>(r.command), command);
    QCOMPARE(r.station, std::uint8_t(3));
    QCOMPARE(r.start, spec.address);
    QCOMPARE(r.values, written);
    QVERIFY2(validateRequest(r, Protocol::Facon).ok(), r.describe().c_str());
    // What was written reads back as the text typed (the same value).
    QCOMPARE(values.parse(values.text(values.join(r.values))).value(), *raw);
}

void TestItemValues::typingErrors_data()
{
    QTest::addColumn<WatchItemSpec>("spec");
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("message");
    QTest::newRow("16-bit overflow") << item("R0", DisplayFormat::Signed) << "70000"
                                     << "does not fit a 16-bit register";
    QTest::newRow("32-bit overflow") << item("DR0", DisplayFormat::Signed) << "0x100000000"
                                     << "does not fit a 32-bit value";
    QTest::newRow("float typed into an integer") << item("R0", DisplayFormat::Signed) << "1.5"
                                                 << "is not a number";
    QTest::newRow("not a float") << item("R0", DisplayFormat::Float32) << "abc"
                                 << "is not a number";
    QTest::newRow("float too large") << item("R0", DisplayFormat::Float32) << "1e39"
                                     << "does not fit a 32-bit float";
    QTest::newRow("discrete 2") << item("Y0", DisplayFormat::Bit) << "2"
                                << "is not a bit value";
    // Issue 48: a signed item reads 32768 back as -32768, an unsigned one -0x1 as 65535.
    QTest::newRow("signed 32768") << item("R0", DisplayFormat::Signed) << "32768"
                                  << "32768 does not fit a 16-bit register (-32768..32767)";
    QTest::newRow("unsigned -0x1") << item("R0", DisplayFormat::Unsigned) << "-0x1"
                                   << "-0x1 does not fit a 16-bit register (0..65535)";
    QTest::newRow("empty") << item("R0", DisplayFormat::Signed) << "  "
                           << "No value typed";
    QTest::newRow("bcd digit") << item("R0", DisplayFormat::Bcd) << "12A4"
                               << "not a BCD number";
    QTest::newRow("ascii too long") << item("R0", DisplayFormat::Ascii) << "ABC"
                                    << "holds 2 ASCII characters";
}

void TestItemValues::typingErrors()
{
    QFETCH(WatchItemSpec, spec);
    QFETCH(QString, text);
    QFETCH(QString, message);
    const auto raw = ItemValues(spec).parse(text);
    QVERIFY(!raw.ok());
    const QString error = QString::fromStdString(raw.error().text());
    QVERIFY2(error.contains(message), qPrintable(error));
}

// Issue 48: NaN and infinities went to a float register as "inf" while 1e39 was refused. The one
// check of every writer (watch tables, fatek-cli write, the gateway's value and words).
void TestItemValues::nonFiniteOnlyWhereAllowed()
{
    WatchItemSpec spec = item("R20", DisplayFormat::Float32);
    const ItemValues strict(spec);
    for (const char *text : {"nan", "inf", "-inf", "Infinity", "0x7F800000", "0xFFC00000"}) {
        const auto raw = strict.parse(QString::fromLatin1(text));
        QVERIFY2(!raw.ok(), text);
        QCOMPARE(raw.error().message.id, MsgId::ValueNotFinite);
    }
    QCOMPARE(QString::fromStdString(strict.parse(QStringLiteral(" inf ")).error().text()),
             QStringLiteral("inf is not a finite number: NaN and infinities are written only to "
                            "an item whose \"allowNonFinite\" option is on"));
    // +inf as the words the gateway takes, swapped or not.
    QCOMPARE(strict.fromWords(words({0, 0x7F80})).error().message.id, MsgId::ValueNotFinite);
    QVERIFY(strict.fromWords(words({0, 0x3FC0})).ok());
    const ItemValues swapped(item("R20", DisplayFormat::Float32, true));
    QCOMPARE(swapped.fromWords(words({0x7F80, 0})).error().message.id, MsgId::ValueNotFinite);
    QVERIFY(swapped.fromWords(words({0, 0x7F80})).ok()); // a tiny number, swapped
    const ItemValues doubles(item("R20", DisplayFormat::Double64));
    QCOMPARE(doubles.parse(QStringLiteral("-Inf")).error().message.id, MsgId::ValueNotFinite);
    // The same bits in an integer format are a number like any other.
    QVERIFY(ItemValues(item("DR20", DisplayFormat::Hex)).parse(QStringLiteral("0x7F800000")).ok());

    spec.allowNonFinite = true;
    const ItemValues allowed(spec);
    QCOMPARE(allowed.parse(QStringLiteral("-inf")).value(), std::uint64_t(0xFF800000));
    QVERIFY(std::isnan(std::bit_cast<float>(
        static_cast<std::uint32_t>(allowed.parse(QStringLiteral("nan")).value()))));
    QCOMPARE(allowed.fromWords(words({0, 0x7F80})).value(), std::uint64_t(0x7F800000));
    // Too large stays too large: the option is about NaN and infinities only.
    QVERIFY(!allowed.parse(QStringLiteral("1e39")).ok());
}

// Issue 48: join() keeps an element's bits only, so {"words":[70000]} wrote 4464 and [2] on a
// bit wrote OFF. fromWords() refuses them, naming the element.
void TestItemValues::wordsMustFitTheirElements()
{
    const auto refused = [](const WatchItemSpec &spec, std::vector<std::uint32_t> given) {
        const auto raw = ItemValues(spec).fromWords(given);
        return raw.ok() ? QString() : QString::fromStdString(raw.error().text());
    };
    QCOMPARE(refused(item("R100", DisplayFormat::Signed), words({70000})),
             QStringLiteral("R100: 70000 does not fit a 16-bit register (0..65535)"));
    QCOMPARE(refused(item("M10", DisplayFormat::Bit), words({2})),
             QStringLiteral("M10: 2 does not fit a bit (0..1)"));
    QCOMPARE(refused(item("Y4", DisplayFormat::Bit), words({1000})),
             QStringLiteral("Y4: 1000 does not fit a bit (0..1)"));
    QCOMPARE(refused(item("R100", DisplayFormat::Float32), words({0, 65536})),
             QStringLiteral("R101: 65536 does not fit a 16-bit register (0..65535)"));
    QCOMPARE(refused(item("R100", DisplayFormat::Unsigned), words({65535})), QString());
    QCOMPARE(refused(item("M10", DisplayFormat::Bit), words({1})), QString());
    QCOMPARE(refused(item("DR10", DisplayFormat::Unsigned), words({0xFFFFFFFF})), QString());
    const ItemValues dr(item("DR10", DisplayFormat::Signed));
    QCOMPARE(dr.fromWords(words({0xFFFFFFFF})).value(), std::uint64_t(0xFFFFFFFF));
}

void TestItemValues::setItemRenewsIdsOnlyWhenElementsChange()
{
    ItemValues values(item("R100", DisplayFormat::Signed));
    const std::vector<std::uint64_t> first(values.pollIds().begin(), values.pollIds().end());
    auto ids = [&] {
        return std::vector<std::uint64_t>(values.pollIds().begin(), values.pollIds().end());
    };

    // Same elements: name, station, another one-register format.
    WatchItemSpec spec = values.item();
    spec.name = QStringLiteral("Tank");
    spec.station = 4;
    spec.format = DisplayFormat::Hex;
    QVERIFY(!values.setItem(spec));
    QCOMPARE(ids(), first);
    QCOMPARE(values.item(), spec);
    QCOMPARE(values.pollEntries(100).front().station, std::uint8_t(4));

    // A float spans two registers: new ids, none of the old ones.
    spec.format = DisplayFormat::Float32;
    QVERIFY(values.setItem(spec));
    QCOMPARE(values.pollIds().size(), std::size_t(2));
    QCOMPARE(values.elementOf(first.front()), -1);
    const std::vector<std::uint64_t> asFloat = ids();

    // Swapping words keeps the elements.
    spec.swapWords = true;
    QVERIFY(!values.setItem(spec));
    QCOMPARE(ids(), asFloat);

    // Another address with as many elements is another pair of elements.
    spec.address = *Address::parse("R200");
    QVERIFY(values.setItem(spec));
    QVERIFY(ids() != asFloat);
    QCOMPARE(addressesOf(values.pollEntries(100)), (QStringList{"R200", "R201"}));
}

namespace {

WatchValue elementValue(std::uint64_t pollId, std::uint32_t value,
                        ValueQuality quality = ValueQuality::Good, int second = 0)
{
    WatchValue v;
    v.itemId = pollId;
    v.value = value;
    v.quality = quality;
    v.timestamp = QDateTime(QDate(2026, 11, 27), QTime(8, 0, second), Qt::UTC);
    if (quality != ValueQuality::Good)
        v.error = Message::text("timeout");
    return v;
}

} // namespace

void TestItemValues::assemblerJoinsElementsIntoItems()
{
    ItemAssembler assembler;
    assembler.setItems({{11, item("R100", DisplayFormat::Float32), 250},
                        {12, item("X0", DisplayFormat::Bit), 1000},
                        {13, item("DR10", DisplayFormat::Double64), 250}});
    const QList<WatchEntry> entries = assembler.pollEntries();
    QCOMPARE(addressesOf(entries), (QStringList{"R100", "R101", "X0", "DR10", "DR12"}));
    QCOMPARE(entries.at(2).intervalMs, 1000);

    // 1.5f = 0x3FC00000 (high word in R101); X0 not in this batch; the double's high half is
    // stale: the item is stale, and has no value until every element was read once.
    QList<WatchItemValue> values = assembler.assemble(
        {elementValue(entries.at(1).id, 0x3FC0, ValueQuality::Good, 2),
         elementValue(entries.at(0).id, 0x0000, ValueQuality::Good, 1),
         elementValue(entries.at(3).id, 0), elementValue(entries.at(4).id, 7, ValueQuality::Stale),
         elementValue(999999999, 5)});
    QCOMPARE(values.size(), 2);
    QCOMPARE(values.at(0).key, std::uint64_t(11));
    QCOMPARE(values.at(0).raw, std::uint64_t(0x3FC00000));
    QCOMPARE(values.at(0).words, words({0x0000, 0x3FC0}));
    QVERIFY(values.at(0).hasValue);
    QCOMPARE(values.at(0).quality, ValueQuality::Good);
    QCOMPARE(values.at(0).time.time().second(), 2); // the newest element's time
    QCOMPARE(values.at(1).key, std::uint64_t(13));
    QCOMPARE(values.at(1).quality, ValueQuality::Stale);
    QCOMPARE(values.at(1).error, Message::text("timeout"));
    QVERIFY(!values.at(1).hasValue);
    QCOMPARE(values.at(1).words, words({0, 0})); // a stale word is not taken as read

    // Only one of the float's elements came: stale, "not read in this cycle", the last words kept.
    values = assembler.assemble({elementValue(entries.at(0).id, 0x0001)});
    QCOMPARE(values.size(), 1);
    QCOMPARE(values.at(0).quality, ValueQuality::Stale);
    QCOMPARE(values.at(0).error.id, MsgId::GatewayNoValueThisCycle);
    QCOMPARE(values.at(0).raw, std::uint64_t(0x3FC00001));

    // A refused element makes the item an error, whatever its other element says.
    values = assembler.assemble({elementValue(entries.at(0).id, 0, ValueQuality::Error),
                                 elementValue(entries.at(1).id, 0x4000)});
    QCOMPARE(values.at(0).quality, ValueQuality::Error);

    // The link went away: every item at once, the last words kept.
    values = assembler.markAll(ValueQuality::Stale, Message::text("link lost"));
    QCOMPARE(values.size(), 3);
    QCOMPARE(values.at(0).raw, std::uint64_t(0x40000001));
    QCOMPARE(values.at(2).error, Message::text("link lost"));
}

void TestItemValues::assemblerKeepsWordsAcrossBatchesAndFormats()
{
    ItemAssembler assembler;
    assembler.setItems({{21, item("R0", DisplayFormat::Signed), 100},
                        {22, item("R10", DisplayFormat::Unsigned), 100}});
    QList<WatchEntry> entries = assembler.pollEntries();
    assembler.assemble({elementValue(entries.at(0).id, 0xFFFF), elementValue(entries.at(1).id, 9)});

    // Another one-register format over the same element: the same poll ids, the words stay.
    // Another span, or another station: new poll ids, nothing of the old.
    WatchItemSpec hex = item("R0", DisplayFormat::Hex);
    WatchItemSpec otherStation = item("R10", DisplayFormat::Unsigned, false, 2);
    assembler.setItems({{21, hex, 100}, {22, otherStation, 100}});
    const QList<WatchEntry> next = assembler.pollEntries();
    QCOMPARE(next.at(0).id, entries.at(0).id);
    QVERIFY(next.at(1).id != entries.at(1).id);
    QCOMPARE(next.at(1).station, std::uint8_t(2));
    QList<WatchItemValue> values = assembler.markAll(ValueQuality::Stale, {});
    QCOMPARE(values.at(0).raw, std::uint64_t(0xFFFF));
    QVERIFY(values.at(0).hasValue);
    QVERIFY(!values.at(1).hasValue);
    // Values for the old poll ids match nothing.
    QVERIFY(assembler.assemble({elementValue(entries.at(1).id, 3)}).isEmpty());

    assembler.setItems({{21, item("R0", DisplayFormat::Float32), 100}});
    QCOMPARE(assembler.itemCount(), 1);
    QCOMPARE(assembler.pollEntries().size(), 2);
    QVERIFY(assembler.assemble({elementValue(entries.at(0).id, 1)}).isEmpty());
    QVERIFY(!assembler.markAll(ValueQuality::Stale, {}).at(0).hasValue);
}

QTEST_MAIN(TestItemValues)
#include "tst_itemvalues.moc"
