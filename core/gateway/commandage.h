#pragma once

#include "core/protocol/message.h"

#include <QDateTime>

#include <optional>

namespace Fatek {

// How old a command from the broker is, and whether it is too old to carry out: the one rule for
// write commands (GatewayCommands) and alarm commands (AlarmNorth), so that an operator's
// acknowledgement is judged by the same clock as a write (docs/gateway.md, "Writes").
namespace CommandAge {

// How far a command's "time" may lie ahead of the gateway's clock. Clocks of machines that sync
// over NTP differ by milliseconds, by a few seconds when one drifted; further ahead the time is
// wrong, and taken as it is it would keep a command alive past its age limit for as long (a time
// in 2099 never expired). 5 s stretches the 10 s default by half at most.
inline constexpr int MaxAheadSec = 5;

// Why a command is too old to carry out (empty: it is not). `time` is the command's own (if it
// has one), `queued` whether the broker kept it while this gateway was away, `brokerDownAt` when
// the gateway last lost the broker (invalid: never since it started).
Message tooOld(const std::optional<QDateTime> &time, bool queued, const QDateTime &brokerDownAt,
               int maxAgeSec);
// The command's age: the older of its own time and, for a command the broker kept, the time since
// this gateway lost the broker; a live command without a time came now.
qint64 ageMs(const std::optional<QDateTime> &time, bool queued, const QDateTime &brokerDownAt);

} // namespace CommandAge

} // namespace Fatek
