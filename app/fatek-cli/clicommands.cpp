#include "clicommands.h"

#include "app/common/linkarguments.h"
#include "clicheckoutcommand.h"
#include "clicontext.h"
#include "clicontrolcommand.h"
#include "clidiffcommand.h"
#include "cliforcedcommand.h"
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

// The commands: name, what it runs, how many arguments it takes (-1: no limit), whether it needs
// an answer (not for broadcasts), the parser of its arguments and the object that runs it.
struct CommandSpec
{
    const char *name;
    CliCommandKind command;
    int minArgs;
    int maxArgs;
    bool needsAnswer;
    QString (*parse)(CliStepArgs &);
    std::unique_ptr<CliCommand> (*create)(CliContext &);
};

constexpr CommandSpec commands[] = {
    {"status", CliCommandKind::ShowStatus, 0, 0, true, parseNoArguments, make<CliStatusCommand>},
    {"run", CliCommandKind::Run, 0, 0, false, parseNoArguments, make<CliRunStopCommand>},
    {"stop", CliCommandKind::Stop, 0, 0, false, parseNoArguments, make<CliRunStopCommand>},
    {"read", CliCommandKind::Read, 1, -1, true, CliReadCommand::parse, make<CliReadCommand>},
    {"write", CliCommandKind::Write, 2, -1, false, CliWriteCommand::parse, make<CliWriteCommand>},
    {"set", CliCommandKind::Control, 1, 1, false, CliControlCommand::parse,
     make<CliControlCommand>},
    {"reset", CliCommandKind::Control, 1, 1, false, CliControlCommand::parse,
     make<CliControlCommand>},
    {"enable", CliCommandKind::Control, 1, 1, false, CliControlCommand::parse,
     make<CliControlCommand>},
    {"disable", CliCommandKind::Control, 1, 1, false, CliControlCommand::parse,
     make<CliControlCommand>},
    {"forced", CliCommandKind::Forced, 1, 2, true, CliReadCommand::parse, make<CliForcedCommand>},
    {"loopback", CliCommandKind::Loopback, 0, -1, true, CliLoopbackCommand::parse,
     make<CliLoopbackCommand>},
    {"monitor", CliCommandKind::Monitor, 1, -1, true, CliMonitorCommand::parse,
     make<CliMonitorCommand>},
    {"raw", CliCommandKind::Raw, 1, -1, false, CliRawCommand::parse, make<CliRawCommand>},
    {"scan", CliCommandKind::Scan, 0, 1, false, CliScanCommand::parse, make<CliScanCommand>},
    {"backup", CliCommandKind::Backup, 1, 1, true, CliProgramCommand::parse,
     make<CliProgramCommand>},
    {"restore", CliCommandKind::Restore, 1, 1, true, CliProgramCommand::parse,
     make<CliProgramCommand>},
    {"snapshot", CliCommandKind::Snapshot, 1, -1, true, CliSnapshotFileCommand::parseFileAndRanges,
     make<CliSnapshotCommand>},
    {"diff", CliCommandKind::Diff, 1, -1, true, CliDiffCommand::parse, make<CliDiffCommand>},
    {"restore-values", CliCommandKind::RestoreValues, 1, -1, true,
     CliSnapshotFileCommand::parseFileAndRanges, make<CliRestoreValuesCommand>},
    {"checkout", CliCommandKind::Checkout, 1, -1, true, CliCheckoutCommand::parse,
     make<CliCheckoutCommand>},
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
