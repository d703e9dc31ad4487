#pragma once

// The commands of fatek-cli: one table (name, argument counts, whether an answer is needed) and a
// parser per command that fills a CliStep.

#include "clioptions.h"

#include <QString>
#include <QStringList>

namespace Fatek {

// Parses one command with its arguments (the command's name first) into `step`; returns the
// usage error, or an empty text. The --frame/--hex/--ascii options apply to raw.
QString parseStep(const QStringList &arguments, bool frameGiven, bool forceHex, bool forceAscii,
                  CliStep *step);
// The command names in the order --help lists them.
QStringList commandNames();
// Whether the command needs the PLC's answer (and so cannot go to the broadcast station).
bool commandNeedsAnswer(const QString &name);

} // namespace Fatek
