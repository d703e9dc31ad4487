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

static QChar parityLetter(LinkSettings::Parity parity)
{
    switch (parity) {
    case LinkSettings::Parity::None: return QLatin1Char('N');
    case LinkSettings::Parity::Even: return QLatin1Char('E');
    case LinkSettings::Parity::Odd: return QLatin1Char('O');
    }
    return QLatin1Char('?');
}

QString LinkSettings::toString() const
{
    QString medium;
    switch (kind) {
    case Kind::Tcp: medium = QStringLiteral("TCP %1:%2").arg(host).arg(port); break;
    case Kind::Udp: medium = QStringLiteral("UDP %1:%2").arg(host).arg(port); break;
    case Kind::Serial:
        medium = QStringLiteral("%1 %2 %3%4%5")
                     .arg(portName.isEmpty() ? QStringLiteral("(no port)") : portName)
                     .arg(baudRate)
                     .arg(dataBits)
                     .arg(parityLetter(parity))
                     .arg(stopBits);
        if (flowControl == FlowControl::Hardware)
            medium += QStringLiteral(" RTS/CTS");
        else if (flowControl == FlowControl::Software)
            medium += QStringLiteral(" XON/XOFF");
        break;
    }
    return medium + QStringLiteral(", ") + protocolChoiceName(protocol);
}

QString LinkSettings::validate() const
{
    switch (kind) {
    case Kind::Tcp:
    case Kind::Udp:
        if (host.trimmed().isEmpty())
            return QStringLiteral("Enter the PLC's IP address or host name.");
        if (port == 0)
            return QStringLiteral(
                "Port 0 is not usable; FATEK Ethernet modules usually listen on 500.");
        break;
    case Kind::Serial:
        if (portName.trimmed().isEmpty())
            return QStringLiteral("Choose a serial port.");
        if (baudRate < 1200 || baudRate > 921600)
            return QStringLiteral("Baud rate %1 is out of range (1200 to 921600).").arg(baudRate);
        if (dataBits != 7 && dataBits != 8)
            return QStringLiteral("Data bits must be 7 or 8, not %1.").arg(dataBits);
        if (stopBits != 1 && stopBits != 2)
            return QStringLiteral("Stop bits must be 1 or 2, not %1.").arg(stopBits);
        break;
    }
    if (timeoutMs < 1 || timeoutMs > 60000)
        return QStringLiteral("Timeout %1 ms is out of range (1 to 60000 ms).").arg(timeoutMs);
    if (retries < 0 || retries > 10)
        return QStringLiteral("Retries %1 is out of range (0 to 10).").arg(retries);
    if (interFrameMs < 0 || interFrameMs > 1000)
        return QStringLiteral("Inter-frame silence %1 ms is out of range (0 to 1000 ms).")
            .arg(interFrameMs);
    if (connectTimeoutMs < 1)
        return QStringLiteral("Connect timeout must be at least 1 ms.");
    if (reconnectMinMs < 1 || reconnectMaxMs < reconnectMinMs)
        return QStringLiteral(
            "Reconnect delays must be positive, the maximum not below the minimum.");
    return {};
}

} // namespace Fatek
