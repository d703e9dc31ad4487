#include "binarycodec.h"

#include <algorithm>
#include <cstdio>
#include <string_view>

namespace Fatek {

namespace {

// header, ID, length (2) before the payload; CRC (2) and terminator (2) after it.
constexpr std::size_t kHeadSize = 4;
constexpr std::size_t kTailSize = 4;
constexpr std::size_t kOverhead = kHeadSize + kTailSize;

std::string hex2(std::uint32_t value)
{
    char buf[8];
    std::snprintf(buf, sizeof buf, "%02X", value & 0xFFu);
    return buf;
}

std::string hexValue(std::uint32_t value, ElementType type)
{
    if (isDiscrete(type))
        return std::to_string(value);
    char buf[16];
    std::snprintf(buf, sizeof buf, isDoubleWord(type) ? "%08X" : "%04X", value);
    return buf;
}

std::string hexBytes(std::span<const std::uint8_t> bytes, std::size_t maxBytes)
{
    std::string s;
    for (std::size_t i = 0; i < bytes.size() && i < maxBytes; ++i) {
        if (i)
            s += ' ';
        s += hex2(bytes[i]);
    }
    if (bytes.size() > maxBytes)
        s += " ...";
    return s;
}

std::string commandText(std::uint8_t code)
{
    if (!isKnownCommand(code))
        return hex2(code) + " unknown command";
    return hex2(code) + " " + std::string(commandName(static_cast<Command>(code)));
}

// Bytes one value takes on the wire.
std::size_t valueSize(ElementType type)
{
    switch (elementInfo(type).width) {
    case ElementWidth::Bit: return 1;
    case ElementWidth::Word: return 2;
    case ElementWidth::DoubleWord: return 4;
    }
    return 2;
}

void appendValue(Bytes &out, ElementType type, std::uint32_t value)
{
    switch (valueSize(type)) {
    case 1: out.push_back(value != 0 ? 1 : 0); break;
    case 4:
        out.push_back(static_cast<std::uint8_t>(value >> 24));
        out.push_back(static_cast<std::uint8_t>(value >> 16));
        [[fallthrough]];
    default:
        out.push_back(static_cast<std::uint8_t>(value >> 8));
        out.push_back(static_cast<std::uint8_t>(value));
        break;
    }
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

std::size_t addressSize(ElementType type)
{
    return elementInfo(type).symbol.size() + 2;
}

// Every element type whose symbol begins `bytes`, longest symbol first.
std::vector<ElementType> symbolCandidates(std::span<const std::uint8_t> bytes)
{
    std::vector<ElementType> found;
    for (const ElementInfo &info : allElements()) {
        if (info.symbol.size() > bytes.size())
            continue;
        bool same = true;
        for (std::size_t i = 0; i < info.symbol.size() && same; ++i)
            same = static_cast<std::uint8_t>(info.symbol[i]) == bytes[i];
        if (same)
            found.push_back(info.type);
    }
    std::stable_sort(found.begin(), found.end(), [](ElementType a, ElementType b) {
        return elementInfo(a).symbol.size() > elementInfo(b).symbol.size();
    });
    return found;
}

std::uint32_t readNumber(std::span<const std::uint8_t> bytes, std::size_t pos, std::size_t size)
{
    std::uint32_t v = 0;
    for (std::size_t i = 0; i < size; ++i)
        v = (v << 8) | bytes[pos + i];
    return v;
}

struct ParsedFrame
{
    std::uint8_t header = 0;
    std::span<const std::uint8_t> payload;
};

// Header, ID, length, terminator and CRC. The payload view points into `frame`.
Result<ParsedFrame> parseFrame(std::span<const std::uint8_t> frame)
{
    if (frame.size() < kOverhead + 2) {
        return makeError(ErrorKind::BadFrame, "Binary frame too short ("
                                                  + std::to_string(frame.size())
                                                  + " bytes): a frame has at least 10 bytes.");
    }
    if (frame[0] != BinaryCodec::queryHeader && frame[0] != BinaryCodec::responseHeader) {
        return makeError(ErrorKind::BadFrame, "Binary frame starts with " + hex2(frame[0])
                                                  + " instead of 51 (query) or 52 (answer).");
    }
    if (frame[1] != BinaryCodec::frameId)
        return makeError(ErrorKind::BadFrame,
                         "Binary frame ID is " + hex2(frame[1]) + " instead of 10.");
    const std::size_t length = readNumber(frame, 2, 2);
    if (length + kOverhead != frame.size()) {
        return makeError(
            ErrorKind::BadFrame,
            "Binary frame length field says " + std::to_string(length)
                + " payload bytes but the frame carries "
                + std::to_string(frame.size() < kOverhead ? 0 : frame.size() - kOverhead) + ".");
    }
    if (frame[frame.size() - 2] != BinaryCodec::terminator[0]
        || frame[frame.size() - 1] != BinaryCodec::terminator[1]) {
        return makeError(ErrorKind::BadFrame, "Binary frame ends with "
                                                  + hexBytes(frame.subspan(frame.size() - 2), 2)
                                                  + " instead of the terminator 55 AA.");
    }
    const std::uint16_t expected = BinaryCodec::crc16(frame.subspan(2, length + 2));
    const std::uint16_t got = static_cast<std::uint16_t>(frame[kHeadSize + length]
                                                         | (frame[kHeadSize + length + 1] << 8));
    if (expected != got) {
        return makeError(ErrorKind::BadChecksum,
                         "Binary frame CRC is " + hex2(got) + " " + hex2(got >> 8u) + ", computed "
                             + hex2(expected) + " "
                             + hex2(static_cast<std::uint32_t>(expected) >> 8u) + ".");
    }
    if (length < 2)
        return makeError(ErrorKind::BadFrame, "Binary frame without station and command.");
    return ParsedFrame{frame[0], frame.subspan(kHeadSize, length)};
}

Bytes frameOf(std::uint8_t header, std::span<const std::uint8_t> payload)
{
    // The length field has 16 bits; nothing legal comes near it, so a longer body is cut.
    if (payload.size() > 0xFFFF)
        payload = payload.first(0xFFFF);
    Bytes frame;
    frame.reserve(payload.size() + kOverhead);
    frame.push_back(header);
    frame.push_back(BinaryCodec::frameId);
    frame.push_back(static_cast<std::uint8_t>(payload.size() >> 8));
    frame.push_back(static_cast<std::uint8_t>(payload.size()));
    frame.insert(frame.end(), payload.begin(), payload.end());
    const std::uint16_t crc = BinaryCodec::crc16(std::span<const std::uint8_t>(frame).subspan(2));
    frame.push_back(static_cast<std::uint8_t>(crc & 0xFFu));
    frame.push_back(static_cast<std::uint8_t>(crc >> 8));
    frame.push_back(BinaryCodec::terminator[0]);
    frame.push_back(BinaryCodec::terminator[1]);
    return frame;
}

// ---- slave side: query payloads ---------------------------------------------------------------

ProtocolError queryError(int plcCode, std::string message,
                         ErrorKind kind = ErrorKind::InvalidRequest)
{
    return makeError(kind, std::move(message), plcCode);
}

// One address at `pos` of a single-type command whose remaining payload must be exactly
// `restSize(type)` bytes after the address: of the symbols that match, the one for which the
// length is consistent wins (D + 0x52xx looks like DR).
template<typename RestSize>
Result<Address> singleAddress(std::span<const std::uint8_t> data, std::size_t pos,
                              RestSize restSize)
{
    const auto candidates = symbolCandidates(data.subspan(pos));
    if (candidates.empty()) {
        return queryError(0xA, "Unknown element type code " + hexBytes(data.subspan(pos), 3) + ".",
                          ErrorKind::InvalidAddress);
    }
    for (ElementType type : candidates) {
        const std::size_t need = addressSize(type) + restSize(type);
        if (pos + need == data.size())
            return Address{type, readNumber(data, pos + addressSize(type) - 2, 2)};
    }
    return queryError(4, "Query length " + std::to_string(data.size())
                             + " bytes does not fit its element count and element type.");
}

// Addresses (and values for 49) of a mixed command, longest symbol first; backtracks to a
// shorter symbol only when the longest one leaves a payload that cannot be parsed.
class MixedParser
{
public:
    MixedParser(std::span<const std::uint8_t> data, std::size_t count, bool withValues)
        : m_data(data)
        , m_count(count)
        , m_withValues(withValues)
        , m_failed((data.size() + 1) * (count + 1), false)
    {}

    bool parse(std::size_t pos) { return step(pos, 0); }
    bool unknownSymbol() const { return m_unknownSymbol; }

    std::vector<Address> addresses;
    std::vector<std::uint32_t> values;

private:
    bool step(std::size_t pos, std::size_t index)
    {
        if (index == m_count)
            return pos == m_data.size();
        const std::size_t state = pos * (m_count + 1) + index;
        if (m_failed[state])
            return false;
        const auto candidates = symbolCandidates(m_data.subspan(pos));
        if (candidates.empty())
            m_unknownSymbol = true;
        for (ElementType type : candidates) {
            const std::size_t vsize = m_withValues ? valueSize(type) : 0;
            const std::size_t size = addressSize(type) + vsize;
            if (pos + size > m_data.size())
                continue;
            const Address a{type, readNumber(m_data, pos + addressSize(type) - 2, 2)};
            addresses.push_back(a);
            if (m_withValues)
                values.push_back(readNumber(m_data, pos + addressSize(type), vsize));
            if (step(pos + size, index + 1))
                return true;
            addresses.pop_back();
            if (m_withValues)
                values.pop_back();
        }
        m_failed[state] = true;
        return false;
    }

    std::span<const std::uint8_t> m_data;
    std::size_t m_count;
    bool m_withValues;
    std::vector<bool> m_failed; // (pos, index) pairs known to lead nowhere
    bool m_unknownSymbol = false;
};

Result<Request> parseQueryPayload(std::span<const std::uint8_t> p)
{
    const std::uint8_t station = p[0];
    const std::uint8_t code = p[1];
    const auto data = p.subspan(2);
    const std::string name = commandText(code);
    auto malformed = [&name](std::string what) {
        return queryError(4, name + ": " + std::move(what));
    };
    auto noData = [&](Request r) -> Result<Request> {
        if (!data.empty())
            return malformed(std::to_string(data.size()) + " unexpected data bytes.");
        return r;
    };

    switch (code) {
    case 0x40: return noData(Request::briefStatus(station));
    case 0x53: return noData(Request::detailStatus(station));
    case 0x41:
        if (data.size() != 1)
            return malformed("expected one control byte, got " + std::to_string(data.size())
                             + " bytes.");
        if (data[0] > 1)
            return queryError(2, "RUN/STOP control byte " + hex2(data[0])
                                     + " is not 00 (stop) or 01 (run).");
        return Request::runStop(station, data[0] == 1);
    case 0x42: {
        if (data.empty())
            return malformed("operation byte missing.");
        if (data[0] < 1 || data[0] > 4)
            return queryError(2, "Discrete operation " + hex2(data[0]) + " is not 01..04.");
        auto a = singleAddress(data, 1, [](ElementType) { return std::size_t(0); });
        if (!a)
            return a.error();
        return Request::discreteControl(station, static_cast<DiscreteOp>(data[0]), *a);
    }
    case 0x43:
    case 0x44:
    case 0x46: {
        if (data.empty())
            return malformed("element count missing.");
        auto a = singleAddress(data, 1, [](ElementType) { return std::size_t(0); });
        if (!a)
            return a.error();
        std::uint32_t n = data[0];
        if (code == 0x46) {
            if (n == 0)
                return malformed("element count 0.");
            return Request::readRegisters(station, *a, n);
        }
        if (n == 0)
            n = 256;
        return code == 0x43 ? Request::readEnableFlags(station, *a, n)
                            : Request::readDiscretes(station, *a, n);
    }
    case 0x45:
    case 0x47: {
        if (data.empty())
            return malformed("element count missing.");
        std::size_t n = data[0];
        if (n == 0) {
            if (code == 0x47)
                return malformed("element count 0.");
            n = 256;
        }
        auto a = singleAddress(data, 1, [n](ElementType t) { return n * valueSize(t); });
        if (!a)
            return a.error();
        std::vector<std::uint32_t> values;
        const std::size_t vsize = valueSize(a->type);
        const std::size_t first = 1 + addressSize(a->type);
        for (std::size_t i = 0; i < n; ++i) {
            const std::uint32_t v = readNumber(data, first + i * vsize, vsize);
            if (isDiscrete(a->type) && v > 1) {
                return queryError(2, "Value " + hex2(v) + " for "
                                         + a->advanced(static_cast<std::uint32_t>(i)).toString()
                                         + " is not 00 or 01.");
            }
            values.push_back(v);
        }
        return code == 0x45 ? Request::writeDiscretes(station, *a, std::move(values))
                            : Request::writeRegisters(station, *a, std::move(values));
    }
    case 0x48:
    case 0x49: {
        if (data.empty())
            return malformed("element count missing.");
        const std::size_t n = data[0];
        if (n == 0)
            return malformed("element count 0.");
        // An entry takes 3 to 5 address bytes (plus 1 to 4 value bytes for 49): reject
        // impossible lengths before searching.
        const std::size_t most = n * (code == 0x49 ? 9 : 5);
        if (data.size() - 1 < n * 3 || data.size() - 1 > most) {
            return malformed(std::to_string(data.size() - 1) + " address bytes cannot hold "
                             + std::to_string(n) + " elements.");
        }
        MixedParser parser(data, n, code == 0x49);
        if (!parser.parse(1)) {
            if (parser.unknownSymbol())
                return queryError(0xA, name + ": unknown element type code in the address list.",
                                  ErrorKind::InvalidAddress);
            return malformed("the address list does not match its count of " + std::to_string(n)
                             + " and " + std::to_string(data.size()) + " data bytes.");
        }
        if (code == 0x48)
            return Request::mixedRead(station, std::move(parser.addresses));
        for (std::size_t i = 0; i < n; ++i) {
            if (isDiscrete(parser.addresses[i].type) && parser.values[i] > 1) {
                return queryError(2, "Value " + hex2(parser.values[i]) + " for "
                                         + parser.addresses[i].toString() + " is not 00 or 01.");
            }
        }
        return Request::mixedWrite(station, std::move(parser.addresses), std::move(parser.values));
    }
    case 0x4E: return Request::loopback(station, Bytes(data.begin(), data.end()));
    default:
        return queryError(4, "Command " + hex2(code) + " is not part of the binary protocol.",
                          ErrorKind::Unsupported);
    }
}

// ---- master side: answer data -----------------------------------------------------------------

std::string queryDetail(const Request &r)
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
    case Command::RunStop: return r.run ? ": RUN" : ": STOP";
    case Command::DiscreteControl:
        return ": " + std::string(discreteOpName(r.op)) + " " + r.start.toString();
    case Command::ReadEnableFlags:
    case Command::ReadDiscretes:
    case Command::ReadRegisters: return ": " + std::to_string(r.count) + " x " + r.start.toString();
    case Command::WriteDiscretes:
    case Command::WriteRegisters:
        return ": " + std::to_string(r.values.size()) + " x " + r.start.toString() + " ="
               + values(r.start);
    case Command::MixedRead: return ": " + r.target();
    case Command::MixedWrite: {
        std::string s = ":";
        for (std::size_t i = 0; i < r.addresses.size() && i < r.values.size(); ++i) {
            s += i ? ", " : " ";
            s += r.addresses[i].toString() + "=" + hexValue(r.values[i], r.addresses[i].type);
        }
        return s;
    }
    case Command::Loopback: return ": " + std::to_string(r.data.size()) + " bytes";
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
        return makeError(ErrorKind::Unsupported,
                         "Program pages (4F/50) exist only in the FACON protocol.");
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
        return makeError(ErrorKind::BadFrame, "Received a query frame (51) instead of an answer "
                                              "(52): probably the echo of our own query.");
    }
    const auto p = parsed->payload;
    const std::uint8_t code = static_cast<std::uint8_t>(request.command);
    if (p[0] != request.station) {
        return makeError(ErrorKind::StationMismatch,
                         "Answer from station " + std::to_string(p[0]) + " while station "
                             + std::to_string(request.station) + " was asked (" + request.describe()
                             + ").");
    }
    if (p[1] != code) {
        return makeError(ErrorKind::CommandMismatch, "Answer to command " + hex2(p[1]) + " while "
                                                         + commandText(code) + " was sent ("
                                                         + request.describe() + ").");
    }
    auto malformed = [&request](std::string message) {
        return makeError(ErrorKind::MalformedResponse,
                         "Answer to " + request.describe() + ": " + std::move(message));
    };

