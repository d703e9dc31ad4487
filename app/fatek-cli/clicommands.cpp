#include "clicommands.h"

#include "app/common/linkarguments.h"
#include "clialarms.h"
#include "clicheckoutcommand.h"
#include "clicontext.h"
#include "clicontrolcommand.h"
#include "clidiffcommand.h"
#include "cliforcedcommand.h"
#include "clihistory.h"
#include "cliloopbackcommand.h"
#include "climonitorcommand.h"
#include "cliprogramcommand.h"
#include "clirawcommand.h"
#include "clireadcommand.h"
#include "clirestorevaluescommand.h"
#include "clirunstopcommand.h"
#include "cliscancommand.h"
#include "clisnapshotcommand.h"
#include "clistatuscommand.h"
#include "cliwritecommand.h"

namespace Fatek {

QString CliStepArgs::countArg(const QString &text, std::uint32_t max, std::uint32_t *out) const
{
    qint64 c = 0;
    if (!parseIntInRange(text, 1, max, &c))
        return QStringLiteral("%1: COUNT must be 1..%2, not \"%3\".").arg(cmd()).arg(max).arg(text);
    *out = static_cast<std::uint32_t>(c);
    return {};
}

namespace {

QString parseNoArguments(CliStepArgs &)
{
    return {};
}

template<class Command>
std::unique_ptr<CliCommand> make(CliContext &context)
{
    return std::make_unique<Command>(context);
}

// How --help lists a command: its synopsis and what it does (wrapped by the help). A command
// listed with another ("run | stop") has none of its own.
struct CommandUsage
{
    const char *synopsis = nullptr;
    const char *summary = nullptr;
};

// The commands: name, what it runs, how many arguments it takes (-1: no limit), whether it needs
// an answer (not for broadcasts), the parser of its arguments, the object that runs it, and its
// lines in --help (the man page's COMMANDS section is checked against them by
// tests/docs/check_cli_man.py).
struct CommandSpec
{
    const char *name;
    CliCommandKind command;
    int minArgs;
    int maxArgs;
    bool needsAnswer;
    QString (*parse)(CliStepArgs &);
    std::unique_ptr<CliCommand> (*create)(CliContext &);
    CommandUsage usage[2] = {};
};

constexpr CommandSpec commands[] = {
    {"status",
     CliCommandKind::ShowStatus,
     0,
     0,
     true,
     parseNoArguments,
     make<CliStatusCommand>,
     {{"status", "STATUS1 bits and the detail status (53)"}}},
    {"run",
     CliCommandKind::Run,
     0,
     0,
     false,
     parseNoArguments,
     make<CliRunStopCommand>,
     {{"run | stop", "switch the PLC to RUN / STOP"}}},
    {"stop", CliCommandKind::Stop, 0, 0, false, parseNoArguments, make<CliRunStopCommand>},
    {"read",
     CliCommandKind::Read,
     1,
     -1,
     true,
     CliReadCommand::parse,
     make<CliReadCommand>,
     {{"read ADDR[:FORMAT] [COUNT]",
       "consecutive elements (ADDR may be a range R0..R99, read in as many requests as it "
       "takes); with a FORMAT, COUNT items in it (R200:float 2 reads R200..R203 as two floats)"},
      {"read ADDR[:FORMAT] ADDR...", "a mixed list (48 without formats)"}}},
    {"write",
     CliCommandKind::Write,
     2,
     -1,
     false,
     CliWriteCommand::parse,
     make<CliWriteCommand>,
     {{"write ADDR[:FORMAT] VALUE...",
       "typed as in a watch table: 12, -5, 0x1A, 1Ah, 0b1010; discretes 0/1/on/off; R0:float "
       "1.5 writes R0 and R1; several = consecutive items, up to 1024, in as many requests as "
       "it takes"}}},
    {"set",
     CliCommandKind::Control,
     1,
     1,
     false,
     CliControlCommand::parse,
     make<CliControlCommand>,
     {{"set | reset | enable | disable ADDR", "discrete control (42)"}}},
    {"reset", CliCommandKind::Control, 1, 1, false, CliControlCommand::parse,
     make<CliControlCommand>},
    {"enable", CliCommandKind::Control, 1, 1, false, CliControlCommand::parse,
     make<CliControlCommand>},
    {"disable", CliCommandKind::Control, 1, 1, false, CliControlCommand::parse,
     make<CliControlCommand>},
    {"forced",
     CliCommandKind::Forced,
     1,
     2,
     true,
     CliReadCommand::parse,
     make<CliForcedCommand>,
     {{"forced ADDR [COUNT]", "which discretes are disabled (forced) (43)"}}},
    {"loopback",
     CliCommandKind::Loopback,
     0,
     -1,
     true,
     CliLoopbackCommand::parse,
     make<CliLoopbackCommand>,
     {{"loopback [TEXT] [--count N]", "round trips: min/mean/max, mismatches, timeouts"}}},
    {"monitor",
     CliCommandKind::Monitor,
     1,
     -1,
     true,
     CliMonitorCommand::parse,
     make<CliMonitorCommand>,
     {{"monitor ADDR[:FORMAT]... [--interval MS] [--cycles N] [--format FORMAT] [--output FILE] "
       "[--names LIST]",
       "poll, one line per cycle (ADDR may be a range); FORMAT: %FORMATS%; --output appends a "
       "CSV data log (timestamp, values, status) to FILE; --names LIST names the columns from "
       "the ladder project's comment/symbol list (CSV or tab-separated: address, name, "
       "comment)"}}},
    {"raw",
     CliCommandKind::Raw,
     1,
     -1,
     false,
     CliRawCommand::parse,
     make<CliRawCommand>,
     {{"raw BYTES [--frame] [--hex|--ascii]",
       "send bytes (\"01 40\" is hex, \"0140\" ASCII); --frame adds the protocol's framing "
       "and checksum (under auto: binary framing for hex bytes, FACON for ASCII text)"}}},
    {"scan",
     CliCommandKind::Scan,
     0,
     1,
     false,
     CliScanCommand::parse,
     make<CliScanCommand>,
     {{"scan [FROM..TO]", "which stations answer (default 1..254)"}}},
    {"backup",
     CliCommandKind::Backup,
     1,
     1,
     true,
     CliProgramCommand::parse,
     make<CliProgramCommand>,
     {{"backup FILE", "read the PLC's program (53, 4F every page) into FILE (JSON)"}}},
    {"restore",
     CliCommandKind::Restore,
     1,
     1,
     true,
     CliProgramCommand::parse,
     make<CliProgramCommand>,
     {{"restore FILE",
       "write the program in FILE to the PLC (50 every page, read back and compared); shows "
       "the pages that differ and asks first; the PLC must be in STOP (fatek-cli stop --then "
       "restore FILE)"}}},
    {"snapshot",
     CliCommandKind::Snapshot,
     1,
     -1,
     true,
     CliSnapshotFileCommand::parseFileAndRanges,
     make<CliSnapshotCommand>,
     {{"snapshot FILE [RANGES]",
       "save element values to FILE (.json or .csv); RANGES like \"R0..R99, X0..X255\" "
       "(default: every element the PLC reports)"}}},
    {"diff",
     CliCommandKind::Diff,
     1,
     -1,
     true,
     CliDiffCommand::parse,
     make<CliDiffCommand>,
     {{"diff FILE [FILE2] [RANGES]",
       "differences, one line per element: FILE against the PLC, or against FILE2 (no link "
       "needed); RANGES: only these"}}},
    {"restore-values",
     CliCommandKind::RestoreValues,
     1,
     -1,
     true,
     CliSnapshotFileCommand::parseFileAndRanges,
     make<CliRestoreValuesCommand>,
     {{"restore-values FILE [RANGES]",
       "write FILE's values back (default: all but X), after a confirmation (--yes), then read "
       "them back and compare"}}},
    {"checkout",
     CliCommandKind::Checkout,
     1,
     -1,
     true,
     CliCheckoutCommand::parse,
     make<CliCheckoutCommand>,
     {{"checkout PLAN [--report FILE] [--punch FILE] [--lang en|zh_TW] [--save FILE]",
       "I/O checkout (--report FILE.pdf or FILE.csv, --punch FILE.csv the punch list, --crlf CSV "
       "with Windows line ends; --project, --customer, --document, --revision, --engineer, "
       "--company, --witness, --witness-company and --customer-signatory T name them in the "
       "report): PLAN is ranges (\"X0..X15, Y0..Y7\"), a plan CSV or a checkout file (.json, "
       "resumed and saved as it goes); inputs are named one at a time (Enter skips, f fails, d "
       "REASON defers, r REMARK passes with a remark, na, t tests again; another input moving is "
       "crossed wiring), outputs forced one at a time and the answer asked (y, n [comment], r "
       "REMARK, d REASON, na; a terminal, or --yes with the answers on standard input), analog "
       "points read at each check of their scale (as left after an adjustment); points the PLC "
       "refuses: exit 2, nothing forced; exit 6 when a point failed, was deferred or stayed "
       "untested"}}},
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
    names << QStringLiteral("alarms");  // a program of its own (clialarms.h), not a step
    names << QStringLiteral("history"); // a program of its own (clihistory.h), not a step
    return names;
}

QList<std::pair<QString, QString>> commandUsage()
{
    QList<std::pair<QString, QString>> rows;
    for (const CommandSpec &c : commands) {
        for (const CommandUsage &u : c.usage) {
            if (u.synopsis)
                rows.append({QLatin1String(u.synopsis), QLatin1String(u.summary)});
        }
    }
    rows.append({QLatin1String(AlarmsWatchSynopsis),
                 QStringLiteral("watch the watch list's alarms (ISA-18.2: limits, bits, quality) "
                                "through the link, one line per event (raised, returned, "
                                "acknowledged, shelved...) until Ctrl-C; --journal also records "
                                "them (and brings back the states kept there); NAME names the "
                                "connection in the journal (default: the file's base name)")});
    rows.append({QLatin1String(AlarmsReadSynopsis) + QStringLiteral(" [--csv]"),
                 QStringLiteral("read the journal's events, oldest first; TIME: ISO 8601 "
                                "(2026-12-07, 2026-12-07T08:00[:00][+08:00], local without an "
                                "offset), now, or before now (-90s, -30m, -2h, -7d); --until is "
                                "exclusive; --csv: time (local, with its UTC offset), connection, "
                                "alarm, kind, event, state, priority, group, message, value, "
                                "user, comment, shelved until")});
    rows.append({QLatin1String(HistorySynopsis),
                 QStringLiteral("read a history store (an SQLite file or a postgresql:// URL; "
                                "docs/history.md): without ITEM its series, else each ITEM's "
                                "samples from --from (default -1h) to --to (default now, "
                                "exclusive), oldest first; ITEM: a series (line1/1-R100), an "
                                "item (1-R100, R100 for station 1) or a label naming one; TIME as "
                                "for alarms; --csv: time (local, with its UTC offset), series, "
                                "value, raw, quality")});
    return rows;
}

bool commandNeedsAnswer(const QString &name)
{
    const CommandSpec *spec = findCommand(name);
    return spec && spec->needsAnswer;
}

QString parseStep(const QStringList &arguments, bool frameGiven, bool forceHex, bool forceAscii,
                  CliStep *result)
{
    CliStepArgs a{arguments.mid(1), *result, frameGiven, forceHex, forceAscii};
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

std::unique_ptr<CliCommand> createCommand(CliCommandKind kind, CliContext &context)
{
    for (const CommandSpec &c : commands) {
        if (c.command == kind)
            return c.create(context);
    }
    return nullptr;
}

} // namespace Fatek
