#include "core/watch/valueformat.h"

#include <QTest>

#include <bit>
#include <cmath>
#include <limits>

using namespace Fatek;

Q_DECLARE_METATYPE(Fatek::DisplayFormat)

namespace {

QString errorText(const Result<std::uint64_t> &r)
{
    return r.ok() ? QString() : QString::fromStdString(r.error().text());
}

quint64 bitsOf(float f)
{
    return std::bit_cast<std::uint32_t>(f);
}

quint64 bitsOf(double d)
{
    return std::bit_cast<std::uint64_t>(d);
}

} // namespace

class TestValueFormat : public QObject
{
    Q_OBJECT

private slots:
    void names();
    void availability();
    void widthsOfAddresses();
    void swapWordsIsItsOwnInverse();
    void format_data();
    void format();
    void parse_data();
    void parse();
    void parseNaN();
    void rejects_data();
    void rejects();
    void roundTripExact_data();
    void roundTripExact();
    void roundTripFloatText_data();
    void roundTripFloatText();
    void numberIsWhatTheValueStandsFor();
};

void TestValueFormat::names()
{
    const QList<DisplayFormat> all = ValueFormat::allFormats();
    QCOMPARE(all.size(), 9);
    const QStringList expected{"bit", "unsigned", "signed", "hex",   "binary",
                               "bcd", "float",    "ascii",  "double"};
    QStringList names;
    for (DisplayFormat f : all) {
        names.append(ValueFormat::name(f));
        QCOMPARE(ValueFormat::fromName(ValueFormat::name(f)), std::optional<DisplayFormat>(f));
    }
    QCOMPARE(names, expected);
    QCOMPARE(ValueFormat::fromName(u"FLOAT"), std::optional<DisplayFormat>(DisplayFormat::Float32));
    QCOMPARE(ValueFormat::fromName(u" Hex "), std::optional<DisplayFormat>(DisplayFormat::Hex));
    QCOMPARE(ValueFormat::fromName(u"float32"),
             std::optional<DisplayFormat>(DisplayFormat::Float32));
    QCOMPARE(ValueFormat::fromName(u"double64"),
             std::optional<DisplayFormat>(DisplayFormat::Double64));
    QVERIFY(!ValueFormat::fromName(u"decimal"));
    QVERIFY(!ValueFormat::fromName(u""));
}

void TestValueFormat::availability()
{
    using F = DisplayFormat;
    QVERIFY(ValueFormat::isAvailable(F::Bit, 1));
    QVERIFY(!ValueFormat::isAvailable(F::Bit, 16));
    QVERIFY(ValueFormat::isAvailable(F::Unsigned, 1));
    QVERIFY(ValueFormat::isAvailable(F::Hex, 64));
    QVERIFY(!ValueFormat::isAvailable(F::Signed, 1));
    QVERIFY(ValueFormat::isAvailable(F::Signed, 16));
    QVERIFY(!ValueFormat::isAvailable(F::Bcd, 1));
    QVERIFY(!ValueFormat::isAvailable(F::Float32, 16));
    QVERIFY(ValueFormat::isAvailable(F::Float32, 32));
    QVERIFY(!ValueFormat::isAvailable(F::Float32, 64));
    QVERIFY(!ValueFormat::isAvailable(F::Double64, 32));
    QVERIFY(ValueFormat::isAvailable(F::Double64, 64));
    QVERIFY(ValueFormat::isAvailable(F::Ascii, 64));
    QVERIFY(!ValueFormat::isAvailable(F::Unsigned, 8));
    QVERIFY(!ValueFormat::isAvailable(F::Unsigned, 0));
}

void TestValueFormat::widthsOfAddresses()
{
    const auto addr = [](const char *text) {
        return *Address::parse(text);
    };
    using F = DisplayFormat;
    QCOMPARE(ValueFormat::valueWidth(addr("X0"), F::Bit), 1);
    QCOMPARE(ValueFormat::elementCount(addr("X0"), F::Bit), 1);
    QCOMPARE(ValueFormat::valueWidth(addr("X0"), F::Float32), 0);
    QCOMPARE(ValueFormat::elementCount(addr("X0"), F::Signed), 0);
    QCOMPARE(ValueFormat::valueWidth(addr("R100"), F::Signed), 16);
    QCOMPARE(ValueFormat::valueWidth(addr("R100"), F::Bit), 0);
    QCOMPARE(ValueFormat::valueWidth(addr("R100"), F::Float32), 32);
    QCOMPARE(ValueFormat::elementCount(addr("R100"), F::Float32), 2);
    QCOMPARE(ValueFormat::valueWidth(addr("R100"), F::Double64), 64);
    QCOMPARE(ValueFormat::elementCount(addr("R100"), F::Double64), 4);
    QCOMPARE(ValueFormat::valueWidth(addr("DR100"), F::Unsigned), 32);
    QCOMPARE(ValueFormat::elementCount(addr("DR100"), F::Float32), 1);
    QCOMPARE(ValueFormat::elementCount(addr("DR100"), F::Double64), 2);
    QCOMPARE(ValueFormat::elementCount(addr("WY0"), F::Float32), 2);
    QCOMPARE(ValueFormat::defaultFormat(addr("Y3")), F::Bit);
    QCOMPARE(ValueFormat::defaultFormat(addr("D7")), F::Signed);
    QCOMPARE(ValueFormat::defaultFormat(addr("DWM0")), F::Signed);
}

