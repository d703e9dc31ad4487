#pragma once

#include "core/alarm/alarmtypes.h"

#include <QColor>
#include <QCoreApplication>
#include <QString>

namespace Fatek {

// The alarms' words in the UI language (states, priorities, kinds, events) and the colour of each
// priority, one place for the summary, the journal and the definition dialog.
class AlarmText
{
    Q_DECLARE_TR_FUNCTIONS(Fatek::AlarmText)

public:
    static QString state(AlarmState state);
    static QString priority(AlarmPriority priority);
    static QString kind(AlarmKind kind);
    static QString event(AlarmEventType type);
    // Critical red, high orange, medium yellow, low blue: the usual HMI convention.
    static QColor priorityColor(AlarmPriority priority);
    // Local time with the date when it is not today ("14:03:12", "2026-12-06 14:03:12").
    static QString time(qint64 ms);
    // "12 min", "1 h 5 min": what is left of a shelve.
    static QString duration(qint64 ms);
};

} // namespace Fatek
