#pragma once

#include "deframer.h"

namespace Fatek {

// 0x51/0x52 0x10 len payload CRC 55 AA frames. A master expects responses (0x52), a slave
// (the simulator) queries (0x51); the other header is garbage, so a 2-wire RS-485 echo of our
// own query is never taken for an answer.
class BinaryDeframer final : public Deframer
{
public:
    enum class Direction { Query, Response };

    explicit BinaryDeframer(Direction expect = Direction::Response);

    void feed(std::span<const std::uint8_t> bytes, std::vector<DeframedItem> &out) override;
    void reset() override;
    std::size_t bufferedBytes() const override { return m_buffer.size(); }
    std::size_t discardedBytes() const override { return m_discarded; }
    std::size_t maxFrameSize() const override;

private:
    void scan(std::vector<DeframedItem> &out);
    void dropHeaderByte();
    // Drops `count` bytes from the front as garbage.
    void consume(std::size_t count);

    Direction m_expect;
    Bytes m_buffer; // empty, or starts with the expected header
    std::size_t m_discarded = 0;
    std::size_t m_reported = 0; // front bytes already delivered in a rejected item, being rescanned
};

} // namespace Fatek