void TestValueFormat::swapWordsIsItsOwnInverse()
{
    QCOMPARE(quint64(ValueFormat::swapWords(0x12345678u, 32)), quint64(0x56781234u));
    QCOMPARE(quint64(ValueFormat::swapWords(0x1111222233334444ull, 64)),
             quint64(0x4444333322221111ull));
    QCOMPARE(quint64(ValueFormat::swapWords(0x1234u, 16)), quint64(0x1234u));
    for (quint64 v : {0ull, 0x0102030405060708ull, ~0ull, 0x8000000000000001ull}) {
        QCOMPARE(quint64(ValueFormat::swapWords(ValueFormat::swapWords(v, 64), 64)), v);
        const quint64 low = v & 0xFFFFFFFFu;
        QCOMPARE(quint64(ValueFormat::swapWords(ValueFormat::swapWords(low, 32), 32)), low);
    }
}

void TestValueFormat::format_data()
{
    QTest::addColumn<quint64>("raw");
    QTest::addColumn<int>("width");
    QTest::addColumn<DisplayFormat>("fmt");
    QTest::addColumn<bool>("swap");
    QTest::addColumn<QString>("text");
    using F = DisplayFormat;

    QTest::newRow("bit on") << 1ull << 1 << F::Bit << false << "ON";
    QTest::newRow("bit off") << 0ull << 1 << F::Bit << false << "OFF";
    QTest::newRow("bit unsigned") << 1ull << 1 << F::Unsigned << false << "1";
    QTest::newRow("bit hex") << 1ull << 1 << F::Hex << false << "0x1";
    QTest::newRow("bit binary") << 1ull << 1 << F::Binary << false << "1";

    QTest::newRow("u16 0") << 0ull << 16 << F::Unsigned << false << "0";
    QTest::newRow("u16 max") << 0xFFFFull << 16 << F::Unsigned << false << "65535";
    QTest::newRow("u16 masks high bits") << 0x12345ull << 16 << F::Unsigned << false << "9029";
    QTest::newRow("u32 max") << 0xFFFFFFFFull << 32 << F::Unsigned << false << "4294967295";
    QTest::newRow("u32 swapped") << 0x00010002ull << 32 << F::Unsigned << true << "131073";
    QTest::newRow("u64 max") << ~0ull << 64 << F::Unsigned << false << "18446744073709551615";

    QTest::newRow("s16 -1") << 0xFFFFull << 16 << F::Signed << false << "-1";
    QTest::newRow("s16 min") << 0x8000ull << 16 << F::Signed << false << "-32768";
    QTest::newRow("s16 max") << 0x7FFFull << 16 << F::Signed << false << "32767";
    QTest::newRow("s32 min") << 0x80000000ull << 32 << F::Signed << false << "-2147483648";
    QTest::newRow("s32 swapped -2") << 0xFFFEFFFFull << 32 << F::Signed << true << "-2";
    QTest::newRow("s64 min") << 0x8000000000000000ull << 64 << F::Signed << false
                             << "-9223372036854775808";
    QTest::newRow("s64 max") << 0x7FFFFFFFFFFFFFFFull << 64 << F::Signed << false
                             << "9223372036854775807";

    QTest::newRow("hex16") << 0x1Aull << 16 << F::Hex << false << "0x001A";
    QTest::newRow("hex16 max") << 0xFFFFull << 16 << F::Hex << false << "0xFFFF";
    QTest::newRow("hex32") << 0xABCDEFull << 32 << F::Hex << false << "0x00ABCDEF";
    QTest::newRow("hex32 swapped") << 0x12345678ull << 32 << F::Hex << true << "0x56781234";
    QTest::newRow("hex64") << 0x1ull << 64 << F::Hex << false << "0x0000000000000001";
    QTest::newRow("hex64 swapped")
        << 0x1111222233334444ull << 64 << F::Hex << true << "0x4444333322221111";

    QTest::newRow("bin16") << 1ull << 16 << F::Binary << false << "0000 0000 0000 0001";
    QTest::newRow("bin16 pattern")
        << 0xA5C3ull << 16 << F::Binary << false << "1010 0101 1100 0011";
    QTest::newRow("bin32") << 0x80000001ull << 32 << F::Binary << false
                           << "1000 0000 0000 0000 0000 0000 0000 0001";

    QTest::newRow("bcd16") << 0x1234ull << 16 << F::Bcd << false << "1234";
    QTest::newRow("bcd16 zero") << 0ull << 16 << F::Bcd << false << "0";
    QTest::newRow("bcd16 leading zeros") << 0x0042ull << 16 << F::Bcd << false << "42";
    QTest::newRow("bcd16 invalid") << 0x1A00ull << 16 << F::Bcd << false << "?BCD 0x1A00";
    QTest::newRow("bcd32 max") << 0x99999999ull << 32 << F::Bcd << false << "99999999";
    QTest::newRow("bcd32 swapped") << 0x56781234ull << 32 << F::Bcd << true << "12345678";

    QTest::newRow("float pi") << 0x40490FDBull << 32 << F::Float32 << false << "3.141593";
    QTest::newRow("float 1") << 0x3F800000ull << 32 << F::Float32 << false << "1";
    QTest::newRow("float -2.5") << 0xC0200000ull << 32 << F::Float32 << false << "-2.5";
    QTest::newRow("float 0.1") << bitsOf(0.1f) << 32 << F::Float32 << false << "0.1";
    QTest::newRow("float big") << bitsOf(1.5e10f) << 32 << F::Float32 << false << "1.5e+10";
    QTest::newRow("float nan") << 0x7FC00000ull << 32 << F::Float32 << false << "NaN";
    QTest::newRow("float nan payload") << 0xFFC00001ull << 32 << F::Float32 << false << "NaN";
    QTest::newRow("float inf") << 0x7F800000ull << 32 << F::Float32 << false << "Inf";
    QTest::newRow("float -inf") << 0xFF800000ull << 32 << F::Float32 << false << "-Inf";
    QTest::newRow("float -0") << 0x80000000ull << 32 << F::Float32 << false << "-0";
    QTest::newRow("float pi low word high")
        << 0x0FDB4049ull << 32 << F::Float32 << true << "3.141593";

    QTest::newRow("double pi") << bitsOf(3.141592653589793) << 64 << F::Double64 << false
                               << "3.141592653589793";
    QTest::newRow("double 0.1") << bitsOf(0.1) << 64 << F::Double64 << false << "0.1";
    QTest::newRow("double 1 swapped") << 0x3FF0ull << 64 << F::Double64 << true << "1";
    QTest::newRow("double nan") << bitsOf(std::numeric_limits<double>::quiet_NaN()) << 64
                                << F::Double64 << false << "NaN";
    QTest::newRow("double -inf") << bitsOf(-std::numeric_limits<double>::infinity()) << 64
                                 << F::Double64 << false << "-Inf";

    QTest::newRow("ascii16") << 0x4142ull << 16 << F::Ascii << false << "AB";
    QTest::newRow("ascii16 nul") << 0x4100ull << 16 << F::Ascii << false << "A.";
    QTest::newRow("ascii16 control") << 0x0D7Full << 16 << F::Ascii << false << "..";
    QTest::newRow("ascii32 R(n) first") << 0x43444142ull << 32 << F::Ascii << false << "ABCD";
    QTest::newRow("ascii32 swapped") << 0x43444142ull << 32 << F::Ascii << true << "CDAB";
    QTest::newRow("ascii64") << 0x4748454643444142ull << 64 << F::Ascii << false << "ABCDEFGH";

    QTest::newRow("float on 16 bits")
        << 0ull << 16 << F::Float32 << false << "(float needs 32 bits)";
    QTest::newRow("bit on 16 bits") << 0ull << 16 << F::Bit << false << "(bit needs a single bit)";
    QTest::newRow("signed on 1 bit")
        << 0ull << 1 << F::Signed << false << "(signed needs 16 bits or more)";
    QTest::newRow("8 bits") << 0ull << 8 << F::Unsigned << false << "(no 8-bit values)";
}

