#include "simulatedplc.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace Fatek {

namespace {

constexpr std::uint8_t errNone = 0x0;
constexpr std::uint8_t errValue = 0x2;
constexpr std::uint8_t errFormat = 0x4;
constexpr std::uint8_t errAddress = 0xA;

Response answer(const Request &r, std::uint8_t code = errNone)
{
    Response resp;
    resp.station = r.station;
    resp.command = r.command;
    resp.errorCode = code;
    return resp;
}

bool valueFits(const Address &a, std::uint32_t v)
{
    switch (a.width()) {
    case ElementWidth::Bit: return v <= 1;
    case ElementWidth::Word: return v <= 0xFFFF;
    case ElementWidth::DoubleWord: return true;
    }
    return false;
}

// Whether the element kind exists in the protocol at all (F and DF are binary only).
bool inProtocol(const Address &a, Protocol protocol)
{
    return protocol == Protocol::Binary || a.info().faconDigits != 0;
}

} // namespace

SimulatedPlc::SimulatedPlc(const ModelProfile &profile)
    : m_memory(profile)
    , m_powerOnProgram(profile.powerOnProgram())
    , m_program(m_powerOnProgram)
    , m_running(true) // a PLC holding a program powers up in RUN
{}

ModelProfile SimulatedPlc::profile() const
{
    const std::lock_guard lock(m_mutex);
    return m_memory.profile();
}

bool SimulatedPlc::isRunning() const
{
    const std::lock_guard lock(m_mutex);
    return m_running;
}

void SimulatedPlc::setRunning(bool running)
{
    const std::lock_guard lock(m_mutex);
    m_running = running;
}

void SimulatedPlc::setRunRefusalCode(std::uint8_t code)
{
    const std::lock_guard lock(m_mutex);
    m_runRefusal = code;
}

std::uint8_t SimulatedPlc::runRefusalCode() const
{
    const std::lock_guard lock(m_mutex);
    return m_runRefusal;
}

void SimulatedPlc::setStatusFlags(const PlcStatus &flags)
{
    const std::lock_guard lock(m_mutex);
    m_flags = flags;
}

PlcStatus SimulatedPlc::status() const
{
    const std::lock_guard lock(m_mutex);
    return PlcStatus::fromStatus1(status1Locked());
}

std::uint8_t SimulatedPlc::status1Locked() const
{
    PlcStatus s = m_flags;
    s.running = m_running;
    return s.toStatus1();
}

Bytes SimulatedPlc::briefStatusBytes() const
{
    const std::lock_guard lock(m_mutex);
    const ModelProfile &p = m_memory.profile();
    return {status1Locked(), p.status2, p.status3};
}

Bytes SimulatedPlc::detailStatusBytes() const
{
    const std::lock_guard lock(m_mutex);
    return m_memory.profile().detailStatus(status1Locked());
}

std::uint64_t SimulatedPlc::scanCount() const
{
    const std::lock_guard lock(m_mutex);
    return m_scans;
}

std::optional<std::uint32_t> SimulatedPlc::value(const Address &address) const
{
    const std::lock_guard lock(m_mutex);
    if (!m_memory.contains(address))
        return std::nullopt;
    return m_memory.read(address);
}

bool SimulatedPlc::setValue(const Address &address, std::uint32_t v)
{
    const std::lock_guard lock(m_mutex);
    if (!m_memory.contains(address) || !valueFits(address, v))
        return false;
    m_memory.write(address, v);
    return true;
}

std::optional<bool> SimulatedPlc::isDisabled(const Address &discrete) const
{
    const std::lock_guard lock(m_mutex);
    if (!Fatek::isDiscrete(discrete.type) || !m_memory.contains(discrete))
        return std::nullopt;
    return m_memory.isDisabled(discrete.type, discrete.number);
}

bool SimulatedPlc::setDisabled(const Address &discrete, bool disabled)
{
    const std::lock_guard lock(m_mutex);
    if (!Fatek::isDiscrete(discrete.type) || !m_memory.contains(discrete))
        return false;
    m_memory.setDisabled(discrete.type, discrete.number, disabled);
    return true;
}

std::vector<std::uint32_t> SimulatedPlc::programPage(std::uint16_t page) const
{
    const std::lock_guard lock(m_mutex);
    const std::size_t first = std::size_t{page} * Limits::programPageWords;
    if (first + Limits::programPageWords > m_program.size())
        return {};
    return {m_program.begin() + static_cast<std::ptrdiff_t>(first),
            m_program.begin() + static_cast<std::ptrdiff_t>(first + Limits::programPageWords)};
}

