#include "changecheck.h"

#include "plcstatus.h"

namespace Fatek::ChangeCheck {

std::optional<Request> readBack(const Request &change)
{
    if (change.station == Limits::broadcastStation)
        return std::nullopt; // no PLC answers a broadcast, a read-back included
    const auto count = static_cast<std::uint32_t>(change.values.size());
    switch (change.command) {
    case Command::WriteRegisters:
        return Request::readRegisters(change.station, change.start, count);
    case Command::WriteDiscretes:
        return Request::readDiscretes(change.station, change.start, count);
    case Command::MixedWrite: return Request::mixedRead(change.station, change.addresses);
    case Command::RunStop: return Request::briefStatus(change.station);
    case Command::DiscreteControl:
        switch (change.op) {
        case DiscreteOp::Disable:
        case DiscreteOp::Enable: return Request::readEnableFlags(change.station, change.start, 1);
        case DiscreteOp::Set:
        case DiscreteOp::Reset: return Request::readDiscretes(change.station, change.start, 1);
        }
        return std::nullopt;
    default: return std::nullopt;
    }
}

bool inPlace(const Request &change, const Response &answer)
{
    switch (change.command) {
    case Command::WriteRegisters:
    case Command::WriteDiscretes:
    case Command::MixedWrite: return answer.values == change.values;
    case Command::RunStop:
        return !answer.data.empty()
               && PlcStatus::fromStatus1(answer.data.front()).running == change.run;
    case Command::DiscreteControl: {
        if (answer.values.size() != 1)
            return false;
        const std::uint32_t v = answer.values.front();
        switch (change.op) {
        case DiscreteOp::Disable: return v == 1; // the flag reads 1 while disabled
        case DiscreteOp::Enable: return v == 0;
        case DiscreteOp::Set: return v == 1;
        case DiscreteOp::Reset: return v == 0;
        }
        return false;
    }
    default: return false;
    }
}

} // namespace Fatek::ChangeCheck
