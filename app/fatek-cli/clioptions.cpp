#include "clioptions.h"

#include "app/common/linkarguments.h"
#include "clicommands.h"
#include "climonitorcommand.h"
#include "clisnapshotfilecommand.h"
#include "clitext.h"
#include "core/watch/watchlist.h"

#include <QFileInfo>

namespace Fatek {

namespace {

// The command table's lines (commandUsage()): the synopsis in a column of 25, the summary
// wrapped beside it (below it when the synopsis is wider).
QString commandsText()
{
    constexpr qsizetype indent = 27;
    constexpr qsizetype width = 92;
    QString text;
    for (const auto &[synopsis, summary] : commandUsage()) {
        QString line = QStringLiteral("  ") + synopsis;
        if (line.size() < indent - 1)
            line = line.leftJustified(indent, QLatin1Char(' '));
        else {
            text += line + QLatin1Char('\n');
            line = QString(indent, QLatin1Char(' '));
        }
        const QString words
            = QString(summary).replace(QStringLiteral("%FORMATS%"), CliText::formatNames());
        bool first = true;
        for (const QString &word : words.split(QLatin1Char(' '), Qt::SkipEmptyParts)) {
            if (!first && line.size() + 1 + word.size() > width) {
                text += line + QLatin1Char('\n');
                line = QString(indent, QLatin1Char(' '));
                first = true;
            }
            line += (first ? QString() : QStringLiteral(" ")) + word;
            first = false;
        }
        text += line + QLatin1Char('\n');
    }
    return text;
}

// The exit code table's lines: the code in a column of 5, its meaning wrapped beside it.
QString exitCodesText()
{
    QString text = QStringLiteral("Exit codes:\n");
    for (const auto &[code, meaning] : exitCodeUsage()) {
        QString line = QStringLiteral("  %1").arg(code, -5);
        bool first = true;
        for (const QString &word : meaning.split(QLatin1Char(' '), Qt::SkipEmptyParts)) {
            if (!first && line.size() + 1 + word.size() > 92) {
                text += line + QLatin1Char('\n');
                line = QString(7, QLatin1Char(' '));
                first = true;
            }
            line += (first ? QString() : QStringLiteral(" ")) + word;
            first = false;
        }
        text += line + QLatin1Char('\n');
    }
    return text;
}

} // namespace

QList<std::pair<int, QString>> exitCodeUsage()
{
    return {
        {ExitCode::Ok, QStringLiteral("ok")},
        {ExitCode::Internal,
         QStringLiteral("a file or the output not written (the reason on stderr; also a missing "
                        "folder, a read-only medium, a full disk), the simulator could not "
                        "listen")},
        {ExitCode::Usage,
         QStringLiteral("usage (also a damaged file, another model, a restore not confirmed, "
                        "checkout: points the PLC refuses)")},
        {ExitCode::Link, QStringLiteral("link failure (timeout, no connection)")},
        {ExitCode::Plc,
         QStringLiteral("PLC error (also RUN during restore, program verification failed)")},
        {ExitCode::ReadOnly, QStringLiteral("refused by --read-only")},
        {ExitCode::Differ,
         QStringLiteral("differences found (diff; restore-values read back other values; "
                        "checkout: a point failed, deferred or untested)")},
        {ExitCode::Unknown,
         QStringLiteral("a change sent and not answered, and reading it back could not tell "
                        "whether the PLC carried it out: check the PLC")},
        {ExitCode::Interrupted, QStringLiteral("interrupted (Ctrl-C, SIGTERM)")},
        {ExitCode::ClosedPipe,
         QStringLiteral("the output's reader is gone (a closed pipe, as \"| head\")")},
    };
}

bool isDevice(const QString &path)
{
    const QFileInfo info(path); // follows links: a link to a device is one
    return info.exists() && !info.isFile() && !info.isDir();
}

QString usageText()
{
    return QStringLiteral(
               "Usage: fatek-cli [LINK] [OPTIONS] COMMAND [ARGS]\n"
               "\n"
               "Link (exactly one; without one, FATEK_LINK, and FATEK_STATION for --station):\n"
               "  --link URL|@NAME         tcp://HOST[:PORT], udp://HOST[:PORT],\n"
               "                           serial:///dev/ttyUSB0?baud=19200&format=7E1 (or COM3); "
               "settings\n"
               "                           protocol, timeout, retries, station; @NAME: a line NAME "
               "= URL\n"
               "                           in ~/.config/fatek-studio/links.conf\n"
               "  --tcp HOST[:PORT]        FATEK over TCP (port 500 if not given)\n"
               "  --udp HOST[:PORT]        FATEK over UDP (port 500 if not given)\n"
               "  --serial DEV             serial line, with --baud N (9600) --parity N|E|O (E) "
               "--data "
               "7|8 (7) --stop 1|2 (1)\n"
               "  --sim                    embedded simulator (FBs profile, demo ladder, RUN) on "
               "127.0.0.1\n"
               "\n"
               "Options:\n"
               "  --protocol facon|binary|auto   (auto for a real link, facon for --sim)\n"
               "  --station N              station 1..254 (0 = broadcast, no answer) [1]\n"
               "  --timeout MS             per attempt [1000]\n"
               "  --retries N              extra attempts after a timeout [2]\n"
               "  --read-only              operator mode: writes, RUN/STOP, forcing and raw frames "
               "are "
               "refused\n"
               "  --yes                    confirm restore / restore-values without asking (needed "
               "when\n"
               "                           standard input is not a terminal)\n"
               "  --other-model            restore-values: write a snapshot of another PLC model "
               "(its\n"
               "                           elements must still exist on this PLC)\n"
               "  --json | --csv           output one JSON object per line / CSV instead of a "
               "table\n"
               "  --crlf                   CSV files written (monitor --output, snapshot, "
               "checkout)\n"
               "                           with Windows line ends (CSV on stdout keeps LF)\n"
               "  --then                   run the next command on the same link (status --then "
               "read R0)\n"
               "  --completion bash|zsh    print the shell completion script (the .deb installs "
               "both)\n"
               "  --help, --version\n"
               "\n"
               "Commands:\n"
               "%1"
               "\n"
               "%2")
        .arg(commandsText(), exitCodesText());
}

QStringList valuedOptionNames()
{
    return LinkArguments::names()
           + QStringList{QStringLiteral("count"),
                         QStringLiteral("interval"),
                         QStringLiteral("cycles"),
                         QStringLiteral("output"),
                         QStringLiteral("format"),
                         QStringLiteral("names"),
                         QStringLiteral("completion"),
                         QStringLiteral("report"),
                         QStringLiteral("lang"),
                         QStringLiteral("save"),
                         QStringLiteral("project"),
                         QStringLiteral("customer"),
                         QStringLiteral("engineer"),
                         QStringLiteral("document"),
                         QStringLiteral("revision"),
                         QStringLiteral("company"),
                         QStringLiteral("witness"),
                         QStringLiteral("witness-company"),
                         QStringLiteral("customer-signatory"),
                         QStringLiteral("punch")};
}

QStringList flagOptionNames()
{
    return {QStringLiteral("help"),  QStringLiteral("version"), QStringLiteral("sim"),
            QStringLiteral("json"),  QStringLiteral("csv"),     QStringLiteral("read-only"),
            QStringLiteral("yes"),   QStringLiteral("frame"),   QStringLiteral("hex"),
            QStringLiteral("ascii"), QStringLiteral("then"),    QStringLiteral("other-model"),
            QStringLiteral("crlf")};
}

CliParseResult parseCommandLine(const QStringList &arguments)
{
    CliOptions o;
    QStringList positional;
    LinkArguments link;
    bool linkCount = false;
    bool forceHex = false, forceAscii = false;
    bool countGiven = false, intervalGiven = false, cyclesGiven = false, frameGiven = false;
    bool checkoutGiven = false;
    QString countText, intervalText, cyclesText;
    auto fail = [](const QString &message) {
        return CliParseResult{std::nullopt, message};
    };

    const QStringList valued = valuedOptionNames();
    bool onlyPositional = false;
    for (qsizetype i = 0; i < arguments.size(); ++i) {
        const QString &arg = arguments.at(i);
        if (onlyPositional || !arg.startsWith(QLatin1String("--"))) {
            if (!onlyPositional && (arg == QLatin1String("-h")))
                o.help = true;
            else if (!onlyPositional && (arg == QLatin1String("-v")))
                o.version = true;
            else if (!onlyPositional && arg.size() > 1 && arg.at(0) == QLatin1Char('-')
                     && arg.at(1).isLetter()
                     && (positional.isEmpty() || positional.last() == QLatin1String("\x01then")))
                // Where a command is due, "-x" is a mistyped option, not a command ("write R0
                // -5" and other values keep their dash).
                return fail(QStringLiteral("Unknown option %1 (see --help).").arg(arg));
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
            if (name == QLatin1String("completion")) {
                if (value != QLatin1String("bash") && value != QLatin1String("zsh"))
                    return fail(
                        QStringLiteral("--completion takes bash or zsh, not \"%1\".").arg(value));
                o.completion = value;
                continue;
            }
            if (name == QLatin1String("punch")) {
                if (value.trimmed().isEmpty())
                    return fail(QStringLiteral("--punch needs a file name."));
                if (!value.endsWith(QLatin1String(".csv"), Qt::CaseInsensitive) && !isDevice(value))
                    return fail(QStringLiteral("--punch: the punch list is a CSV file: its name "
                                               "ends in .csv, not \"%1\".")
                                    .arg(value));
                o.checkoutPunch = value;
                checkoutGiven = true;
                continue;
            }
            if (QString *field
                = name == QLatin1String("document")             ? &o.checkoutDocument
                  : name == QLatin1String("revision")           ? &o.checkoutRevision
                  : name == QLatin1String("company")            ? &o.checkoutCompany
                  : name == QLatin1String("witness")            ? &o.checkoutWitness
                  : name == QLatin1String("witness-company")    ? &o.checkoutWitnessCompany
                  : name == QLatin1String("customer-signatory") ? &o.checkoutSignatory
                                                                : nullptr) {
                *field = value.trimmed();
                checkoutGiven = true;
                continue;
            }
            if (name == QLatin1String("report") || name == QLatin1String("save")) {
                if (value.trimmed().isEmpty())
                    return fail(QStringLiteral("--%1 needs a file name.").arg(name));
                // A device (/dev/stdout, /dev/full) is written directly, as CSV.
                if (name == QLatin1String("report")
                    && !value.endsWith(QLatin1String(".pdf"), Qt::CaseInsensitive)
                    && !value.endsWith(QLatin1String(".csv"), Qt::CaseInsensitive)
                    && !isDevice(value))
                    return fail(QStringLiteral("--report: a report file name ends in .pdf or "
                                               ".csv, not \"%1\".")
                                    .arg(value));
                (name == QLatin1String("report") ? o.checkoutReport : o.checkoutSave) = value;
                checkoutGiven = true;
                continue;
            }
            if (name == QLatin1String("lang")) {
                if (value != QLatin1String("en") && value != QLatin1String("zh_TW"))
                    return fail(QStringLiteral("--lang takes en or zh_TW, not \"%1\".").arg(value));
                o.checkoutLanguage = value;
                checkoutGiven = true;
                continue;
            }
            if (name == QLatin1String("project") || name == QLatin1String("customer")
                || name == QLatin1String("engineer")) {
                (name == QLatin1String("project")    ? o.checkoutProject
                 : name == QLatin1String("customer") ? o.checkoutCustomer
                                                     : o.checkoutEngineer)
                    = value;
                checkoutGiven = true;
                continue;
            }
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
            } else if (name == QLatin1String("names")) {
                if (value.trimmed().isEmpty())
                    return fail(QStringLiteral("--names needs a file name."));
                o.namesPath = value;
            } else if (name == QLatin1String("format")) {
                o.valueFormat = ValueFormat::fromName(value.trimmed());
                if (!o.valueFormat)
                    return fail(QStringLiteral("--format takes one of %1, not \"%2\".")
                                    .arg(CliText::formatNames(), value));
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
        } else if (name == QLatin1String("json") || name == QLatin1String("csv")) {
            const OutputFormat format
                = name == QLatin1String("json") ? OutputFormat::Json : OutputFormat::Csv;
            if (o.format != OutputFormat::Table && o.format != format)
                return fail(QStringLiteral("Give only one of --json and --csv."));
            o.format = format;
        } else if (name == QLatin1String("read-only"))
            o.readOnly = true;
        else if (name == QLatin1String("yes"))
            o.assumeYes = true;
        else if (name == QLatin1String("other-model"))
            o.otherModel = true;
        else if (name == QLatin1String("crlf"))
            o.crlf = true;
        else if (name == QLatin1String("frame"))
            frameGiven = true;
        else if (name == QLatin1String("hex"))
            forceHex = true;
        else if (name == QLatin1String("ascii"))
            forceAscii = true;
        else
            return fail(QStringLiteral("Unknown option --%1 (see --help).").arg(name));
    }
    if (o.help || o.version || !o.completion.isEmpty())
        return {o, {}};

    // The link.
    LinkArgumentRules rules;
    rules.alternative = QStringLiteral("--sim");
    rules.alternativeGiven = linkCount;
    rules.defaultProtocol
        = o.sim ? LinkSettings::ProtocolChoice::Facon : LinkSettings::ProtocolChoice::Auto;
    rules.environment = true;
    // "diff FILE FILE2 [RANGES]" compares two files: no PLC, so no link is needed.
    o.offline = !linkCount && link.media.isEmpty() && positional.size() >= 3
                && positional.first().compare(QLatin1String("diff"), Qt::CaseInsensitive) == 0
                && CliSnapshotFileCommand::isSnapshotFileName(positional.at(2));
    if (o.offline)
        rules.environment = false; // FATEK_LINK does not turn a file comparison into a PLC one
    const LinkArgumentsResult resolved = resolveLinkArguments(link, rules);
    if (!resolved.error.isEmpty() && !o.offline)
        return fail(resolved.error);
    o.link = resolved.link;
    o.link.autoReconnect = false; // a script wants the failure, not a retry loop
    o.protocolGiven = resolved.protocolGiven;
    o.timeoutGiven = resolved.timeoutGiven;
    o.station = resolved.station;
    qint64 v = 0;

    // The commands, separated by --then.
    if (positional.isEmpty()) {
        return fail(QStringLiteral("No command given (%1).")
                        .arg(commandNames().join(QStringLiteral(", "))));
    }
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
    if ((!o.outputPath.isEmpty() || o.valueFormat || !o.namesPath.isEmpty()) && !uses("monitor"))
        return fail(QStringLiteral("--output, --format and --names only apply to monitor."));
    if (checkoutGiven && !uses("checkout"))
        return fail(QStringLiteral("--report, --punch, --lang, --save, --project, "
                                   "--customer, --engineer, --company, --document, --revision, "
                                   "--witness, --witness-company and --customer-signatory only "
                                   "apply to checkout."));
    if (o.crlf && !uses("monitor") && !uses("snapshot") && !uses("checkout"))
        return fail(QStringLiteral("--crlf only applies to the CSV files that monitor --output, "
                                   "snapshot and checkout write."));
    if (o.otherModel && !uses("restore-values"))
        return fail(QStringLiteral("--other-model only applies to restore-values."));
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
        if (o.station == Limits::broadcastStation && commandNeedsAnswer(step.name))
            return fail(
                QStringLiteral("%1 needs an answer: station 0 is broadcast, PLCs do not answer it "
                               "(use --station 1..254).")
                    .arg(step.name));
        if (step.command == CliCommandKind::Monitor) {
            if (const QString itemError = CliMonitorCommand::resolveItems(step, o);
                !itemError.isEmpty())
                return fail(itemError);
        }
        if (step.command == CliCommandKind::Monitor && o.cycles == 0 && n + 1 < parts.size())
            return fail(
                QStringLiteral("monitor before --then needs --cycles: it would never end."));
        o.steps << step;
    }
    return {o, {}};
}

} // namespace Fatek
