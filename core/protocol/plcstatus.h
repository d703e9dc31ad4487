#pragma once

#include "element.h"

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace Fatek {

// STATUS1 of commands 40 and 53.
struct PlcStatus
{
    bool running = false;
    bool batteryLow = false;
    bool ladderChecksumError = false;
    bool memoryPack = false; // ROM pack (FBs) / memory card (M series)
    bool watchdogError = false;
    bool idSet = false;
    bool emergencyStop = false;

    static PlcStatus fromStatus1(std::uint8_t status1);
    std::uint8_t toStatus1() const;
    bool operator==(const PlcStatus &) const = default;
};

// Answer of 53 (detail status), decoded leniently: public clients expect 21, 28 or 64 status
// bytes, so any length is accepted and only what is present is decoded. The raw bytes are kept.
struct DetailStatus
{
    std::vector<std::uint8_t> raw;
    PlcStatus status;                         // STATUS1
    std::optional<std::uint8_t> mainUnitType; // STATUS2: 0 MA/MU, 1 MC
    std::optional<std::uint8_t> ioPointsCode; // STATUS3: 1 = 20 points, 2 = 28, 3 = 40 ...
    std::optional<std::uint8_t> osVersion;    // STATUS4: 0x31 = V3.1
    std::optional<std::uint16_t> ladderSize;  // STATUS5..6, words
    std::optional<std::uint16_t> discreteInputs, discreteOutputs, analogInputs, analogOutputs;
    std::optional<std::uint16_t> mRelays, sRelays, lRelays, rRegisters, dRegisters, timers,
        counters;

    static DetailStatus decode(std::span<const std::uint8_t> statusBytes);
    // How many points of a discrete kind (X Y M S T C) the PLC reports, numbered from 0; nothing
    // when the answer is too short to say or the kind is not a discrete.
    std::optional<std::uint16_t> discreteCount(ElementType type) const;
    // The model as printed on the unit ("FBs-28MC", "FBs-20MA/MU"), when STATUS2 and STATUS3 say
    // it; only the FACON answer has them.
    std::optional<std::string> modelName() const;
    // I/O points of the main unit (20, 28, 40, 60) from STATUS3's code.
    std::optional<int> ioPoints() const;
    // "V3.1" from STATUS4 (0x31: one BCD digit each); nothing when absent or not BCD.
    std::optional<std::string> osVersionText() const;
    // "FBs-28MC, OS V3.1, program 13184 words" as far as known.
    std::string summary() const;
    // The same for a model named from elsewhere (a program header's family): "M series, OS V3.1,
    // program 16384 words".
    std::string summaryNamed(const std::string &model) const;
};

} // namespace Fatek
