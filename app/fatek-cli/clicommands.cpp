#include "clicommands.h"

#include "app/common/linkarguments.h"
#include "clioptions.h"
#include "clitext.h"
#include "core/commission/memorysnapshot.h"
#include "core/commission/snapshotfile.h"
#include "core/watch/itemvalues.h"
#include "core/watch/watchlist.h"

#include <QRegularExpression>

#include <utility>

namespace Fatek {

namespace {

Result<Address> parseAddress(const QString &text)
{
    return Address::parse(text.toStdString());
}

// One address, or a range "R0..R9" or "R0-9" (monitor, read).
Result<QList<Address>> parseAddressOrRange(const QString &text)
{
    return WatchList::expandRange(text);
}

// One command being parsed: its arguments after the name, the step it fills, and the raw options.
struct StepArgs
{
    QStringList positional;
    CliStep &step;
    bool frameGiven;
    bool forceHex;
    bool forceAscii;

    const QString &cmd() const { return step.name; }
    QString countArg(const QString &text, std::uint32_t max, std::uint32_t *out) const
    {
        qint64 c = 0;
        if (!parseIntInRange(text, 1, max, &c))
            return QStringLiteral("%1: COUNT must be 1..%2, not \"%3\".")
                .arg(cmd())
                .arg(max)
                .arg(text);
        *out = static_cast<std::uint32_t>(c);
        return {};
    }
};

QString parseNoArguments(StepArgs &)
{
    return {};
}

// read ADDR [COUNT], read ADDR ADDR... (48), forced ADDR [COUNT].
QString parseReadOrForced(StepArgs &a)
{
    CliStep &s = a.step;
    const QStringList &positional = a.positional;
    auto first = parseAddressOrRange(positional.at(0));
    if (!first)
        return CliText::error(first.error());
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
                return CliText::error(more.error());
            s.addresses += more.value();
        }
        s.mixed = true;
        s.count = static_cast<std::uint32_t>(s.addresses.size());
        return {};
    }
    if (positional.size() > 2)
        return QStringLiteral("%1: unexpected argument \"%2\".").arg(a.cmd(), positional.at(2));
    if (s.command == CliCommand::Forced && !isDiscrete(s.addresses.first().type))
        return QStringLiteral("forced reads discretes (X Y M S T C), not %1.")
            .arg(QString::fromStdString(s.addresses.first().toString()));
    if (positional.size() == 2) {
        if (range)
            return QStringLiteral("%1: give a range or a COUNT, not both.").arg(a.cmd());
        const std::uint32_t max = isDiscrete(s.addresses.first().type) ? Limits::maxDiscretes
                                                                       : Limits::maxRegisterWords;
        if (QString err = a.countArg(positional.at(1), max, &s.count); !err.isEmpty())
            return err;
    } else {
        s.count = static_cast<std::uint32_t>(s.addresses.size());
    }
    s.addresses = {s.addresses.first()};
    const Status span = validateSpan(s.addresses.first(), s.count);
    return span ? QString() : CliText::error(span.error());
}

// write ADDR[:FORMAT] VALUE...
QString parseWrite(StepArgs &a)
{
    CliStep &s = a.step;
    const QStringList &positional = a.positional;
    // "R100:float 1.5": the values are typed in FORMAT, each one an item of as many elements as
    // the format spans (R100 and R101 here); without it, in the element's default format.
    const QString &target = positional.at(0);
    const qsizetype colon = target.indexOf(QLatin1Char(':'));
    auto address = parseAddress(colon >= 0 ? target.left(colon) : target);
    if (!address)
        return CliText::error(address.error());
    WatchItemSpec item;
    item.address = address.value();
    item.format = ValueFormat::defaultFormat(item.address);
    if (colon >= 0) {
        const auto format = ValueFormat::fromName(target.mid(colon + 1).trimmed());
        if (!format)
            return QStringLiteral("Unknown format \"%1\" in %2 (%3).")
                .arg(target.mid(colon + 1), target, CliText::formatNames());
        item.format = *format;
        if (const Status valid = WatchList::validateEntry(item); !valid)
            return CliText::error(valid.error());
    }
    s.addresses = {item.address};
    // Several values go to consecutive items; validateSpan below checks that they all exist.
    const auto elements = static_cast<std::uint32_t>(ItemValues(item).elementCount());
    for (qsizetype i = 1; i < positional.size(); ++i) {
        const QString &text = positional.at(i);
        item.address = s.addresses.first().advanced(static_cast<std::uint32_t>(i - 1) * elements);
        const ItemValues values(item);
        const auto raw = values.parse(text);
        if (!raw) {
            // Discretes keep the sentence fatek-cli has always given them.
            if (isDiscrete(item.address.type))
                return QStringLiteral("%1 is a discrete: write 0, 1, on or off, not \"%2\".")
                    .arg(QString::fromStdString(item.address.toString()), text.trimmed());
            return QStringLiteral("%1: %2").arg(QString::fromStdString(item.address.toString()),
                                                CliText::error(raw.error()));
        }
        const std::vector<std::uint32_t> words = values.split(*raw);
        s.values.insert(s.values.end(), words.cbegin(), words.cend());
    }
    s.count = static_cast<std::uint32_t>(s.values.size());
    const Status span = validateSpan(s.addresses.first(), s.count);
    return span ? QString() : CliText::error(span.error());
}

