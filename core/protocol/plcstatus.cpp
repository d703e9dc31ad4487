#include "plcstatus.h"

namespace Fatek {

PlcStatus PlcStatus::fromStatus1(std::uint8_t s)
{
    PlcStatus p;
    p.running = s & 0x01;
    p.batteryLow = s & 0x02;
    p.ladderChecksumError = s & 0x04;
    p.memoryPack = s & 0x08;
    p.watchdogError = s & 0x10;
    p.idSet = s & 0x20;
    p.emergencyStop = s & 0x40;
    return p;
}

std::uint8_t PlcStatus::toStatus1() const
{
    return static_cast<std::uint8_t>((running ? 0x01 : 0) | (batteryLow ? 0x02 : 0)
                                     | (ladderChecksumError ? 0x04 : 0) | (memoryPack ? 0x08 : 0)
                                     | (watchdogError ? 0x10 : 0) | (idSet ? 0x20 : 0)
                                     | (emergencyStop ? 0x40 : 0));
}

DetailStatus DetailStatus::decode(std::span<const std::uint8_t> b)
{
    DetailStatus d;
    d.raw.assign(b.begin(), b.end());
    // STATUSn is b[n - 1]; 16-bit counts are high byte first.
    auto byte = [&](std::size_t n) -> std::optional<std::uint8_t> {
        if (n == 0 || n > b.size())
            return std::nullopt;
        return b[n - 1];
    };
    auto word = [&](std::size_t n) -> std::optional<std::uint16_t> {
        if (n + 1 > b.size())
            return std::nullopt;
        return static_cast<std::uint16_t>((b[n - 1] << 8) | b[n]);
    };
    if (auto s1 = byte(1))
        d.status = PlcStatus::fromStatus1(*s1);
    d.mainUnitType = byte(2);
    d.ioPointsCode = byte(3);
    d.osVersion = byte(4);
    d.ladderSize = word(5);
    d.discreteInputs = word(7);
    d.discreteOutputs = word(9);
    d.analogInputs = word(11);
    d.analogOutputs = word(13);
    d.mRelays = word(15);
    d.sRelays = word(17);
    d.lRelays = word(19);
    d.rRegisters = word(21);
    d.dRegisters = word(23);
    d.timers = word(25);
    d.counters = word(27);
    return d;
}

std::optional<std::uint16_t> DetailStatus::discreteCount(ElementType type) const
{
    switch (type) {
    case ElementType::X: return discreteInputs;
    case ElementType::Y: return discreteOutputs;
    case ElementType::M: return mRelays;
    case ElementType::S: return sRelays;
    case ElementType::T: return timers;
    case ElementType::C: return counters;
    default: return std::nullopt;
    }
}

std::optional<int> DetailStatus::ioPoints() const
{
    static const int points[] = {0, 20, 28, 40, 60};
    if (!ioPointsCode || *ioPointsCode < 1 || *ioPointsCode > 4)
        return std::nullopt;
    return points[*ioPointsCode];
}

std::optional<std::string> DetailStatus::osVersionText() const
{
    if (!osVersion)
        return std::nullopt;
    const int major = *osVersion >> 4;
    const int minor = *osVersion & 0x0F;
    if (major < 1 || major > 9 || minor > 9)
        return std::nullopt;
    return "V" + std::to_string(major) + "." + std::to_string(minor);
}

std::optional<std::string> DetailStatus::modelName() const
{
    const std::optional<int> points = ioPoints();
    if (!mainUnitType || !points)
        return std::nullopt;
    switch (*mainUnitType) {
    case 0: return "FBs-" + std::to_string(*points) + "MA/MU";
    case 1: return "FBs-" + std::to_string(*points) + "MC";
    default: return std::nullopt;
    }
}

std::string DetailStatus::summary() const
{
    std::string s;
    auto add = [&](const std::string &part) {
        if (!s.empty())
            s += ", ";
        s += part;
    };
    if (const std::optional<std::string> model = modelName())
        add(*model);
    else if (mainUnitType) {
        switch (*mainUnitType) {
        case 0: add("main unit MA/MU"); break;
        case 1: add("main unit MC"); break;
        default: add("main unit type " + std::to_string(*mainUnitType)); break;
        }
    }
    if (ioPointsCode && !modelName()) {
        if (const std::optional<int> points = ioPoints())
            add(std::to_string(*points) + " I/O points");
        else
            add("I/O code " + std::to_string(*ioPointsCode));
    }
    if (const std::optional<std::string> os = osVersionText())
        add("OS " + *os);
    else if (osVersion)
        add("OS code " + std::to_string(*osVersion));
    if (ladderSize)
        add("program " + std::to_string(*ladderSize) + " words");
    if (raw.empty())
        add("no status bytes");
    return s;
}

std::string DetailStatus::summaryNamed(const std::string &model) const
{
    std::string s = model;
    if (const std::optional<std::string> os = osVersionText())
        s += ", OS " + *os;
    if (ladderSize)
        s += ", program " + std::to_string(*ladderSize) + " words";
    return s;
}

} // namespace Fatek