void TestValueFormat::format()
{
    QFETCH(quint64, raw);
    QFETCH(int, width);
    QFETCH(DisplayFormat, fmt);
    QFETCH(bool, swap);
    QFETCH(QString, text);
    QCOMPARE(ValueFormat::format(raw, width, fmt, swap), text);
}

void TestValueFormat::parse_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<int>("width");
    QTest::addColumn<DisplayFormat>("fmt");
    QTest::addColumn<bool>("swap");
    QTest::addColumn<quint64>("raw");
    using F = DisplayFormat;

    QTest::newRow("bit ON") << "ON" << 1 << F::Bit << false << 1ull;
    QTest::newRow("bit on") << "on" << 1 << F::Bit << false << 1ull;
    QTest::newRow("bit true") << "True" << 1 << F::Bit << false << 1ull;
    QTest::newRow("bit 1") << "1" << 1 << F::Bit << false << 1ull;
    QTest::newRow("bit 0x1") << "0x1" << 1 << F::Bit << false << 1ull;
    QTest::newRow("bit OFF") << " OFF " << 1 << F::Bit << false << 0ull;
    QTest::newRow("bit false") << "false" << 1 << F::Bit << false << 0ull;
    QTest::newRow("bit 0") << "0" << 1 << F::Bit << false << 0ull;
    QTest::newRow("bit as unsigned ON") << "ON" << 1 << F::Unsigned << false << 1ull;

    QTest::newRow("decimal") << "100" << 16 << F::Signed << false << 100ull;
    QTest::newRow("plus") << "+5" << 16 << F::Signed << false << 5ull;
    QTest::newRow("spaces") << "  42 " << 16 << F::Unsigned << false << 42ull;
    QTest::newRow("-1") << "-1" << 16 << F::Signed << false << 0xFFFFull;
    QTest::newRow("-32768") << "-32768" << 16 << F::Signed << false << 0x8000ull;
    QTest::newRow("32767 signed") << "32767" << 16 << F::Signed << false << 0x7FFFull;
    // Bits typed as such fill the register in any format (issue 48: a decimal does not).
    QTest::newRow("0xFFFF signed") << "0xFFFF" << 16 << F::Signed << false << 0xFFFFull;
    QTest::newRow("-0x8000 signed") << "-0x8000" << 16 << F::Signed << false << 0x8000ull;
    QTest::newRow("65535 unsigned") << "65535" << 16 << F::Unsigned << false << 0xFFFFull;
    QTest::newRow("0x1A") << "0x1A" << 16 << F::Signed << false << 0x1Aull;
    QTest::newRow("0X1a") << "0X1a" << 16 << F::Unsigned << false << 0x1Aull;
    QTest::newRow("1Ah") << "1Ah" << 16 << F::Signed << false << 0x1Aull;
    QTest::newRow("ffffh") << "ffffh" << 16 << F::Unsigned << false << 0xFFFFull;
    QTest::newRow("0b101") << "0b101" << 16 << F::Signed << false << 5ull;
    QTest::newRow("-0x10") << "-0x10" << 16 << F::Signed << false << 0xFFF0ull;
    QTest::newRow("s32 min") << "-2147483648" << 32 << F::Signed << false << 0x80000000ull;
    QTest::newRow("u32 max") << "4294967295" << 32 << F::Unsigned << false << 0xFFFFFFFFull;
    QTest::newRow("s32 swapped") << "1" << 32 << F::Signed << true << 0x00010000ull;
    QTest::newRow("u64 max") << "18446744073709551615" << 64 << F::Unsigned << false << ~0ull;
    QTest::newRow("s64 min") << "-9223372036854775808" << 64 << F::Signed << false
                             << 0x8000000000000000ull;
    QTest::newRow("u64 swapped") << "1" << 64 << F::Unsigned << true << 0x0001000000000000ull;

    QTest::newRow("hex bare") << "1A" << 16 << F::Hex << false << 0x1Aull;
    QTest::newRow("hex shown") << "0x001A" << 16 << F::Hex << false << 0x1Aull;
    QTest::newRow("hex 0B12 is hex") << "0B12" << 16 << F::Hex << false << 0xB12ull;
    QTest::newRow("hex h") << "FFh" << 16 << F::Hex << false << 0xFFull;
    QTest::newRow("hex grouped") << "dead_beef" << 32 << F::Hex << false << 0xDEADBEEFull;
    QTest::newRow("hex32 swapped") << "0x56781234" << 32 << F::Hex << true << 0x12345678ull;

    QTest::newRow("binary shown") << "0000 0000 0000 0001" << 16 << F::Binary << false << 1ull;
    QTest::newRow("binary bare") << "101" << 16 << F::Binary << false << 5ull;
    QTest::newRow("binary 0b") << "0b1111 0000" << 16 << F::Binary << false << 0xF0ull;
    QTest::newRow("binary hex") << "0x10" << 16 << F::Binary << false << 0x10ull;

    QTest::newRow("bcd") << "1234" << 16 << F::Bcd << false << 0x1234ull;
    QTest::newRow("bcd leading zeros") << "00001234" << 16 << F::Bcd << false << 0x1234ull;
    QTest::newRow("bcd 0") << "0" << 16 << F::Bcd << false << 0ull;
    QTest::newRow("bcd raw hex") << "0x1A00" << 16 << F::Bcd << false << 0x1A00ull;
    QTest::newRow("bcd32 swapped") << "12345678" << 32 << F::Bcd << true << 0x56781234ull;

    QTest::newRow("float 1") << "1" << 32 << F::Float32 << false << 0x3F800000ull;
    QTest::newRow("float -2.5") << "-2.5" << 32 << F::Float32 << false << 0xC0200000ull;
    QTest::newRow("float exp") << "1.5e+10" << 32 << F::Float32 << false << bitsOf(1.5e10f);
    QTest::newRow("float 0.1") << "0.1" << 32 << F::Float32 << false << bitsOf(0.1f);
    QTest::newRow("float .5") << ".5" << 32 << F::Float32 << false << 0x3F000000ull;
    QTest::newRow("float inf") << "inf" << 32 << F::Float32 << false << 0x7F800000ull;
    QTest::newRow("float -Inf") << "-Inf" << 32 << F::Float32 << false << 0xFF800000ull;
    QTest::newRow("float -0") << "-0" << 32 << F::Float32 << false << 0x80000000ull;
    QTest::newRow("float raw bits") << "0x3F800000" << 32 << F::Float32 << false << 0x3F800000ull;
    QTest::newRow("float raw h") << "3F800000h" << 32 << F::Float32 << false << 0x3F800000ull;
    QTest::newRow("float swapped") << "1" << 32 << F::Float32 << true << 0x00003F80ull;
    QTest::newRow("float max") << "3.402823e+38" << 32 << F::Float32 << false
                               << bitsOf(3.402823e38f);

    QTest::newRow("double 1") << "1" << 64 << F::Double64 << false << 0x3FF0000000000000ull;
    QTest::newRow("double swapped") << "1" << 64 << F::Double64 << true << 0x3FF0ull;
    QTest::newRow("double 1e300") << "1e300" << 64 << F::Double64 << false << bitsOf(1e300);
    QTest::newRow("double -infinity") << "-Infinity" << 64 << F::Double64 << false
                                      << bitsOf(-std::numeric_limits<double>::infinity());

    QTest::newRow("ascii16") << "AB" << 16 << F::Ascii << false << 0x4142ull;
    QTest::newRow("ascii16 short") << "A" << 16 << F::Ascii << false << 0x4100ull;
    QTest::newRow("ascii16 spaces kept") << " A" << 16 << F::Ascii << false << 0x2041ull;
    QTest::newRow("ascii empty") << "" << 16 << F::Ascii << false << 0ull;
    QTest::newRow("ascii32") << "ABCD" << 32 << F::Ascii << false << 0x43444142ull;
    QTest::newRow("ascii32 swapped") << "ABCD" << 32 << F::Ascii << true << 0x41424344ull;
    QTest::newRow("ascii64") << "ABCDEFGH" << 64 << F::Ascii << false << 0x4748454643444142ull;
    QTest::newRow("ascii digits are text") << "12" << 16 << F::Ascii << false << 0x3132ull;
}