// set|reset|enable|disable ADDR
QString parseControl(StepArgs &a)
{
    CliStep &s = a.step;
    auto address = parseAddress(a.positional.at(0));
    if (!address)
        return CliText::error(address.error());
    if (!isDiscrete(address.value().type))
        return QStringLiteral("%1 works on discretes (X Y M S T C), not %2.")
            .arg(a.cmd(), QString::fromStdString(address.value().toString()));
    s.addresses = {address.value()};
    const DiscreteOp op = a.cmd() == QLatin1String("set")      ? DiscreteOp::Set
                          : a.cmd() == QLatin1String("reset")  ? DiscreteOp::Reset
                          : a.cmd() == QLatin1String("enable") ? DiscreteOp::Enable
                                                               : DiscreteOp::Disable;
    s.controlOp = static_cast<int>(op);
    return {};
}

// loopback [TEXT]
QString parseLoopback(StepArgs &a)
{
    const QString text = a.positional.isEmpty() ? QStringLiteral("FATEK-CLI")
                                                : a.positional.join(QLatin1Char(' '));
    a.step.loopbackData = text.toLatin1();
    if (a.step.loopbackData.isEmpty()
        || static_cast<std::uint32_t>(a.step.loopbackData.size()) > Limits::maxLoopback)
        return QStringLiteral("loopback TEXT must be 1..%1 characters.").arg(Limits::maxLoopback);
    return {};
}

// monitor ADDR[:FORMAT]...
QString parseMonitor(StepArgs &a)
{
    CliStep &s = a.step;
    for (const QString &text : std::as_const(a.positional)) {
        // "R0..R3:hex": a format after the colon applies to every element of the argument.
        const qsizetype colon = text.indexOf(QLatin1Char(':'));
        std::optional<DisplayFormat> format;
        if (colon >= 0) {
            format = ValueFormat::fromName(text.mid(colon + 1).trimmed());
            if (!format)
                return QStringLiteral("Unknown format \"%1\" in %2 (%3).")
                    .arg(text.mid(colon + 1), text, CliText::formatNames());
        }
        auto more = parseAddressOrRange(colon >= 0 ? text.left(colon) : text);
        if (!more)
            return CliText::error(more.error());
        s.addresses += more.value();
        for (qsizetype n = 0; n < more.value().size(); ++n)
            s.formats << format;
    }
    if (s.addresses.size() > WatchList::MaxRangeItems)
        return QStringLiteral("monitor watches at most %1 elements.").arg(WatchList::MaxRangeItems);
    return {};
}

// raw HEX|ASCII
QString parseRaw(StepArgs &a)
{
    if (a.forceHex && a.forceAscii)
        return QStringLiteral("raw: give --hex or --ascii, not both.");
    QString err;
    a.step.rawBytes = parseRawText(a.positional.join(QLatin1Char(' ')), a.forceHex, a.forceAscii,
                                   &err, &a.step.rawHex);
    a.step.rawFrame = a.frameGiven;
    return err;
}

// scan [FROM..TO]
QString parseScan(StepArgs &a)
{
    if (a.positional.isEmpty())
        return {};
    static const QRegularExpression range(QStringLiteral("^(\\d+)(?:\\.\\.(\\d+))?$"));
    const auto m = range.match(a.positional.at(0).trimmed());
    qint64 first = 0, last = 0;
    if (!m.hasMatch() || !parseIntInRange(m.captured(1), 1, Limits::maxStation, &first)
        || !parseIntInRange(m.captured(2).isEmpty() ? m.captured(1) : m.captured(2), 1,
                            Limits::maxStation, &last)
        || last < first)
        return QStringLiteral("scan takes a station range like 1..16 (1..254), not \"%1\".")
            .arg(a.positional.at(0));
    a.step.scanFirst = static_cast<int>(first);
    a.step.scanLast = static_cast<int>(last);
    return {};
}

// backup FILE, restore FILE
QString parseProgramFile(StepArgs &a)
{
    a.step.file = a.positional.at(0);
    if (a.step.file.trimmed().isEmpty())
        return QStringLiteral("%1 needs a file name.").arg(a.cmd());
    return {};
}

