#include "commandage.h"

#include "core/mqtt/mqttmessages.h"

#include <algorithm>

namespace Fatek {

Message CommandAge::tooOld(const std::optional<QDateTime> &time, bool queued,
                           const QDateTime &brokerDownAt, int maxAgeSec)
{
    const QDateTime now = QDateTime::currentDateTimeUtc();
    const qint64 maxMs = qint64(maxAgeSec) * 1000;
    const auto seconds = [](qint64 ms) {
        return QString::number(static_cast<double>(ms) / 1000.0, 'f', 1).toStdString();
    };
    if (time) {
        const qint64 age = time->msecsTo(now);
        if (age < -qint64(MaxAheadSec) * 1000)
            return msg<MsgId::GatewayWriteFuture>(seconds(-age), MaxAheadSec);
        if (age > maxMs)
            return msg<MsgId::GatewayWriteExpired>(seconds(age), maxAgeSec);
    }
    if (!queued)
        return {}; // came straight through: as old as the broker's hand-over
    // Kept by the broker while this gateway was away: at most as old as the outage. Checked with
    // a "time" too: that is the sender's word, the outage the gateway's own measure.
    if (!brokerDownAt.isValid()) {
        // Away since this program started: only the command's time tells its age.
        return time ? Message{} : msg<MsgId::GatewayWriteAgeUnknown>(maxAgeSec);
    }
    const qint64 waited = brokerDownAt.msecsTo(now);
    return waited > maxMs ? msg<MsgId::GatewayWriteWaited>(seconds(waited), maxAgeSec) : Message{};
}

qint64 CommandAge::ageMs(const std::optional<QDateTime> &time, bool queued,
                         const QDateTime &brokerDownAt)
{
    // tooOld refused a time in the future.
    const QDateTime now = QDateTime::currentDateTimeUtc();
    qint64 age = time ? time->msecsTo(now) : 0;
    if (queued && brokerDownAt.isValid())
        age = std::max(age, brokerDownAt.msecsTo(now));
    return std::max<qint64>(0, age);
}

} // namespace Fatek