void TestValueFormat::parse()
{
    QFETCH(QString, text);
    QFETCH(int, width);
    QFETCH(DisplayFormat, fmt);
    QFETCH(bool, swap);
    QFETCH(quint64, raw);
    const auto r = ValueFormat::parse(text, width, fmt, swap);
    QVERIFY2(r.ok(), qPrintable(errorText(r)));
    QCOMPARE(quint64(*r), raw);
}

void TestValueFormat::parseNaN()
{
    for (const QString &text :
         {QStringLiteral("NaN"), QStringLiteral("nan"), QStringLiteral("-NaN")}) {
        const auto f = ValueFormat::parse(text, 32, DisplayFormat::Float32);
        QVERIFY(f.ok());
        QVERIFY(std::isnan(std::bit_cast<float>(static_cast<std::uint32_t>(*f))));
        QCOMPARE(ValueFormat::format(*f, 32, DisplayFormat::Float32), QStringLiteral("NaN"));
        const auto d = ValueFormat::parse(text, 64, DisplayFormat::Double64, true);
        QVERIFY(d.ok());
        QVERIFY(std::isnan(std::bit_cast<double>(ValueFormat::swapWords(*d, 64))));
        QCOMPARE(ValueFormat::format(*d, 64, DisplayFormat::Double64, true), QStringLiteral("NaN"));
    }
}

