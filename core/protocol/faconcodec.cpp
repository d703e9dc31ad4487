#include "faconcodec.h"

#include <algorithm>
#include <string_view>

namespace Fatek {

namespace {

constexpr char kHexDigits[] = "0123456789ABCDEF";
// Smallest frame: STX, station (2), command (2), LRC (2), ETX.
constexpr std::size_t kMinFrameSize = 8;

std::optional<std::uint32_t> hexValue(char c)
{
    if (c >= '0' && c <= '9')
        return static_cast<std::uint32_t>(c - '0');
    if (c >= 'A' && c <= 'F')
        return static_cast<std::uint32_t>(c - 'A' + 10);
    // Lower case is not what the PLC sends, but costs nothing to accept.
    if (c >= 'a' && c <= 'f')
        return static_cast<std::uint32_t>(c - 'a' + 10);
    return std::nullopt;
}

// Fixed-width hex field (1..8 chars); nullopt on any non-hex character.
std::optional<std::uint32_t> parseHex(std::string_view text)
{
    if (text.empty() || text.size() > 8)
        return std::nullopt;
    std::uint32_t value = 0;
    for (char c : text) {
        const auto digit = hexValue(c);
        if (!digit)
            return std::nullopt;
        value = (value << 4) | *digit;
    }
    return value;
}

void appendHex(std::string &out, std::uint32_t value, int digits)
{
    for (int shift = (digits - 1) * 4; shift >= 0; shift -= 4)
        out += kHexDigits[(value >> shift) & 0xFu];
}

std::string hex2(std::uint32_t value)
{
    std::string s;
    appendHex(s, value, 2);
    return s;
}

// Characters of one value on the wire: discrete 1, 16-bit 4, 32-bit 8.
std::size_t valueChars(ElementType type)
{
    switch (elementInfo(type).width) {
    case ElementWidth::Bit: return 1;
    case ElementWidth::Word: return 4;
    case ElementWidth::DoubleWord: return 8;
    }
    return 4;
}

void appendValue(std::string &out, ElementType type, std::uint32_t value)
{
    if (isDiscrete(type))
        out += value != 0 ? '1' : '0';
    else
        appendHex(out, value, static_cast<int>(valueChars(type)));
}

std::string printable(std::string_view text, std::size_t maxChars)
{
    std::string out;
    for (std::size_t i = 0; i < text.size() && i < maxChars; ++i) {
        const auto c = static_cast<unsigned char>(text[i]);
        if (c >= 0x20 && c <= 0x7E) {
            out += static_cast<char>(c);
        } else {
            out += "<";
            out += hex2(c);
            out += ">";
        }
    }
    if (text.size() > maxChars)
        out += "...";
    return out;
}

Bytes frameOf(std::string_view body)
{
    Bytes frame;
    frame.reserve(body.size() + 4);
    frame.push_back(FaconCodec::STX);
    for (char c : body)
        frame.push_back(static_cast<std::uint8_t>(c));
    const std::uint8_t sum = FaconCodec::lrc(frame);
    frame.push_back(static_cast<std::uint8_t>(kHexDigits[sum >> 4]));
    frame.push_back(static_cast<std::uint8_t>(kHexDigits[sum & 0xF]));
    frame.push_back(FaconCodec::ETX);
    return frame;
}

std::string headerText(std::uint8_t station, std::uint8_t command)
{
    return hex2(station) + hex2(command);
}

struct ParsedFrame
{
    std::uint8_t station = 0;
    std::uint8_t command = 0;
    std::string_view data; // between the command and the LRC
};

// Framing, hex header and LRC. The view points into `frame`.
Result<ParsedFrame> parseFrame(std::span<const std::uint8_t> frame)
{
    if (frame.size() < kMinFrameSize) {
        return makeError(ErrorKind::BadFrame,
                         "FACON frame too short (" + std::to_string(frame.size())
                             + " bytes; at least 8: STX, station, command, LRC, ETX).");
    }
    if (frame.size() > FaconCodec::maxFrameSize) {
        return makeError(ErrorKind::BadFrame,
                         "FACON frame too long (" + std::to_string(frame.size())
                             + " bytes; at most " + std::to_string(FaconCodec::maxFrameSize)
                             + ").");
    }
    if (frame.front() != FaconCodec::STX)
        return makeError(ErrorKind::BadFrame, "FACON frame does not start with STX.");
    if (frame.back() != FaconCodec::ETX)
        return makeError(ErrorKind::BadFrame, "FACON frame does not end with ETX.");
    const std::string_view text(reinterpret_cast<const char *>(frame.data()), frame.size());
    for (std::size_t i = 1; i + 1 < text.size(); ++i) {
        if (frame[i] == FaconCodec::STX || frame[i] == FaconCodec::ETX)
            return makeError(ErrorKind::BadFrame,
                             "FACON frame contains a stray STX or ETX inside.");
    }
    const auto station = parseHex(text.substr(1, 2));
    const auto command = parseHex(text.substr(3, 2));
    if (!station || !command) {
        return makeError(ErrorKind::BadFrame, "FACON frame header \""
                                                  + printable(text.substr(1, 4), 4)
                                                  + "\" is not station and command in hex.");
    }
    const auto received = parseHex(text.substr(text.size() - 3, 2));
    if (!received) {
        return makeError(ErrorKind::BadFrame, "FACON checksum \""
                                                  + printable(text.substr(text.size() - 3, 2), 2)
                                                  + "\" is not two hex characters.");
    }
    const std::uint8_t computed = FaconCodec::lrc(frame.first(frame.size() - 3));
    if (computed != *received) {
        return makeError(ErrorKind::BadChecksum, "FACON checksum error: frame says "
                                                     + hex2(*received) + ", computed "
                                                     + hex2(computed) + ".");
    }
    ParsedFrame parsed;
    parsed.station = static_cast<std::uint8_t>(*station);
    parsed.command = static_cast<std::uint8_t>(*command);
    parsed.data = text.substr(5, text.size() - 8);
    return parsed;
}

// ---- slave side: reading the data of a query ----------------------------------------------------

ProtocolError queryError(int code, std::string message)
{
    return makeError(code == 0xA ? ErrorKind::InvalidAddress : ErrorKind::InvalidRequest,
                     std::move(message), code);
}

class Reader
{
public:
    explicit Reader(std::string_view data)
        : m_data(data)
    {}

