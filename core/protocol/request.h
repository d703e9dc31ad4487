#pragma once

#include "address.h"
#include "result.h"

#include <cstdint>
#include <string>
#include <vector>

namespace Fatek {

using Bytes = std::vector<std::uint8_t>;

enum class Protocol : std::uint8_t { Facon, Binary };
std::string_view protocolName(Protocol protocol); // "FACON", "binary"

// Command codes, the same in both protocols. Other byte values may appear in frames from the wire.
enum class Command : std::uint8_t {
    BriefStatus = 0x40,
    RunStop = 0x41,
    DiscreteControl = 0x42,
    ReadEnableFlags = 0x43,
    ReadDiscretes = 0x44,
    WriteDiscretes = 0x45,
    ReadRegisters = 0x46,
    WriteRegisters = 0x47,
    MixedRead = 0x48,
    MixedWrite = 0x49,
    Loopback = 0x4E,
    ReadProgram = 0x4F,  // FACON only
    WriteProgram = 0x50, // FACON only
    DetailStatus = 0x53,
};
bool isKnownCommand(std::uint8_t code);
std::string_view commandName(Command command); // "read consecutive registers"
// The same as a message, translated where shown (the names are shared by both protocols).
Message commandMessage(Command command);
// Whether the command changes the PLC (operator mode refuses these).
bool isWriteCommand(Command command);

enum class DiscreteOp : std::uint8_t { Disable = 1, Enable = 2, Set = 3, Reset = 4 };
std::string_view discreteOpName(DiscreteOp op); // "disable"
// "disable X0" for the traffic log.
Message discreteOpMessage(DiscreteOp op, const std::string &target);

namespace Limits {
inline constexpr std::uint32_t maxDiscretes = 256;      // 43 44 45
inline constexpr std::uint32_t maxRegisterWords = 64;   // 46 47 (32-bit elements count 2)
inline constexpr std::uint32_t maxMixedReadWords = 64;  // 48
inline constexpr std::uint32_t maxMixedWriteWords = 32; // 49
inline constexpr std::uint32_t maxLoopback = 256;       // 4E bytes / chars
inline constexpr std::uint32_t programPageWords = 64;   // 4F 50
inline constexpr std::uint8_t broadcastStation = 0;
inline constexpr std::uint8_t maxStation = 254;
} // namespace Limits

// A typed query. One struct for all commands: only the fields a command uses are read.
struct Request
{
    std::uint8_t station = 1;
    Command command = Command::BriefStatus;
    bool run = false;                  // 41
    DiscreteOp op = DiscreteOp::Set;   // 42
    Address start;                     // 42 43 44 45 46 47
    std::uint32_t count = 0;           // 43 44 46 (45 and 47 count their values)
    std::vector<Address> addresses;    // 48 49
    std::vector<std::uint32_t> values; // 45 (0/1), 47, 49 (one per address), 50 (64 words)
    Bytes data;                        // 4E test data
    std::uint16_t page = 0;            // 4F 50

    bool operator==(const Request &) const = default;

    static Request briefStatus(std::uint8_t station);
    static Request runStop(std::uint8_t station, bool run);
    static Request discreteControl(std::uint8_t station, DiscreteOp op, Address discrete);
    static Request readEnableFlags(std::uint8_t station, Address start, std::uint32_t count);
    static Request readDiscretes(std::uint8_t station, Address start, std::uint32_t count);
    static Request writeDiscretes(std::uint8_t station, Address start,
                                  std::vector<std::uint32_t> values);
    static Request readRegisters(std::uint8_t station, Address start, std::uint32_t count);
    static Request writeRegisters(std::uint8_t station, Address start,
                                  std::vector<std::uint32_t> values);
    static Request mixedRead(std::uint8_t station, std::vector<Address> addresses);
    static Request mixedWrite(std::uint8_t station, std::vector<Address> addresses,
                              std::vector<std::uint32_t> values);
    static Request loopback(std::uint8_t station, Bytes data);
    static Request readProgram(std::uint8_t station, std::uint16_t page);
    static Request writeProgram(std::uint8_t station, std::uint16_t page,
                                std::vector<std::uint32_t> words);
    static Request detailStatus(std::uint8_t station);

    // Number of values a successful answer carries (43 44 46 48 4F), else 0.
    std::uint32_t expectedValueCount() const;
    // Short text for logs: "read R12..R14", "write Y0=1".
    std::string describe() const;
    // What the request addresses, for error messages: "R12..R14", "Y0", "R1, Y9, DWM0", "" (40 41
    // 4E 53). Decoders build PLC errors as makePlcError(code, request.target()) -> "PLC error A:
    // illegal address R70000".
    std::string target() const;
};

// Every check that can be made before sending: station, element kinds, ranges, alignment,
// protocol limits (32-bit elements count twice), value ranges, protocol support.
Status validateRequest(const Request &request, Protocol protocol);

} // namespace Fatek