void TestValueFormat::rejects_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<int>("width");
    QTest::addColumn<DisplayFormat>("fmt");
    QTest::addColumn<QString>("message");
    using F = DisplayFormat;

    QTest::newRow("70000") << "70000" << 16 << F::Signed
                           << "70000 does not fit a 16-bit register (-32768..32767)";
    QTest::newRow("-32769") << "-32769" << 16 << F::Signed
                            << "-32769 does not fit a 16-bit register (-32768..32767)";
    QTest::newRow("0x10000") << "0x10000" << 16 << F::Hex
                             << "0x10000 does not fit a 16-bit register (0..65535)";
    // Issue 48: each format takes what it shows again (32768 read back as -32768, -1 as 65535).
    QTest::newRow("32768 signed") << "32768" << 16 << F::Signed
                                  << "32768 does not fit a 16-bit register (-32768..32767)";
    QTest::newRow("65535 signed") << "65535" << 16 << F::Signed
                                  << "65535 does not fit a 16-bit register (-32768..32767)";
    QTest::newRow("-1 unsigned") << "-1" << 32 << F::Unsigned
                                 << "-1 does not fit a 32-bit value (0..4294967295)";
    QTest::newRow("-0x1 unsigned")
        << "-0x1" << 16 << F::Unsigned << "-0x1 does not fit a 16-bit register (0..65535)";
    QTest::newRow("-0x1 hex") << "-0x1" << 16 << F::Hex
                              << "-0x1 does not fit a 16-bit register (0..65535)";
    QTest::newRow("-1 hex") << "-1" << 16 << F::Hex
                            << "-1 does not fit a 16-bit register (0..65535)";
    QTest::newRow("-1 binary") << "-1" << 16 << F::Binary
                               << "-1 does not fit a 16-bit register (0..65535)";
    QTest::newRow("-0x8001 signed")
        << "-0x8001" << 16 << F::Signed << "-0x8001 does not fit a 16-bit register (-32768..32767)";
    QTest::newRow("float negative bits")
        << "-0x3F800000" << 32 << F::Float32
        << "-0x3F800000 does not fit a 32-bit value (0..4294967295)";
    QTest::newRow("12G") << "12G" << 16 << F::Signed << "\"12G\" is not a number";
    QTest::newRow("1.5 integer") << "1.5" << 16 << F::Signed << "\"1.5\" is not a number";
    // Out of range in exponent notation (issue 33): too large, not "not a number".
    QTest::newRow("1e308") << "1e308" << 16 << F::Signed
                           << "1e308 does not fit a 16-bit register (-32768..32767)";
    QTest::newRow("-2.5e9 32-bit")
        << "-2.5e9" << 32 << F::Signed
        << "-2.5e9 does not fit a 32-bit value (-2147483648..2147483647)";
    QTest::newRow("1e400") << "1e400" << 16 << F::Unsigned
                           << "1e400 does not fit a 16-bit register (0..65535)";
    QTest::newRow("4e4 signed") << "4e4" << 16 << F::Signed
                                << "4e4 does not fit a 16-bit register (-32768..32767)";
    QTest::newRow("1e3 in range") << "1e3" << 16 << F::Signed << "\"1e3\" is not a number";
    QTest::newRow("sign space") << "- 5" << 16 << F::Signed << "\"- 5\" is not a number";
    QTest::newRow("0x only") << "0x" << 16 << F::Signed << "\"0x\" is not a number";
    QTest::newRow("bad hex") << "0x1G" << 16 << F::Signed << "\"0x1G\" is not a hexadecimal number";
    QTest::newRow("bad hex bare") << "12G" << 16 << F::Hex << "\"12G\" is not a hexadecimal number";
    QTest::newRow("bad binary") << "102" << 16 << F::Binary
                                << "\"102\" is not a binary number (only 0 and 1)";
    QTest::newRow("empty") << "" << 16 << F::Signed
                           << "No value typed: type a number such as 12, -5, 0x1A or 1Ah.";
    QTest::newRow("blank") << "   " << 32 << F::Float32
                           << "No value typed: type a number such as 12, -5, 0x1A or 1Ah.";
    QTest::newRow("u32 over") << "4294967296" << 32 << F::Unsigned
                              << "4294967296 does not fit a 32-bit value (0..4294967295)";
    QTest::newRow("s32 under")
        << "-2147483649" << 32 << F::Signed
        << "-2147483649 does not fit a 32-bit value (-2147483648..2147483647)";
    QTest::newRow("u64 over") << "18446744073709551616" << 64 << F::Unsigned
                              << "18446744073709551616 does not fit a 64-bit value "
                                 "(0..18446744073709551615)";
    QTest::newRow("s64 under") << "-9223372036854775809" << 64 << F::Signed
                               << "-9223372036854775809 does not fit a 64-bit value "
                                  "(-9223372036854775808..9223372036854775807)";
    QTest::newRow("bcd too big") << "12345" << 16 << F::Bcd
                                 << "12345 does not fit a 16-bit register as BCD (0..9999)";
    QTest::newRow("bcd negative") << "-5" << 16 << F::Bcd
                                  << "BCD values cannot be negative (\"-5\")";
    QTest::newRow("bcd letter") << "12A" << 16 << F::Bcd
                                << "\"12A\" is not a BCD number (digits 0-9 only)";
    QTest::newRow("float too big")
        << "1e39" << 32 << F::Float32 << "1e39 does not fit a 32-bit float (largest about ±3.4e38)";
    QTest::newRow("double too big")
        << "1e400" << 64 << F::Double64
        << "1e400 does not fit a 64-bit double (largest about ±1.8e308)";
    QTest::newRow("float text") << "abc" << 32 << F::Float32 << "\"abc\" is not a number";
    QTest::newRow("float comma") << "1,5" << 32 << F::Float32 << "\"1,5\" is not a number";
    QTest::newRow("float grouped") << "1,000" << 32 << F::Float32 << "\"1,000\" is not a number";
    QTest::newRow("double grouped")
        << "1,000.5" << 64 << F::Double64 << "\"1,000.5\" is not a number";
    QTest::newRow("ascii long")
        << "ABC" << 16 << F::Ascii
        << "\"ABC\" is too long: a 16-bit register holds 2 ASCII characters";
    QTest::newRow("ascii umlaut") << QString::fromUtf8("\xC3\xA4") << 16 << F::Ascii
                                  << QString::fromUtf8(
                                         "\"\xC3\xA4\" contains a character that is not plain "
                                         "printable ASCII (letters, digits, punctuation and space "
                                         "only)");
    QTest::newRow("bit 2") << "2" << 1 << F::Bit
                           << "\"2\" is not a bit value: type ON, OFF, 1 or 0";
    QTest::newRow("bit -1") << "-1" << 1 << F::Bit
                            << "\"-1\" is not a bit value: type ON, OFF, 1 or 0";
    QTest::newRow("bit yes") << "yes" << 1 << F::Bit
                             << "\"yes\" is not a bit value: type ON, OFF, 1 or 0";
    QTest::newRow("bit empty") << "" << 1 << F::Bit << "No value typed: type ON, OFF, 1 or 0.";
    QTest::newRow("float on 16") << "5" << 16 << F::Float32
                                 << "The float format needs 32 bits; this value has 16 bits.";
    QTest::newRow("bit on 16") << "1" << 16 << F::Bit
                               << "The bit format needs a single bit; this value has 16 bits.";
    QTest::newRow("width 8") << "1" << 8 << F::Unsigned
                             << "A 8-bit value cannot be written (only 1, 16, 32 or 64 bits).";
}

