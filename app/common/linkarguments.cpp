#include "linkarguments.h"

#include "core/protocol/request.h"

#include <QCommandLineParser>
#include <QCoreApplication>

namespace Fatek {

namespace {

// "plc1:502", "plc1" (port 500), "[::1]:502".
bool parseHostPort(const QString &text, QString *host, quint16 *port)
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
    }
    if (h.isEmpty())
        return false;
    *host = h;
    *port = 500;
    if (!p.isEmpty()) {
        qint64 v = 0;
        if (!parseIntInRange(p, 1, 65535, &v))
            return false;
        *port = static_cast<quint16>(v);
    }
    return true;
}

struct OptionText
{
    const char *name;
    const char *valueName;
    const char *description;
};

// The help texts of commandLineOptions(), in the order of names(); fatek-studio shows them in
// its language (context "main", scanned by lupdate with app/fatek-studio/main.cpp).
const OptionText optionTexts[] = {
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
    if (name == QLatin1String("tcp")) {
        tcp = value;
        ++links;
    } else if (name == QLatin1String("udp")) {
        udp = value;
        ++links;
    } else if (name == QLatin1String("serial")) {
        serial = value;
        ++links;
    } else if (name == QLatin1String("baud"))
        baud = value;
    else if (name == QLatin1String("parity"))
        parity = value;
    else if (name == QLatin1String("data"))
        data = value;
    else if (name == QLatin1String("stop"))
        stop = value;
    else if (name == QLatin1String("protocol"))
        protocol = value;
    else if (name == QLatin1String("station"))
        station = value;
    else if (name == QLatin1String("timeout"))
        timeout = value;
    else if (name == QLatin1String("retries"))
        retries = value;
    else
        return false;
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
    return links > 0 || !baud.isEmpty() || !parity.isEmpty() || !data.isEmpty() || !stop.isEmpty()
           || !protocol.isEmpty() || !station.isEmpty() || !timeout.isEmpty() || !retries.isEmpty();
}

LinkArgumentsResult resolveLinkArguments(const LinkArguments &a, const LinkArgumentRules &rules)
{
    LinkArgumentsResult r;
    auto fail = [&r](const QString &message) {
        r.error = message;
        return r;
    };
    const int given = a.links + (rules.alternativeGiven ? 1 : 0);
    if (given == 0 && rules.linkRequired)
        return fail(rules.alternative.isEmpty()
                        ? QStringLiteral("No link given: use --tcp HOST[:PORT], --udp HOST[:PORT] "
                                         "or --serial DEV.")
                        : QStringLiteral("No link given: use --tcp HOST[:PORT], --udp HOST[:PORT], "
                                         "--serial DEV or %1.")
                              .arg(rules.alternative));
    if (given > 1)
        return fail(rules.alternative.isEmpty()
                        ? QStringLiteral("Give only one of --tcp, --udp and --serial.")
                        : QStringLiteral("Give only one of --tcp, --udp, --serial and %1.")
                              .arg(rules.alternative));
    if (a.serial.isEmpty()
        && !(a.baud.isEmpty() && a.parity.isEmpty() && a.data.isEmpty() && a.stop.isEmpty()))
        return fail(QStringLiteral("--baud, --parity, --data and --stop only apply to --serial."));
    if (given == 0
        && !(a.protocol.isEmpty() && a.station.isEmpty() && a.timeout.isEmpty()
             && a.retries.isEmpty()))
        return fail(QStringLiteral("--protocol, --station, --timeout and --retries need a link: "
                                   "--tcp HOST[:PORT], --udp HOST[:PORT] or --serial DEV."));
    if (!a.tcp.isEmpty() || !a.udp.isEmpty()) {
        QString host;
        quint16 port = 500;
        const QString &text = a.tcp.isEmpty() ? a.udp : a.tcp;
        if (!parseHostPort(text, &host, &port))
            return fail(
                QStringLiteral("--%1 needs HOST or HOST:PORT (port 1..65535), not \"%2\".")
                    .arg(a.tcp.isEmpty() ? QStringLiteral("udp") : QStringLiteral("tcp"), text));
        r.link = a.tcp.isEmpty() ? LinkSettings::udp(host, port) : LinkSettings::tcp(host, port);
        r.hasLink = true;
    } else if (!a.serial.isEmpty()) {
        r.link = LinkSettings::serial(a.serial);
        r.hasLink = true;
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
    r.link.protocol = rules.defaultProtocol;
    if (!a.protocol.isEmpty()) {
        const QString p = a.protocol.toLower();
        r.protocolGiven = true;
        if (p == QLatin1String("facon"))
            r.link.protocol = LinkSettings::ProtocolChoice::Facon;
        else if (p == QLatin1String("binary"))
            r.link.protocol = LinkSettings::ProtocolChoice::Binary;
        else if (p == QLatin1String("auto"))
            r.link.protocol = LinkSettings::ProtocolChoice::Auto;
        else
            return fail(QStringLiteral("--protocol takes facon, binary or auto, not \"%1\".")
                            .arg(a.protocol));
    }
    qint64 v = 0;
    if (!a.station.isEmpty()) {
        if (!parseIntInRange(a.station, rules.minStation, Limits::maxStation, &v))
            return fail(rules.minStation == 0
                            ? QStringLiteral("--station takes 0..254, not \"%1\".").arg(a.station)
                            : QStringLiteral("--station takes %1..254, not \"%2\".")
                                  .arg(rules.minStation)
                                  .arg(a.station));
        r.station = static_cast<std::uint8_t>(v);
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
