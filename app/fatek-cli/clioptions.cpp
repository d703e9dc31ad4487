#include "clioptions.h"

#include "app/common/linkarguments.h"
#include "core/protocol/frametext.h"
#include "core/protocol/request.h"
#include "core/watch/itemvalues.h"
#include "core/watch/watchlist.h"

#include <QRegularExpression>

namespace Fatek {

namespace {

using Kind = LinkSettings::Kind;

Result<Address> parseAddress(const QString &text)
{
    return Address::parse(text.toStdString());
}

// One address, or a range "R0..R9" or "R0-9" (monitor, read).
Result<QList<Address>> parseAddressOrRange(const QString &text)
{
    return WatchList::expandRange(text);
}

QString errorOf(const ProtocolError &e)
{
    return QString::fromStdString(e.message);
}

QString formatNames()
{
    QStringList names;
    for (const DisplayFormat f : ValueFormat::allFormats())
        names << ValueFormat::name(f);
    return names.join(QStringLiteral(", "));
}

// Parses one command with its arguments into `s`; returns the usage error or nothing.
QString parseStep(const QStringList &arguments, bool frameGiven, bool forceHex, bool forceAscii,
                  CliStep *result)
{
    CliStep &s = *result;
    // The command.
    QStringList positional = arguments;
    s.name = positional.takeFirst().toLower();
    const QString &cmd = s.name;
    auto fail = [](const QString &message) {
        return message;
    };
    auto argCount = [&](qsizetype min, qsizetype max) -> QString {
        if (positional.size() < min)
            return QStringLiteral("%1 needs more arguments (see --help).").arg(cmd);
        if (max >= 0 && positional.size() > max)
            return QStringLiteral("%1: unexpected argument \"%2\".").arg(cmd, positional.at(max));
        return {};
    };
    auto countArg = [&](const QString &text, std::uint32_t max, std::uint32_t *out) -> QString {
        qint64 c = 0;
        if (!parseIntInRange(text, 1, max, &c))
            return QStringLiteral("%1: COUNT must be 1..%2, not \"%3\".")
                .arg(cmd)
                .arg(max)
                .arg(text);
        *out = static_cast<std::uint32_t>(c);
        return {};
    };
    QString err;

    if (cmd == QLatin1String("status") || cmd == QLatin1String("run")
        || cmd == QLatin1String("stop")) {
        if (!(err = argCount(0, 0)).isEmpty())
            return fail(err);
        s.command = cmd == QLatin1String("status") ? CliCommand::ShowStatus
                    : cmd == QLatin1String("run")  ? CliCommand::Run
                                                   : CliCommand::Stop;
    } else if (cmd == QLatin1String("read") || cmd == QLatin1String("forced")) {
        if (!(err = argCount(1, cmd == QLatin1String("forced") ? 2 : -1)).isEmpty())
            return fail(err);
        s.command = cmd == QLatin1String("read") ? CliCommand::Read : CliCommand::Forced;
        auto first = parseAddressOrRange(positional.at(0));
        if (!first)
            return fail(errorOf(first.error()));
        s.addresses = first.value();
        const bool range = s.addresses.size() > 1;
        bool secondIsAddress = false;
        if (positional.size() >= 2) {
            bool isNumber = false;
            positional.at(1).toLongLong(&isNumber);
            secondIsAddress = !isNumber && s.command == CliCommand::Read;
        }
        if (secondIsAddress) {
            // A mixed list (48): every further argument is an address or a range.
            for (qsizetype i = 1; i < positional.size(); ++i) {
                auto more = parseAddressOrRange(positional.at(i));
                if (!more)
                    return fail(errorOf(more.error()));
                s.addresses += more.value();
            }
            s.mixed = true;
            s.count = static_cast<std::uint32_t>(s.addresses.size());
        } else {
            if (positional.size() > 2)
                return fail(
                    QStringLiteral("%1: unexpected argument \"%2\".").arg(cmd, positional.at(2)));
            if (s.command == CliCommand::Forced && !isDiscrete(s.addresses.first().type))
                return fail(QStringLiteral("forced reads discretes (X Y M S T C), not %1.")
                                .arg(QString::fromStdString(s.addresses.first().toString())));
            if (positional.size() == 2) {
                if (range)
                    return fail(QStringLiteral("%1: give a range or a COUNT, not both.").arg(cmd));
                const std::uint32_t max = isDiscrete(s.addresses.first().type)
                                              ? Limits::maxDiscretes
                                              : Limits::maxRegisterWords;
                if (!(err = countArg(positional.at(1), max, &s.count)).isEmpty())
                    return fail(err);
            } else {
                s.count = static_cast<std::uint32_t>(s.addresses.size());
            }
            s.addresses = {s.addresses.first()};
            const Status span = validateSpan(s.addresses.first(), s.count);
            if (!span)
                return fail(errorOf(span.error()));
        }
    } else if (cmd == QLatin1String("write")) {
        if (!(err = argCount(2, -1)).isEmpty())
            return fail(err);
        s.command = CliCommand::Write;
        // "R100:float 1.5": the values are typed in FORMAT, each one an item of as many elements
        // as the format spans (R100 and R101 here); without it, in the element's default format.
        const QString &target = positional.at(0);
        const qsizetype colon = target.indexOf(QLatin1Char(':'));
        auto a = parseAddress(colon >= 0 ? target.left(colon) : target);
        if (!a)
            return fail(errorOf(a.error()));
        WatchItemSpec item;
        item.address = a.value();
        item.format = ValueFormat::defaultFormat(item.address);
        if (colon >= 0) {
            const auto format = ValueFormat::fromName(target.mid(colon + 1).trimmed());
            if (!format)
                return fail(QStringLiteral("Unknown format \"%1\" in %2 (%3).")
                                .arg(target.mid(colon + 1), target, formatNames()));
            item.format = *format;
            if (const Status valid = WatchList::validateEntry(item); !valid)
                return fail(errorOf(valid.error()));
        }
        s.addresses = {item.address};
        // Several values go to consecutive items; validateSpan below checks that they all exist.
        const auto elements = static_cast<std::uint32_t>(ItemValues(item).elementCount());
        for (qsizetype i = 1; i < positional.size(); ++i) {
            const QString &text = positional.at(i);
            item.address
                = s.addresses.first().advanced(static_cast<std::uint32_t>(i - 1) * elements);
            const ItemValues values(item);
            const auto raw = values.parse(text);
            if (!raw) {
                // Discretes keep the sentence fatek-cli has always given them.
                if (isDiscrete(item.address.type))
                    return fail(
                        QStringLiteral("%1 is a discrete: write 0, 1, on or off, not "
                                       "\"%2\".")
                            .arg(QString::fromStdString(item.address.toString()), text.trimmed()));
                return fail(QStringLiteral("%1: %2").arg(
                    QString::fromStdString(item.address.toString()), errorOf(raw.error())));
            }
            const std::vector<std::uint32_t> words = values.split(*raw);
            s.values.insert(s.values.end(), words.cbegin(), words.cend());
        }
        s.count = static_cast<std::uint32_t>(s.values.size());
        const Status span = validateSpan(s.addresses.first(), s.count);
        if (!span)
            return fail(errorOf(span.error()));
    } else if (cmd == QLatin1String("set") || cmd == QLatin1String("reset")
               || cmd == QLatin1String("enable") || cmd == QLatin1String("disable")) {
        if (!(err = argCount(1, 1)).isEmpty())
            return fail(err);
        s.command = CliCommand::Control;
        auto a = parseAddress(positional.at(0));
        if (!a)
            return fail(errorOf(a.error()));
        if (!isDiscrete(a.value().type))
            return fail(QStringLiteral("%1 works on discretes (X Y M S T C), not %2.")
                            .arg(cmd, QString::fromStdString(a.value().toString())));
        s.addresses = {a.value()};
        const DiscreteOp op = cmd == QLatin1String("set")      ? DiscreteOp::Set
                              : cmd == QLatin1String("reset")  ? DiscreteOp::Reset
                              : cmd == QLatin1String("enable") ? DiscreteOp::Enable
                                                               : DiscreteOp::Disable;
        s.controlOp = static_cast<int>(op);
    } else if (cmd == QLatin1String("loopback")) {
        if (!(err = argCount(0, -1)).isEmpty())
            return fail(err);
        s.command = CliCommand::Loopback;
        const QString text = positional.isEmpty() ? QStringLiteral("FATEK-CLI")
                                                  : positional.join(QLatin1Char(' '));
        s.loopbackData = text.toLatin1();
        if (s.loopbackData.isEmpty()
            || static_cast<std::uint32_t>(s.loopbackData.size()) > Limits::maxLoopback)
            return fail(
                QStringLiteral("loopback TEXT must be 1..%1 characters.").arg(Limits::maxLoopback));
    } else if (cmd == QLatin1String("monitor")) {
        if (!(err = argCount(1, -1)).isEmpty())
            return fail(err);
        s.command = CliCommand::Monitor;
        for (const QString &text : positional) {
            // "R0..R3:hex": a format after the colon applies to every element of the argument.
            const qsizetype colon = text.indexOf(QLatin1Char(':'));
            std::optional<DisplayFormat> format;
            if (colon >= 0) {
                format = ValueFormat::fromName(text.mid(colon + 1).trimmed());
                if (!format)
                    return fail(QStringLiteral("Unknown format \"%1\" in %2 (%3).")
                                    .arg(text.mid(colon + 1), text, formatNames()));
            }
            auto more = parseAddressOrRange(colon >= 0 ? text.left(colon) : text);
            if (!more)
                return fail(errorOf(more.error()));
            s.addresses += more.value();
            for (qsizetype n = 0; n < more.value().size(); ++n)
                s.formats << format;
        }
        if (s.addresses.size() > WatchList::MaxRangeItems)
            return fail(QStringLiteral("monitor watches at most %1 elements.")
                            .arg(WatchList::MaxRangeItems));
    } else if (cmd == QLatin1String("raw")) {
        if (!(err = argCount(1, -1)).isEmpty())
            return fail(err);
        s.command = CliCommand::Raw;
        if (forceHex && forceAscii)
            return fail(QStringLiteral("raw: give --hex or --ascii, not both."));
        s.rawBytes = parseRawText(positional.join(QLatin1Char(' ')), forceHex, forceAscii, &err,
                                  &s.rawHex);
        if (!err.isEmpty())
            return fail(err);
        s.rawFrame = frameGiven;
    } else if (cmd == QLatin1String("scan")) {
        if (!(err = argCount(0, 1)).isEmpty())
            return fail(err);
        s.command = CliCommand::Scan;
        if (!positional.isEmpty()) {
            static const QRegularExpression range(QStringLiteral("^(\\d+)(?:\\.\\.(\\d+))?$"));
            const auto m = range.match(positional.at(0).trimmed());
            qint64 first = 0, last = 0;
            if (!m.hasMatch() || !parseIntInRange(m.captured(1), 1, Limits::maxStation, &first)
                || !parseIntInRange(m.captured(2).isEmpty() ? m.captured(1) : m.captured(2), 1,
                                    Limits::maxStation, &last)
                || last < first)
                return fail(
                    QStringLiteral("scan takes a station range like 1..16 (1..254), not \"%1\".")
                        .arg(positional.at(0)));
            s.scanFirst = static_cast<int>(first);
            s.scanLast = static_cast<int>(last);
        }
    } else {
        return fail(QStringLiteral("Unknown command \"%1\" (see --help).").arg(cmd));
    }
    return {};
}

} // namespace

QString usageText()
{
    return QStringLiteral(
        "Usage: fatek-cli [LINK] [OPTIONS] COMMAND [ARGS]\n"
        "\n"
        "Link (exactly one):\n"
        "  --tcp HOST[:PORT]        FATEK over TCP (port 500 if not given)\n"
        "  --udp HOST[:PORT]        FATEK over UDP (port 500 if not given)\n"
        "  --serial DEV             serial line, with --baud N (9600) --parity N|E|O (E) --data "
        "7|8 (7) --stop 1|2 (1)\n"
        "  --sim                    embedded simulator (FBs profile, demo ladder, RUN) on "
        "127.0.0.1\n"
        "\n"
        "Options:\n"
        "  --protocol facon|binary|auto   (auto for a real link, facon for --sim)\n"
        "  --station N              station 1..254 (0 = broadcast, no answer) [1]\n"
        "  --timeout MS             per attempt [1000]\n"
        "  --retries N              extra attempts after a timeout [2]\n"
        "  --read-only              operator mode: writes, RUN/STOP, forcing and raw frames are "
        "refused\n"
        "  --json | --csv           output one JSON object per line / CSV instead of a table\n"
        "  --help, --version\n"
        "\n"
        "Commands:\n"
        "  status                   STATUS1 bits and the detail status (53)\n"
        "  run | stop               switch the PLC to RUN / STOP\n"
        "  read ADDR [COUNT]        consecutive elements (ADDR may be a range R0..R9)\n"
        "  read ADDR ADDR...        a mixed list (48)\n"
        "  write ADDR[:FORMAT] VALUE...   typed as in a watch table: 12, -5, 0x1A, 1Ah, 0b1010;\n"
        "                           discretes 0/1/on/off; R0:float 1.5 writes R0 and R1; several "
        "=\n"
        "                           consecutive items\n"
        "  set|reset|enable|disable ADDR   discrete control (42)\n"
        "  forced ADDR [COUNT]      which discretes are disabled (forced) (43)\n"
        "  loopback [TEXT] [--count N]     round trips: min/mean/max, mismatches, timeouts\n"
        "  monitor ADDR[:FORMAT]... [--interval MS] [--cycles N] [--format FORMAT] [--output "
        "FILE]\n"
        "                           poll, one line per cycle (ADDR may be a range); FORMAT: "
        "unsigned,\n"
        "                           signed, hex, binary, bcd, float, double, bit; --output "
        "appends a CSV\n"
        "                           data log (timestamp, values, status) to FILE\n"
        "  raw HEX|ASCII [--frame] [--hex|--ascii]   send bytes (\"01 40\" is hex, \"0140\" "
        "ASCII);\n"
        "                           --frame adds the protocol's framing and checksum (under "
        "auto:\n"
        "                           binary framing for hex bytes, FACON for ASCII text)\n"
        "  scan [FROM..TO]          which stations answer (default 1..254)\n"
        "\n"
        "Exit codes: 0 ok, 2 usage, 3 link failure (timeout, no connection), 4 PLC error, 5 "
        "refused by --read-only.\n");
}

QByteArray parseRawText(const QString &text, bool forceHex, bool forceAscii, QString *error,
                        bool *isHex)
{
    const QString t = text.trimmed();
    if (t.isEmpty()) {
        *error = QStringLiteral("raw needs the bytes to send.");
        return {};
    }
    const FrameText::Typed typed = forceHex     ? FrameText::Typed::Hex
                                   : forceAscii ? FrameText::Typed::Ascii
                                                : FrameText::Typed::Guess;
    const Result<Bytes> bytes = FrameText::parse(t.toStdString(), typed, isHex);
    if (!bytes) {
        *error
            = QStringLiteral("\"%1\": %2").arg(text, QString::fromStdString(bytes.error().message));
        return {};
    }
    return QByteArray(reinterpret_cast<const char *>(bytes->data()),
                      static_cast<qsizetype>(bytes->size()));
}

CliParseResult parseCommandLine(const QStringList &arguments)
{
    CliOptions o;
    QStringList positional;
    LinkArguments link;
    bool linkCount = false;
    bool forceHex = false, forceAscii = false;
    bool countGiven = false, intervalGiven = false, cyclesGiven = false, frameGiven = false;
    QString countText, intervalText, cyclesText;
    auto fail = [](const QString &message) {
        return CliParseResult{std::nullopt, message};
    };

    const QStringList valued = LinkArguments::names()
                               + QStringList{QStringLiteral("count"), QStringLiteral("interval"),
                                             QStringLiteral("cycles"), QStringLiteral("output"),
                                             QStringLiteral("format")};
    bool onlyPositional = false;
    for (qsizetype i = 0; i < arguments.size(); ++i) {
        const QString &arg = arguments.at(i);
        if (onlyPositional || !arg.startsWith(QLatin1String("--"))) {
            if (!onlyPositional && (arg == QLatin1String("-h")))
                o.help = true;
            else if (!onlyPositional && (arg == QLatin1String("-v")))
                o.version = true;
            else
                positional << arg;
            continue;
        }
        if (arg == QLatin1String("--then")) {
            positional << QStringLiteral("\x01then");
            continue;
        }
        if (arg == QLatin1String("--")) {
            onlyPositional = true;
            continue;
        }
        QString name = arg.mid(2);
        QString value;
        bool hasValue = false;
        if (const qsizetype eq = name.indexOf(QLatin1Char('=')); eq >= 0) {
            value = name.mid(eq + 1);
            name = name.left(eq);
            hasValue = true;
        }
        if (valued.contains(name)) {
            if (!hasValue) {
                if (i + 1 >= arguments.size())
                    return fail(QStringLiteral("--%1 needs a value.").arg(name));
                value = arguments.at(++i);
            }
            if (link.set(name, value))
                continue;
            if (name == QLatin1String("count")) {
                countText = value;
                countGiven = true;
            } else if (name == QLatin1String("interval")) {
                intervalText = value;
                intervalGiven = true;
            } else if (name == QLatin1String("cycles")) {
                cyclesText = value;
                cyclesGiven = true;
            } else if (name == QLatin1String("output")) {
                if (value.trimmed().isEmpty())
                    return fail(QStringLiteral("--output needs a file name."));
                o.outputPath = value;
            } else if (name == QLatin1String("format")) {
                o.valueFormat = ValueFormat::fromName(value.trimmed());
                if (!o.valueFormat)
                    return fail(QStringLiteral("--format takes one of %1, not \"%2\".")
                                    .arg(formatNames(), value));
            }
            continue;
        }
        if (hasValue)
            return fail(QStringLiteral("--%1 takes no value.").arg(name));
        if (name == QLatin1String("help"))
            o.help = true;
        else if (name == QLatin1String("version"))
            o.version = true;
        else if (name == QLatin1String("sim")) {
            o.sim = true;
            linkCount = true;
        } else if (name == QLatin1String("json"))
            o.format = OutputFormat::Json;
        else if (name == QLatin1String("csv"))
            o.format = OutputFormat::Csv;
        else if (name == QLatin1String("read-only"))
            o.readOnly = true;
        else if (name == QLatin1String("frame"))
            frameGiven = true;
        else if (name == QLatin1String("hex"))
            forceHex = true;
        else if (name == QLatin1String("ascii"))
            forceAscii = true;
        else
            return fail(QStringLiteral("Unknown option --%1 (see --help).").arg(name));
    }
    if (o.help || o.version)
        return {o, {}};

    // The link.
    LinkArgumentRules rules;
    rules.alternative = QStringLiteral("--sim");
    rules.alternativeGiven = linkCount;
    rules.defaultProtocol
        = o.sim ? LinkSettings::ProtocolChoice::Facon : LinkSettings::ProtocolChoice::Auto;
    const LinkArgumentsResult resolved = resolveLinkArguments(link, rules);
    if (!resolved.error.isEmpty())
        return fail(resolved.error);
    o.link = resolved.link;
    o.link.autoReconnect = false; // a script wants the failure, not a retry loop
    o.protocolGiven = resolved.protocolGiven;
    o.timeoutGiven = resolved.timeoutGiven;
    o.station = resolved.station;
    qint64 v = 0;

    // The commands, separated by --then.
    if (positional.isEmpty())
        return fail(QStringLiteral(
            "No command given (status, run, stop, read, write, set, reset, enable, disable, "
            "forced, loopback, monitor, raw, scan)."));
    QList<QStringList> parts{QStringList{}};
    for (const QString &p : positional) {
        if (p == QLatin1String("\x01then"))
            parts << QStringList{};
        else
            parts.last() << p;
    }
    QStringList names;
    for (const QStringList &part : parts) {
        if (part.isEmpty())
            return fail(QStringLiteral("--then needs a command on both sides."));
        names << part.first().toLower();
    }
    auto uses = [&](const char *name) {
        return names.contains(QLatin1String(name));
    };
    if (countGiven && !uses("loopback"))
        return fail(QStringLiteral("--count only applies to loopback."));
    if ((intervalGiven || cyclesGiven) && !uses("monitor"))
        return fail(QStringLiteral("--interval and --cycles only apply to monitor."));
    if ((!o.outputPath.isEmpty() || o.valueFormat) && !uses("monitor"))
        return fail(QStringLiteral("--output and --format only apply to monitor."));
    if ((frameGiven || forceHex || forceAscii) && !uses("raw"))
        return fail(QStringLiteral("--frame, --hex and --ascii only apply to raw."));
    if (countGiven) {
        if (!parseIntInRange(countText, 1, 100000, &v))
            return fail(QStringLiteral("--count takes 1..100000, not \"%1\".").arg(countText));
        o.loopbackCount = static_cast<int>(v);
    }
    if (intervalGiven) {
        if (!parseIntInRange(intervalText, WatchList::MinIntervalMs, WatchList::MaxIntervalMs, &v))
            return fail(QStringLiteral("--interval takes %1..%2 ms, not \"%3\".")
                            .arg(WatchList::MinIntervalMs)
                            .arg(WatchList::MaxIntervalMs)
                            .arg(intervalText));
        o.intervalMs = static_cast<int>(v);
    }
    if (cyclesGiven) {
        if (!parseIntInRange(cyclesText, 1, 100000000, &v))
            return fail(
                QStringLiteral("--cycles takes a positive number, not \"%1\".").arg(cyclesText));
        o.cycles = static_cast<int>(v);
    }
    for (qsizetype n = 0; n < parts.size(); ++n) {
        CliStep step;
        const QString error = parseStep(parts.at(n), frameGiven, forceHex, forceAscii, &step);
        if (!error.isEmpty())
            return fail(error);
        const bool answerNeeded
            = step.command == CliCommand::ShowStatus || step.command == CliCommand::Read
              || step.command == CliCommand::Forced || step.command == CliCommand::Loopback
              || step.command == CliCommand::Monitor;
        if (o.station == Limits::broadcastStation && answerNeeded)
            return fail(
                QStringLiteral("%1 needs an answer: station 0 is broadcast, PLCs do not answer it "
                               "(use --station 1..254).")
                    .arg(step.name));
        if (step.command == CliCommand::Monitor) {
            for (qsizetype i = 0; i < step.addresses.size(); ++i) {
                WatchItemSpec item;
                item.address = step.addresses.at(i);
                item.station = o.station;
                item.format = step.formats.value(i).value_or(
                    o.valueFormat.value_or(ValueFormat::defaultFormat(item.address)));
                // A global --format that does not fit an element (bit for R0) falls back to the
                // element's default; a format asked for that element alone must fit.
                if (!step.formats.value(i)
                    && ValueFormat::valueWidth(item.address, item.format) == 0)
                    item.format = ValueFormat::defaultFormat(item.address);
                // Station 0 is refused above for monitor; validate with a real one.
                WatchItemSpec check = item;
                check.station = 1;
                if (const Status valid = WatchList::validateEntry(check); !valid)
                    return fail(errorOf(valid.error()));
                step.items << item;
            }
        }
        if (step.command == CliCommand::Monitor && o.cycles == 0 && n + 1 < parts.size())
            return fail(
                QStringLiteral("monitor before --then needs --cycles: it would never end."));
        o.steps << step;
    }
    return {o, {}};
}

} // namespace Fatek
