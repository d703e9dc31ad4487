#include "address.h"

#include "textscan.h"

#include <cctype>

namespace Fatek {

std::string Address::toString() const
{
    return std::string(info().symbol) + std::to_string(number);
}

std::string Address::toFaconString() const
{
    const ElementInfo &i = info();
    if (i.faconDigits == 0)
        return {};
    std::string digits = std::to_string(number);
    if (digits.size() < static_cast<std::size_t>(i.faconDigits))
        digits.insert(0, static_cast<std::size_t>(i.faconDigits) - digits.size(), '0');
    return std::string(i.symbol) + digits;
}

Result<Address> Address::parse(std::string_view text)
{
    text = TextScan::trimmed(text);
    const std::string shown(text);
    if (text.empty())
        return makeError(ErrorKind::InvalidAddress, msg<MsgId::AddressEmpty>());

    std::size_t split = 0;
    while (split < text.size() && std::isalpha(static_cast<unsigned char>(text[split])))
        ++split;
    const std::string_view symbol = text.substr(0, split);
    const std::string_view digits = text.substr(split);
    if (symbol.empty()) {
        return makeError(ErrorKind::InvalidAddress, msg<MsgId::AddressNoType>(shown));
    }
    const auto type = elementTypeFromSymbol(symbol);
    if (!type) {
        return makeError(
            ErrorKind::InvalidAddress,
            msg<MsgId::AddressUnknownType>(
                shown, symbol, "X Y M S T C, WX..WC, RT RC R D F, DWX..DWC, DRT DRC DR DD DF"));
    }
    if (digits.empty()) {
        return makeError(
            ErrorKind::InvalidAddress,
            msg<MsgId::AddressNoNumber>(shown, std::string(elementInfo(*type).symbol) + "0"));
    }
    std::uint64_t number = 0;
    for (char c : digits) {
        if (!std::isdigit(static_cast<unsigned char>(c))) {
            return makeError(ErrorKind::InvalidAddress,
                             msg<MsgId::AddressNotDecimal>(shown, digits));
        }
        number = number * 10 + static_cast<std::uint64_t>(c - '0');
        if (number > 0xFFFFFFFFu) {
            return makeError(ErrorKind::InvalidAddress, msg<MsgId::AddressNumberTooLarge>(shown));
        }
    }
    Address address{*type, static_cast<std::uint32_t>(number)};
    if (Status s = validateAddress(address); !s)
        return s.error();
    return address;
}

Status validateAddress(const Address &address)
{
    const ElementInfo &i = address.info();
    if (address.number > i.maxNumber) {
        return makeError(ErrorKind::InvalidAddress,
                         msg<MsgId::AddressOutOfRange>(address.toString(), i.symbol, i.maxNumber));
    }
    if (address.number % i.alignment != 0) {
        return makeError(ErrorKind::InvalidAddress,
                         msg<MsgId::AddressNotAligned>(
                             address.toString(), i.symbol, i.alignment,
                             std::string(i.symbol)
                                 + std::to_string(address.number / i.alignment * i.alignment)));
    }
    return Ok{};
}

Status validateSpan(const Address &start, std::uint32_t count)
{
    if (Status s = validateAddress(start); !s)
        return s;
    if (count == 0)
        return Ok{};
    const ElementInfo &i = start.info();
    const std::uint64_t last = std::uint64_t(start.number) + std::uint64_t(count - 1) * i.step;
    if (last > i.maxNumber) {
        return makeError(ErrorKind::InvalidAddress,
                         msg<MsgId::AddressRunPast>(
                             count, start.toString(),
                             std::string(i.symbol) + std::to_string(i.maxNumber), i.symbol));
    }
    return Ok{};
}

} // namespace Fatek
