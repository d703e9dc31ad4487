#include "valueformat.h"

#include <QLocale>
#include <QRegularExpression>

#include <array>
#include <bit>
#include <charconv>
#include <cmath>
#include <limits>

namespace Fatek::ValueFormat {

namespace {

struct FormatName
{
    DisplayFormat format;
    const char *name;
};

constexpr std::array<FormatName, 9> kNames = {{
    {DisplayFormat::Bit, "bit"},
    {DisplayFormat::Unsigned, "unsigned"},
    {DisplayFormat::Signed, "signed"},
    {DisplayFormat::Hex, "hex"},
    {DisplayFormat::Binary, "binary"},
    {DisplayFormat::Bcd, "bcd"},
    {DisplayFormat::Float32, "float"},
    {DisplayFormat::Ascii, "ascii"},
    {DisplayFormat::Double64, "double"},
}};

bool validWidth(int width)
{
    return width == 1 || width == 16 || width == 32 || width == 64;
}

std::uint64_t widthMask(int width)
{
    return width >= 64 ? ~std::uint64_t(0) : (std::uint64_t(1) << width) - 1;
}

Message widthPhrase(int width)
{
    switch (width) {
    case 1: return msg<MsgId::ValueWidthBit>();
    case 16: return msg<MsgId::ValueWidthRegister>();
    default: return msg<MsgId::ValueWidthBits>(width);
    }
}

std::string str(const QString &text)
{
    return text.toStdString();
}

QString needsText(DisplayFormat format)
{
    switch (format) {
    case DisplayFormat::Bit: return QStringLiteral("a single bit");
    case DisplayFormat::Float32: return QStringLiteral("32 bits");
    case DisplayFormat::Double64: return QStringLiteral("64 bits");
    case DisplayFormat::Signed:
    case DisplayFormat::Bcd:
    case DisplayFormat::Ascii: return QStringLiteral("16 bits or more");
    case DisplayFormat::Unsigned:
    case DisplayFormat::Hex:
    case DisplayFormat::Binary: break;
    }
    return QStringLiteral("1, 16, 32 or 64 bits");
}

ProtocolError valueError(Message message)
{
    return makeError(ErrorKind::InvalidRequest, std::move(message));
}

ProtocolError valueError(const QString &text)
{
    return makeError(ErrorKind::InvalidRequest, text.toStdString());
}

QString hexText(std::uint64_t value, int width)
{
    return QStringLiteral("0x")
           + QString::number(value, 16).toUpper().rightJustified((width + 3) / 4, QLatin1Char('0'));
}

QString binaryText(std::uint64_t value, int width)
{
    QString text;
    text.reserve(width + width / 4);
    for (int bit = width - 1; bit >= 0; --bit) {
        text += (value >> bit) & 1 ? QLatin1Char('1') : QLatin1Char('0');
        // Nibble groups counted from the least significant bit, as the digits of the hex form.
        if (bit > 0 && bit % 4 == 0)
            text += QLatin1Char(' ');
    }
    return text;
}

bool isValidBcd(std::uint64_t value)
{
    for (; value != 0; value >>= 4) {
        if ((value & 0xF) > 9)
            return false;
    }
    return true;
}

// precision: significant digits, or QLocale::FloatingPointShortest.
QString floatText(double value, int precision)
{
    if (std::isnan(value))
        return QStringLiteral("NaN");
    if (std::isinf(value))
        return value > 0 ? QStringLiteral("Inf") : QStringLiteral("-Inf");
    if (value == 0 && std::signbit(value))
        return QStringLiteral("-0"); // QString::number drops the sign, but the bits differ from 0
    return QString::number(value, 'g', precision);
}

QString asciiText(std::uint64_t value, int width)
{
    QString text;
    for (int word = 0; word < width / 16; ++word) {
        for (int shift : {8, 0}) {
            const auto byte = static_cast<unsigned>((value >> (16 * word + shift)) & 0xFF);
            text += byte >= 0x20 && byte <= 0x7E ? QChar(static_cast<char16_t>(byte))
                                                 : QLatin1Char('.');
        }
    }
    return text;
}

QString signedText(std::uint64_t value, int width)
{
    if (width < 64 && (value >> (width - 1)) & 1)
        return QString::number(static_cast<qint64>(value)
                               - static_cast<qint64>(std::uint64_t(1) << width));
    return QString::number(static_cast<qint64>(value));
}

// What a value typed in `format` may be: a signed item reads 32768 back as -32768, an unsigned
// one -1 as 65535, so each takes only what it shows again (issue 48). Bits typed as such (0x8000,
// 8000h, 0b...) fill the whole width in any format: they are the register's bits, not a number.
struct Range
{
    std::uint64_t negative = 0; // largest magnitude below zero (0: none)
    std::uint64_t positive = 0;