void TestValueFormat::rejects()
{
    QFETCH(QString, text);
    QFETCH(int, width);
    QFETCH(DisplayFormat, fmt);
    QFETCH(QString, message);
    const auto r = ValueFormat::parse(text, width, fmt);
    QVERIFY(!r.ok());
    QCOMPARE(errorText(r), message);
    QCOMPARE(r.error().kind, ErrorKind::InvalidRequest);
}

// Exact formats: parse(format(raw)) gives raw back for every width, with and without word swap.
void TestValueFormat::roundTripExact_data()
{
    QTest::addColumn<DisplayFormat>("fmt");
    QTest::addColumn<int>("width");
    QTest::addColumn<bool>("swap");
    QTest::addColumn<QList<quint64>>("raws");

    const QList<quint64> generic16{0, 1, 0x7FFF, 0x8000, 0xFFFF, 0x1234, 0xA5C3};
    const QList<quint64> generic32{0,          1,          0x7FFFFFFF, 0x80000000,
                                   0xFFFFFFFF, 0x12345678, 0x0000FFFF, 0xFFFF0000};
    const QList<quint64> generic64{0,
                                   1,
                                   0x7FFFFFFFFFFFFFFF,
                                   0x8000000000000000,
                                   ~0ull,
                                   0x0123456789ABCDEF,
                                   0x00000000FFFF0000};
    const QList<quint64> bcd16{0, 1, 0x9999, 0x1234, 0x0900};
    const QList<quint64> bcd32{0, 0x99999999, 0x12345678, 0x00090000};
    const QList<quint64> bcd64{0, 0x9999999999999999, 0x1234567890123456};
    const QList<quint64> ascii16{0x4142, 0x2020, 0x7E21, 0x3039};
    const QList<quint64> ascii32{0x43444142, 0x20202020, 0x7A7A4141};
    const QList<quint64> ascii64{0x4748454643444142, 0x2121212121212121};

    for (bool swap : {false, true}) {
        const char *s = swap ? " swapped" : "";
        QTest::addRow("bit%s", s) << DisplayFormat::Bit << 1 << swap << QList<quint64>{0, 1};
        for (DisplayFormat f :
             {DisplayFormat::Unsigned, DisplayFormat::Hex, DisplayFormat::Binary}) {
            const QByteArray n = ValueFormat::name(f).toLatin1();
            QTest::addRow("%s 1%s", n.constData(), s) << f << 1 << swap << QList<quint64>{0, 1};
        }
        for (DisplayFormat f : {DisplayFormat::Unsigned, DisplayFormat::Signed, DisplayFormat::Hex,
                                DisplayFormat::Binary}) {
            const QByteArray n = ValueFormat::name(f).toLatin1();
            QTest::addRow("%s 16%s", n.constData(), s) << f << 16 << swap << generic16;
            QTest::addRow("%s 32%s", n.constData(), s) << f << 32 << swap << generic32;
            QTest::addRow("%s 64%s", n.constData(), s) << f << 64 << swap << generic64;
        }
        QTest::addRow("bcd 16%s", s) << DisplayFormat::Bcd << 16 << swap << bcd16;
        // Swapped BCD: the raw words are exchanged, so valid BCD stays valid.
        QTest::addRow("bcd 32%s", s) << DisplayFormat::Bcd << 32 << swap << bcd32;
        QTest::addRow("bcd 64%s", s) << DisplayFormat::Bcd << 64 << swap << bcd64;
        QTest::addRow("ascii 16%s", s) << DisplayFormat::Ascii << 16 << swap << ascii16;
        QTest::addRow("ascii 32%s", s) << DisplayFormat::Ascii << 32 << swap << ascii32;
        QTest::addRow("ascii 64%s", s) << DisplayFormat::Ascii << 64 << swap << ascii64;
        QTest::addRow("float exact%s", s)
            << DisplayFormat::Float32 << 32 << swap
            << QList<quint64>{
                   0,          0x80000000, 0x3F800000,   0xC0200000,      0x7F800000,
                   0xFF800000, 0x7FC00000, bitsOf(0.1f), bitsOf(1234.5f), bitsOf(-1.0e-5f)};
        QTest::addRow("double exact%s", s)
            << DisplayFormat::Double64 << 64 << swap
            << QList<quint64>{0,
                              0x8000000000000000,
                              bitsOf(1.0),
                              bitsOf(0.1),
                              bitsOf(-123456.789),
                              bitsOf(std::numeric_limits<double>::infinity()),
                              0x7FF8000000000000};
    }
}

