#pragma once

#include "address.h"
#include "plcstatus.h"

#include <array>
#include <cstdint>
#include <optional>
#include <string>

namespace Fatek {

// A PLC model's element ranges: how many elements of each plain kind it has, numbered from 0
// without gaps. The simulator's profiles (core/sim) are built on these tables; a restore of values
// (core/commission) checks a snapshot against them before it writes.
struct PlcModel
{
    enum class Family { FBs, M, Reported };

    // FBs and M: the project's table. Reported: a PLC that did not say its family, with the sizes
    // its detail status gives (a kind it does not report is not limited here: the PLC refuses what
    // it lacks itself).
    Family family = Family::FBs;
    // Points per discrete kind, indexed X Y M S T C.
    std::array<std::uint32_t, 6> discretes{};
    // Registers per kind, indexed RT RC R D F (0: the model has none).
    std::array<std::uint32_t, 5> registers{};

    // Number of elements of a plain kind (X..C, RT..F); 0 for views (W, DW, DR types).
    std::uint32_t size(ElementType plainType) const;
    // Whether `count` consecutive elements from `start` all exist on this model and the start is
    // aligned (W/DW on a multiple of 8). DRn needs R(n+1) too.
    bool contains(const Address &start, std::uint32_t count = 1) const;
    // The plain kind's elements as a range ("R0-3839"); "no F" when the model has none.
    std::string rangeText(ElementType plainType) const;
    // "FBs series", "M series", "PLC" (Reported).
    std::string familyName() const;
    bool sameFamily(const PlcModel &other) const { return family == other.family; }

    static PlcModel fbs();
    static PlcModel mSeries();
    // The model a 53 detail status is from. Its main-unit byte is documented for the FB series
    // only (0 MA/MU, 1 MC); an M-series PLC answers with a value reserved there. No main-unit byte
    // (a short answer): Reported with the sizes it gives; nothing when it gives none either.
    static std::optional<PlcModel> fromDetailStatus(const DetailStatus &status);
    // The family a model text names (a snapshot's "model", a program backup's): "FBs-28MC, ...",
    // "M series, ...", or an older snapshot's 53 summary ("main unit type 255, ..." is no FBs).
    // Nothing when the text does not say (empty, hand-written).
    static std::optional<Family> familyOfText(const std::string &modelText);
    // The model text a tool records for a PLC: the 53 summary when it names an FBs unit
    // ("FBs-28MC, OS V3.1, program 13184 words"), else the family the answer shows ("M series,
    // OS V3.1, program 16384 words").
    static std::string modelText(const DetailStatus &status);
};

} // namespace Fatek
