#include "sessionjob.h"

namespace Fatek {

bool SessionJob::isWrite() const
{
    return !probe && (raw || isWriteCommand(request.command));
}

quint8 SessionJob::station() const
{
    if (raw)
        return options.station > 0 && options.station <= Limits::maxStation
                   ? static_cast<quint8>(options.station)
                   : quint8(0);
    return request.station;
}

int SessionJob::timeoutMs(const LinkSettings &settings) const
{
    return options.timeoutMs > 0 ? options.timeoutMs : settings.timeoutMs;
}

int SessionJob::retries(const LinkSettings &settings) const
{
    if (raw)
        return 0; // a console frame is sent once, as typed
    // A change is sent once (docs/reliability.md): a copy sent again can land late, after the
    // deadline, behind a line that held the first one, and the PLC acts twice. Its unanswered
    // outcome is unknown, and a read-back (ChangeVerifier) tells what it became.
    if (isWriteCommand(request.command))
        return 0;
    return options.retries >= 0 ? options.retries : settings.retries;
}

} // namespace Fatek