// A snapshot file name: .json or .csv.
QString snapshotFileArg(StepArgs &a, const QString &path, QString *out)
{
    if (!SnapshotFile::formatFor(path))
        return QStringLiteral("%1: \"%2\" is not a .json or .csv file name.").arg(a.cmd(), path);
    *out = path;
    return {};
}

// RANGES: every further argument, "R0..R99, X0..X255" or "R0..R99 X0..X255".
QString rangesArg(StepArgs &a, qsizetype from)
{
    const QString text = a.positional.mid(from).join(QLatin1Char(' '));
    if (text.trimmed().isEmpty())
        return {};
    const auto ranges = Snapshot::parseRanges(text);
    if (!ranges)
        return QStringLiteral("%1: %2").arg(a.cmd(), CliText::error(ranges.error()));
    a.step.ranges = ranges.value();
    return {};
}

// snapshot FILE [RANGES], restore-values FILE [RANGES]
QString parseSnapshotFileAndRanges(StepArgs &a)
{
    if (QString err = snapshotFileArg(a, a.positional.at(0), &a.step.file); !err.isEmpty())
        return err;
    return rangesArg(a, 1);
}

// diff FILE [FILE2]
QString parseDiff(StepArgs &a)
{
    if (QString err = snapshotFileArg(a, a.positional.at(0), &a.step.file); !err.isEmpty())
        return err;
    if (a.positional.size() > 1)
        return snapshotFileArg(a, a.positional.at(1), &a.step.file2);
    return {};
}

// The commands: name, what it runs, how many arguments it takes (-1: no limit), whether it needs
// an answer (not for broadcasts), and the parser of its arguments.
struct CommandSpec
{
    const char *name;
    CliCommand command;
    int minArgs;
    int maxArgs;
    bool needsAnswer;
    QString (*parse)(StepArgs &);
};

constexpr CommandSpec commands[] = {
    {"status", CliCommand::ShowStatus, 0, 0, true, parseNoArguments},
    {"run", CliCommand::Run, 0, 0, false, parseNoArguments},
    {"stop", CliCommand::Stop, 0, 0, false, parseNoArguments},
    {"read", CliCommand::Read, 1, -1, true, parseReadOrForced},
    {"write", CliCommand::Write, 2, -1, false, parseWrite},
    {"set", CliCommand::Control, 1, 1, false, parseControl},
    {"reset", CliCommand::Control, 1, 1, false, parseControl},
    {"enable", CliCommand::Control, 1, 1, false, parseControl},
    {"disable", CliCommand::Control, 1, 1, false, parseControl},
    {"forced", CliCommand::Forced, 1, 2, true, parseReadOrForced},
    {"loopback", CliCommand::Loopback, 0, -1, true, parseLoopback},
    {"monitor", CliCommand::Monitor, 1, -1, true, parseMonitor},
    {"raw", CliCommand::Raw, 1, -1, false, parseRaw},
    {"scan", CliCommand::Scan, 0, 1, false, parseScan},
    {"backup", CliCommand::Backup, 1, 1, true, parseProgramFile},
    {"restore", CliCommand::Restore, 1, 1, true, parseProgramFile},
    {"snapshot", CliCommand::Snapshot, 1, -1, true, parseSnapshotFileAndRanges},
    {"diff", CliCommand::Diff, 1, 2, true, parseDiff},
    {"restore-values", CliCommand::RestoreValues, 1, -1, true, parseSnapshotFileAndRanges},
};

const CommandSpec *findCommand(const QString &name)
{
    for (const CommandSpec &c : commands) {
        if (name == QLatin1String(c.name))
            return &c;
    }
    return nullptr;
}

} // namespace

QStringList commandNames()
{
    QStringList names;
    for (const CommandSpec &c : commands)
        names << QLatin1String(c.name);
    return names;
}

bool commandNeedsAnswer(const QString &name)
{
    const CommandSpec *spec = findCommand(name);
    return spec && spec->needsAnswer;
}

QString parseStep(const QStringList &arguments, bool frameGiven, bool forceHex, bool forceAscii,
                  CliStep *result)
{
    StepArgs a{arguments.mid(1), *result, frameGiven, forceHex, forceAscii};
    a.step.name = arguments.first().toLower();
    const CommandSpec *spec = findCommand(a.cmd());
    if (!spec)
        return QStringLiteral("Unknown command \"%1\" (see --help).").arg(a.cmd());
    if (a.positional.size() < spec->minArgs)
        return QStringLiteral("%1 needs more arguments (see --help).").arg(a.cmd());
    if (spec->maxArgs >= 0 && a.positional.size() > spec->maxArgs)
        return QStringLiteral("%1: unexpected argument \"%2\".")
            .arg(a.cmd(), a.positional.at(spec->maxArgs));
    a.step.command = spec->command;
    return spec->parse(a);
}

} // namespace Fatek
