#include "wiresize.h"

namespace Fatek::WireSize {

namespace {

// Everything around the data. FACON: STX, station(2), command(2), LRC(2), ETX.
// Binary: 51/52, 10, length(2), STN, CMD, CRC(2), 55 AA.
std::size_t frameBytes(Protocol p)
{
    return p == Protocol::Facon ? 8 : 10;
}

std::size_t countBytes(Protocol p)
{
    return p == Protocol::Facon ? 2 : 1;
}

std::size_t statusByteBytes(Protocol p)
{
    return p == Protocol::Facon ? 2 : 1;
}

constexpr std::size_t errorBytes = 1; // FACON error digit or binary ERR byte

} // namespace

std::size_t addressBytes(const Address &a, Protocol p)
{
    const ElementInfo &info = a.info();
    if (p == Protocol::Facon)
        return info.symbol.size() + static_cast<std::size_t>(info.faconDigits);
    return info.symbol.size() + 2; // symbol in ASCII + 2-byte number
}

std::size_t valueBytes(ElementType type, Protocol p)
{
    switch (elementInfo(type).width) {
    case ElementWidth::Bit: return 1;
    case ElementWidth::Word: return p == Protocol::Facon ? 4 : 2;
    case ElementWidth::DoubleWord: return p == Protocol::Facon ? 8 : 4;
    }
    return 0;
}

std::size_t queryBytes(const Request &r, Protocol p)
{
    std::size_t data = 0;
    switch (r.command) {
    case Command::BriefStatus:
    case Command::DetailStatus: break;
    case Command::RunStop: data = 1; break;
    case Command::DiscreteControl: data = 1 + addressBytes(r.start, p); break;
    case Command::ReadEnableFlags:
    case Command::ReadDiscretes:
    case Command::ReadRegisters: data = countBytes(p) + addressBytes(r.start, p); break;
    case Command::WriteDiscretes:
    case Command::WriteRegisters:
        data = countBytes(p) + addressBytes(r.start, p)
               + r.values.size() * valueBytes(r.start.type, p);
        break;
    case Command::MixedRead:
        data = countBytes(p);
        for (const Address &a : r.addresses)
            data += addressBytes(a, p);
        break;
    case Command::MixedWrite:
        data = countBytes(p);
        for (const Address &a : r.addresses)
            data += addressBytes(a, p) + valueBytes(a.type, p);
        break;
    case Command::Loopback: data = r.data.size(); break;
    case Command::ReadProgram:
    case Command::WriteProgram:
        if (p != Protocol::Facon)
            return 0;
        data = 4 + r.values.size() * 4; // page number, then 64 words (50 only)
        if (r.command == Command::ReadProgram)
            data = 4;
        break;
    }
    return frameBytes(p) + data;
}

std::size_t responseBytes(const Request &r, Protocol p)
{
    std::size_t data = 0;
    switch (r.command) {
    case Command::BriefStatus: data = 3 * statusByteBytes(p); break;
    case Command::DetailStatus: return 0; // length depends on the model (binary: undocumented)
    case Command::RunStop:
    case Command::DiscreteControl:
    case Command::WriteDiscretes:
    case Command::WriteRegisters:
    case Command::MixedWrite: break;
    case Command::WriteProgram:
        if (p != Protocol::Facon)
            return 0;
        break;
    case Command::ReadEnableFlags:
    case Command::ReadDiscretes:
        data = r.count; // one char / byte per point
        break;
    case Command::ReadRegisters: data = r.count * valueBytes(r.start.type, p); break;
    case Command::MixedRead:
        for (const Address &a : r.addresses)
            data += valueBytes(a.type, p);
        break;
    case Command::Loopback:
        return frameBytes(p) + r.data.size(); // the echo carries no error digit/byte
    case Command::ReadProgram:
        if (p != Protocol::Facon)
            return 0;
        data = Limits::programPageWords * 4;
        break;
    }
    return frameBytes(p) + errorBytes + data;
}

} // namespace Fatek::WireSize
