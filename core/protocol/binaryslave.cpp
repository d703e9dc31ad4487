#include "binaryslave.h"

#include "binarycodec.h"
#include "binarywire.h"

#include <algorithm>

namespace Fatek {

using namespace BinaryWire;

namespace {

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

} // namespace

Result<Request> BinarySlave::parseQueryPayload(std::span<const std::uint8_t> p)
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

Result<Request> BinaryCodec::decodeRequest(std::span<const std::uint8_t> frame) const
{
    auto parsed = parseFrame(frame);
    if (!parsed)
        return parsed.error(); // plcCode 0: a broken frame gets no answer
    if (parsed->header != queryHeader) {
        return makeError(ErrorKind::BadFrame,
                         "Frame starts with 52 (an answer), not 51 (a query).");
    }
    auto request = BinarySlave::parseQueryPayload(parsed->payload);
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

} // namespace Fatek
