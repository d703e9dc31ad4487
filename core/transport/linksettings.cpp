#include "linksettings.h"

namespace Fatek {

LinkSettings LinkSettings::tcp(const QString &host, quint16 port, ProtocolChoice protocol)
{
    LinkSettings s;
    s.kind = Kind::Tcp;
    s.host = host;
    s.port = port;
    s.protocol = protocol;
    return s;
}

LinkSettings LinkSettings::udp(const QString &host, quint16 port, ProtocolChoice protocol)
{
    LinkSettings s = tcp(host, port, protocol);
    s.kind = Kind::Udp;
    return s;
}

LinkSettings LinkSettings::serial(const QString &portName, qint32 baudRate, ProtocolChoice protocol)
{
    LinkSettings s;
    s.kind = Kind::Serial;
    s.portName = portName;
    s.baudRate = baudRate;
    s.protocol = protocol;
    return s;
}

QString protocolChoiceName(LinkSettings::ProtocolChoice choice)
{
    switch (choice) {
    case LinkSettings::ProtocolChoice::Facon: return QStringLiteral("FACON");
    case LinkSettings::ProtocolChoice::Binary: return QStringLiteral("binary");
    case LinkSettings::ProtocolChoice::Auto: return QStringLiteral("auto-detect");
    }
    return {};
}

QChar LinkSettings::parityLetter(Parity parity)
{
    switch (parity) {
    case Parity::None: return QLatin1Char('N');
    case Parity::Even: return QLatin1Char('E');
    case Parity::Odd: return QLatin1Char('O');
    }
    return QLatin1Char('?');
}

std::optional<int> LinkSettings::dataBitsFromText(const QString &text)
{
    bool ok = false;
    const int bits = text.trimmed().toInt(&ok);
    if (!ok || (bits != 7 && bits != 8))
        return std::nullopt;
    return bits;
}

std::optional<LinkSettings::Parity> LinkSettings::parityFromText(const QString &text)
{
    const QString p = text.trimmed().toUpper();
    if (p == QLatin1String("N") || p == QLatin1String("NONE"))
        return Parity::None;
    if (p == QLatin1String("E") || p == QLatin1String("EVEN"))
        return Parity::Even;
    if (p == QLatin1String("O") || p == QLatin1String("ODD"))
        return Parity::Odd;
    return std::nullopt;
}

std::optional<int> LinkSettings::stopBitsFromText(const QString &text)
{
    bool ok = false;
    const int bits = text.trimmed().toInt(&ok);
    if (!ok || (bits != 1 && bits != 2))
        return std::nullopt;
    return bits;
}

QString LinkSettings::setSerialFormat(const QString &text)
{
    const QString format = text.trimmed();
    if (format.size() != 3)
        return QStringLiteral("Serial format \"%1\" is not valid: write data bits, parity and "
                              "stop bits, e.g. 7E1 or 8N1.")
            .arg(text);
    const std::optional<int> data = dataBitsFromText(format.mid(0, 1));
    if (!data)
        return QStringLiteral("Serial format \"%1\": data bits must be 7 or 8, not %2.")
            .arg(text, format.mid(0, 1));
    const std::optional<Parity> p = parityFromText(format.mid(1, 1));
    if (!p)
        return QStringLiteral("Serial format \"%1\": parity must be N, E or O, not %2.")
            .arg(text, format.mid(1, 1));
    const std::optional<int> stop = stopBitsFromText(format.mid(2, 1));
    if (!stop)
        return QStringLiteral("Serial format \"%1\": stop bits must be 1 or 2, not %2.")
            .arg(text, format.mid(2, 1));
    dataBits = *data;
    parity = *p;
    stopBits = *stop;
    return {};
}

QString LinkSettings::serialFormat() const
{
    return QStringLiteral("%1%2%3").arg(dataBits).arg(parityLetter(parity)).arg(stopBits);
}

QString LinkSettings::toString() const
{
    QString medium;
    switch (kind) {
    case Kind::Tcp: medium = QStringLiteral("TCP %1:%2").arg(host).arg(port); break;
    case Kind::Udp: medium = QStringLiteral("UDP %1:%2").arg(host).arg(port); break;
    case Kind::Serial:
        medium = QStringLiteral("%1 %2 %3")
                     .arg(portName.isEmpty() ? QStringLiteral("(no port)") : portName)
                     .arg(baudRate)
                     .arg(serialFormat());
        if (flowControl == FlowControl::Hardware)
            medium += QStringLiteral(" RTS/CTS");
        else if (flowControl == FlowControl::Software)
            medium += QStringLiteral(" XON/XOFF");
        break;
    }
    return medium + QStringLiteral(", ") + protocolChoiceName(protocol);
}

Message LinkSettings::validate() const
{
    switch (kind) {
    case Kind::Tcp:
    case Kind::Udp:
        if (host.trimmed().isEmpty())
            return msg<MsgId::SettingsNoHost>();
        if (port == 0)
            return msg<MsgId::SettingsPortZero>();
        break;
    case Kind::Serial:
        if (portName.trimmed().isEmpty())
            return msg<MsgId::SettingsNoSerialPort>();
        if (baudRate < 1200 || baudRate > 921600)
            return msg<MsgId::SettingsBaudRate>(baudRate);
        if (dataBits != 7 && dataBits != 8)
            return msg<MsgId::SettingsDataBits>(dataBits);
        if (stopBits != 1 && stopBits != 2)
            return msg<MsgId::SettingsStopBits>(stopBits);
        break;
    }
    if (timeoutMs < 1 || timeoutMs > 60000)
        return msg<MsgId::SettingsTimeout>(timeoutMs);
    if (retries < 0 || retries > 10)
        return msg<MsgId::SettingsRetries>(retries);
    if (demoteAfter < 0 || demoteAfter > 100)
        return msg<MsgId::SettingsDemoteAfter>(demoteAfter);
    if (demotionMs < 1000 || demotionMs > 600000)
        return msg<MsgId::SettingsDemotion>(demotionMs);
    if (interFrameMs < 0 || interFrameMs > 1000)
        return msg<MsgId::SettingsInterFrame>(interFrameMs);
    if (connectTimeoutMs < 1)
        return msg<MsgId::SettingsConnectTimeout>();
    if (reconnectMinMs < 1 || reconnectMaxMs < reconnectMinMs)
        return msg<MsgId::SettingsReconnectDelays>();
    return {};
}

} // namespace Fatek
