#include "frametext.h"

#include <QCoreApplication>
#include <QRegularExpression>

namespace Fatek {

namespace {

const char *const controlNames[32]
    = {"NUL", "SOH", "STX", "ETX", "EOT", "ENQ", "ACK", "BEL", "BS",  "HT",  "LF",
       "VT",  "FF",  "CR",  "SO",  "SI",  "DLE", "DC1", "DC2", "DC3", "DC4", "NAK",
       "SYN", "ETB", "CAN", "EM",  "SUB", "ESC", "FS",  "GS",  "RS",  "US"};

std::optional<quint8> hexPair(const QByteArray &bytes, qsizetype at)
{
    if (at + 2 > bytes.size())
        return std::nullopt;
    bool ok = false;
    const uint v = bytes.mid(at, 2).toUInt(&ok, 16);
    if (!ok)
        return std::nullopt;
    return static_cast<quint8>(v);
}

} // namespace

QString FrameText::toHex(const QByteArray &bytes)
{
    return QString::fromLatin1(bytes.toHex(' ')).toUpper();
}

QString FrameText::toAscii(const QByteArray &bytes)
{
    QString out;
    out.reserve(bytes.size());
    for (const char c : bytes) {
        const auto b = static_cast<quint8>(c);
        if (b < 32)
            out += QLatin1Char('<') + QLatin1String(controlNames[b]) + QLatin1Char('>');
        else if (b < 127)
            out += QLatin1Char(c);
        else
            out += QStringLiteral("<%1>").arg(b, 2, 16, QLatin1Char('0')).toUpper();
    }
    return out;
}

Result<QByteArray> FrameText::parseHex(const QString &text)
{
    QString digits = text;
    digits.remove(QRegularExpression(QStringLiteral("0[xX](?=[0-9A-Fa-f])")));
    digits.remove(QRegularExpression(QStringLiteral(R"([\s,;:\-])")));
    static const QRegularExpression nonHex(QStringLiteral("[^0-9A-Fa-f]"));
    const QRegularExpressionMatch bad = nonHex.match(digits);
    if (bad.hasMatch()) {
        return makeError(ErrorKind::InvalidRequest,
                         QCoreApplication::translate(
                             "Fatek::FrameText", "\u201c%1\u201d is not a hex digit; type bytes "
                                                 "like 01 46 03 52 00 0C.")
                             .arg(bad.captured())
                             .toStdString());
    }
    if (digits.isEmpty())
        return makeError(ErrorKind::InvalidRequest,
                         QCoreApplication::translate(
                             "Fatek::FrameText", "Nothing to send: type the frame's bytes in hex.")
                             .toStdString());
    if (digits.size() % 2 != 0)
        return makeError(
            ErrorKind::InvalidRequest,
            QCoreApplication::translate("Fatek::FrameText",
                                        "Odd number of hex digits: each byte needs two (0C, "
                                        "not C).")
                .toStdString());
    return QByteArray::fromHex(digits.toLatin1());
}

Result<QByteArray> FrameText::parseAscii(const QString &text)
{
    QByteArray out;
    for (qsizetype i = 0; i < text.size(); ++i) {
        const QChar c = text.at(i);
        if (c == QLatin1Char('<')) {
            const qsizetype end = text.indexOf(QLatin1Char('>'), i + 1);
            if (end > i + 1) {
                const QString name = text.mid(i + 1, end - i - 1).toUpper();
                bool found = false;
                for (int code = 0; code < 32; ++code) {
                    if (name == QLatin1String(controlNames[code])) {
                        out += static_cast<char>(code);
                        found = true;
                        break;
                    }
                }
                bool ok = false;
                const uint value = name.toUInt(&ok, 16);
                if (!found && ok && name.size() == 2) {
                    out += static_cast<char>(value);
                    found = true;
                }
                if (found) {
                    i = end;
                    continue;
                }
            }
        }
        if (c.unicode() < 32 || c.unicode() > 126) {
            return makeError(
                ErrorKind::InvalidRequest,
                QCoreApplication::translate("Fatek::FrameText",
                                            "Only printable ASCII can be typed; write control "
                                            "characters as <STX>, <ETX> or <0D>.")
                    .toStdString());
        }
        out += static_cast<char>(c.unicode());
    }
    if (out.isEmpty())
        return makeError(
            ErrorKind::InvalidRequest,
            QCoreApplication::translate("Fatek::FrameText", "Nothing to send: type the frame.")
                .toStdString());
    return out;
}

std::optional<FrameText::Header> FrameText::header(const QByteArray &frame)
{
    if (frame.isEmpty())
        return std::nullopt;
    const auto first = static_cast<quint8>(frame.at(0));
    if (first == 0x02)
        return bodyHeader(frame.mid(1), true);
    // Binary: header (51 query / 52 answer), ID 10, length (2), then STN CMD.
    if ((first == 0x51 || first == 0x52) && frame.size() >= 6
        && static_cast<quint8>(frame.at(1)) == 0x10)
        return Header{static_cast<quint8>(frame.at(4)), static_cast<quint8>(frame.at(5))};
    return std::nullopt;
}

std::optional<FrameText::Header> FrameText::bodyHeader(const QByteArray &body, bool facon)
{
    if (facon) {
        const auto station = hexPair(body, 0);
        const auto command = hexPair(body, 2);
        if (!station || !command)
            return std::nullopt;
        return Header{*station, *command};
    }
    if (body.size() < 2)
        return std::nullopt;
    return Header{static_cast<quint8>(body.at(0)), static_cast<quint8>(body.at(1))};
}

} // namespace Fatek
