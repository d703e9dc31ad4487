#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

namespace Fatek {

// Every element type of the reference. The order groups by width; do not rely on values.
enum class ElementType : std::uint8_t {
    // discretes
    X,
    Y,
    M,
    S,
    T,
    C,
    // 16-bit views over 16 discretes
    WX,
    WY,
    WM,
    WS,
    WT,
    WC,
    // 16-bit registers
    RT,
    RC,
    R,
    D,
    F,
    // 32-bit views over 32 discretes
    DWX,
    DWY,
    DWM,
    DWS,
    DWT,
    DWC,
    // 32-bit registers: DRn = R(n+1):R(n)
    DRT,
    DRC,
    DR,
    DD,
    DF,
};

enum class ElementWidth : std::uint8_t { Bit, Word, DoubleWord };

struct ElementInfo
{
    ElementType type;
    std::string_view symbol; // "DWM"; also its ASCII code in the binary protocol
    std::string_view name;   // "internal relay (32-bit view)"
    ElementWidth width;
    std::optional<ElementType> discrete; // W/DW types: the discretes they view
    std::optional<ElementType> word;     // DR types: the 16-bit register they pair
    std::uint32_t maxNumber;             // highest valid number on the largest model
    std::uint32_t step;                  // numbers between two consecutive elements (WY0, WY16: 16)
    std::uint32_t alignment;             // start must be a multiple of this (8 for W/DW, else 1)
    int faconDigits;                     // digits of the fixed-width FACON address; 0: not in FACON
};

const ElementInfo &elementInfo(ElementType type);
std::span<const ElementInfo> allElements();

// Exact symbol, case-insensitive ("dwm" -> DWM).
std::optional<ElementType> elementTypeFromSymbol(std::string_view symbol);

inline bool isDiscrete(ElementType t)
{
    return elementInfo(t).width == ElementWidth::Bit;
}
inline bool isRegister(ElementType t)
{
    return !isDiscrete(t);
}
inline bool isDoubleWord(ElementType t)
{
    return elementInfo(t).width == ElementWidth::DoubleWord;
}
// Words an element occupies in the 46/47/48/49 limits: 1 for discretes and 16-bit, 2 for 32-bit.
inline int wordCount(ElementType t)
{
    return isDoubleWord(t) ? 2 : 1;
}

} // namespace Fatek