void TestValueFormat::roundTripExact()
{
    QFETCH(DisplayFormat, fmt);
    QFETCH(int, width);
    QFETCH(bool, swap);
    QFETCH(QList<quint64>, raws);
    for (quint64 raw : raws) {
        // Swapped rows store the same values with their words exchanged.
        const quint64 stored = swap ? ValueFormat::swapWords(raw, width) : raw;
        const QString text = ValueFormat::format(stored, width, fmt, swap);
        const auto back = ValueFormat::parse(text, width, fmt, swap);
        QVERIFY2(back.ok(), qPrintable(text + QStringLiteral(": ") + errorText(back)));
        QVERIFY2(quint64(*back) == stored, qPrintable(QStringLiteral("%1 -> \"%2\" -> %3")
                                                          .arg(stored, 0, 16)
                                                          .arg(text)
                                                          .arg(*back, 0, 16)));
    }
}

// Floats shown with 7 digits do not always give the same bits back, but the shown text must be
// stable: typing what is shown writes a value that shows the same.
void TestValueFormat::roundTripFloatText_data()
{
    QTest::addColumn<DisplayFormat>("fmt");
    QTest::addColumn<int>("width");
    QTest::addColumn<quint64>("raw");

    const QList<float> floats{std::numeric_limits<float>::max(),
                              std::numeric_limits<float>::lowest(),
                              std::numeric_limits<float>::min(),
                              std::numeric_limits<float>::denorm_min(),
                              3.14159265f,
                              -2.7182818f,
                              1.0e-30f,
                              123456789.0f};
    for (float f : floats)
        QTest::addRow("float %g", double(f)) << DisplayFormat::Float32 << 32 << bitsOf(f);
    const QList<double> doubles{std::numeric_limits<double>::max(),
                                std::numeric_limits<double>::lowest(),
                                std::numeric_limits<double>::min(),
                                std::numeric_limits<double>::denorm_min(),
                                3.141592653589793,
                                1.0 / 3.0,
                                -6.02214076e23};
    for (double d : doubles)
        QTest::addRow("double %g", d) << DisplayFormat::Double64 << 64 << bitsOf(d);
}

