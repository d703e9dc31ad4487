#include "plcmodel.h"

#include "addressrange.h"

#include <limits>

namespace Fatek {

namespace {

std::optional<std::size_t> discreteIndex(ElementType t)
{
    switch (t) {
    case ElementType::X: return 0;
    case ElementType::Y: return 1;
    case ElementType::M: return 2;
    case ElementType::S: return 3;
    case ElementType::T: return 4;
    case ElementType::C: return 5;
    default: return std::nullopt;
    }
}

std::optional<std::size_t> registerIndex(ElementType t)
{
    switch (t) {
    case ElementType::RT: return 0;
    case ElementType::RC: return 1;
    case ElementType::R: return 2;
    case ElementType::D: return 3;
    case ElementType::F: return 4;
    default: return std::nullopt;
    }
}

// A kind a Reported model has no size for: not limited (numbers end at 65535 anyway).
constexpr std::uint32_t unlimited = std::numeric_limits<std::uint32_t>::max();

} // namespace

std::uint32_t PlcModel::size(ElementType plainType) const
{
    if (auto i = discreteIndex(plainType))
        return discretes[*i];
    if (auto i = registerIndex(plainType))
        return registers[*i];
    return 0;
}

bool PlcModel::contains(const Address &start, std::uint32_t count) const
{
    if (count == 0)
        return false;
    const ElementInfo &info = start.info();
    if (start.number % info.alignment != 0)
        return false;
    // Elements of a view occupy `step` numbers of the plain kind (WY0 = Y0..Y15, DR0 = R0..R1).
    std::uint32_t plainSize = 0;
    std::uint64_t span = count;
    if (info.discrete) {
        plainSize = size(*info.discrete);
        span = std::uint64_t{count} * info.step;
    } else if (info.word) {
        plainSize = size(*info.word);
        span = std::uint64_t{count} * info.step;
    } else {
        plainSize = size(start.type);
    }
    return std::uint64_t{start.number} + span <= plainSize;
}

std::string PlcModel::rangeText(ElementType plainType) const
{
    const std::uint32_t n = size(plainType);
    if (n == 0)
        return "no " + std::string(elementInfo(plainType).symbol);
    if (n == unlimited)
        return std::string(elementInfo(plainType).symbol);
    return AddressRange{Address{plainType, 0}, n}.toString();
}

std::string PlcModel::familyName() const
{
    switch (family) {
    case Family::FBs: return "FBs series";
    case Family::M: return "M series";
    case Family::Reported: return "PLC";
    }
    return "PLC";
}

PlcModel PlcModel::fbs()
{
    PlcModel m;
    m.family = Family::FBs;
    // X Y M S T C
    m.discretes = {256, 256, 2002, 1000, 256, 256};
    // RT RC R D F: FBs has no file registers in the protocols.
    m.registers = {256, 256, 3840, 3000, 0};
    return m;
}

PlcModel PlcModel::mSeries()
{
    PlcModel m;
    m.family = Family::M;
    m.discretes = {10000, 10000, 10000, 10000, 10000, 10000};
    m.registers = {10000, 10000, 65536, 65536, 65536};
    return m;
}

std::optional<PlcModel> PlcModel::fromDetailStatus(const DetailStatus &status)
{
    if (status.mainUnitType)
        return *status.mainUnitType <= 1 ? fbs() : mSeries();
    PlcModel m;
    m.family = Family::Reported;
    m.discretes.fill(unlimited);
    m.registers.fill(unlimited);
    bool any = false;
    auto take = [&any](std::uint32_t &slot, const std::optional<std::uint16_t> &count) {
        if (count) {
            slot = *count;
            any = true;
        }
    };
    for (ElementType t : {ElementType::X, ElementType::Y, ElementType::M, ElementType::S,
                          ElementType::T, ElementType::C})
        take(m.discretes[*discreteIndex(t)], status.discreteCount(t));
    take(m.registers[*registerIndex(ElementType::R)], status.rRegisters);
    take(m.registers[*registerIndex(ElementType::D)], status.dRegisters);
    if (!any)
        return std::nullopt;
    return m;
}

std::optional<PlcModel::Family> PlcModel::familyOfText(const std::string &text)
{
    if (text.starts_with("FBs") || text.starts_with("main unit MA/MU")
        || text.starts_with("main unit MC"))
        return Family::FBs;
    // "main unit type N": a value documented for no FBs unit (an M-series PLC's 53, as snapshots
    // recorded it before they named the family).
    if (text.starts_with("M series") || text.starts_with("main unit type "))
        return Family::M;
    return std::nullopt;
}

std::string PlcModel::modelText(const DetailStatus &status)
{
    const std::optional<PlcModel> model = fromDetailStatus(status);
    if (status.modelName() || !model || model->family != Family::M)
        return status.summary();
    return status.summaryNamed(model->familyName());
}

} // namespace Fatek
