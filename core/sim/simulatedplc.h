#pragma once

#include "core/protocol/plcstatus.h"
#include "core/protocol/request.h"
#include "core/protocol/response.h"
#include "modelprofile.h"
#include "plcmemory.h"

#include <cstdint>
#include <mutex>
#include <optional>
#include <vector>

namespace Fatek {

// A PLC that executes typed requests like the reference says: memory per model profile, RUN/STOP,
// forcing, program pages and a small demo ladder. Thread-safe: every public method locks.
class SimulatedPlc
{
public:
    explicit SimulatedPlc(const ModelProfile &profile = ModelProfile::fbs());

    ModelProfile profile() const;

    // The answer a PLC gives; errorCode 2 (value), 4 (format / cannot execute), A (address) or the
    // RUN refusal code, never a crash. `protocol` matters for FACON-only commands (4F 50).
    Response execute(const Request &request, Protocol protocol = Protocol::Facon);

    bool isRunning() const;
    void setRunning(bool running);
    // Code answered to a RUN command (5, 6, 7 or 9); 0 accepts RUN.
    void setRunRefusalCode(std::uint8_t code);
    std::uint8_t runRefusalCode() const;
    // STATUS1 flags other than RUN (battery low, ROM pack, ID set ...); `running` is ignored.
    void setStatusFlags(const PlcStatus &flags);
    PlcStatus status() const;
    Bytes briefStatusBytes() const;  // 40: STATUS1..3
    Bytes detailStatusBytes() const; // 53: 64 bytes

    // One scan of the demo ladder at `msSinceStart`; does nothing in STOP. The ladder: R0 counts
    // scans, R1 a signed sine (+-1000, 10 s period), Y0 blinks at 1 Hz, DR10 ramps 0..99999
    // (one step per 10 ms), X0..X7 a walking bit (250 ms per step). Disabled discretes keep their
    // value.
    void scan(std::int64_t msSinceStart);
    std::uint64_t scanCount() const;

    // Direct access for tests and the GUI: like the master's writes (reaches disabled discretes).
    std::optional<std::uint32_t> value(const Address &address) const;
    bool setValue(const Address &address, std::uint32_t value);
    std::optional<bool> isDisabled(const Address &discrete) const;
    bool setDisabled(const Address &discrete, bool disabled);
    std::vector<std::uint32_t> programPage(std::uint16_t page) const; // empty if no such page
    // Replaces one page (64 words) or the whole program memory (programPages() x 64 words);
    // false when the page or the size does not fit this model.
    bool setProgramPage(std::uint16_t page, const std::vector<std::uint32_t> &words);
    bool setProgram(const std::vector<std::uint16_t> &words);
    // Memory, flags and program back to power-on (STOP stays as it is).
    void clear();

private:
    Response executeLocked(const Request &request, Protocol protocol);
    std::uint8_t status1Locked() const;

    mutable std::mutex m_mutex;
    PlcMemory m_memory;
    // The profile's program memory at power-on, built once: clear() copies it back only when the
    // program was written since (the fuzzer clears a PLC for every input).
    std::vector<std::uint16_t> m_powerOnProgram;
    std::vector<std::uint16_t> m_program;
    bool m_programChanged = false;
    PlcStatus m_flags;
    bool m_running = false;
    std::uint8_t m_runRefusal = 0;
    std::uint64_t m_scans = 0;
};

} // namespace Fatek
