#include "element.h"

#include <array>
#include <cctype>

namespace Fatek {

namespace {

using E = ElementType;
using W = ElementWidth;
constexpr std::optional<ElementType> none = std::nullopt;

constexpr std::array<ElementInfo, 28> kElements = {{
    {E::X, "X", "input", W::Bit, none, none, 9999, 1, 1, 4},
    {E::Y, "Y", "output relay", W::Bit, none, none, 9999, 1, 1, 4},
    {E::M, "M", "internal relay", W::Bit, none, none, 9999, 1, 1, 4},
    {E::S, "S", "step relay", W::Bit, none, none, 9999, 1, 1, 4},
    {E::T, "T", "timer contact", W::Bit, none, none, 9999, 1, 1, 4},
    {E::C, "C", "counter contact", W::Bit, none, none, 9999, 1, 1, 4},
    {E::WX, "WX", "inputs as 16-bit word", W::Word, E::X, none, 9984, 16, 8, 4},
    {E::WY, "WY", "outputs as 16-bit word", W::Word, E::Y, none, 9984, 16, 8, 4},
    {E::WM, "WM", "internal relays as 16-bit word", W::Word, E::M, none, 9984, 16, 8, 4},
    {E::WS, "WS", "step relays as 16-bit word", W::Word, E::S, none, 9984, 16, 8, 4},
    {E::WT, "WT", "timer contacts as 16-bit word", W::Word, E::T, none, 9984, 16, 8, 4},
    {E::WC, "WC", "counter contacts as 16-bit word", W::Word, E::C, none, 9984, 16, 8, 4},
    {E::RT, "RT", "timer register", W::Word, none, none, 9999, 1, 1, 4},
    {E::RC, "RC", "counter register", W::Word, none, none, 9999, 1, 1, 4},
    {E::R, "R", "data register", W::Word, none, none, 65535, 1, 1, 5},
    {E::D, "D", "data register", W::Word, none, none, 65535, 1, 1, 5},
    {E::F, "F", "file register", W::Word, none, none, 65535, 1, 1, 0},
    {E::DWX, "DWX", "inputs as 32-bit word", W::DoubleWord, E::X, none, 9968, 32, 8, 4},
    {E::DWY, "DWY", "outputs as 32-bit word", W::DoubleWord, E::Y, none, 9968, 32, 8, 4},
    {E::DWM, "DWM", "internal relays as 32-bit word", W::DoubleWord, E::M, none, 9968, 32, 8, 4},
    {E::DWS, "DWS", "step relays as 32-bit word", W::DoubleWord, E::S, none, 9968, 32, 8, 4},
    {E::DWT, "DWT", "timer contacts as 32-bit word", W::DoubleWord, E::T, none, 9968, 32, 8, 4},
    {E::DWC, "DWC", "counter contacts as 32-bit word", W::DoubleWord, E::C, none, 9968, 32, 8, 4},
    {E::DRT, "DRT", "timer register pair", W::DoubleWord, none, E::RT, 9998, 2, 1, 4},
    {E::DRC, "DRC", "counter register pair", W::DoubleWord, none, E::RC, 9998, 2, 1, 4},
    {E::DR, "DR", "data register pair", W::DoubleWord, none, E::R, 65534, 2, 1, 5},
    {E::DD, "DD", "data register pair", W::DoubleWord, none, E::D, 65534, 2, 1, 5},
    {E::DF, "DF", "file register pair", W::DoubleWord, none, E::F, 65534, 2, 1, 0},
}};

constexpr bool tableInEnumOrder()
{
    for (std::size_t i = 0; i < kElements.size(); ++i) {
        if (static_cast<std::size_t>(kElements[i].type) != i)
            return false;
    }
    return true;
}
static_assert(tableInEnumOrder(), "kElements must follow the order of ElementType");

} // namespace

const ElementInfo &elementInfo(ElementType type)
{
    return kElements[static_cast<std::size_t>(type)];
}

std::span<const ElementInfo> allElements()
{
    return kElements;
}

std::optional<ElementType> elementTypeFromSymbol(std::string_view symbol)
{
    for (const ElementInfo &info : kElements) {
        if (info.symbol.size() != symbol.size())
            continue;
        bool same = true;
        for (std::size_t i = 0; i < symbol.size() && same; ++i) {
            same = std::toupper(static_cast<unsigned char>(symbol[i])) == info.symbol[i];
        }
        if (same)
            return info.type;
    }
    return std::nullopt;
}

} // namespace Fatek
