// Address::parse on arbitrary text: never crashes, and whatever it accepts formats back to itself.
#include "core/protocol/address.h"

#include <cstdlib>
#include <string_view>

using namespace Fatek;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    const std::string_view text(reinterpret_cast<const char *>(data), size);
    const auto parsed = Address::parse(text);
    if (!parsed.ok())
        return 0;
    const auto again = Address::parse(parsed->toString());
    if (!again.ok() || *again != *parsed)
        std::abort();
    if (!validateAddress(*parsed).ok())
        std::abort();
    return 0;
}
