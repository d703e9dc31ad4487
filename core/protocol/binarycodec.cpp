#include "binarycodec.h"

// BinaryCodec's master side (queries out, answers in), framing and the traffic-log summary; the
// slave side is in binaryslave.cpp.

#include "binaryslave.h"
#include "binarywire.h"

#include <algorithm>
#include <cstdio>
#include <string_view>

namespace Fatek {

using namespace BinaryWire;

namespace {

std::string hexValue(std::uint32_t value, ElementType type)
{
    if (isDiscrete(type))
        return std::to_string(value);
    char buf[16];
    std::snprintf(buf, sizeof buf, isDoubleWord(type) ? "%08X" : "%04X", value);
    return buf;
}

void appendAddress(Bytes &out, const Address &address)
{
    for (char c : address.info().symbol)
        out.push_back(static_cast<std::uint8_t>(c));
    out.push_back(static_cast<std::uint8_t>(address.number >> 8));
    out.push_back(static_cast<std::uint8_t>(address.number));
}

// N byte of 43/44/45: 256 is sent as 0.
std::uint8_t countByte(std::size_t count)
{
    return static_cast<std::uint8_t>(count & 0xFFu);
}

// What a query asks, after its command's name (empty when the name says it all).
Message queryDetail(const Request &r)
{
    auto values = [&r](const Address &a) {
        std::string s;
        for (std::size_t i = 0; i < r.values.size() && i < 8; ++i)
            s += " " + hexValue(r.values[i], a.type);
        if (r.values.size() > 8)
            s += " ...";
        return s;
    };
    switch (r.command) {
    case Command::RunStop: return Message::text(r.run ? "RUN" : "STOP");
    case Command::DiscreteControl: return discreteOpMessage(r.op, r.start.toString());
    case Command::ReadEnableFlags:
    case Command::ReadDiscretes:
    case Command::ReadRegisters:
        return Message::text(std::to_string(r.count) + " x " + r.start.toString());
    case Command::WriteDiscretes:
    case Command::WriteRegisters:
        return Message::text(std::to_string(r.values.size()) + " x " + r.start.toString() + " ="
                             + values(r.start));
    case Command::MixedRead: return Message::text(r.target());
    case Command::MixedWrite: {
        std::string s;
        for (std::size_t i = 0; i < r.addresses.size() && i < r.values.size(); ++i) {
            s += i ? ", " : "";
            s += r.addresses[i].toString() + "=" + hexValue(r.values[i], r.addresses[i].type);
        }
        return Message::text(s);
    }
    case Command::Loopback: return Message::text(std::to_string(r.data.size()) + " bytes");
    default: return {};
    }
}

} // namespace

std::uint16_t BinaryCodec::crc16(std::span<const std::uint8_t> bytes)
{
    std::uint16_t crc = 0xFFFF;
    for (std::uint8_t b : bytes) {
        crc = static_cast<std::uint16_t>(crc ^ b);
        for (int bit = 0; bit < 8; ++bit) {
            const bool lsb = (crc & 1u) != 0;
            crc = static_cast<std::uint16_t>(crc >> 1);
            if (lsb)
                crc = static_cast<std::uint16_t>(crc ^ 0xA001u);
        }
    }
    return crc;
}

Result<Bytes> BinaryCodec::encodeRequest(const Request &request) const
{
    if (Status s = validateRequest(request, Protocol::Binary); !s)
        return s.error();

    Bytes p;
    // Room for the largest query up front: GCC 12 at -O2 otherwise sees the growth path of the
    // loopback insert below as an out-of-bounds copy (-Warray-bounds, a known false positive).
    p.reserve(maxPayload);
    p.push_back(request.station);
    p.push_back(static_cast<std::uint8_t>(request.command));
    switch (request.command) {
    case Command::BriefStatus:
    case Command::DetailStatus: break;
    case Command::RunStop: p.push_back(request.run ? 1 : 0); break;
    case Command::DiscreteControl:
        p.push_back(static_cast<std::uint8_t>(request.op));
        appendAddress(p, request.start);
        break;
    case Command::ReadEnableFlags:
    case Command::ReadDiscretes:
    case Command::ReadRegisters:
        p.push_back(countByte(request.count));
        appendAddress(p, request.start);
        break;
    case Command::WriteDiscretes:
    case Command::WriteRegisters:
        p.push_back(countByte(request.values.size()));
        appendAddress(p, request.start);
        for (std::uint32_t v : request.values)
            appendValue(p, request.start.type, v);
        break;
    case Command::MixedRead:
        p.push_back(countByte(request.addresses.size()));
        for (const Address &a : request.addresses)
            appendAddress(p, a);
        break;
    case Command::MixedWrite:
        p.push_back(countByte(request.addresses.size()));
        for (std::size_t i = 0; i < request.addresses.size(); ++i) {
            appendAddress(p, request.addresses[i]);
            appendValue(p, request.addresses[i].type, request.values[i]);
        }
        break;
    case Command::Loopback: p.insert(p.end(), request.data.begin(), request.data.end()); break;
    case Command::ReadProgram:
    case Command::WriteProgram:
        // validateRequest refuses these for the binary protocol; kept for a complete switch.
        return makeError(ErrorKind::Unsupported, msg<MsgId::RequestProgramFaconOnly>());
    }
    return frameOf(queryHeader, p);
}

Result<Response> BinaryCodec::decodeResponse(std::span<const std::uint8_t> frame,
                                             const Request &request) const
{
    auto parsed = parseFrame(frame);
    if (!parsed)
        return parsed.error();
    if (parsed->header != responseHeader) {
        return makeError(ErrorKind::BadFrame, msg<MsgId::BinaryQueryEcho>());
    }
    const auto p = parsed->payload;
    const std::uint8_t code = static_cast<std::uint8_t>(request.command);
    if (p[0] != request.station) {
        return makeError(ErrorKind::StationMismatch,
                         msg<MsgId::AnswerWrongStation>(p[0], request.station, request.describe()));
    }
    if (p[1] != code) {
        return makeError(ErrorKind::CommandMismatch,
                         msg<MsgId::BinaryAnswerWrongCommand>(hex2(p[1]), commandText(code),
                                                              request.describe()));
    }
    auto malformed = [&request](Message detail) {
        return makeError(ErrorKind::MalformedResponse,
                         msg<MsgId::AnswerTo>(request.describe(), std::move(detail)));
    };

    Response response;
    response.station = p[0];
    response.command = request.command;

    // Loopback answers carry the test data right after the command, without an error byte.
    if (request.command == Command::Loopback) {
        const auto data = p.subspan(2);
        if (!std::equal(data.begin(), data.end(), request.data.begin(), request.data.end())) {
            return malformed(msg<MsgId::AnswerEchoDiffers>(data.size(), request.data.size()));
        }
        response.data.assign(data.begin(), data.end());
        return response;
    }

    if (p.size() < 3)
        return malformed(msg<MsgId::AnswerNoErrorByte>());
    if (p[2] != 0) {
        const std::string target = request.target();
        return makePlcError(p[2], target.empty() ? "for " + request.describe() : target);
    }
    const auto data = p.subspan(3);
    auto expectSize = [&](std::size_t size, std::string_view what) -> Status {
        if (data.size() != size) {
            return malformed(msg<MsgId::AnswerDataBytes>(data.size(), size, what));
        }
        return Ok{};
    };

    switch (request.command) {
    case Command::BriefStatus:
        if (Status s = expectSize(3, "3 status bytes"); !s)
            return s.error();
        response.data.assign(data.begin(), data.end());
        break;
    case Command::DetailStatus:
        // The binary documents do not describe this answer: keep whatever status bytes came.
        response.data.assign(data.begin(), data.end());
        break;
    case Command::ReadEnableFlags:
    case Command::ReadDiscretes: {
        if (Status s
            = expectSize(request.count, std::to_string(request.count) + " points, one byte each");
            !s)
            return s.error();
        for (std::size_t i = 0; i < data.size(); ++i) {
            if (data[i] > 1) {
                return malformed(msg<MsgId::AnswerValueNotDiscrete>(
                    hex2(data[i]),
                    request.start.advanced(static_cast<std::uint32_t>(i)).toString()));
            }
            response.values.push_back(data[i]);
        }
        break;
    }
    case Command::ReadRegisters: {
        const std::size_t vsize = valueSize(request.start.type);
        if (Status s = expectSize(request.count * vsize, std::to_string(request.count) + " x "
                                                             + std::to_string(vsize) + " bytes");
            !s)
            return s.error();
        for (std::size_t i = 0; i < request.count; ++i)
            response.values.push_back(readNumber(data, i * vsize, vsize));
        break;
    }
    case Command::MixedRead: {
        std::size_t total = 0;
        for (const Address &a : request.addresses)
            total += valueSize(a.type);
        if (Status s = expectSize(total, "values of " + std::to_string(request.addresses.size())
                                             + " elements");
            !s)
            return s.error();
        std::size_t pos = 0;
        for (const Address &a : request.addresses) {
            const std::size_t vsize = valueSize(a.type);
            const std::uint32_t v = readNumber(data, pos, vsize);
            if (isDiscrete(a.type) && v > 1)
                return malformed(msg<MsgId::AnswerValueNotDiscrete>(hex2(v), a.toString()));
            response.values.push_back(v);
            pos += vsize;
        }
        break;
    }
    default:
        if (Status s = expectSize(0, "this command answers without data"); !s)
            return s.error();
        break;
    }
    return response;
}

std::optional<FrameHeader> BinaryCodec::frameHeader(std::span<const std::uint8_t> frame) const
{
    auto parsed = parseFrame(frame);
    if (!parsed)
        return std::nullopt;
    return FrameHeader{parsed->payload[0], parsed->payload[1]};
}

std::optional<FrameHeader> BinaryCodec::peekHeader(std::span<const std::uint8_t> frame) const
{
    // Header (51 query / 52 answer), ID, length (2), then station and command.
    if (frame.size() < 6 || (frame[0] != queryHeader && frame[0] != responseHeader)
        || frame[1] != frameId)
        return std::nullopt;
    return FrameHeader{frame[4], frame[5]};
}

Bytes BinaryCodec::wrap(std::span<const std::uint8_t> body, bool response) const
{
    return frameOf(response ? responseHeader : queryHeader, body);
}

Message BinaryCodec::summary(std::span<const std::uint8_t> frame) const
{
    auto parsed = parseFrame(frame);
    if (!parsed)
        return msg<MsgId::FrameBadBinary>(frame.size(), parsed.error().message);
    const auto p = parsed->payload;
    auto station = [&p](Message rest) {
        return msg<MsgId::FrameStation>(p[0], hex2(p[1]), std::move(rest));
    };
    if (parsed->header == queryHeader) {
        const Message name = isKnownCommand(p[1]) ? commandMessage(static_cast<Command>(p[1]))
                                                  : msg<MsgId::CommandUnknown>();
        auto request = BinarySlave::parseQueryPayload(p);
        Message detail = request ? queryDetail(*request) : request.error().message;
        if (detail.empty())
            return station(name);
        return station(msg<MsgId::Joined>(name, std::move(detail)));
    }
    if (p[1] == static_cast<std::uint8_t>(Command::Loopback))
        return station(msg<MsgId::FrameAnswerEcho>(p.size() - 2));
    if (p.size() < 3)
        return station(msg<MsgId::FrameAnswerNoErrorByte>());
    if (p[2] != 0) {
        return station(msg<MsgId::FrameAnswerError>(p[2] < 16 ? hex2(p[2]).substr(1) : hex2(p[2]),
                                                    plcCodeMessage(p[2])));
    }
    const auto data = p.subspan(3);
    if (data.empty())
        return station(msg<MsgId::FrameAnswerOk>());
    return station(msg<MsgId::FrameAnswerOkBytes>(data.size(), hexBytes(data, 16)));
}

} // namespace Fatek
