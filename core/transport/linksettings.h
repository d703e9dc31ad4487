#pragma once

#include "core/qtbridge/qtmessage.h"

#include <QChar>
#include <QMetaType>
#include <QString>

#include <optional>

namespace Fatek {

// Everything needed to open one link to one or several PLCs: the medium, its parameters, the
// protocol spoken on it and the timing policy of the session that owns it. A plain value type.
struct LinkSettings
{
    enum class Kind { Serial, Tcp, Udp };
    enum class ProtocolChoice { Facon, Binary, Auto };
    enum class Parity { None, Even, Odd };
    enum class FlowControl { None, Hardware, Software };

    Kind kind = Kind::Tcp;

    // TCP / UDP
    QString host = QStringLiteral("127.0.0.1");
    quint16 port = 500;

    // Serial line; FACON defaults 9600 7E1.
    QString portName;
    qint32 baudRate = 9600;
    int dataBits = 7;
    Parity parity = Parity::Even;
    int stopBits = 1;
    FlowControl flowControl = FlowControl::None;

    ProtocolChoice protocol = ProtocolChoice::Facon;

    // Session policy
    int timeoutMs = 1000;        // per attempt, unless a request brings its own
    int retries = 2;             // extra attempts after a timeout or checksum error
    int interFrameMs = 5;        // serial only: line silence before a new query
    int connectTimeoutMs = 3000; // TCP connect
    bool autoReconnect = true;
    int reconnectMinMs = 500;   // first reconnect delay, doubled after each failure ...
    int reconnectMaxMs = 10000; // ... up to this
    // A station that leaves this many poll requests in a row unanswered is demoted: not polled
    // for demotionMs, then tried once, so that it does not hold up the other stations (0: never).
    int demoteAfter = 3;
    int demotionMs = 10000;

    static LinkSettings tcp(const QString &host, quint16 port = 500,
                            ProtocolChoice protocol = ProtocolChoice::Facon);
    static LinkSettings udp(const QString &host, quint16 port = 500,
                            ProtocolChoice protocol = ProtocolChoice::Facon);
    static LinkSettings serial(const QString &portName, qint32 baudRate = 9600,
                               ProtocolChoice protocol = ProtocolChoice::Facon);

    // Serial format as written on PLC manuals and command lines: "7E1", "8N1", "8o2" (data bits 7
    // or 8, parity N/E/O in any case, stop bits 1 or 2). Sets the three fields and returns an
    // empty string, or returns one sentence saying what is wrong and changes nothing.
    QString setSerialFormat(const QString &text);
    // "7E1"
    QString serialFormat() const;
    // The parts alone (fatek-cli's --data, --parity, --stop): "7"/"8"; "N", "E", "O" or "none",
    // "even", "odd" in any case; "1"/"2". Surrounding blanks allowed.
    static std::optional<int> dataBitsFromText(const QString &text);
    static std::optional<Parity> parityFromText(const QString &text);
    static std::optional<int> stopBitsFromText(const QString &text);
    static QChar parityLetter(Parity parity);

    // "TCP 127.0.0.1:500, FACON", "UDP plc1:500, binary", "/dev/ttyUSB0 9600 7E1, auto-detect".
    QString toString() const;

    // A link a script can name (fatek-cli --link, FATEK_LINK, named links, the gateway's config):
    //   tcp://HOST[:PORT]   udp://HOST[:PORT]   (port 500; IPv6 in brackets: tcp://[fe80::1]:500)
    //   serial:///dev/ttyUSB0   serial://COM3   /dev/ttyUSB0   COM3   (9600 7E1)
    // with settings after '?', joined by '&': protocol=facon|binary|auto, timeout=MS, retries=N,
    // station=N and, on serial links, baud=N, format=7E1, flow=none|rtscts|xonxoff.
    // Settings not given keep the defaults of `defaults` (the medium's fields are replaced).
    // On error returns nothing and sets `error` to what is wrong, naming the part.
    struct Parsed;
    static std::optional<Parsed> fromUrl(const QString &url, Message *error,
                                         const LinkSettings &defaults);
    static std::optional<Parsed> fromUrl(const QString &url, Message *error);
    // The URL of these settings: the protocol and the settings that differ from the defaults;
    // fromUrl reads it back to equal settings (station 0 or less: none).
    QString toUrl(int station = -1) const;
    // "plc1:502", "plc1" (port 500), "[::1]:502": false if the text is not one of these.
    static bool hostPortFromText(const QString &text, QString *host, quint16 *port);
    // Empty when usable, else one sentence saying what to fix.
    Message validate() const;

    bool operator==(const LinkSettings &) const = default;
};

// What LinkSettings::fromUrl read: the settings, and the station when the URL named one.
struct LinkSettings::Parsed
{
    LinkSettings settings;
    std::optional<int> station;
};

QString protocolChoiceName(LinkSettings::ProtocolChoice choice);
// "facon", "binary", "auto" (any case): the choice; nothing for another text.
std::optional<LinkSettings::ProtocolChoice> protocolChoiceFromText(const QString &text);

} // namespace Fatek

Q_DECLARE_METATYPE(Fatek::LinkSettings)
