#include "clitext.h"

#include "core/protocol/frametext.h"
#include "core/qtbridge/qtmessage.h"
#include "core/session/qtbytes.h"
#include "core/watch/valueformat.h"

#include <QTextStream>

#include <cstdio>
#include <span>

#ifdef Q_OS_WIN
#include <io.h>
#define FATEK_ISATTY(fd) _isatty(fd)
#else
#include <unistd.h>
#define FATEK_ISATTY(fd) isatty(fd)
#endif

namespace Fatek::CliText {

QString hexBytes(const Bytes &bytes)
{
    return QString::fromStdString(FrameText::toHex(bytes));
}

QString hexBytes(const QByteArray &bytes)
{
    return QString::fromStdString(FrameText::toHex(bytesOf(bytes)));
}

QString asciiView(const QByteArray &bytes)
{
    return QString::fromStdString(FrameText::toAscii(bytesOf(bytes), FrameText::Controls::Hex));
}

QString addressText(const Address &address)
{
    return QString::fromStdString(address.toString());
}

QString valueHex(std::uint32_t value, const Address &address)
{
    if (isDiscrete(address.type))
        return {};
    const int digits = isDoubleWord(address.type) ? 8 : 4;
    return QStringLiteral("0x%1")
        .arg(value, digits, 16, QLatin1Char('0'))
        .toUpper()
        .replace(QLatin1String("0X"), QLatin1String("0x"));
}

QString yesNo(bool b)
{
    return b ? QStringLiteral("yes") : QStringLiteral("no");
}

QString ms(double v)
{
    return QString::number(v, 'f', 2);
}

QString error(const ProtocolError &e)
{
    return QString::fromStdString(e.text());
}

QString formatNames()
{
    QStringList names;
    for (const DisplayFormat f : ValueFormat::allFormats())
        names << ValueFormat::name(f);
    return names.join(QStringLiteral(", "));
}

bool stderrIsTerminal()
{
    return FATEK_ISATTY(fileno(stderr));
}

Confirmation confirm(const QString &question, bool assumeYes)
{
    if (assumeYes)
        return Confirmation::Yes;
    if (!FATEK_ISATTY(fileno(stdin)))
        return Confirmation::NoTerminal;
    QTextStream err(stderr);
    err << question << QStringLiteral(" [y/N] ") << Qt::flush;
    // Blocking on purpose: nothing is written before the person answers.
    const QString answer = QTextStream(stdin).readLine().trimmed().toLower();
    return answer == QLatin1String("y") || answer == QLatin1String("yes") ? Confirmation::Yes
                                                                          : Confirmation::No;
}

QString checkoutPoint(const CheckoutPoint &point)
{
    const QString a = QString::fromStdString(point.address.toString());
    return point.name.isEmpty() ? a : QStringLiteral("%1 (%2)").arg(a, point.name);
}

QString checkoutResult(const CheckoutPoint &point)
{
    QString text = QStringLiteral("%1: %2").arg(checkoutPoint(point),
                                                englishText(checkoutResultMessage(point.result)));
    if (const QString measured = englishText(point.measured()); !measured.isEmpty())
        text += QStringLiteral(" (%1)").arg(measured);
    if (!point.comment.isEmpty())
        text += QStringLiteral(": %1").arg(point.comment);
    return text;
}

} // namespace Fatek::CliText
