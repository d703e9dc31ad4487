#include "writerequest.h"

namespace Fatek {

Request makeWriteRequest(const WatchItemSpec &item, std::uint64_t raw)
{
    if (isDiscrete(item.address.type))
        return Request::writeDiscretes(item.station, item.address,
                                       {static_cast<std::uint32_t>(raw & 1u)});
    const int count = std::max(1, ValueFormat::elementCount(item.address, item.format));
    const int bits = isDoubleWord(item.address.type) ? 32 : 16;
    const std::uint64_t mask = bits == 32 ? 0xFFFFFFFFull : 0xFFFFull;
    std::vector<std::uint32_t> values;
    for (int i = 0; i < count; ++i)
        values.push_back(static_cast<std::uint32_t>((raw >> (i * bits)) & mask));
    return Request::writeRegisters(item.station, item.address, std::move(values));
}

} // namespace Fatek
