#include "binarydeframer.h"

#include "binarycodec.h"

#include <algorithm>

namespace Fatek {

namespace {
constexpr std::size_t kHeadSize = 4; // header, ID, length (2)
constexpr std::size_t kTailSize = 4; // CRC (2), terminator (2)
} // namespace

BinaryDeframer::BinaryDeframer(Direction expect)
    : m_expect(expect)
{}

std::size_t BinaryDeframer::maxFrameSize() const
{
    return BinaryCodec::maxFrameSize;
}

void BinaryDeframer::reset()
{
    // A dropped partial frame was never delivered: count it as skipped.
    consume(m_buffer.size());
}

void BinaryDeframer::feed(std::span<const std::uint8_t> bytes, std::vector<DeframedItem> &out)
{
    // Append in pieces so the buffer never grows past one frame, even for a huge chunk: after
    // scan() it holds less than a complete frame, so there is always room for one more byte.
    while (!bytes.empty()) {
        const std::size_t room = maxFrameSize() - m_buffer.size();
        const std::size_t take = std::min(room, bytes.size());
        m_buffer.insert(m_buffer.end(), bytes.begin(),
                        bytes.begin() + static_cast<std::ptrdiff_t>(take));
        bytes = bytes.subspan(take);
        scan(out);
    }
}

void BinaryDeframer::scan(std::vector<DeframedItem> &out)
{
    const std::uint8_t header
        = m_expect == Direction::Query ? BinaryCodec::queryHeader : BinaryCodec::responseHeader;
    for (;;) {
        // Skip garbage up to the next header byte.
        const auto start = std::find(m_buffer.begin(), m_buffer.end(), header);
        consume(static_cast<std::size_t>(start - m_buffer.begin()));
        if (m_buffer.empty())
            return;

        // A header byte followed by a wrong ID or an impossible length is garbage that happens to
        // contain 0x51/0x52: drop that byte only, the next real frame may start right after it.
        if (m_buffer.size() >= 2 && m_buffer[1] != BinaryCodec::frameId) {
            dropHeaderByte();
            continue;
        }
        if (m_buffer.size() < kHeadSize)
            return;
        const std::size_t length = (static_cast<std::size_t>(m_buffer[2]) << 8) | m_buffer[3];
        if (length < 2 || length > BinaryCodec::maxPayload) {
            dropHeaderByte();
            continue;
        }
        const std::size_t total = kHeadSize + length + kTailSize;
        if (m_buffer.size() < total)
            return;

        const std::span<const std::uint8_t> frame(m_buffer.data(), total);
        DeframedItem item;
        item.frame.assign(frame.begin(), frame.end());
        if (frame[total - 2] != BinaryCodec::terminator[0]
            || frame[total - 1] != BinaryCodec::terminator[1]) {
            item.error = makeError(ErrorKind::BadFrame, msg<MsgId::BinaryFrameNoTerminator>(total));
        } else {
            const std::uint16_t expected = BinaryCodec::crc16(frame.subspan(2, length + 2));
            const auto got = static_cast<std::uint16_t>(frame[kHeadSize + length]
                                                        | (frame[kHeadSize + length + 1] << 8));
            if (got != expected) {
                item.error
                    = makeError(ErrorKind::BadChecksum, msg<MsgId::BinaryFrameWrongCrc>(total));
            }
        }
        const bool rejected = item.error.has_value();
        out.push_back(std::move(item));
        if (rejected) {
            // The length may have been garbage and swallowed the next real frame: rescan from the
            // byte after the rejected header. Those bytes were reported in the rejected item, so
            // they do not count as skipped garbage again.
            m_buffer.erase(m_buffer.begin());
            m_reported = std::max(m_reported - std::min(m_reported, std::size_t(1)), total - 1);
        } else {
            m_reported -= std::min(m_reported, total);
            m_buffer.erase(m_buffer.begin(), m_buffer.begin() + static_cast<std::ptrdiff_t>(total));
        }
    }
}

void BinaryDeframer::dropHeaderByte()
{
    consume(1);
}

void BinaryDeframer::consume(std::size_t count)
{
    const std::size_t alreadyReported = std::min(m_reported, count);
    m_reported -= alreadyReported;
    m_discarded += count - alreadyReported;
    m_buffer.erase(m_buffer.begin(), m_buffer.begin() + static_cast<std::ptrdiff_t>(count));
}

} // namespace Fatek
