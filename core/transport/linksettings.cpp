#include "linksettings.h"

#include <QRegularExpression>
#include <QUrl>

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

std::optional<LinkSettings::ProtocolChoice> protocolChoiceFromText(const QString &text)
{
    const QString p = text.trimmed().toLower();
    if (p == QLatin1String("facon"))
        return LinkSettings::ProtocolChoice::Facon;
    if (p == QLatin1String("binary"))
        return LinkSettings::ProtocolChoice::Binary;
    if (p == QLatin1String("auto"))
        return LinkSettings::ProtocolChoice::Auto;
    return std::nullopt;
}

bool LinkSettings::hostPortFromText(const QString &text, QString *host, quint16 *port)
{
    QString h = text.trimmed();
    QString p;
    if (h.startsWith(QLatin1Char('['))) {
        const qsizetype close = h.indexOf(QLatin1Char(']'));
        if (close < 0)
            return false;
        const QString rest = h.mid(close + 1);
        if (rest.startsWith(QLatin1Char(':')))
            p = rest.mid(1);
        else if (!rest.isEmpty())
            return false;
        h = h.mid(1, close - 1);
    } else if (h.count(QLatin1Char(':')) == 1) {
        p = h.section(QLatin1Char(':'), 1);
        h = h.section(QLatin1Char(':'), 0, 0);
        if (p.isEmpty())
            return false; // "plc1:" lost its port
    } else if (h.contains(QLatin1Char(':'))) {
        return false; // "h:p:5", "tcp://h", or an IPv6 address without brackets
    }
    if (h.isEmpty() || h.contains(QLatin1Char('/')) || h.contains(QLatin1Char(' ')))
        return false;
    *host = h;
    *port = 500;
    if (!p.isEmpty()) {
        bool ok = false;
        const int v = p.toInt(&ok, 10);
        if (!ok || v < 1 || v > 65535)
            return false;
        *port = static_cast<quint16>(v);
    }
    return true;
}

std::optional<LinkSettings::Parsed> LinkSettings::fromUrl(const QString &url, Message *error,
                                                          const LinkSettings &defaults)
{
    auto fail = [error](Message message) -> std::optional<Parsed> {
        if (error)
            *error = std::move(message);
        return std::nullopt;
    };
    const QString text = url.trimmed();
    if (text.isEmpty())
        return fail(msg<MsgId::SettingsUrlEmpty>());
    const std::string quoted = url.toStdString();
    QString scheme;
    QString rest = text;
    if (const qsizetype at = text.indexOf(QLatin1String("://")); at >= 0) {
        scheme = text.left(at).toLower();
        rest = text.mid(at + 3);
    } else {
        // Without a scheme only a serial port is plain: a device path or a Windows COM name.
        static const QRegularExpression comName(QStringLiteral(R"(^(\\\\\.\\)?COM[0-9]+($|\?))"),
                                                QRegularExpression::CaseInsensitiveOption);
        if (!text.startsWith(QLatin1Char('/')) && !comName.match(text).hasMatch())
            return fail(msg<MsgId::SettingsUrlScheme>(quoted));
        scheme = QStringLiteral("serial");
    }
    QString target = rest.section(QLatin1Char('?'), 0, 0);
    const QString query
        = rest.contains(QLatin1Char('?')) ? rest.section(QLatin1Char('?'), 1) : QString();
    Parsed parsed;
    LinkSettings &s = parsed.settings;
    s = defaults;
    if (scheme == QLatin1String("tcp") || scheme == QLatin1String("udp")) {
        QString host;
        quint16 port = 500;
        if (!hostPortFromText(QUrl::fromPercentEncoding(target.toUtf8()), &host, &port))
            return fail(msg<MsgId::SettingsUrlHostPort>(quoted));
        s.kind = scheme == QLatin1String("tcp") ? Kind::Tcp : Kind::Udp;
        s.host = host;
        s.port = port;
    } else if (scheme == QLatin1String("serial")) {
        target = QUrl::fromPercentEncoding(target.toUtf8()).trimmed();
        if (target.isEmpty())
            return fail(msg<MsgId::SettingsUrlNoPort>(quoted));
        s.kind = Kind::Serial;
        s.portName = target;
    } else {
        return fail(msg<MsgId::SettingsUrlScheme>(quoted));
    }
    const bool serialLink = s.kind == Kind::Serial;
    const char *known = serialLink ? "baud, format, flow, protocol, timeout, retries, station"
                                   : "protocol, timeout, retries, station";
    for (const QString &pair : query.split(QLatin1Char('&'), Qt::SkipEmptyParts)) {
        const QString key = QUrl::fromPercentEncoding(pair.section(QLatin1Char('='), 0, 0).toUtf8())
                                .trimmed()
                                .toLower();
        const QString value
            = QUrl::fromPercentEncoding(pair.section(QLatin1Char('='), 1).toUtf8()).trimmed();
        auto bad = [&](const char *takes) {
            return fail(msg<MsgId::SettingsUrlValue>(quoted, key.toStdString(), value.toStdString(),
                                                     std::string(takes)));
        };
        auto number = [&value](int min, int max) -> std::optional<int> {
            bool ok = false;
            const int v = value.toInt(&ok, 10);
            return ok && v >= min && v <= max ? std::optional<int>(v) : std::nullopt;
        };
        if (key == QLatin1String("protocol")) {
            const auto choice = protocolChoiceFromText(value);
            if (!choice)
                return bad("facon, binary or auto");
            s.protocol = *choice;
        } else if (key == QLatin1String("timeout")) {
            const auto v = number(10, 60000);
            if (!v)
                return bad("10 to 60000 (ms)");
            s.timeoutMs = *v;
        } else if (key == QLatin1String("retries")) {
            const auto v = number(0, 10);
            if (!v)
                return bad("0 to 10");
            s.retries = *v;
        } else if (key == QLatin1String("station")) {
            const auto v = number(0, 254);
            if (!v)
                return bad("0 to 254");
            parsed.station = *v;
        } else if (serialLink && key == QLatin1String("baud")) {
            const auto v = number(50, 10000000);
            if (!v)
                return bad("a speed such as 9600 or 19200");
            s.baudRate = *v;
        } else if (serialLink && key == QLatin1String("format")) {
            if (!s.setSerialFormat(value).isEmpty())
                return bad("data bits, parity and stop bits such as 7E1 or 8N1");
        } else if (serialLink && key == QLatin1String("flow")) {
            const QString flow = value.toLower();
            if (flow == QLatin1String("none"))
                s.flowControl = FlowControl::None;
            else if (flow == QLatin1String("rtscts"))
                s.flowControl = FlowControl::Hardware;
            else if (flow == QLatin1String("xonxoff"))
                s.flowControl = FlowControl::Software;
            else
                return bad("none, rtscts or xonxoff");
        } else {
            return fail(
                msg<MsgId::SettingsUrlUnknown>(quoted, key.toStdString(), std::string(known)));
        }
    }
    return parsed;
}

