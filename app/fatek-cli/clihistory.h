#pragma once

// fatek-cli history (issue 51): reads a history store (an SQLite file or a PostgreSQL URL): its
// series, or one or more series' samples over a range. A program of its own inside fatek-cli,
// as alarms is: main() hands it the command line when the command is "history".

#include <QStringList>

namespace Fatek {

inline constexpr const char *HistorySynopsis
    = "history DB [ITEM...] [--from TIME] [--to TIME] [--limit N] [--csv|--json]";

// Runs the command (`arguments`: the command line without the program and the word
// "history"); returns the exit code.
int runHistory(const QStringList &arguments);

} // namespace Fatek
