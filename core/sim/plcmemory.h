#pragma once

#include "core/protocol/address.h"
#include "modelprofile.h"

#include <array>
#include <cstdint>
#include <vector>

namespace Fatek {

// The element memory of one PLC, sized by its profile. Discretes carry a value and a disable
// (force) flag; W/DW are computed views over the discretes (bit 0 = lowest point) and DRn is
// R(n+1):R(n). Not thread-safe: SimulatedPlc serialises access.
class PlcMemory
{
public:
    explicit PlcMemory(const ModelProfile &profile);

    const ModelProfile &profile() const { return m_profile; }

    // Whether `count` elements from `start` exist on this model (and the start is aligned).
    bool contains(const Address &start, std::uint32_t count = 1) const
    {
        return m_profile.contains(start, count);
    }

    // Value of any element type. Precondition: contains(address).
    std::uint32_t read(const Address &address) const;
    // Write as the master does: reaches disabled discretes too. Precondition: contains(address).
    void write(const Address &address, std::uint32_t value);
    // Write as the ladder does: a disabled discrete keeps its value.
    void writeFromLadder(const Address &address, std::uint32_t value);

    // Plain discretes (X..C). Precondition: contains({type, number}).
    bool bit(ElementType type, std::uint32_t number) const;
    bool isDisabled(ElementType type, std::uint32_t number) const;
    void setDisabled(ElementType type, std::uint32_t number, bool disabled);

    // Every value and flag back to 0. Only the kinds written since the last clear() are zeroed
    // (the fuzzer clears a PLC for every input; M-series memory is about half a megabyte).
    void clear();

private:
    static constexpr std::uint8_t valueBit = 0x01;
    static constexpr std::uint8_t disabledBit = 0x02;

    std::uint8_t &cell(ElementType type, std::uint32_t number);
    std::uint8_t cell(ElementType type, std::uint32_t number) const;
    std::uint16_t &word(ElementType type, std::uint32_t number);
    std::uint16_t word(ElementType type, std::uint32_t number) const;
    void setBit(ElementType type, std::uint32_t number, bool on, bool fromLadder);
    void writeAny(const Address &address, std::uint32_t value, bool fromLadder);

    ModelProfile m_profile;
    std::array<std::vector<std::uint8_t>, 6> m_discretes;  // X Y M S T C
    std::array<std::vector<std::uint16_t>, 5> m_registers; // RT RC R D F
    // Whether a kind may hold a non-zero value or flag: set by every mutable access.
    std::array<bool, 6> m_discretesDirty{};
    std::array<bool, 5> m_registersDirty{};
};

} // namespace Fatek
