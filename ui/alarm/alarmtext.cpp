#include "alarmtext.h"

#include <QDateTime>

namespace Fatek {

QString AlarmText::state(AlarmState state)
{
    switch (state) {
    case AlarmState::Normal: return tr("normal");
    case AlarmState::ActiveUnacked: return tr("active, unacknowledged");
    case AlarmState::ActiveAcked: return tr("active, acknowledged");
    case AlarmState::ReturnedUnacked: return tr("returned, unacknowledged");
    case AlarmState::Shelved: return tr("shelved");
    case AlarmState::OutOfService: return tr("out of service");
    }
    return {};
}

QString AlarmText::priority(AlarmPriority priority)
{
    switch (priority) {
    case AlarmPriority::Critical: return tr("critical");
    case AlarmPriority::High: return tr("high");
    case AlarmPriority::Medium: return tr("medium");
    case AlarmPriority::Low: return tr("low");
    }
    return {};
}

QString AlarmText::kind(AlarmKind kind)
{
    switch (kind) {
    case AlarmKind::HighHigh: return tr("High-high");
    case AlarmKind::High: return tr("High");
    case AlarmKind::Low: return tr("Low");
    case AlarmKind::LowLow: return tr("Low-low");
    case AlarmKind::On: return tr("Bit on (1)");
    case AlarmKind::Off: return tr("Bit off (0)");
    case AlarmKind::Quality: return tr("Bad quality");
    }
    return {};
}

QString AlarmText::event(AlarmEventType type)
{
    switch (type) {
    case AlarmEventType::Raised: return tr("raised");
    case AlarmEventType::Returned: return tr("returned");
    case AlarmEventType::Acknowledged: return tr("acknowledged");
    case AlarmEventType::Shelved: return tr("shelved");
    case AlarmEventType::Unshelved: return tr("unshelved");
    case AlarmEventType::OutOfService: return tr("out of service");
    case AlarmEventType::InService: return tr("in service");
    }
    return {};
}

QColor AlarmText::priorityColor(AlarmPriority priority)
{
    switch (priority) {
    case AlarmPriority::Critical: return QColor(0xd3, 0x2f, 0x2f);
    case AlarmPriority::High: return QColor(0xef, 0x7d, 0x1a);
    case AlarmPriority::Medium: return QColor(0xf2, 0xc8, 0x1f);
    case AlarmPriority::Low: return QColor(0x42, 0x85, 0xd6);
    }
    return {};
}

QString AlarmText::time(qint64 ms)
{
    if (ms <= 0)
        return {};
    const QDateTime t = QDateTime::fromMSecsSinceEpoch(ms).toLocalTime();
    return t.date() == QDate::currentDate() ? t.toString(QStringLiteral("HH:mm:ss"))
                                            : t.toString(QStringLiteral("yyyy-MM-dd HH:mm:ss"));
}

QString AlarmText::duration(qint64 ms)
{
    const qint64 minutes = (std::max<qint64>(ms, 0) + 59999) / 60000;
    if (minutes < 60)
        return tr("%1 min").arg(minutes);
    return minutes % 60 == 0 ? tr("%1 h").arg(minutes / 60)
                             : tr("%1 h %2 min").arg(minutes / 60).arg(minutes % 60);
}

} // namespace Fatek
