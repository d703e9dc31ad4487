#pragma once

// fatek-cli alarms (issue 50): watches the alarms of a watch list through a link, or reads an
// alarm journal. A program of its own inside fatek-cli (a plant connection and an AlarmEngine,
// not a step of the runner): main() hands it the command line when the command is "alarms".

#include <QString>
#include <QStringList>

#include <optional>

namespace Fatek {

// The command's synopses and summaries for --help, the man page check and the completions.
inline constexpr const char *AlarmsWatchSynopsis
    = "alarms WATCHLIST [--journal DB] [--connection NAME]";
inline constexpr const char *AlarmsReadSynopsis
    = "alarms --journal DB [--since TIME] [--until TIME] [--connection NAME]";

// Runs the command (`arguments`: the whole command line without the program and without the
// word "alarms") in the running application's event loop; returns the exit code.
int runAlarms(const QStringList &arguments);

namespace CliAlarms {
// TIME of --since and --until: ISO 8601 (2026-12-07, 2026-12-07T08:00, 2026-12-07T08:00:00+08:00,
// ...Z; local time without an offset), "now", or before now: -90s, -30m, -2h, -7d. Milliseconds
// since the epoch, or nothing when the text is none of these.
std::optional<qint64> parseTime(const QString &text, qint64 nowMs);
// The usage error of a TIME option (`name` without its dashes) that parseTime refused.
int badTime(const char *name, const QString &text, bool json);
} // namespace CliAlarms

} // namespace Fatek