    QString text() const
    {
        const QString low
            = negative == 0 ? QStringLiteral("0") : QLatin1Char('-') + QString::number(negative);
        return QStringLiteral("%1..%2").arg(low, QString::number(positive));
    }
};

Range rangeOf(int width, DisplayFormat format, bool bits)
{
    const std::uint64_t mask = widthMask(width);
    if (format != DisplayFormat::Signed)
        return {0, mask};
    const std::uint64_t half = std::uint64_t(1) << (width - 1);
    return {half, bits ? mask : half - 1};
}

bool startsWithPrefix(QStringView text, char16_t lower)
{
    return text.size() > 2 && text[0] == QLatin1Char('0') && text[1].toLower() == QChar(lower);
}

bool isRawNotation(QStringView text)
{
    if (text.startsWith(QLatin1Char('-')) || text.startsWith(QLatin1Char('+')))
        text = text.mid(1);
    return startsWithPrefix(text, u'x') || startsWithPrefix(text, u'b')
           || (text.size() > 1 && text.back().toLower() == QLatin1Char('h'));
}

// A decimal number in a notation the integer grammar does not take ("1e308", "-2.5e9") whose
// value lies outside `range`: too large, not "not a number" (issue 33).
bool decimalOutOfRange(const QString &text, const Range &range)
{
    static const QRegularExpression decimal(
        QStringLiteral(R"(^[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?$)"));
    if (!decimal.match(text).hasMatch())
        return false;
    const QByteArray latin = text.toLatin1();
    // from_chars: no locale (the desktop's decimal comma), and no leading '+'.
    const char *begin = latin.constData() + (latin.startsWith('+') ? 1 : 0);
    double value = 0;
    const auto [end, error] = std::from_chars(begin, latin.constData() + latin.size(), value);
    if (error == std::errc::result_out_of_range)
        return true; // beyond a double: 1e400
    if (error != std::errc{} || end != latin.constData() + latin.size())
        return false;
    return value > static_cast<double>(range.positive)
           || value < -static_cast<double>(range.negative);
}

// Integer text as the interpreted value (before the word swap), masked to `width`.
Result<std::uint64_t> parseInteger(const QString &text, int width, DisplayFormat format)
{
    QStringView body = text;
    bool negative = false;
    if (body.startsWith(QLatin1Char('-')) || body.startsWith(QLatin1Char('+'))) {
        negative = body.front() == QLatin1Char('-');
        body = body.mid(1);
    }

    int base = 10;
    bool bcd = false;
    if (startsWithPrefix(body, u'x')) {
        base = 16;
        body = body.mid(2);
    } else if (format != DisplayFormat::Hex && startsWithPrefix(body, u'b')) {
        // In Hex format "0B12" is a hex number, so the binary prefix is not looked for there.
        base = 2;
        body = body.mid(2);
    } else if (body.size() > 1 && body.back().toLower() == QLatin1Char('h')) {
        base = 16;
        body.chop(1);
    } else if (format == DisplayFormat::Hex) {
        base = 16;
    } else if (format == DisplayFormat::Binary) {
        base = 2;
    } else if (format == DisplayFormat::Bcd) {
        bcd = true;
    }

    const auto notANumber = [&] {
        if (bcd)
            return valueError(msg<MsgId::ValueNotBcd>(str(text)));
        if (base == 16)
            return valueError(msg<MsgId::ValueNotHex>(str(text)));
        if (base == 2)
            return valueError(msg<MsgId::ValueNotBinary>(str(text)));
        if (const Range range = rangeOf(width, format, false); decimalOutOfRange(text, range))
            return valueError(
                msg<MsgId::ValueTooLarge>(str(text), widthPhrase(width), str(range.text())));
        return valueError(msg<MsgId::ValueNotNumber>(str(text)));
    };

    const std::uint64_t radix = bcd ? 16 : static_cast<std::uint64_t>(base);
    std::uint64_t magnitude = 0;
    int digits = 0;
    bool overflow = false;
    for (QChar c : body) {
        // Spaces and underscores group hex and binary digits ("0000 0001" as shown by format()).
        if (base != 10 && (c == QLatin1Char(' ') || c == QLatin1Char('_')) && digits > 0)
            continue;
        const int digit
            = c.isDigit() && c.unicode() < 0x80 ? c.unicode() - '0'
              : base == 16 && c.toLower() >= QLatin1Char('a') && c.toLower() <= QLatin1Char('f')
                  ? c.toLower().unicode() - 'a' + 10
                  : -1;
        if (digit < 0 || digit >= base)
            return notANumber();
        ++digits;
        const auto d = static_cast<std::uint64_t>(digit);
        if (magnitude > (std::numeric_limits<std::uint64_t>::max() - d) / radix)
            overflow = true;
        else
            magnitude = magnitude * radix + d;
    }
    if (digits == 0)
        return notANumber();

    if (bcd) {
        if (negative)
            return valueError(msg<MsgId::ValueBcdNegative>(str(text)));
        if (overflow || magnitude > widthMask(width)) {
            return valueError(msg<MsgId::ValueBcdTooLarge>(
                str(text), widthPhrase(width),
                std::string(static_cast<std::size_t>(width / 4), '9')));
        }
        return magnitude;
    }

    // A sign makes a number of any notation ("-0x10" is -16), so only the signed range has room
    // for it; without one, hex and binary digits are the bits.
    const Range range = rangeOf(width, format, !negative && base != 10);
    if (overflow || magnitude > (negative ? range.negative : range.positive))
        return valueError(
            msg<MsgId::ValueTooLarge>(str(text), widthPhrase(width), str(range.text())));
    return negative ? (~magnitude + 1) & widthMask(width) : magnitude;
}

Result<std::uint64_t> parseBit(const QString &text, DisplayFormat format)
{
    const QString lower = text.toLower();
    if (lower == QLatin1String("on") || lower == QLatin1String("true"))
        return std::uint64_t(1);
    if (lower == QLatin1String("off") || lower == QLatin1String("false"))
        return std::uint64_t(0);
    if (!text.startsWith(QLatin1Char('-'))) {
        if (auto value = parseInteger(text, 1, format); value)
            return value;
    }
    return valueError(msg<MsgId::ValueNotBit>(str(text)));
}

Result<std::uint64_t> parseFloat(const QString &text, int width)
{
    const QString lower = text.toLower();
    double value = 0;
    if (lower == QLatin1String("nan") || lower == QLatin1String("+nan")
        || lower == QLatin1String("-nan")) {
        value = std::numeric_limits<double>::quiet_NaN();
    } else if (lower == QLatin1String("inf") || lower == QLatin1String("+inf")
               || lower == QLatin1String("infinity") || lower == QLatin1String("+infinity")) {
        value = std::numeric_limits<double>::infinity();
    } else if (lower == QLatin1String("-inf") || lower == QLatin1String("-infinity")) {
        value = -std::numeric_limits<double>::infinity();
    } else {
        bool ok = false;
        // Always C locale: a PLC value is typed with a decimal point whatever the desktop language.
        // Group separators are refused: "1,000" is 1000 to some and 1.0 to others.
        QLocale cLocale = QLocale::c();
        cLocale.setNumberOptions(QLocale::RejectGroupSeparator);
        value = cLocale.toDouble(text, &ok);
        const bool finite = ok && std::isfinite(value);
        if (!finite || (width == 32 && std::fabs(value) > std::numeric_limits<float>::max())) {
            // toDouble() reports too-large numbers as a failure; tell them apart from typing
            // errors.
            bool looksNumeric = !text.isEmpty();
            for (QChar c : text) {
                if (!(c.isDigit() || c == QLatin1Char('.') || c == QLatin1Char('e')
                      || c == QLatin1Char('E') || c == QLatin1Char('-') || c == QLatin1Char('+')))
                    looksNumeric = false;
            }
            if (finite || looksNumeric) {
                return valueError(width == 32
                                      ? msg<MsgId::ValueFloatTooLarge>(str(text), "3.4e38")
                                      : msg<MsgId::ValueDoubleTooLarge>(str(text), "1.8e308"));
            }
            return valueError(msg<MsgId::ValueNotNumber>(str(text)));
        }
    }
    if (width == 32)
        return std::uint64_t(std::bit_cast<std::uint32_t>(static_cast<float>(value)));
    return std::bit_cast<std::uint64_t>(value);
}

Result<std::uint64_t> parseAscii(const QString &text, int width)
{
    const int capacity = width / 8;
    if (text.size() > capacity) {
        return valueError(msg<MsgId::ValueAsciiTooLong>(str(text), widthPhrase(width), capacity));
    }
    std::uint64_t value = 0;
    for (int i = 0; i < text.size(); ++i) {
        const char16_t c = text[i].unicode();
        if (c < 0x20 || c > 0x7E) {
            return valueError(msg<MsgId::ValueNotPrintable>(str(text)));
        }
        // Word i/2 (R(n) first), high byte first inside the word.
        value |= std::uint64_t(c) << (16 * (i / 2) + (i % 2 == 0 ? 8 : 0));
    }
    return value;
}

} // namespace

QString name(DisplayFormat format)
{
    for (const FormatName &entry : kNames) {
        if (entry.format == format)
            return QString::fromLatin1(entry.name);
    }
    return {};
}

std::optional<DisplayFormat> fromName(QStringView name)
{
    const QString lower = name.trimmed().toString().toLower();
    if (lower == QLatin1String("float32"))
        return DisplayFormat::Float32;
    if (lower == QLatin1String("double64"))
        return DisplayFormat::Double64;
    for (const FormatName &entry : kNames) {
        if (lower == QLatin1String(entry.name))
            return entry.format;
    }
    return std::nullopt;
}

QList<DisplayFormat> allFormats()
{
    QList<DisplayFormat> formats;
    for (const FormatName &entry : kNames)
        formats.append(entry.format);
    return formats;
}

bool isAvailable(DisplayFormat format, int width)
{
    if (!validWidth(width))
        return false;
    switch (format) {
    case DisplayFormat::Bit: return width == 1;
    case DisplayFormat::Unsigned:
    case DisplayFormat::Hex:
    case DisplayFormat::Binary: return true;
    case DisplayFormat::Signed:
    case DisplayFormat::Bcd:
    case DisplayFormat::Ascii: return width >= 16;
    case DisplayFormat::Float32: return width == 32;
    case DisplayFormat::Double64: return width == 64;
    }
    return false;
}

int valueWidth(const Address &address, DisplayFormat format)
{
    int natural = 1;
    switch (address.width()) {
    case ElementWidth::Bit: natural = 1; break;
    case ElementWidth::Word: natural = 16; break;
    case ElementWidth::DoubleWord: natural = 32; break;
    }
    if (natural >= 16 && format == DisplayFormat::Float32)
        return 32;
    if (natural >= 16 && format == DisplayFormat::Double64)
        return 64;
    return isAvailable(format, natural) ? natural : 0;
}

int elementCount(const Address &address, DisplayFormat format)
{
    const int width = valueWidth(address, format);
    switch (address.width()) {
    case ElementWidth::Bit: return width;
    case ElementWidth::Word: return width / 16;
    case ElementWidth::DoubleWord: return width / 32;
    }
    return 0;
}

DisplayFormat defaultFormat(const Address &address)
{
    return address.width() == ElementWidth::Bit ? DisplayFormat::Bit : DisplayFormat::Signed;
}

std::uint64_t swapWords(std::uint64_t raw, int width)
{
    if (width == 32)
        return ((raw & 0xFFFF) << 16) | ((raw >> 16) & 0xFFFF);
    if (width == 64) {
        std::uint64_t swapped = 0;
        for (int word = 0; word < 4; ++word)
            swapped |= ((raw >> (16 * word)) & 0xFFFF) << (16 * (3 - word));
        return swapped;
    }
    return raw;
}

std::optional<double> number(std::uint64_t raw, int width, DisplayFormat format, bool swap)
{
    if (width == 0 || !isAvailable(format, width))
        return std::nullopt;
    const std::uint64_t mask = width >= 64 ? ~std::uint64_t(0) : (std::uint64_t(1) << width) - 1;
    // Words swapped only for a value shown swapped.
    const std::uint64_t v = (swap ? swapWords(raw & mask, width) : raw) & mask;
    switch (format) {
    case DisplayFormat::Bit: return (v & 1u) ? 1.0 : 0.0;
    case DisplayFormat::Unsigned: return static_cast<double>(v);
    // Hex and binary are ways of writing the element's bits, not another number: a register
    // holds a signed value (its default format), and a trend of it must not jump from 0 to
    // 65535 when it goes below zero.
    case DisplayFormat::Hex:
    case DisplayFormat::Binary:
    case DisplayFormat::Signed: {
        if (width < 64 && (v >> (width - 1)) & 1u)
            return static_cast<double>(static_cast<std::int64_t>(v | ~mask));
        return static_cast<double>(static_cast<std::int64_t>(v));
    }
    case DisplayFormat::Bcd: {
        double value = 0;
        double scale = 1;
        for (int shift = 0; shift < width; shift += 4) {
            const auto digit = static_cast<unsigned>((v >> shift) & 0xF);
            if (digit > 9)
                return std::nullopt; // not BCD: no honest number to plot
            value += digit * scale;
            scale *= 10;
        }
        return value;
    }
    case DisplayFormat::Float32: {
        const float f = std::bit_cast<float>(static_cast<std::uint32_t>(v));
        if (!std::isfinite(f))
            return std::nullopt;
        return static_cast<double>(f);
    }
    case DisplayFormat::Double64: {
        const double d = std::bit_cast<double>(v);
        if (!std::isfinite(d))
            return std::nullopt;
        return d;
    }
    case DisplayFormat::Ascii: return std::nullopt;
    }
    return std::nullopt;
}

bool isFinite(std::uint64_t raw, int width, DisplayFormat format, bool swap)
{
    if ((format != DisplayFormat::Float32 || width != 32)
        && (format != DisplayFormat::Double64 || width != 64))
        return true;
    const std::uint64_t value
        = (swap ? swapWords(raw & widthMask(width), width) : raw) & widthMask(width);
    return width == 32 ? std::isfinite(std::bit_cast<float>(static_cast<std::uint32_t>(value)))
                       : std::isfinite(std::bit_cast<double>(value));
}

QString format(std::uint64_t raw, int width, DisplayFormat format, bool swap)
{
    if (!validWidth(width))
        return QStringLiteral("(no %1-bit values)").arg(width);
    if (!isAvailable(format, width))
        return QStringLiteral("(%1 needs %2)").arg(name(format), needsText(format));

    std::uint64_t value = raw & widthMask(width);
    if (swap)
        value = swapWords(value, width);

    switch (format) {
    case DisplayFormat::Bit: return value ? QStringLiteral("ON") : QStringLiteral("OFF");
    case DisplayFormat::Unsigned: return QString::number(value);
    case DisplayFormat::Signed: return signedText(value, width);
    case DisplayFormat::Hex: return hexText(value, width);
    case DisplayFormat::Binary: return binaryText(value, width);
    case DisplayFormat::Bcd:
        // Valid BCD nibbles read as hex digits are the decimal digits.
        return isValidBcd(value) ? QString::number(value, 16)
                                 : QStringLiteral("?BCD ") + hexText(value, width);
    case DisplayFormat::Float32:
        return floatText(
            static_cast<double>(std::bit_cast<float>(static_cast<std::uint32_t>(value))), 7);
    case DisplayFormat::Ascii: return asciiText(value, width);
    case DisplayFormat::Double64:
        // Shortest text that reads back as the same double: 0.1 shows as "0.1", nothing is lost.
        return floatText(std::bit_cast<double>(value), QLocale::FloatingPointShortest);
    }
    return {};
}

Result<std::uint64_t> parse(const QString &text, int width, DisplayFormat format, bool swap)
{
    if (!validWidth(width))
        return valueError(msg<MsgId::ValueCannotWriteWidth>(width));
    if (!isAvailable(format, width)) {
        return valueError(
            QStringLiteral("The %1 format needs %2; this value has %3.")
                .arg(name(format), needsText(format))
                .arg(width == 1 ? QStringLiteral("1 bit") : QStringLiteral("%1 bits").arg(width)));
    }

    Result<std::uint64_t> value = std::uint64_t(0);
    if (format == DisplayFormat::Ascii) {
        // Spaces are characters here, so the text is not trimmed.
        value = parseAscii(text, width);
    } else {
        const QString trimmed = text.trimmed();
        if (trimmed.isEmpty()) {
            return valueError(width == 1 ? msg<MsgId::ValueNoBitTyped>()
                                         : msg<MsgId::ValueNoNumberTyped>());
        }
        if (width == 1)
            value = parseBit(trimmed, format);
        else if ((format == DisplayFormat::Float32 || format == DisplayFormat::Double64)
                 && !isRawNotation(trimmed))
            value = parseFloat(trimmed, width);
        else
            value = parseInteger(trimmed, width, format);
    }
    if (!value)
        return value;
    return swap ? swapWords(*value, width) : *value;
}

} // namespace Fatek::ValueFormat
