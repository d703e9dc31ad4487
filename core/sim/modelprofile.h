#pragma once

#include "core/protocol/element.h"
#include "core/protocol/plcmodel.h"
#include "core/protocol/programheader.h"
#include "core/protocol/request.h"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace Fatek {

// What one simulated PLC model has: its element ranges (PlcModel, the project's table) and the
// identity it reports in its status bytes.
struct ModelProfile : PlcModel
{
    std::string name;        // "fbs", "m": what --profile accepts
    std::string description; // "FBs-28MC, OS V3.1, 13K program"

    std::uint8_t status2 = 0; // 40: program capacity / model code
    std::uint8_t status3 = 0;
    std::uint8_t mainUnitType = 1; // 53 STATUS2: 1 = MC
    std::uint8_t ioPointsCode = 2; // 53 STATUS3: 2 = 28 points
    std::uint8_t osVersion = 0x31; // 53 STATUS4: V3.1
    std::uint16_t programWords = 13184;
    char programFamily = 'B'; // program header byte 1: 'B' FBs, 'M' M series
    std::uint16_t analogInputs = 0;
    std::uint16_t analogOutputs = 0;

    // Program pages 4F/50 can address: page 0 (header) plus the program itself.
    std::uint16_t programPages() const;
    // Page 0 of this model's program: family, two digits ("13" for 13K words), ladder size.
    ProgramHeader programHeader() const;
    // The program memory at power-on (programPages() x 64 words): the header, then a small
    // recognisable ladder image in page 1 (the same every time), zeros after it.
    std::vector<std::uint16_t> powerOnProgram() const;

    // 64 bytes of detail status (53) for the given STATUS1, layout of the FACON documentation.
    Bytes detailStatus(std::uint8_t status1) const;

    static ModelProfile fbs();
    static ModelProfile mSeries();
    static std::optional<ModelProfile> byName(const std::string &name);
    static std::vector<std::string> names();
};

} // namespace Fatek
