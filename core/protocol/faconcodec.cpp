#include "faconcodec.h"

// FaconCodec's master side (queries out, answers in), framing and the traffic-log summary; the
// slave side is in faconslave.cpp.

#include "faconslave.h"
#include "faconwire.h"

#include <string_view>

namespace Fatek {

using namespace FaconWire;

namespace {

// What a query asks, after its command's name (empty when the name says it all).
Message queryDetails(const Request &r)
{
    // Discretes as one run of 0/1 ("1001"), registers as hex words (" AAAA 5555").
    auto listValues = [](const Address &start, const std::vector<std::uint32_t> &values) {
        std::string s;
        for (std::size_t i = 0; i < values.size() && i < 8; ++i) {
            if (!isDiscrete(start.type))
                s += ' ';
            appendValue(s, start.type, values[i]);
        }
        if (values.size() > 8)
            s += " ...";
        return s;
    };
    switch (r.command) {
    case Command::BriefStatus:
    case Command::DetailStatus: return {};
    case Command::RunStop: return Message::text(r.run ? "RUN" : "STOP");
    case Command::DiscreteControl: return discreteOpMessage(r.op, r.start.toFaconString());
    case Command::ReadEnableFlags:
    case Command::ReadDiscretes:
    case Command::ReadRegisters:
        return Message::text(std::to_string(r.count) + " x " + r.start.toFaconString());
    case Command::WriteDiscretes:
    case Command::WriteRegisters:
        return Message::text(std::to_string(r.values.size()) + " x " + r.start.toFaconString()
                             + " =" + (isDiscrete(r.start.type) ? " " : "")
                             + listValues(r.start, r.values));
    case Command::MixedRead:
    case Command::MixedWrite: {
        std::string s;
        for (std::size_t i = 0; i < r.addresses.size() && i < 8; ++i) {
            s += ' ';
            s += r.addresses[i].toFaconString();
            if (r.command == Command::MixedWrite && i < r.values.size()) {
                s += '=';
                appendValue(s, r.addresses[i].type, r.values[i]);
            }
        }
        if (r.addresses.size() > 8)
            s += " ...";
        return msg<MsgId::FrameElements>(r.addresses.size(), s);
    }
    case Command::Loopback:
        return msg<MsgId::FrameChars>(
            r.data.size(), printable(std::string_view(reinterpret_cast<const char *>(r.data.data()),
                                                      r.data.size()),
                                     32));
    case Command::ReadProgram: return msg<MsgId::FramePage>(r.page);
    case Command::WriteProgram: return msg<MsgId::FramePageWords>(r.page);
    }
    return {};
}

// Decoded answer data for the master: everything after the error digit.
Result<Response> decodeAnswerData(const Request &request, std::string_view data, Response response)
{
    auto malformed = [&request](Message detail) {
        return makeError(ErrorKind::MalformedResponse,
                         msg<MsgId::AnswerTo>(request.describe(), std::move(detail)));
    };
    auto expectLength = [&](std::size_t expected, std::string_view what) -> Status {
        if (data.size() != expected) {
            return malformed(msg<MsgId::AnswerExpectedChars>(expected, what, data.size()));
        }
        return Ok{};
    };
    auto hexBytes = [&](std::string_view text) -> Status {
        for (std::size_t i = 0; i + 1 < text.size(); i += 2) {
            const auto b = parseHex(text.substr(i, 2));
            if (!b)
                return malformed(
                    msg<MsgId::AnswerStatusByteNotHex>(printable(text.substr(i, 2), 2)));
            response.data.push_back(static_cast<std::uint8_t>(*b));
        }
        return Ok{};
    };
    auto readValue = [&](std::size_t &pos, ElementType type) -> Result<std::uint32_t> {
        const std::size_t n = valueChars(type);
        const std::string_view field = data.substr(pos, n);
        pos += n;
        if (n == 1) {
            if (field != "0" && field != "1")
                return malformed(msg<MsgId::AnswerDiscreteNotBinary>(printable(field, 1)));
            return static_cast<std::uint32_t>(field[0] - '0');
        }
        const auto v = parseHex(field);
        if (!v)
            return malformed(msg<MsgId::AnswerValueNotHex>(printable(field, n)));
        return *v;
    };

    switch (request.command) {
    case Command::BriefStatus:
        if (Status s = expectLength(6, "STATUS1..3"); !s)
            return s.error();
        if (Status s = hexBytes(data); !s)
            return s.error();
        break;
    case Command::DetailStatus:
        // Models answer 21, 28 or 64 status bytes: accept any whole number of bytes.
        if (data.size() % 2 != 0)
            return malformed(msg<MsgId::AnswerOddStatusChars>(data.size()));
        if (Status s = hexBytes(data); !s)
            return s.error();
        break;
    case Command::ReadEnableFlags:
    case Command::ReadDiscretes:
    case Command::ReadRegisters: {
        const std::size_t width = valueChars(request.start.type);
        if (Status s = expectLength(std::size_t{request.count} * width,
                                    std::to_string(request.count) + " x " + std::to_string(width));
            !s)
            return s.error();
        std::size_t pos = 0;
        for (std::uint32_t i = 0; i < request.count; ++i) {
            auto v = readValue(pos, request.start.type);
            if (!v)
                return v.error();
            response.values.push_back(*v);
        }
        break;
    }
    case Command::MixedRead: {
        std::size_t expected = 0;
        for (const Address &a : request.addresses)
            expected += valueChars(a.type);
        if (Status s = expectLength(expected, "one value per element"); !s)
            return s.error();
        std::size_t pos = 0;
        for (const Address &a : request.addresses) {
            auto v = readValue(pos, a.type);
            if (!v)
                return v.error();
            response.values.push_back(*v);
        }
        break;
    }
    case Command::ReadProgram: {
        if (Status s = expectLength(Limits::programPageWords * 4, "64 words"); !s)
            return s.error();
        std::size_t pos = 0;
        for (std::uint32_t i = 0; i < Limits::programPageWords; ++i) {
            auto v = readValue(pos, ElementType::R);
            if (!v)
                return v.error();
            response.values.push_back(*v);
        }
        break;
    }
    case Command::Loopback: break; // handled by the caller
    case Command::RunStop:
    case Command::DiscreteControl:
    case Command::WriteDiscretes:
    case Command::WriteRegisters:
    case Command::MixedWrite:
    case Command::WriteProgram:
        if (Status s = expectLength(0, "none after the error digit"); !s)
            return s.error();
        break;
    }
    return response;
}

} // namespace

std::uint8_t FaconCodec::lrc(std::span<const std::uint8_t> bytes)
{
    unsigned sum = 0;
    for (std::uint8_t b : bytes)
        sum += b;
    return static_cast<std::uint8_t>(sum & 0xFFu);
}

Result<Bytes> FaconCodec::encodeRequest(const Request &request) const
{
    if (Status s = validateRequest(request, Protocol::Facon); !s)
        return s.error();
    std::string body = headerText(request.station, static_cast<std::uint8_t>(request.command));
    // A FACON address is always non-empty here: validateRequest refuses types without a FACON form.
    switch (request.command) {
    case Command::BriefStatus:
    case Command::DetailStatus: break;
    case Command::RunStop: body += request.run ? '1' : '0'; break;
    case Command::DiscreteControl:
        body += static_cast<char>('0' + static_cast<int>(request.op));
        body += request.start.toFaconString();
        break;
    case Command::ReadEnableFlags:
    case Command::ReadDiscretes:
    case Command::ReadRegisters:
        appendHex(body, request.count & 0xFFu, 2); // 256 points -> 00
        body += request.start.toFaconString();
        break;
    case Command::WriteDiscretes:
    case Command::WriteRegisters:
        appendHex(body, static_cast<std::uint32_t>(request.values.size()) & 0xFFu, 2);
        body += request.start.toFaconString();
        for (std::uint32_t v : request.values)
            appendValue(body, request.start.type, v);
        break;
    case Command::MixedRead:
    case Command::MixedWrite:
        appendHex(body, static_cast<std::uint32_t>(request.addresses.size()), 2);
        for (std::size_t i = 0; i < request.addresses.size(); ++i) {
            body += request.addresses[i].toFaconString();
            if (request.command == Command::MixedWrite)
                appendValue(body, request.addresses[i].type, request.values[i]);
        }
        break;
    case Command::Loopback:
        for (std::uint8_t b : request.data)
            body += static_cast<char>(b);
        break;
    case Command::ReadProgram:
    case Command::WriteProgram:
        appendHex(body, request.page, 4);
        if (request.command == Command::WriteProgram) {
            for (std::uint32_t w : request.values)
                appendHex(body, w, 4);
        }
        break;
    }
    if (body.size() - 4 > maxDataChars) {
        return makeError(ErrorKind::LimitExceeded,
                         msg<MsgId::FaconTooManyDataChars>(request.describe(), body.size() - 4));
    }
    return frameOf(body);
}

Result<Response> FaconCodec::decodeResponse(std::span<const std::uint8_t> frame,
                                            const Request &request) const
{
    auto parsed = parseFrame(frame);
    if (!parsed)
        return parsed.error();
    const ParsedFrame &f = *parsed;
    if (f.station != request.station) {
        return makeError(
            ErrorKind::StationMismatch,
            msg<MsgId::AnswerWrongStation>(f.station, request.station, request.describe()));
    }
    if (f.command != static_cast<std::uint8_t>(request.command)) {
        return makeError(ErrorKind::CommandMismatch,
                         msg<MsgId::FaconAnswerWrongCommand>(
                             hex2(f.command), hex2(static_cast<std::uint8_t>(request.command)),
                             commandMessage(request.command)));
    }
    Response response;
    response.station = f.station;
    response.command = request.command;
    if (request.command == Command::Loopback) {
        // The only answer without an error digit: the test data comes back as sent.
        const std::string_view sent(reinterpret_cast<const char *>(request.data.data()),
                                    request.data.size());
        if (f.data != sent) {
            return makeError(
                ErrorKind::MalformedResponse,
                msg<MsgId::AnswerLoopbackDiffers>(printable(sent, 32), printable(f.data, 32)));
        }
        response.data.assign(request.data.begin(), request.data.end());
        return response;
    }
    if (request.command == Command::ReadProgram
        && f.data.size() == std::size_t{Limits::programPageWords} * 4) {
        // The seed draws the 4F answer without an error digit (64 words only), the reference
        // with one: told apart by length. A single character is an error digit.
        return decodeAnswerData(request, f.data, std::move(response));
    }
    if (f.data.empty()) {
        return makeError(ErrorKind::MalformedResponse,
                         msg<MsgId::AnswerNoErrorDigit>(request.describe()));
    }
    const auto code = hexValue(f.data[0]);
    if (!code) {
        return makeError(ErrorKind::MalformedResponse,
                         msg<MsgId::AnswerErrorDigitNotHex>(request.describe(),
                                                            printable(f.data.substr(0, 1), 1)));
    }
    if (*code != 0)
        return makePlcError(static_cast<int>(*code), request.target());
    return decodeAnswerData(request, f.data.substr(1), std::move(response));
}

std::optional<FrameHeader> FaconCodec::frameHeader(std::span<const std::uint8_t> frame) const
{
    auto parsed = parseFrame(frame);
    if (!parsed)
        return std::nullopt;
    return FrameHeader{parsed->station, parsed->command};
}

std::optional<FrameHeader> FaconCodec::peekHeader(std::span<const std::uint8_t> frame) const
{
    if (frame.size() < 5 || frame.front() != STX)
        return std::nullopt;
    const std::string_view text(reinterpret_cast<const char *>(frame.data()), 5);
    const auto station = parseHex(text.substr(1, 2));
    const auto command = parseHex(text.substr(3, 2));
    if (!station || !command)
        return std::nullopt;
    return FrameHeader{static_cast<std::uint8_t>(*station), static_cast<std::uint8_t>(*command)};
}

Bytes FaconCodec::wrap(std::span<const std::uint8_t> body, bool /*response*/) const
{
    // Same framing both ways in FACON.
    return frameOf(std::string_view(reinterpret_cast<const char *>(body.data()), body.size()));
}

Message FaconCodec::summary(std::span<const std::uint8_t> frame) const
{
    auto parsed = parseFrame(frame);
    if (!parsed)
        return msg<MsgId::FrameInvalidFacon>(frame.size(), parsed.error().message);
    const ParsedFrame &f = *parsed;
    auto station = [&f](Message rest) {
        return msg<MsgId::FrameStation>(f.station, hex2(f.command), std::move(rest));
    };
    if (!isKnownCommand(f.command))
        return station(msg<MsgId::FrameUnknownCommand>(printable(f.data, 40)));
    const auto command = static_cast<Command>(f.command);
    auto named = [&](Message detail) {
        if (detail.empty())
            return station(commandMessage(command));
        return station(msg<MsgId::Joined>(commandMessage(command), std::move(detail)));
    };

    // FACON queries and answers share one format; a frame that parses as a query is shown as one.
    // 41 "0" is both STOP and "no error": say so rather than guess.
    if (command == Command::RunStop && f.data == "0")
        return named(msg<MsgId::FrameStopOrNoError>());
    if (command == Command::Loopback)
        return named(msg<MsgId::FrameChars>(f.data.size(), printable(f.data, 32)));
    if (auto query = FaconSlave::parseQuery(f.station, command, f.data))
        return named(queryDetails(*query));

    if (f.data.empty())
        return station(msg<MsgId::FrameAnswerNoErrorDigit>());
    const auto code = hexValue(f.data[0]);
    if (!code)
        return station(msg<MsgId::FrameAnswerMalformed>(printable(f.data, 40)));
    if (*code != 0) {
        const int plc = static_cast<int>(*code);
        return station(msg<MsgId::FrameAnswerError>(plcCodeDigits(plc), plcCodeMessage(plc)));
    }
    if (f.data.size() == 1)
        return station(msg<MsgId::FrameAnswerOk>());
    return station(
        msg<MsgId::FrameAnswerOkChars>(f.data.size() - 1, printable(f.data.substr(1), 40)));
}

} // namespace Fatek