bool SimulatedPlc::setProgramPage(std::uint16_t page, const std::vector<std::uint32_t> &words)
{
    const std::lock_guard lock(m_mutex);
    const std::size_t first = std::size_t{page} * Limits::programPageWords;
    if (words.size() != Limits::programPageWords || first + words.size() > m_program.size())
        return false;
    for (std::size_t i = 0; i < words.size(); ++i)
        m_program[first + i] = static_cast<std::uint16_t>(words[i] & 0xFFFFu);
    m_programChanged = true;
    return true;
}

bool SimulatedPlc::setProgram(const std::vector<std::uint16_t> &words)
{
    const std::lock_guard lock(m_mutex);
    if (words.size() != m_program.size())
        return false;
    m_program = words;
    m_programChanged = true;
    return true;
}

void SimulatedPlc::clear()
{
    const std::lock_guard lock(m_mutex);
    m_memory.clear();
    if (m_programChanged)
        m_program = m_powerOnProgram; // same size: copies in place, allocates nothing
    m_programChanged = false;
    m_scans = 0;
}

void SimulatedPlc::scan(std::int64_t ms)
{
    const std::lock_guard lock(m_mutex);
    if (!m_running)
        return;
    ++m_scans;
    auto put = [this](ElementType t, std::uint32_t n, std::uint32_t v) {
        const Address a{t, n};
        if (m_memory.contains(a))
            m_memory.writeFromLadder(a, v);
    };
    put(ElementType::R, 0, static_cast<std::uint32_t>(m_scans & 0xFFFFu));
    const double phase = 2.0 * std::numbers::pi * static_cast<double>(ms % 10000) / 10000.0;
    const auto sine = static_cast<std::int16_t>(std::lround(1000.0 * std::sin(phase)));
    put(ElementType::R, 1, static_cast<std::uint16_t>(sine));
    put(ElementType::Y, 0, (ms % 1000) < 500 ? 1u : 0u);
    put(ElementType::DR, 10, static_cast<std::uint32_t>((ms / 10) % 100000));
    const auto walking = static_cast<std::uint32_t>((ms / 250) % 8);
    for (std::uint32_t i = 0; i < 8; ++i)
        put(ElementType::X, i, i == walking ? 1u : 0u);
}

Response SimulatedPlc::execute(const Request &request, Protocol protocol)
{
    const std::lock_guard lock(m_mutex);
    return executeLocked(request, protocol);
}

