#pragma once

#include "deframer.h"

namespace Fatek {

// STX ... ETX frames; checks LRC and hex characters of station, command and LRC.
class FaconDeframer final : public Deframer
{
public:
    void feed(std::span<const std::uint8_t> bytes, std::vector<DeframedItem> &out) override;
    void reset() override;
    std::size_t bufferedBytes() const override { return m_buffer.size(); }
    std::size_t discardedBytes() const override { return m_discarded; }
    std::size_t maxFrameSize() const override;

private:
    Bytes m_buffer; // empty, or starts with STX
    std::size_t m_discarded = 0;
};

} // namespace Fatek
