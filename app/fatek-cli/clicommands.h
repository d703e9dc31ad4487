#pragma once

// The commands of fatek-cli: one table (name, argument counts, whether an answer is needed, the
// command's parser and its object) and the parsing of one step.

#include "clioptions.h"

#include <QString>
#include <QStringList>

#include <cstdint>
#include <memory>
#include <utility>

namespace Fatek {

class CliCommand;
class CliContext;

// One command being parsed by its command class: its arguments after the name, the step it
// fills, and the raw options.
struct CliStepArgs
{
    QStringList positional;
    CliStep &step;
    bool frameGiven;
    bool forceHex;
    bool forceAscii;

    const QString &cmd() const { return step.name; }
    // A COUNT argument, 1..max; the usage error, or an empty text.
    QString countArg(const QString &text, std::uint32_t max, std::uint32_t *out) const;
};

// Parses one command with its arguments (the command's name first) into `step`; returns the
// usage error, or an empty text. The --frame/--hex/--ascii options apply to raw.
QString parseStep(const QStringList &arguments, bool frameGiven, bool forceHex, bool forceAscii,
                  CliStep *step);
// The command names in the order --help lists them.
QStringList commandNames();
// --help's command lines, in its order: synopsis ("read ADDR[:FORMAT] [COUNT]") and summary
// (one paragraph; "%FORMATS%" stands for the format names).
QList<std::pair<QString, QString>> commandUsage();
// Whether the command needs the PLC's answer (and so cannot go to the broadcast station).
bool commandNeedsAnswer(const QString &name);
// The object that runs the steps of `kind`.
std::unique_ptr<CliCommand> createCommand(CliCommandKind kind, CliContext &context);

} // namespace Fatek
