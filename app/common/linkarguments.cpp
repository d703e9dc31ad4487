#include "linkarguments.h"

#include "core/protocol/request.h"
#include "core/qtbridge/qtmessage.h"
#include "namedlinks.h"

#include <QCommandLineParser>
#include <QCoreApplication>

namespace Fatek {

namespace {

struct OptionText
{
    const char *name;
    const char *valueName;
    const char *description;
};

// The help texts of commandLineOptions(), in the order of names(); fatek-studio shows them in
// its language (context "main", scanned by lupdate with app/fatek-studio/main.cpp).
const OptionText optionTexts[] = {
    {"link", "url|@name",
     QT_TRANSLATE_NOOP("main", "Open a link by URL (tcp://HOST[:PORT], udp://HOST[:PORT], "
                               "serial://PORT?baud=19200&format=7E1) or by its name in "
                               "links.conf (@line1).")},
    {"tcp", "host[:port]",
     QT_TRANSLATE_NOOP("main", "Open a FATEK link over TCP (port 500 if not given).")},
    {"udp", "host[:port]",
     QT_TRANSLATE_NOOP("main", "Open a FATEK link over UDP (port 500 if not given).")},
    {"serial", "device", QT_TRANSLATE_NOOP("main", "Open a FATEK link on a serial line.")},
    {"baud", "n", QT_TRANSLATE_NOOP("main", "With --serial: speed (9600).")},
    {"parity", "N|E|O", QT_TRANSLATE_NOOP("main", "With --serial: parity (E).")},
    {"data", "7|8", QT_TRANSLATE_NOOP("main", "With --serial: data bits (7).")},
    {"stop", "1|2", QT_TRANSLATE_NOOP("main", "With --serial: stop bits (1).")},
    {"protocol", "facon|binary|auto", QT_TRANSLATE_NOOP("main", "Protocol on the link (auto).")},
    {"station", "n", QT_TRANSLATE_NOOP("main", "Station number of the link (1).")},
    {"timeout", "ms", QT_TRANSLATE_NOOP("main", "Answer timeout per attempt (1000).")},
    {"retries", "n", QT_TRANSLATE_NOOP("main", "Extra attempts after a timeout (2).")},
};

} // namespace

bool parseIntInRange(const QString &text, qint64 min, qint64 max, qint64 *out)
{
    bool ok = false;
    const qint64 v = text.trimmed().toLongLong(&ok, 10);
    if (!ok || v < min || v > max)
        return false;
    *out = v;
    return true;
}

const QStringList &LinkArguments::names()
{
    static const QStringList list = [] {
        QStringList l;
        for (const OptionText &o : optionTexts)
            l << QLatin1String(o.name);
        return l;
    }();
    return list;
}

bool LinkArguments::set(const QString &name, const QString &value)
{
    QString *field = nullptr;
    if (name == QLatin1String("link"))
        field = &link;
    else if (name == QLatin1String("tcp"))
        field = &tcp;
    else if (name == QLatin1String("udp"))
        field = &udp;
    else if (name == QLatin1String("serial"))
        field = &serial;
    else if (name == QLatin1String("baud"))
        field = &baud;
    else if (name == QLatin1String("parity"))
        field = &parity;
    else if (name == QLatin1String("data"))
        field = &data;
    else if (name == QLatin1String("stop"))
        field = &stop;
    else if (name == QLatin1String("protocol"))
        field = &protocol;
    else if (name == QLatin1String("station"))
        field = &station;
    else if (name == QLatin1String("timeout"))
        field = &timeout;
    else if (name == QLatin1String("retries"))
        field = &retries;
    else
        return false;
    *field = value;
    if (field == &link || field == &tcp || field == &udp || field == &serial)
        media << name;
    return true;
}

QList<QCommandLineOption> LinkArguments::commandLineOptions()
{
    QList<QCommandLineOption> options;
    for (const OptionText &o : optionTexts)
        options << QCommandLineOption(QLatin1String(o.name),
                                      QCoreApplication::translate("main", o.description),
                                      QLatin1String(o.valueName));
    return options;
}

LinkArguments LinkArguments::fromParser(const QCommandLineParser &parser)
{
    LinkArguments a;
    for (const QString &name : names()) {
        // Every occurrence, in order: a repeated medium counts twice, the last value wins.
        for (const QString &value : parser.values(name))
            a.set(name, value);
    }
    return a;
}

bool LinkArguments::any() const
{
    return !media.isEmpty() || !baud.isEmpty() || !parity.isEmpty() || !data.isEmpty()
           || !stop.isEmpty() || !protocol.isEmpty() || !station.isEmpty() || !timeout.isEmpty()
           || !retries.isEmpty();
}

LinkArgumentsResult resolveLinkArguments(const LinkArguments &a, const LinkArgumentRules &rules)
{
    LinkArgumentsResult r;
    auto fail = [&r](const QString &message) {
        r.error = message;
        return r;
    };
    QString medium = a.media.isEmpty() ? QString() : a.media.constLast();
    QString linkText = a.link;
    QString linkSource = QStringLiteral("--link");
    QString stationText = a.station;
    QString stationSource = QStringLiteral("--station");
    int given = static_cast<int>(a.media.size()) + (rules.alternativeGiven ? 1 : 0);
    if (rules.environment) {
        const QString envLink = qEnvironmentVariable("FATEK_LINK").trimmed();
        if (given == 0 && !envLink.isEmpty()) {
            medium = QStringLiteral("link");
            linkText = envLink;
            linkSource = QStringLiteral("FATEK_LINK");
            given = 1;
        }
        const QString envStation = qEnvironmentVariable("FATEK_STATION").trimmed();
        if (stationText.isEmpty() && !envStation.isEmpty() && given > 0) {
            stationText = envStation;
            stationSource = QStringLiteral("FATEK_STATION");
        }
    }
    const QString media = rules.alternative.isEmpty()
                              ? QStringLiteral("--link URL, --tcp HOST[:PORT], --udp HOST[:PORT] "
                                               "or --serial DEV")
                              : QStringLiteral("--link URL, --tcp HOST[:PORT], --udp "
                                               "HOST[:PORT], --serial DEV or %1")
                                    .arg(rules.alternative);
    if (given == 0 && rules.linkRequired)
        return fail(QStringLiteral("No link given: use %1.").arg(media));
    if (given > 1)
        return fail(rules.alternative.isEmpty()
                        ? QStringLiteral("Give only one of --link, --tcp, --udp and --serial.")
                        : QStringLiteral("Give only one of --link, --tcp, --udp, --serial and %1.")
                              .arg(rules.alternative));
    if (given == 0
        && !(a.protocol.isEmpty() && a.station.isEmpty() && a.timeout.isEmpty()
             && a.retries.isEmpty() && a.baud.isEmpty() && a.parity.isEmpty() && a.data.isEmpty()
             && a.stop.isEmpty()))
        return fail(QStringLiteral("--protocol, --station, --timeout, --retries and the serial "
                                   "options need a link: %1.")
                        .arg(media));
    LinkSettings defaults;
    defaults.protocol = rules.defaultProtocol;
    r.link = defaults;
    if (medium == QLatin1String("tcp") || medium == QLatin1String("udp")) {
        QString host;
        quint16 port = 500;
        const QString &text = medium == QLatin1String("tcp") ? a.tcp : a.udp;
        if (!LinkSettings::hostPortFromText(text, &host, &port))
            return fail(
                text.contains(QLatin1String("://"))
                    ? QStringLiteral("--%1 needs HOST or HOST:PORT, not a URL (\"%2\"): write "
                                     "--link %2.")
                          .arg(medium, text)
                    : QStringLiteral("--%1 needs HOST or HOST:PORT (port 1..65535; IPv6 in "
                                     "brackets), not \"%2\".")
                          .arg(medium, text));
        r.link.kind
            = medium == QLatin1String("tcp") ? LinkSettings::Kind::Tcp : LinkSettings::Kind::Udp;
        r.link.host = host;
        r.link.port = port;
        r.hasLink = true;
    } else if (medium == QLatin1String("serial")) {
        if (a.serial.trimmed().isEmpty())
            return fail(QStringLiteral("--serial needs a port, such as /dev/ttyUSB0 or COM3."));
        r.link.kind = LinkSettings::Kind::Serial;
        r.link.portName = a.serial.trimmed();
        r.hasLink = true;
    } else if (medium == QLatin1String("link")) {
        QString url = linkText.trimmed();
        if (url.startsWith(QLatin1Char('@'))) {
            QString error;
            url = lookUpNamedLink(url.mid(1), &error);
            if (url.isEmpty())
                return fail(QStringLiteral("%1: %2").arg(linkSource, error));
        }
        Message error;
        const std::optional<LinkSettings::Parsed> parsed
            = LinkSettings::fromUrl(url, &error, defaults);
        if (!parsed)
            return fail(QStringLiteral("%1: %2").arg(linkSource, englishText(error)));
        r.link = parsed->settings;
        if (parsed->station)
            r.station = static_cast<std::uint8_t>(*parsed->station);
        const QString query = url.section(QLatin1Char('?'), 1).toLower();
        r.protocolGiven = query.contains(QLatin1String("protocol="));
        r.timeoutGiven = query.contains(QLatin1String("timeout="));
        r.hasLink = true;
    }
    if (r.hasLink && r.link.kind != LinkSettings::Kind::Serial
        && !(a.baud.isEmpty() && a.parity.isEmpty() && a.data.isEmpty() && a.stop.isEmpty()))
        return fail(QStringLiteral("--baud, --parity, --data and --stop only apply to a serial "
                                   "link."));
    if (r.hasLink && r.link.kind == LinkSettings::Kind::Serial) {
        qint64 v = 0;
        if (!a.baud.isEmpty()) {
            if (!parseIntInRange(a.baud, 50, 10000000, &v))
                return fail(
                    QStringLiteral("--baud needs a speed like 9600, not \"%1\".").arg(a.baud));
            r.link.baudRate = static_cast<qint32>(v);
        }
        // The parts of a serial format, read as LinkSettings reads "7E1".
        if (!a.parity.isEmpty()) {
            const auto parity = LinkSettings::parityFromText(a.parity);
            if (!parity)
                return fail(QStringLiteral("--parity takes N, E or O, not \"%1\".").arg(a.parity));
            r.link.parity = *parity;
        }
        if (!a.data.isEmpty()) {
            const auto bits = LinkSettings::dataBitsFromText(a.data);
            if (!bits)
                return fail(QStringLiteral("--data takes 7 or 8, not \"%1\".").arg(a.data));
            r.link.dataBits = *bits;
        }
        if (!a.stop.isEmpty()) {
            const auto bits = LinkSettings::stopBitsFromText(a.stop);
            if (!bits)
                return fail(QStringLiteral("--stop takes 1 or 2, not \"%1\".").arg(a.stop));
            r.link.stopBits = *bits;
        }
    }
    if (!a.protocol.isEmpty()) {
        const std::optional<LinkSettings::ProtocolChoice> choice
            = protocolChoiceFromText(a.protocol);
        if (!choice)
            return fail(QStringLiteral("--protocol takes facon, binary or auto, not \"%1\".")
                            .arg(a.protocol));
        r.link.protocol = *choice;
        r.protocolGiven = true;
    }
    qint64 v = 0;
    if (!stationText.isEmpty()) {
        if (!parseIntInRange(stationText, rules.minStation, Limits::maxStation, &v))
            return fail(QStringLiteral("%1 takes %2..254, not \"%3\".")
                            .arg(stationSource)
                            .arg(rules.minStation)
                            .arg(stationText));
        r.station = static_cast<std::uint8_t>(v);
    } else if (r.station < rules.minStation) {
        return fail(QStringLiteral("%1: station %2 is not allowed here (%3..254).")
                        .arg(linkSource)
                        .arg(r.station)
                        .arg(rules.minStation));
    }
    if (!a.timeout.isEmpty()) {
        if (!parseIntInRange(a.timeout, 10, 60000, &v))
            return fail(QStringLiteral("--timeout takes 10..60000 ms, not \"%1\".").arg(a.timeout));
        r.link.timeoutMs = static_cast<int>(v);
        r.timeoutGiven = true;
    }
    if (!a.retries.isEmpty()) {
        if (!parseIntInRange(a.retries, 0, 10, &v))
            return fail(QStringLiteral("--retries takes 0..10, not \"%1\".").arg(a.retries));
        r.link.retries = static_cast<int>(v);
    }
    return r;
}

} // namespace Fatek
