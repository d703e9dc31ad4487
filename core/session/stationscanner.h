#pragma once

#include "core/protocol/plcstatus.h"
#include "sessionresult.h"

#include <QList>
#include <QObject>

namespace Fatek {

class RequestTracker;
class Session;

// Finds the PLCs on a link (typically an RS-485 bus): asks each station of a range for its brief
// status (40) with a short timeout and no retries, one at a time, and reports who answers.
class StationScanner : public QObject
{
    Q_OBJECT

public:
    struct Hit
    {
        quint8 station = 0;
        PlcStatus status;
        QByteArray statusBytes; // STATUS1..3 as received
    };

    explicit StationScanner(Session *session, QObject *parent = nullptr);
    // Cancels what is still queued.
    ~StationScanner() override;

    // Starts a scan of first..last (clamped to 1..254); a running scan is cancelled first.
    void start(int first = 1, int last = 254, int timeoutMs = 100);
    void cancel();
    bool isRunning() const;
    QList<Hit> hits() const { return m_hits; }

Q_SIGNALS:
    void stationFound(const Fatek::StationScanner::Hit &hit);
    void progress(int done, int total);
    // The scan ended (completed or cancelled); `hits` in station order.
    void finished(const QList<Fatek::StationScanner::Hit> &hits);

private:
    void onAnswer(quint8 station, const SessionResult &result);

    RequestTracker *m_requests; // the scanner may outlive the session
    QList<Hit> m_hits;
    int m_total = 0;
    int m_done = 0;
};

} // namespace Fatek

Q_DECLARE_METATYPE(Fatek::StationScanner::Hit)