    Response response;
    response.station = p[0];
    response.command = request.command;

    // Loopback answers carry the test data right after the command, without an error byte.
    if (request.command == Command::Loopback) {
        const auto data = p.subspan(2);
        if (!std::equal(data.begin(), data.end(), request.data.begin(), request.data.end())) {
            return malformed("the echoed " + std::to_string(data.size()) + " bytes differ from the "
                             + std::to_string(request.data.size()) + " bytes sent.");
        }
        response.data.assign(data.begin(), data.end());
        return response;
    }

    if (p.size() < 3)
        return malformed("the error byte is missing.");
    if (p[2] != 0) {
        const std::string target = request.target();
        return makePlcError(p[2], target.empty() ? "for " + request.describe() : target);
    }
    const auto data = p.subspan(3);
    auto expectSize = [&](std::size_t size, std::string_view what) -> Status {
        if (data.size() != size) {
            return malformed(std::to_string(data.size()) + " data bytes instead of "
                             + std::to_string(size) + " (" + std::string(what) + ").");
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
                return malformed("value " + hex2(data[i]) + " for "
                                 + request.start.advanced(static_cast<std::uint32_t>(i)).toString()
                                 + " is neither 00 nor 01.");
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
                return malformed("value " + hex2(v) + " for " + a.toString()
                                 + " is neither 00 nor 01.");
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

Result<Request> BinaryCodec::decodeRequest(std::span<const std::uint8_t> frame) const
{
    auto parsed = parseFrame(frame);
    if (!parsed)
        return parsed.error(); // plcCode 0: a broken frame gets no answer
    if (parsed->header != queryHeader) {
        return makeError(ErrorKind::BadFrame,
                         "Frame starts with 52 (an answer), not 51 (a query).");
    }
    auto request = parseQueryPayload(parsed->payload);
    if (!request)
        return request.error();
    if (Status s = validateRequest(*request, Protocol::Binary); !s) {
        ProtocolError e = s.error();
        e.plcCode = e.kind == ErrorKind::InvalidAddress ? 0xA : 4;
        return e;
    }
    return request;
}

Bytes BinaryCodec::encodeResponse(const Request &request, const Response &response) const
{
    Bytes p;
    p.push_back(response.station);
    p.push_back(static_cast<std::uint8_t>(response.command));
    if (response.errorCode != 0) {
        p.push_back(response.errorCode);
        return frameOf(responseHeader, p);
    }
    if (response.command == Command::Loopback) {
        p.insert(p.end(), response.data.begin(), response.data.end());
        return frameOf(responseHeader, p);
    }
    p.push_back(0);
    switch (response.command) {
    case Command::BriefStatus:
    case Command::DetailStatus:
        p.insert(p.end(), response.data.begin(), response.data.end());
        break;
    case Command::ReadEnableFlags:
    case Command::ReadDiscretes:
        for (std::uint32_t v : response.values)
            p.push_back(v != 0 ? 1 : 0);
        break;
    case Command::ReadRegisters:
        for (std::uint32_t v : response.values)
            appendValue(p, request.start.type, v);
        break;
    case Command::MixedRead:
        // A value without an address (a simulator bug) is sent as 16-bit rather than dropped
        // silently.
        for (std::size_t i = 0; i < response.values.size(); ++i)
            appendValue(p,
                        i < request.addresses.size() ? request.addresses[i].type : ElementType::R,
                        response.values[i]);
        break;
    default: break;
    }
    return frameOf(responseHeader, p);
}

Bytes BinaryCodec::encodeErrorResponse(FrameHeader header, std::uint8_t errorCode) const
{
    const std::uint8_t p[] = {header.station, header.command, errorCode};
    return frameOf(responseHeader, p);
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

std::string BinaryCodec::summarize(std::span<const std::uint8_t> frame) const
{
    auto parsed = parseFrame(frame);
    if (!parsed)
        return "bad binary frame (" + std::to_string(frame.size())
               + " bytes): " + parsed.error().message;
    const auto p = parsed->payload;
    const std::string head = "station " + std::to_string(p[0]) + ", ";
    if (parsed->header == queryHeader) {
        auto request = parseQueryPayload(p);
        if (!request)
            return head + commandText(p[1]) + ": " + request.error().message;
        return head + commandText(p[1]) + queryDetail(*request);
    }
    const std::string answer = head + hex2(p[1]) + " answer: ";
    if (p[1] == static_cast<std::uint8_t>(Command::Loopback))
        return answer + "echo of " + std::to_string(p.size() - 2) + " bytes";
    if (p.size() < 3)
        return answer + "no error byte";
    if (p[2] != 0)
        return answer + "error " + (p[2] < 16 ? hex2(p[2]).substr(1) : hex2(p[2])) + " ("
               + std::string(plcErrorText(p[2])) + ")";
    const auto data = p.subspan(3);
    if (data.empty())
        return answer + "OK";
    return answer + "OK, " + std::to_string(data.size()) + " data bytes: " + hexBytes(data, 16);
}

} // namespace Fatek