    bool atEnd() const { return m_pos >= m_data.size(); }
    std::size_t remaining() const { return m_data.size() - m_pos; }

    Result<std::uint32_t> hex(std::size_t chars, int badCode, std::string_view what)
    {
        if (remaining() < chars)
            return queryError(4, "Query too short: " + std::string(what) + " missing.");
        const auto v = parseHex(m_data.substr(m_pos, chars));
        if (!v) {
            return queryError(badCode, std::string(what) + " \""
                                           + printable(m_data.substr(m_pos, chars), chars)
                                           + "\" is not hex.");
        }
        m_pos += chars;
        return *v;
    }

    // Fixed-width FACON address: symbol letters then faconDigits decimal digits.
    Result<Address> address()
    {
        std::size_t end = m_pos;
        while (end < m_data.size() && end - m_pos < 3
               && ((m_data[end] >= 'A' && m_data[end] <= 'Z')
                   || (m_data[end] >= 'a' && m_data[end] <= 'z')))
            ++end;
        const std::string_view symbol = m_data.substr(m_pos, end - m_pos);
        if (symbol.empty()) {
            if (atEnd())
                return queryError(4, "Query too short: element address missing.");
            return queryError(4, "Element address expected at \""
                                     + printable(m_data.substr(m_pos), 8) + "\".");
        }
        const auto type = elementTypeFromSymbol(symbol);
        if (!type || elementInfo(*type).faconDigits == 0) {
            return queryError(0xA, "Unknown element \"" + printable(symbol, 3) + "\" in FACON.");
        }
        const auto digits = static_cast<std::size_t>(elementInfo(*type).faconDigits);
        if (m_data.size() - end < digits)
            return queryError(4, "Element address " + printable(m_data.substr(m_pos), 8)
                                     + " is cut short.");
        std::uint32_t number = 0;
        for (std::size_t i = end; i < end + digits; ++i) {
            const char c = m_data[i];
            if (c < '0' || c > '9') {
                return queryError(4, "Element address \""
                                         + printable(m_data.substr(m_pos, end + digits - m_pos), 8)
                                         + "\" has a non-decimal number.");
            }
            number = number * 10 + static_cast<std::uint32_t>(c - '0');
        }
        m_pos = end + digits;
        const Address a{*type, number};
        if (Status s = validateAddress(a); !s)
            return queryError(0xA, s.error().message);
        return a;
    }