void TestValueFormat::roundTripFloatText()
{
    QFETCH(DisplayFormat, fmt);
    QFETCH(int, width);
    QFETCH(quint64, raw);
    for (bool swap : {false, true}) {
        const quint64 stored = swap ? ValueFormat::swapWords(raw, width) : raw;
        const QString text = ValueFormat::format(stored, width, fmt, swap);
        const auto back = ValueFormat::parse(text, width, fmt, swap);
        QVERIFY2(back.ok(), qPrintable(text + QStringLiteral(": ") + errorText(back)));
        QCOMPARE(ValueFormat::format(*back, width, fmt, swap), text);
    }
}

// Issue 34: the number a value stands for (trends, sorting) whatever its text: hex and binary of
// a register are its signed value, not 0..65535.
void TestValueFormat::numberIsWhatTheValueStandsFor()
{
    using F = DisplayFormat;
    QCOMPARE(ValueFormat::number(0xFC18, 16, F::Hex), std::optional<double>(-1000.0));
    QCOMPARE(ValueFormat::number(0xFC18, 16, F::Binary), std::optional<double>(-1000.0));
    QCOMPARE(ValueFormat::number(0xFC18, 16, F::Signed), std::optional<double>(-1000.0));
    QCOMPARE(ValueFormat::number(0xFC18, 16, F::Unsigned), std::optional<double>(64536.0));
    QCOMPARE(ValueFormat::number(0xFFFFFFFE, 32, F::Hex), std::optional<double>(-2.0));
    QCOMPARE(ValueFormat::number(0x1234, 16, F::Bcd), std::optional<double>(1234.0));
    QCOMPARE(ValueFormat::number(0x3FC00000, 32, F::Float32), std::optional<double>(1.5));
    QCOMPARE(ValueFormat::number(1, 1, F::Bit), std::optional<double>(1.0));
    QCOMPARE(ValueFormat::number(0x4142, 16, F::Ascii), std::nullopt);
    QCOMPARE(ValueFormat::number(0x00AB, 16, F::Bcd), std::nullopt);
    QCOMPARE(ValueFormat::number(0x1234, 16, F::Float32), std::nullopt);
}

QTEST_GUILESS_MAIN(TestValueFormat)
#include "tst_valueformat.moc"
