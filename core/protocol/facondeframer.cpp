#include "facondeframer.h"

#include "faconcodec.h"

#include <string>

namespace Fatek {

namespace {

bool isHexChar(std::uint8_t c)
{
    return (c >= '0' && c <= '9') || (c >= 'A' && c <= 'F') || (c >= 'a' && c <= 'f');
}

std::uint32_t hexCharValue(std::uint8_t c)
{
    if (c >= '0' && c <= '9')
        return static_cast<std::uint32_t>(c - '0');
    if (c >= 'A' && c <= 'F')
        return static_cast<std::uint32_t>(c - 'A' + 10);
    return static_cast<std::uint32_t>(c - 'a' + 10);
}

// A complete STX..ETX candidate: the reason to reject it, if any.
std::optional<ProtocolError> checkFrame(const Bytes &frame)
{
    // STX, station (2), command (2), LRC (2), ETX.
    if (frame.size() < 8) {
        return makeError(ErrorKind::BadFrame, msg<MsgId::FaconFrameTooShortLrc>(frame.size()));
    }
    for (std::size_t i = 1; i < 5; ++i) {
        if (!isHexChar(frame[i]))
            return makeError(ErrorKind::BadFrame, msg<MsgId::FaconFrameNonHexHeader>());
    }
    const std::uint8_t hi = frame[frame.size() - 3];
    const std::uint8_t lo = frame[frame.size() - 2];
    if (!isHexChar(hi) || !isHexChar(lo))
        return makeError(ErrorKind::BadFrame, msg<MsgId::FaconFrameChecksumNotHex>());
    const std::uint32_t received = hexCharValue(hi) << 4 | hexCharValue(lo);
    const std::uint8_t computed = FaconCodec::lrc(std::span(frame).first(frame.size() - 3));
    if (received != computed) {
        static constexpr char digits[] = "0123456789ABCDEF";
        return makeError(ErrorKind::BadChecksum,
                         msg<MsgId::FaconChecksumError>(
                             std::string{digits[received >> 4], digits[received & 0xF]},
                             std::string{digits[computed >> 4], digits[computed & 0xF]}));
    }
    return std::nullopt;
}

} // namespace

void FaconDeframer::feed(std::span<const std::uint8_t> bytes, std::vector<DeframedItem> &out)
{
    for (std::uint8_t b : bytes) {
        if (m_buffer.empty()) {
            // Outside a frame only STX matters; anything else is line noise.
            if (b == FaconCodec::STX)
                m_buffer.push_back(b);
            else
                ++m_discarded;
            continue;
        }
        if (b == FaconCodec::STX) {
            // A new frame starts: the sender gave up on the previous one (or we missed its ETX).
            out.push_back({std::move(m_buffer),
                           makeError(ErrorKind::BadFrame, msg<MsgId::FaconFrameNewStx>())});
            m_buffer.clear();
            m_buffer.push_back(b);
            continue;
        }
        m_buffer.push_back(b);
        if (b == FaconCodec::ETX) {
            DeframedItem item{std::move(m_buffer), std::nullopt};
            m_buffer.clear();
            item.error = checkFrame(item.frame);
            out.push_back(std::move(item));
            continue;
        }
        if (m_buffer.size() >= FaconCodec::maxFrameSize) {
            // No legal frame can still end: reject and wait for the next STX.
            out.push_back({std::move(m_buffer),
                           makeError(ErrorKind::FrameTooLong,
                                     msg<MsgId::FaconFrameNoEtx>(FaconCodec::maxFrameSize))});
            m_buffer.clear();
        }
    }
}

void FaconDeframer::reset()
{
    m_buffer.clear();
}

std::size_t FaconDeframer::maxFrameSize() const
{
    return FaconCodec::maxFrameSize;
}

} // namespace Fatek