    Result<std::uint32_t> value(ElementType type)
    {
        if (isDiscrete(type)) {
            if (atEnd())
                return queryError(4, "Query too short: discrete value missing.");
            const char c = m_data[m_pos];
            if (c != '0' && c != '1')
                return queryError(2, "Discrete value \"" + printable(m_data.substr(m_pos, 1), 1)
                                         + "\" is not 0 or 1.");
            ++m_pos;
            return static_cast<std::uint32_t>(c - '0');
        }
        return hex(valueChars(type), 2, "Value");
    }

    // `count` consecutive values of one element type (45, 47).
    Result<std::vector<std::uint32_t>> values(ElementType type, std::uint32_t count)
    {
        std::vector<std::uint32_t> out;
        out.reserve(count);
        for (std::uint32_t i = 0; i < count; ++i) {
            auto v = value(type);
            if (!v)
                return v.error();
            out.push_back(*v);
        }
        return out;
    }

    std::string_view rest() const { return m_data.substr(std::min(m_pos, m_data.size())); }

private:
    std::string_view m_data;
    std::size_t m_pos = 0;
};

int codeForValidation(const ProtocolError &e)
{
    switch (e.kind) {
    case ErrorKind::InvalidAddress: return 0xA;
    default: return 4;
    }
}

Result<Request> parseQuery(std::uint8_t station, Command command, std::string_view data)
{
    Reader in(data);
    Request request;
    // N of 43 44 45: 00 stands for 256.
    auto pointCount = [&in]() -> Result<std::uint32_t> {
        auto n = in.hex(2, 4, "Number of points");
        if (!n)
            return n;
        return *n == 0 ? 256u : *n;
    };

    switch (command) {
    case Command::BriefStatus: request = Request::briefStatus(station); break;
    case Command::DetailStatus: request = Request::detailStatus(station); break;
    case Command::RunStop: {
        if (in.atEnd())
            return queryError(4, "RUN/STOP query without control code.");
        const char c = data[0];
        if (c != '0' && c != '1')
            return queryError(2, "RUN/STOP control code \"" + printable(data.substr(0, 1), 1)
                                     + "\" is not 0 or 1.");
        request = Request::runStop(station, c == '1');
        in = Reader(data.substr(1));
        break;
    }
    case Command::DiscreteControl: {
        if (in.atEnd())
            return queryError(4, "Discrete control query without operation code.");
        const char c = data[0];
        if (c < '1' || c > '4')
            return queryError(2, "Discrete operation \"" + printable(data.substr(0, 1), 1)
                                     + "\" is not 1..4.");
        in = Reader(data.substr(1));
        auto a = in.address();
        if (!a)
            return a.error();
        request = Request::discreteControl(station, static_cast<DiscreteOp>(c - '0'), *a);
        break;
    }
    case Command::ReadEnableFlags:
    case Command::ReadDiscretes: {
        auto n = pointCount();
        if (!n)
            return n.error();
        auto a = in.address();
        if (!a)
            return a.error();
        request = command == Command::ReadEnableFlags ? Request::readEnableFlags(station, *a, *n)
                                                      : Request::readDiscretes(station, *a, *n);
        break;
    }
    case Command::WriteDiscretes: {
        auto n = pointCount();
        if (!n)
            return n.error();
        auto a = in.address();
        if (!a)
            return a.error();
        if (!isDiscrete(a->type))
            return queryError(4, "Write discretes needs a discrete, not " + a->toString() + ".");
        auto values = in.values(a->type, *n);
        if (!values)
            return values.error();
        request = Request::writeDiscretes(station, *a, std::move(values).value());
        break;
    }
    case Command::ReadRegisters: {
        auto n = in.hex(2, 4, "Number of registers");
        if (!n)
            return n.error();
        auto a = in.address();
        if (!a)
            return a.error();
        request = Request::readRegisters(station, *a, *n);
        break;
    }
    case Command::WriteRegisters: {
        auto n = in.hex(2, 4, "Number of registers");
        if (!n)
            return n.error();
        auto a = in.address();
        if (!a)
            return a.error();
        if (!isRegister(a->type))
            return queryError(4, "Write registers needs a register, not " + a->toString() + ".");
        if (*n == 0 || *n > Limits::maxRegisterWords)
            return queryError(4, "Write registers: " + std::to_string(*n)
                                     + " registers is out of 1..64.");
        auto values = in.values(a->type, *n);
        if (!values)
            return values.error();
        request = Request::writeRegisters(station, *a, std::move(values).value());
        break;
    }
    case Command::MixedRead:
    case Command::MixedWrite: {
        auto n = in.hex(2, 4, "Number of elements");
        if (!n)
            return n.error();
        if (*n == 0)
            return queryError(4, "Mixed read/write of 0 elements.");
        std::vector<Address> addresses;
        std::vector<std::uint32_t> values;
        for (std::uint32_t i = 0; i < *n; ++i) {
            auto a = in.address();
            if (!a)
                return a.error();
            addresses.push_back(*a);
            if (command == Command::MixedWrite) {
                auto v = in.value(a->type);
                if (!v)
                    return v.error();
                values.push_back(*v);
            }
        }
        request = command == Command::MixedRead
                      ? Request::mixedRead(station, std::move(addresses))
                      : Request::mixedWrite(station, std::move(addresses), std::move(values));
        break;
    }
    case Command::Loopback: {
        Bytes bytes;
        for (char c : data)
            bytes.push_back(static_cast<std::uint8_t>(c));
        request = Request::loopback(station, std::move(bytes));
        in = Reader({});
        break;
    }
    case Command::ReadProgram:
    case Command::WriteProgram: {
        auto page = in.hex(4, 4, "Program page number");
        if (!page)
            return page.error();
        if (command == Command::ReadProgram) {
            request = Request::readProgram(station, static_cast<std::uint16_t>(*page));
            break;
        }
        std::vector<std::uint32_t> words;
        for (std::uint32_t i = 0; i < Limits::programPageWords; ++i) {
            auto w = in.hex(4, 2, "Program word");
            if (!w)
                return w.error();
            words.push_back(*w);
        }
        request
            = Request::writeProgram(station, static_cast<std::uint16_t>(*page), std::move(words));
        break;
    }
    }
    if (!in.atEnd()) {
        return queryError(4, "Query " + hex2(static_cast<std::uint32_t>(command)) + " has "
                                 + std::to_string(in.remaining())
                                 + " unexpected characters at the end (\""
                                 + printable(in.rest(), 16) + "\").");
    }
    if (Status s = validateRequest(request, Protocol::Facon); !s)
        return makeError(s.error().kind, s.error().message, codeForValidation(s.error()));
    return request;
}

std::string queryDetails(const Request &r)
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
    case Command::RunStop: return r.run ? ": RUN" : ": STOP";
    case Command::DiscreteControl:
        return ": " + std::string(discreteOpName(r.op)) + " " + r.start.toFaconString();
    case Command::ReadEnableFlags:
    case Command::ReadDiscretes:
    case Command::ReadRegisters:
        return ": " + std::to_string(r.count) + " x " + r.start.toFaconString();
    case Command::WriteDiscretes:
    case Command::WriteRegisters:
        return ": " + std::to_string(r.values.size()) + " x " + r.start.toFaconString() + " ="
               + (isDiscrete(r.start.type) ? " " : "") + listValues(r.start, r.values);
    case Command::MixedRead:
    case Command::MixedWrite: {
        std::string s = ": " + std::to_string(r.addresses.size()) + " elements";
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
        return s;
    }
    case Command::Loopback:
        return ": " + std::to_string(r.data.size()) + " chars \""
               + printable(
                   std::string_view(reinterpret_cast<const char *>(r.data.data()), r.data.size()),
                   32)
               + "\"";
    case Command::ReadProgram: return ": page " + std::to_string(r.page);
    case Command::WriteProgram: return ": page " + std::to_string(r.page) + ", 64 words";
    }
    return {};
}

