#include "alarmtypes.h"

// Names of alarm states and events, as files, topics and the journal write them.

#include <array>

namespace Fatek::Alarms {

namespace {

constexpr std::array<std::pair<AlarmState, const char *>, 6> stateNames{{
    {AlarmState::Normal, "normal"},
    {AlarmState::ActiveUnacked, "activeUnacked"},
    {AlarmState::ActiveAcked, "activeAcked"},
    {AlarmState::ReturnedUnacked, "returnedUnacked"},
    {AlarmState::Shelved, "shelved"},
    {AlarmState::OutOfService, "outOfService"},
}};

constexpr std::array<std::pair<AlarmEventType, const char *>, 7> eventNames{{
    {AlarmEventType::Raised, "raised"},
    {AlarmEventType::Returned, "returned"},
    {AlarmEventType::Acknowledged, "acknowledged"},
    {AlarmEventType::Shelved, "shelved"},
    {AlarmEventType::Unshelved, "unshelved"},
    {AlarmEventType::OutOfService, "outOfService"},
    {AlarmEventType::InService, "inService"},
}};

template<typename T, std::size_t N>
QString nameOf(const std::array<std::pair<T, const char *>, N> &names, T value)
{
    for (const auto &[v, name] : names) {
        if (v == value)
            return QLatin1String(name);
    }
    return {};
}

template<typename T, std::size_t N>
std::optional<T> valueOf(const std::array<std::pair<T, const char *>, N> &names,
                         const QString &name)
{
    for (const auto &[v, text] : names) {
        if (name == QLatin1String(text))
            return v;
    }
    return std::nullopt;
}

} // namespace

QString stateName(AlarmState state)
{
    return nameOf(stateNames, state);
}

std::optional<AlarmState> stateFromName(const QString &name)
{
    return valueOf(stateNames, name);
}

QString eventName(AlarmEventType type)
{
    return nameOf(eventNames, type);
}

std::optional<AlarmEventType> eventFromName(const QString &name)
{
    return valueOf(eventNames, name);
}

} // namespace Fatek::Alarms