std::optional<LinkSettings::Parsed> LinkSettings::fromUrl(const QString &url, Message *error)
{
    return fromUrl(url, error, LinkSettings());
}

QString LinkSettings::toUrl(int station) const
{
    const LinkSettings defaults;
    QStringList settings;
    QString url;
    switch (kind) {
    case Kind::Tcp:
    case Kind::Udp: {
        const QString h = host.contains(QLatin1Char(':')) ? QStringLiteral("[%1]").arg(host) : host;
        url = QStringLiteral("%1://%2:%3")
                  .arg(kind == Kind::Tcp ? QStringLiteral("tcp") : QStringLiteral("udp"), h)
                  .arg(port);
        break;
    }
    case Kind::Serial:
        url = QStringLiteral("serial://")
              + QString::fromUtf8(QUrl::toPercentEncoding(portName, "/\\:."));
        if (baudRate != defaults.baudRate)
            settings << QStringLiteral("baud=%1").arg(baudRate);
        if (serialFormat() != defaults.serialFormat())
            settings << QStringLiteral("format=") + serialFormat();
        if (flowControl == FlowControl::Hardware)
            settings << QStringLiteral("flow=rtscts");
        else if (flowControl == FlowControl::Software)
            settings << QStringLiteral("flow=xonxoff");
        break;
    }
    // Always named: the programs differ in their default (fatek-cli and the studio detect).
    settings << QStringLiteral("protocol=")
                    + (protocol == ProtocolChoice::Facon    ? QStringLiteral("facon")
                       : protocol == ProtocolChoice::Binary ? QStringLiteral("binary")
                                                            : QStringLiteral("auto"));
    if (timeoutMs != defaults.timeoutMs)
        settings << QStringLiteral("timeout=%1").arg(timeoutMs);
    if (retries != defaults.retries)
        settings << QStringLiteral("retries=%1").arg(retries);
    if (station > 0)
        settings << QStringLiteral("station=%1").arg(station);
    if (!settings.isEmpty())
        url += QLatin1Char('?') + settings.join(QLatin1Char('&'));
    return url;
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
