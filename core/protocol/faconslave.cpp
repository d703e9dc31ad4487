#include "faconslave.h"

#include "faconcodec.h"
#include "faconwire.h"

#include <algorithm>

namespace Fatek {

using namespace FaconWire;

namespace {

ProtocolError queryError(int code, Message message)
{
    return makeError(code == 0xA ? ErrorKind::InvalidAddress : ErrorKind::InvalidRequest,
                     std::move(message), code);
}

ProtocolError queryError(int code, std::string text)
{
    return queryError(code, Message::text(std::move(text)));
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

} // namespace

Result<Request> FaconSlave::parseQuery(std::uint8_t station, Command command, std::string_view data)
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
    return FaconSlave::parseQuery(f.station, static_cast<Command>(f.command), f.data);
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

} // namespace Fatek
