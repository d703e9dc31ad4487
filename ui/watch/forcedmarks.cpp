#include "forcedmarks.h"

#include "core/session/requesttracker.h"
#include "watchtablemodel.h"

#include <map>
#include <set>

namespace Fatek {

ForcedMarks::ForcedMarks(WatchTableModel *model, QObject *parent)
    : QObject(parent)
    , m_model(model)
    , m_requests(new RequestTracker(this))
{
    m_timer.setInterval(intervalMs);
    connect(&m_timer, &QTimer::timeout, this, &ForcedMarks::readBurst);
}

void ForcedMarks::setTarget(const PlcTarget &target)
{
    target.aim(m_requests);
    m_requests->forgetPending();
    ++m_generation;
    m_pending = 0;
    m_model->clearForced();
    if (target.isDirect())
        m_timer.start();
    else
        m_timer.stop();
}

void ForcedMarks::readBurst()
{
    if (m_pending > 0 || !m_requests->session() || (m_active && !m_active()))
        return;
    // Numbers of the discrete rows per station and kind, in order.
    std::map<std::pair<quint8, ElementType>, std::set<quint32>> points;
    for (int r = 0; r < m_model->rowCount(); ++r) {
        const WatchItemSpec item = m_model->item(r);
        if (isDiscrete(item.address.type))
            points[{item.station, item.address.type}].insert(item.address.number);
    }
    const quint64 generation = m_generation;
    for (const auto &group : points) {
        const quint8 station = group.first.first;
        const ElementType type = group.first.second;
        const std::set<quint32> &numbers = group.second;
        // One request per window of up to 256 points starting at the first number not yet read.
        auto it = numbers.cbegin();
        while (it != numbers.cend()) {
            const quint32 first = *it;
            quint32 last = first;
            while (it != numbers.cend() && *it - first < Limits::maxDiscretes)
                last = *it++;
            const Address start{type, first};
            ++m_pending;
            const quint64 id = m_requests->submit(
                Request::readEnableFlags(station, start, last - first + 1),
                [this, generation, station, start](const SessionResult &result) {
                    if (generation != m_generation)
                        return;
                    --m_pending;
                    // A failed read leaves the marks as they were: the rows say why they fail.
                    if (result.ok())
                        m_model->setForcedFlags(station, start, result.response().values);
                },
                {}, Priority::Poll);
            if (id == 0)
                --m_pending; // no session: no answer will come
        }
    }
}

} // namespace Fatek
