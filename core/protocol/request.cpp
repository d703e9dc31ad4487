#include "request.h"

#include <cstdio>

namespace Fatek {

std::string_view protocolName(Protocol protocol)
{
    return protocol == Protocol::Facon ? "FACON" : "binary";
}

bool isKnownCommand(std::uint8_t code)
{
    switch (code) {
    case 0x40:
    case 0x41:
    case 0x42:
    case 0x43:
    case 0x44:
    case 0x45:
    case 0x46:
    case 0x47:
    case 0x48:
    case 0x49:
    case 0x4E:
    case 0x4F:
    case 0x50:
    case 0x53: return true;
    default: return false;
    }
}

Message commandMessage(Command command)
{
    switch (command) {
    case Command::BriefStatus: return msg<MsgId::CommandBriefStatus>();
    case Command::RunStop: return msg<MsgId::CommandRunStop>();
    case Command::DiscreteControl: return msg<MsgId::CommandDiscreteControl>();
    case Command::ReadEnableFlags: return msg<MsgId::CommandReadEnableFlags>();
    case Command::ReadDiscretes: return msg<MsgId::CommandReadDiscretes>();
    case Command::WriteDiscretes: return msg<MsgId::CommandWriteDiscretes>();
    case Command::ReadRegisters: return msg<MsgId::CommandReadRegisters>();
    case Command::WriteRegisters: return msg<MsgId::CommandWriteRegisters>();
    case Command::MixedRead: return msg<MsgId::CommandMixedRead>();
    case Command::MixedWrite: return msg<MsgId::CommandMixedWrite>();
    case Command::Loopback: return msg<MsgId::CommandLoopback>();
    case Command::ReadProgram: return msg<MsgId::CommandReadProgram>();
    case Command::WriteProgram: return msg<MsgId::CommandWriteProgram>();
    case Command::DetailStatus: return msg<MsgId::CommandDetailStatus>();
    }
    return msg<MsgId::CommandUnknown>();
}

std::string_view commandName(Command command)
{
    // The names take no arguments: their template is the English name.
    return messageTemplate(commandMessage(command).id);
}

bool isWriteCommand(Command command)
{
    switch (command) {
    case Command::RunStop:
    case Command::DiscreteControl:
    case Command::WriteDiscretes:
    case Command::WriteRegisters:
    case Command::MixedWrite:
    case Command::WriteProgram: return true;
    default: return false;
    }
}

std::string_view discreteOpName(DiscreteOp op)
{
    switch (op) {
    case DiscreteOp::Disable: return "disable";
    case DiscreteOp::Enable: return "enable";
    case DiscreteOp::Set: return "set";
    case DiscreteOp::Reset: return "reset";
    }
    return "unknown operation";
}

Message discreteOpMessage(DiscreteOp op, const std::string &target)
{
    switch (op) {
    case DiscreteOp::Disable: return msg<MsgId::FrameDisable>(target);
    case DiscreteOp::Enable: return msg<MsgId::FrameEnable>(target);
    case DiscreteOp::Set: return msg<MsgId::FrameSet>(target);
    case DiscreteOp::Reset: return msg<MsgId::FrameReset>(target);
    }
    return Message::text(std::string(discreteOpName(op)) + " " + target);
}

// ---- factories -------------------------------------------------------------------------------

namespace {
Request make(std::uint8_t station, Command command)
{
    Request r;
    r.station = station;
    r.command = command;
    return r;
}

// Consecutive elements from `first`: `n` of them read, or the values written.
Request makeRead(std::uint8_t station, Command command, Address first, std::uint32_t n)
{
    Request r = make(station, command);
    r.start = first;
    r.count = n;
    return r;
}

Request makeWrite(std::uint8_t station, Command command, Address first,
                  std::vector<std::uint32_t> values)
{
    Request r = make(station, command);
    r.start = first;
    r.count = static_cast<std::uint32_t>(values.size());
    r.values = std::move(values);
    return r;
}
} // namespace

Request Request::briefStatus(std::uint8_t station)
{
    return make(station, Command::BriefStatus);
}
Request Request::detailStatus(std::uint8_t station)
{
    return make(station, Command::DetailStatus);
}

Request Request::runStop(std::uint8_t station, bool runIt)
{
    Request r = make(station, Command::RunStop);
    r.run = runIt;
    return r;
}

Request Request::discreteControl(std::uint8_t station, DiscreteOp operation, Address discrete)
{
    Request r = make(station, Command::DiscreteControl);
    r.op = operation;
    r.start = discrete;
    return r;
}

Request Request::readEnableFlags(std::uint8_t station, Address first, std::uint32_t n)
{
    return makeRead(station, Command::ReadEnableFlags, first, n);
}

Request Request::readDiscretes(std::uint8_t station, Address first, std::uint32_t n)
{
    return makeRead(station, Command::ReadDiscretes, first, n);
}

Request Request::writeDiscretes(std::uint8_t station, Address first, std::vector<std::uint32_t> v)
{
    return makeWrite(station, Command::WriteDiscretes, first, std::move(v));
}

Request Request::readRegisters(std::uint8_t station, Address first, std::uint32_t n)
{
    return makeRead(station, Command::ReadRegisters, first, n);
}

Request Request::writeRegisters(std::uint8_t station, Address first, std::vector<std::uint32_t> v)
{
    return makeWrite(station, Command::WriteRegisters, first, std::move(v));
}

Request Request::mixedRead(std::uint8_t station, std::vector<Address> list)
{
    Request r = make(station, Command::MixedRead);
    r.count = static_cast<std::uint32_t>(list.size());
    r.addresses = std::move(list);
    return r;
}

Request Request::mixedWrite(std::uint8_t station, std::vector<Address> list,
                            std::vector<std::uint32_t> v)
{
    Request r = make(station, Command::MixedWrite);
    r.count = static_cast<std::uint32_t>(list.size());
    r.addresses = std::move(list);
    r.values = std::move(v);
    return r;
}

Request Request::loopback(std::uint8_t station, Bytes testData)
{
    Request r = make(station, Command::Loopback);
    r.data = std::move(testData);
    return r;
}

Request Request::readProgram(std::uint8_t station, std::uint16_t pageNumber)
{
    Request r = make(station, Command::ReadProgram);
    r.page = pageNumber;
    return r;
}

Request Request::writeProgram(std::uint8_t station, std::uint16_t pageNumber,
                              std::vector<std::uint32_t> words)
{
    Request r = make(station, Command::WriteProgram);
    r.page = pageNumber;
    r.values = std::move(words);
    return r;
}

std::uint32_t Request::expectedValueCount() const
{
    switch (command) {
    case Command::ReadEnableFlags:
    case Command::ReadDiscretes:
    case Command::ReadRegisters: return count;
    case Command::MixedRead: return static_cast<std::uint32_t>(addresses.size());
    case Command::ReadProgram: return Limits::programPageWords;
    default: return 0;
    }
}

// ---- text ------------------------------------------------------------------------------------

namespace {

std::string span(const Address &first, std::uint32_t n)
{
    if (n <= 1)
        return first.toString();
    return first.toString() + ".." + first.advanced(n - 1).toString();
}

std::string valueText(const Address &a, std::uint32_t v)
{
    if (isDiscrete(a.type))
        return std::to_string(v);
    char buf[16];
    std::snprintf(buf, sizeof buf, isDoubleWord(a.type) ? "0x%08X" : "0x%04X", v);
    return buf;
}

} // namespace

std::string Request::target() const
{
    switch (command) {
    case Command::DiscreteControl: return start.toString();
    case Command::ReadEnableFlags:
    case Command::ReadDiscretes:
    case Command::ReadRegisters: return span(start, count);
    case Command::WriteDiscretes:
    case Command::WriteRegisters: return span(start, static_cast<std::uint32_t>(values.size()));
    case Command::MixedRead:
    case Command::MixedWrite: {
        std::string s;
        for (const Address &a : addresses) {
            if (!s.empty())
                s += ", ";
            s += a.toString();
        }
        return s;
    }
    case Command::ReadProgram:
    case Command::WriteProgram: return "program page " + std::to_string(page);
    default: return {};
    }
}

std::string Request::describe() const
{
    std::string s;
    switch (command) {
    case Command::BriefStatus: s = "read status"; break;
    case Command::DetailStatus: s = "read detail status"; break;
    case Command::RunStop: s = run ? "RUN" : "STOP"; break;
    case Command::DiscreteControl:
        s = std::string(discreteOpName(op)) + " " + start.toString();
        break;
    case Command::ReadEnableFlags: s = "read disable flags " + target(); break;
    case Command::ReadDiscretes:
    case Command::ReadRegisters:
    case Command::MixedRead: s = "read " + target(); break;
    case Command::WriteDiscretes:
    case Command::WriteRegisters: {
        s = "write " + target() + " =";
        for (std::size_t i = 0; i < values.size() && i < 8; ++i)
            s += " " + valueText(start, values[i]);
        if (values.size() > 8)
            s += " ...";
        break;
    }
    case Command::MixedWrite: {
        s = "write";
        for (std::size_t i = 0; i < addresses.size(); ++i) {
            s += i ? ", " : " ";
            s += addresses[i].toString() + "="
                 + (i < values.size() ? valueText(addresses[i], values[i]) : "?");
        }
        break;
    }
    case Command::Loopback: s = "loopback " + std::to_string(data.size()) + " bytes"; break;
    case Command::ReadProgram: s = "read " + target(); break;
    case Command::WriteProgram: s = "write " + target(); break;
    }
    if (station == Limits::broadcastStation)
        return s + " (broadcast)";
    return s + " (station " + std::to_string(station) + ")";
}

// ---- validation ------------------------------------------------------------------------------

namespace {

ProtocolError invalid(Message message)
{
    return makeError(ErrorKind::InvalidRequest, std::move(message));
}

ProtocolError limit(Message message)
{
    return makeError(ErrorKind::LimitExceeded, std::move(message));
}

Status checkProtocolSupport(const Address &a, Protocol protocol)
{
    if (protocol == Protocol::Facon && a.info().faconDigits == 0)
        return makeError(ErrorKind::Unsupported,
                         msg<MsgId::RequestNotInFacon>(a.toString(), a.info().symbol));
    return Ok{};
}

Status checkValue(const Address &a, std::uint32_t v)
{
    if (isDiscrete(a.type) && v > 1)
        return invalid(msg<MsgId::RequestDiscreteValue>(v, a.toString()));
    if (a.width() == ElementWidth::Word && v > 0xFFFF)
        return invalid(msg<MsgId::RequestRegisterValue>(v, a.toString()));
    return Ok{};
}

Status checkDiscreteSpan(const Request &r, std::uint32_t n, Protocol protocol)
{
    if (!isDiscrete(r.start.type))
        return invalid(
            msg<MsgId::RequestNeedsDiscrete>(commandMessage(r.command), r.start.toString()));
    if (n < 1 || n > Limits::maxDiscretes)
        return limit(msg<MsgId::RequestTooManyPoints>(commandMessage(r.command), n));
    if (Status s = checkProtocolSupport(r.start, protocol); !s)
        return s;
    return validateSpan(r.start, n);
}

Status checkRegisterSpan(const Request &r, std::uint32_t n, Protocol protocol)
{
    if (!isRegister(r.start.type))
        return invalid(
            msg<MsgId::RequestNeedsRegister>(commandMessage(r.command), r.start.toString()));
    const std::uint32_t maxElements
        = Limits::maxRegisterWords / static_cast<std::uint32_t>(r.start.words());
    if (n < 1 || n > maxElements) {
        return limit(
            isDoubleWord(r.start.type)
                ? msg<MsgId::RequestTooManyRegisters32>(commandMessage(r.command), n, maxElements)
                : msg<MsgId::RequestTooManyRegisters16>(commandMessage(r.command), n, maxElements));
    }
    if (Status s = checkProtocolSupport(r.start, protocol); !s)
        return s;
    return validateSpan(r.start, n);
}

Status checkMixed(const Request &r, std::uint32_t maxWords, Protocol protocol)
{
    if (r.addresses.empty())
        return limit(msg<MsgId::RequestNoElement>(commandMessage(r.command)));
    if (r.addresses.size() > 255) {
        return limit(msg<MsgId::RequestTooManyElements>(commandMessage(r.command),
                                                        r.addresses.size(), maxWords));
    }
    std::uint32_t words = 0;
    for (const Address &a : r.addresses) {
        if (Status s = checkProtocolSupport(a, protocol); !s)
            return s;
        if (Status s = validateAddress(a); !s)
            return s;
        words += static_cast<std::uint32_t>(a.words());
    }
    if (words > maxWords)
        return limit(msg<MsgId::RequestTooManyWords>(commandMessage(r.command), words, maxWords));
    return Ok{};
}

} // namespace

Status validateRequest(const Request &r, Protocol protocol)
{
    if (r.station > Limits::maxStation) {
        return invalid(msg<MsgId::RequestBadStation>(r.station));
    }
    switch (r.command) {
    case Command::BriefStatus:
    case Command::DetailStatus:
    case Command::RunStop: return Ok{};
    case Command::DiscreteControl:
        if (r.op < DiscreteOp::Disable || r.op > DiscreteOp::Reset)
            return invalid(msg<MsgId::RequestBadDiscreteOp>(static_cast<int>(r.op)));
        return checkDiscreteSpan(r, 1, protocol);
    case Command::ReadEnableFlags:
    case Command::ReadDiscretes: return checkDiscreteSpan(r, r.count, protocol);
    case Command::WriteDiscretes: {
        const auto n = static_cast<std::uint32_t>(r.values.size());
        if (Status s = checkDiscreteSpan(r, n, protocol); !s)
            return s;
        for (std::uint32_t i = 0; i < n; ++i) {
            if (Status s = checkValue(r.start.advanced(i), r.values[i]); !s)
                return s;
        }
        return Ok{};
    }
    case Command::ReadRegisters: return checkRegisterSpan(r, r.count, protocol);
    case Command::WriteRegisters: {
        const auto n = static_cast<std::uint32_t>(r.values.size());
        if (Status s = checkRegisterSpan(r, n, protocol); !s)
            return s;
        for (std::uint32_t i = 0; i < n; ++i) {
            if (Status s = checkValue(r.start.advanced(i), r.values[i]); !s)
                return s;
        }
        return Ok{};
    }
    case Command::MixedRead: return checkMixed(r, Limits::maxMixedReadWords, protocol);
    case Command::MixedWrite: {
        if (r.values.size() != r.addresses.size()) {
            return invalid(msg<MsgId::RequestMixedCounts>(r.addresses.size(), r.values.size()));
        }
        if (Status s = checkMixed(r, Limits::maxMixedWriteWords, protocol); !s)
            return s;
        for (std::size_t i = 0; i < r.addresses.size(); ++i) {
            if (Status s = checkValue(r.addresses[i], r.values[i]); !s)
                return s;
        }
        return Ok{};
    }
    case Command::Loopback:
        if (r.data.size() > Limits::maxLoopback) {
            return limit(msg<MsgId::RequestLoopbackTooLong>(r.data.size()));
        }
        if (protocol == Protocol::Facon) {
            for (std::uint8_t b : r.data) {
                if (b < 0x20 || b > 0x7E)
                    return invalid(msg<MsgId::RequestLoopbackNotAscii>());
            }
        }
        return Ok{};
    case Command::ReadProgram:
    case Command::WriteProgram:
        if (protocol != Protocol::Facon) {
            return makeError(ErrorKind::Unsupported, msg<MsgId::RequestProgramFaconOnly>());
        }
        if (r.command == Command::WriteProgram) {
            if (r.values.size() != Limits::programPageWords) {
                return invalid(msg<MsgId::RequestProgramPageSize>(r.values.size()));
            }
            for (std::uint32_t w : r.values) {
                if (w > 0xFFFF)
                    return invalid(msg<MsgId::RequestProgramWords>());
            }
        }
        return Ok{};
    }
    return makeError(ErrorKind::Unsupported,
                     msg<MsgId::RequestUnknownCommand>(static_cast<int>(r.command)));
}

} // namespace Fatek