// Decoded answer data for the master: everything after the error digit.
Result<Response> decodeAnswerData(const Request &request, std::string_view data, Response response)
{
    auto malformed = [&request](std::string message) {
        return makeError(ErrorKind::MalformedResponse,
                         "Answer to " + request.describe() + ": " + std::move(message));
    };
    auto expectLength = [&](std::size_t expected, std::string_view what) -> Status {
        if (data.size() != expected) {
            return malformed("expected " + std::to_string(expected) + " data characters ("
                             + std::string(what) + "), got " + std::to_string(data.size()) + ".");
        }
        return Ok{};
    };
    auto hexBytes = [&](std::string_view text) -> Status {
        for (std::size_t i = 0; i + 1 < text.size(); i += 2) {
            const auto b = parseHex(text.substr(i, 2));
            if (!b)
                return malformed("status byte \"" + printable(text.substr(i, 2), 2)
                                 + "\" is not hex.");
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
                return malformed("discrete status \"" + printable(field, 1) + "\" is not 0 or 1.");
            return static_cast<std::uint32_t>(field[0] - '0');
        }
        const auto v = parseHex(field);
        if (!v)
            return malformed("value \"" + printable(field, n) + "\" is not hex.");
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
            return malformed("status bytes have an odd number of hex characters ("
                             + std::to_string(data.size()) + ").");
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
                         request.describe() + ": " + std::to_string(body.size() - 4)
                             + " data characters; a FACON frame carries at most 500.");
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
        return makeError(ErrorKind::StationMismatch,
                         "Answer from station " + std::to_string(f.station) + " while station "
                             + std::to_string(request.station) + " was asked (" + request.describe()
                             + ").");
    }
    if (f.command != static_cast<std::uint8_t>(request.command)) {
        return makeError(ErrorKind::CommandMismatch,
                         "Answer to command " + hex2(f.command) + " while "
                             + hex2(static_cast<std::uint8_t>(request.command)) + " ("
                             + std::string(commandName(request.command)) + ") was sent.");
    }
    Response response;
    response.station = f.station;
    response.command = request.command;
    if (request.command == Command::Loopback) {
        // The only answer without an error digit: the test data comes back as sent.
        const std::string_view sent(reinterpret_cast<const char *>(request.data.data()),
                                    request.data.size());
        if (f.data != sent) {
            return makeError(ErrorKind::MalformedResponse,
                             "Loopback data differs: sent \"" + printable(sent, 32)
                                 + "\", received \"" + printable(f.data, 32) + "\".");
        }
        response.data.assign(request.data.begin(), request.data.end());
        return response;
    }
    if (f.data.empty()) {
        return makeError(ErrorKind::MalformedResponse,
                         "Answer to " + request.describe() + " has no error digit.");
    }
    const auto code = hexValue(f.data[0]);
    if (!code) {
        return makeError(ErrorKind::MalformedResponse,
                         "Answer to " + request.describe() + ": error digit \""
                             + printable(f.data.substr(0, 1), 1) + "\" is not hex.");
    }
    if (*code != 0)
        return makePlcError(static_cast<int>(*code), request.target());
    return decodeAnswerData(request, f.data.substr(1), std::move(response));
}

