#include "stationscanner.h"

#include "qtbytes.h"
#include "requesttracker.h"
#include "session.h"

#include <algorithm>

namespace Fatek {

StationScanner::StationScanner(Session *session, QObject *parent)
    : QObject(parent)
    , m_requests(new RequestTracker(this))
{
    m_requests->setSession(session);
}

StationScanner::~StationScanner()
{
    m_requests->cancelPending();
}

bool StationScanner::isRunning() const
{
    return m_requests->pendingCount() > 0;
}

void StationScanner::start(int first, int last, int timeoutMs)
{
    cancel();
    if (!m_requests->session())
        return;
    first = std::clamp(first, 1, static_cast<int>(Limits::maxStation));
    last = std::clamp(last, 1, static_cast<int>(Limits::maxStation));
    if (last < first)
        std::swap(first, last);
    m_hits.clear();
    m_total = last - first + 1;
    m_done = 0;
    RequestOptions options;
    options.timeoutMs = std::max(1, timeoutMs);
    options.retries = 0;
    // All queued at once in the background queue: the session sends them one by one, and user
    // actions still go first.
    for (int station = first; station <= last; ++station) {
        const auto s = static_cast<quint8>(station);
        m_requests->submit(
            Request::briefStatus(s), [this, s](const SessionResult &r) { onAnswer(s, r); }, options,
            Priority::Background);
    }
    Q_EMIT progress(0, m_total);
}

void StationScanner::cancel()
{
    if (!isRunning())
        return;
    // Late results of this scan are ignored from now on.
    m_requests->cancelPending();
    Q_EMIT finished(m_hits);
}

void StationScanner::onAnswer(quint8 station, const SessionResult &result)
{
    ++m_done;
    // A PLC error is an answer: something lives at that station.
    const bool answered = result.ok() || result.errorKind() == ErrorKind::PlcError;
    if (answered) {
        Hit hit;
        hit.station = station;
        if (result.ok()) {
            const Bytes &data = result.response().data;
            hit.statusBytes = toQByteArray(data);
            if (!data.empty())
                hit.status = PlcStatus::fromStatus1(data.front());
        }
        const auto pos = std::lower_bound(m_hits.begin(), m_hits.end(), station,
                                          [](const Hit &h, quint8 s) { return h.station < s; });
        m_hits.insert(pos, hit);
        Q_EMIT stationFound(hit);
    }
    Q_EMIT progress(m_done, m_total);
    if (!isRunning())
        Q_EMIT finished(m_hits);
}

} // namespace Fatek