Response SimulatedPlc::executeLocked(const Request &r, Protocol protocol)
{
    Response resp = answer(r);

    // Checks every element of a span before touching memory, so a refused write changes nothing.
    auto spanCode = [&](const Address &start, std::uint32_t count) -> std::uint8_t {
        if (!inProtocol(start, protocol) || !m_memory.contains(start, count))
            return errAddress;
        return errNone;
    };

    switch (r.command) {
    case Command::BriefStatus: {
        const ModelProfile &p = m_memory.profile();
        resp.data = {status1Locked(), p.status2, p.status3};
        return resp;
    }
    case Command::DetailStatus:
        resp.data = m_memory.profile().detailStatus(status1Locked());
        return resp;
    case Command::RunStop:
        if (r.run && m_runRefusal != 0)
            return answer(r, m_runRefusal);
        m_running = r.run;
        return resp;
    case Command::DiscreteControl: {
        if (!Fatek::isDiscrete(r.start.type))
            return answer(r, errFormat);
        if (r.op < DiscreteOp::Disable || r.op > DiscreteOp::Reset)
            return answer(r, errValue);
        if (auto c = spanCode(r.start, 1))
            return answer(r, c);
        switch (r.op) {
        case DiscreteOp::Disable: m_memory.setDisabled(r.start.type, r.start.number, true); break;
        case DiscreteOp::Enable: m_memory.setDisabled(r.start.type, r.start.number, false); break;
        case DiscreteOp::Set: m_memory.write(r.start, 1); break;
        case DiscreteOp::Reset: m_memory.write(r.start, 0); break;
        }
        return resp;
    }
    case Command::ReadEnableFlags:
    case Command::ReadDiscretes: {
        if (!Fatek::isDiscrete(r.start.type) || r.count < 1 || r.count > Limits::maxDiscretes)
            return answer(r, errFormat);
        if (auto c = spanCode(r.start, r.count))
            return answer(r, c);
        for (std::uint32_t i = 0; i < r.count; ++i) {
            const std::uint32_t n = r.start.number + i;
            const bool v = r.command == Command::ReadEnableFlags
                               ? m_memory.isDisabled(r.start.type, n)
                               : m_memory.bit(r.start.type, n);
            resp.values.push_back(v ? 1 : 0);
        }
        return resp;
    }
    case Command::WriteDiscretes: {
        const auto n = static_cast<std::uint32_t>(r.values.size());
        if (!Fatek::isDiscrete(r.start.type) || n < 1 || n > Limits::maxDiscretes)
            return answer(r, errFormat);
        if (auto c = spanCode(r.start, n))
            return answer(r, c);
        for (std::uint32_t v : r.values) {
            if (v > 1)
                return answer(r, errValue);
        }
        for (std::uint32_t i = 0; i < n; ++i)
            m_memory.write(r.start.advanced(i), r.values[i]);
        return resp;
    }
    case Command::ReadRegisters:
    case Command::WriteRegisters: {
        const bool write = r.command == Command::WriteRegisters;
        const auto n = write ? static_cast<std::uint32_t>(r.values.size()) : r.count;
        const auto maxElements
            = Limits::maxRegisterWords / static_cast<std::uint32_t>(r.start.words());
        if (!Fatek::isRegister(r.start.type) || n < 1 || n > maxElements)
            return answer(r, errFormat);
        if (auto c = spanCode(r.start, n))
            return answer(r, c);
        if (write) {
            for (std::uint32_t v : r.values) {
                if (!valueFits(r.start, v))
                    return answer(r, errValue);
            }
            for (std::uint32_t i = 0; i < n; ++i)
                m_memory.write(r.start.advanced(i), r.values[i]);
        } else {
            for (std::uint32_t i = 0; i < n; ++i)
                resp.values.push_back(m_memory.read(r.start.advanced(i)));
        }
        return resp;
    }
    case Command::MixedRead:
    case Command::MixedWrite: {
        const bool write = r.command == Command::MixedWrite;
        const std::uint32_t maxWords
            = write ? Limits::maxMixedWriteWords : Limits::maxMixedReadWords;
        if (r.addresses.empty() || (write && r.values.size() != r.addresses.size()))
            return answer(r, errFormat);
        std::uint32_t words = 0;
        for (const Address &a : r.addresses)
            words += static_cast<std::uint32_t>(a.words());
        if (words > maxWords)
            return answer(r, errFormat);
        for (const Address &a : r.addresses) {
            if (auto c = spanCode(a, 1))
                return answer(r, c);
        }
        if (write) {
            for (std::size_t i = 0; i < r.addresses.size(); ++i) {
                if (!valueFits(r.addresses[i], r.values[i]))
                    return answer(r, errValue);
            }
            for (std::size_t i = 0; i < r.addresses.size(); ++i)
                m_memory.write(r.addresses[i], r.values[i]);
        } else {
            for (const Address &a : r.addresses)
                resp.values.push_back(m_memory.read(a));
        }
        return resp;
    }
    case Command::Loopback:
        if (r.data.size() > Limits::maxLoopback)
            return answer(r, errFormat);
        resp.data = r.data;
        return resp;
    case Command::ReadProgram:
    case Command::WriteProgram: {
        if (protocol != Protocol::Facon)
            return answer(r, errFormat);
        if (r.page >= m_memory.profile().programPages())
            return answer(r, errAddress);
        const std::size_t first = std::size_t{r.page} * Limits::programPageWords;
        if (r.command == Command::ReadProgram) {
            for (std::size_t i = 0; i < Limits::programPageWords; ++i)
                resp.values.push_back(m_program[first + i]);
            return resp;
        }
        // A real PLC cannot take a program page while it executes the program.
        if (m_running || r.values.size() != Limits::programPageWords)
            return answer(r, errFormat);
        for (std::uint32_t v : r.values) {
            if (v > 0xFFFF)
                return answer(r, errValue);
        }
        for (std::size_t i = 0; i < Limits::programPageWords; ++i)
            m_program[first + i] = static_cast<std::uint16_t>(r.values[i]);
        m_programChanged = true;
        return resp;
    }
    }
    return answer(r, errFormat); // a command value outside the enum
}

} // namespace Fatek