Result<Request> FaconCodec::decodeRequest(std::span<const std::uint8_t> frame) const
{
    auto parsed = parseFrame(frame);
    if (!parsed)
        return parsed.error(); // plcCode 0: a broken frame gets no answer
    const ParsedFrame &f = *parsed;
    if (!isKnownCommand(f.command)) {
        return makeError(ErrorKind::Unsupported, "Unknown FACON command " + hex2(f.command) + ".",
                         4);
    }
    return parseQuery(f.station, static_cast<Command>(f.command), f.data);
}

Bytes FaconCodec::encodeResponse(const Request &request, const Response &response) const
{
    std::string body = headerText(request.station, static_cast<std::uint8_t>(request.command));
    if (request.command == Command::Loopback && response.errorCode == 0) {
        const Bytes &echo = response.data.empty() ? request.data : response.data;
        for (std::uint8_t b : echo)
            body += static_cast<char>(b);
        return frameOf(body);
    }
    appendHex(body, response.errorCode, 1);
    if (response.errorCode != 0)
        return frameOf(body);
    switch (request.command) {
    case Command::BriefStatus:
    case Command::DetailStatus:
        for (std::uint8_t b : response.data)
            appendHex(body, b, 2);
        break;
    case Command::ReadEnableFlags:
    case Command::ReadDiscretes:
    case Command::ReadRegisters:
        for (std::uint32_t v : response.values)
            appendValue(body, request.start.type, v);
        break;
    case Command::MixedRead:
        for (std::size_t i = 0; i < response.values.size() && i < request.addresses.size(); ++i)
            appendValue(body, request.addresses[i].type, response.values[i]);
        break;
    case Command::ReadProgram:
        for (std::uint32_t w : response.values)
            appendHex(body, w, 4);
        break;
    default: break;
    }
    return frameOf(body);
}

