#include "plcmemory.h"

#include <algorithm>
#include <cassert>
#include <cstring>

namespace Fatek {

namespace {

std::size_t discreteSlot(ElementType t)
{
    const auto i = static_cast<std::size_t>(t) - static_cast<std::size_t>(ElementType::X);
    assert(i < 6);
    return i;
}

std::size_t registerSlot(ElementType t)
{
    const auto i = static_cast<std::size_t>(t) - static_cast<std::size_t>(ElementType::RT);
    assert(i < 5);
    return i;
}

constexpr std::array<ElementType, 6> kDiscretes = {ElementType::X, ElementType::Y, ElementType::M,
                                                   ElementType::S, ElementType::T, ElementType::C};
constexpr std::array<ElementType, 5> kRegisters
    = {ElementType::RT, ElementType::RC, ElementType::R, ElementType::D, ElementType::F};

// memset rather than std::fill: the fuzz build instruments every comparison of an inlined fill
// loop, which made zeroing 65536 registers cost more than the rest of a fuzz input.
template<typename T>
void zero(std::vector<T> &v)
{
    if (!v.empty())
        std::memset(v.data(), 0, v.size() * sizeof(T));
}

} // namespace

PlcMemory::PlcMemory(const ModelProfile &profile)
    : m_profile(profile)
{
    for (ElementType t : kDiscretes)
        m_discretes[discreteSlot(t)].assign(m_profile.size(t), 0);
    for (ElementType t : kRegisters)
        m_registers[registerSlot(t)].assign(m_profile.size(t), 0);
}

void PlcMemory::clear()
{
    for (std::size_t i = 0; i < m_discretes.size(); ++i) {
        if (m_discretesDirty[i])
            zero(m_discretes[i]);
        m_discretesDirty[i] = false;
    }
    for (std::size_t i = 0; i < m_registers.size(); ++i) {
        if (m_registersDirty[i])
            zero(m_registers[i]);
        m_registersDirty[i] = false;
    }
}

std::uint8_t &PlcMemory::cell(ElementType type, std::uint32_t number)
{
    const std::size_t slot = discreteSlot(type);
    m_discretesDirty[slot] = true;
    return m_discretes[slot].at(number);
}

std::uint8_t PlcMemory::cell(ElementType type, std::uint32_t number) const
{
    return m_discretes[discreteSlot(type)].at(number);
}

std::uint16_t &PlcMemory::word(ElementType type, std::uint32_t number)
{
    const std::size_t slot = registerSlot(type);
    m_registersDirty[slot] = true;
    return m_registers[slot].at(number);
}

std::uint16_t PlcMemory::word(ElementType type, std::uint32_t number) const
{
    return m_registers[registerSlot(type)].at(number);
}

bool PlcMemory::bit(ElementType type, std::uint32_t number) const
{
    return (cell(type, number) & valueBit) != 0;
}

bool PlcMemory::isDisabled(ElementType type, std::uint32_t number) const
{
    return (cell(type, number) & disabledBit) != 0;
}

void PlcMemory::setDisabled(ElementType type, std::uint32_t number, bool disabled)
{
    std::uint8_t &c = cell(type, number);
    c = static_cast<std::uint8_t>(disabled ? (c | disabledBit) : (c & ~disabledBit));
}

void PlcMemory::setBit(ElementType type, std::uint32_t number, bool on, bool fromLadder)
{
    std::uint8_t &c = cell(type, number);
    if (fromLadder && (c & disabledBit))
        return; // forced: only the master changes it
    c = static_cast<std::uint8_t>(on ? (c | valueBit) : (c & ~valueBit));
}

std::uint32_t PlcMemory::read(const Address &a) const
{
    const ElementInfo &info = a.info();
    if (info.discrete) {
        const std::uint32_t bits = info.width == ElementWidth::DoubleWord ? 32 : 16;
        std::uint32_t v = 0;
        for (std::uint32_t i = 0; i < bits; ++i) {
            if (bit(*info.discrete, a.number + i))
                v |= 1u << i;
        }
        return v;
    }
    if (info.word) {
        return (std::uint32_t{word(*info.word, a.number + 1)} << 16) | word(*info.word, a.number);
    }
    if (info.width == ElementWidth::Bit)
        return bit(a.type, a.number) ? 1 : 0;
    return word(a.type, a.number);
}

void PlcMemory::writeAny(const Address &a, std::uint32_t value, bool fromLadder)
{
    const ElementInfo &info = a.info();
    if (info.discrete) {
        const std::uint32_t bits = info.width == ElementWidth::DoubleWord ? 32 : 16;
        for (std::uint32_t i = 0; i < bits; ++i)
            setBit(*info.discrete, a.number + i, (value >> i) & 1u, fromLadder);
        return;
    }
    if (info.word) {
        word(*info.word, a.number) = static_cast<std::uint16_t>(value & 0xFFFFu);
        word(*info.word, a.number + 1) = static_cast<std::uint16_t>(value >> 16);
        return;
    }
    if (info.width == ElementWidth::Bit) {
        setBit(a.type, a.number, value != 0, fromLadder);
        return;
    }
    word(a.type, a.number) = static_cast<std::uint16_t>(value & 0xFFFFu);
}

void PlcMemory::write(const Address &address, std::uint32_t value)
{
    writeAny(address, value, false);
}

void PlcMemory::writeFromLadder(const Address &address, std::uint32_t value)
{
    writeAny(address, value, true);
}

} // namespace Fatek