Bytes FaconCodec::encodeErrorResponse(FrameHeader header, std::uint8_t errorCode) const
{
    std::string body = headerText(header.station, header.command);
    appendHex(body, errorCode, 1);
    return frameOf(body);
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

std::string FaconCodec::summarize(std::span<const std::uint8_t> frame) const
{
    auto parsed = parseFrame(frame);
    if (!parsed) {
        return "invalid FACON frame (" + std::to_string(frame.size())
               + " bytes): " + parsed.error().message;
    }
    const ParsedFrame &f = *parsed;
    const std::string head = "station " + std::to_string(f.station) + ", " + hex2(f.command);
    if (!isKnownCommand(f.command))
        return head + " unknown command, data \"" + printable(f.data, 40) + "\"";
    const auto command = static_cast<Command>(f.command);
    const std::string name = head + " " + std::string(commandName(command));

    // FACON queries and answers share one format; a frame that parses as a query is shown as one.
    // 41 "0" is both STOP and "no error": say so rather than guess.
    if (command == Command::RunStop && f.data == "0")
        return name + ": STOP, or answer: no error";
    if (command == Command::Loopback)
        return name + ": " + std::to_string(f.data.size()) + " chars \"" + printable(f.data, 32)
               + "\"";
    if (auto query = parseQuery(f.station, command, f.data))
        return name + queryDetails(*query);

    const std::string answer = head + " answer: ";
    if (f.data.empty())
        return answer + "no error digit";
    const auto code = hexValue(f.data[0]);
    if (!code)
        return answer + "malformed \"" + printable(f.data, 40) + "\"";
    if (*code != 0) {
        return answer + "error " + std::string(1, kHexDigits[*code]) + " ("
               + std::string(plcErrorText(static_cast<int>(*code))) + ")";
    }
    if (f.data.size() == 1)
        return answer + "OK";
    return answer + "OK, " + std::to_string(f.data.size() - 1) + " data chars \""
           + printable(f.data.substr(1), 40) + "\"";
}

} // namespace Fatek
