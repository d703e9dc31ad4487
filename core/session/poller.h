#pragma once

// Internal to fateksession (compiled with QT_NO_KEYWORDS: PlanStep has a member named "slots").

#include "core/planner/pollplanner.h"
#include "core/protocol/address.h"
#include "sessionresult.h"
#include "watchvalue.h"

#include <QDateTime>
#include <QElapsedTimer>
#include <QHash>
#include <QList>
#include <QMetaType>
#include <QObject>
#include <QTimer>

#include <functional>
#include <map>
#include <optional>
#include <set>
#include <vector>

namespace Fatek {

// The polling engine of a session (lives in the worker thread). Items are grouped by interval;
// each group is planned by PollPlanner and cycles on absolute deadlines: period max(interval,
// cycle time), no drift, never catch-up bursts. A batch failing with PLC error A or 2 is split
// until the bad element is found; only that element is marked, and later plans keep it alone.
class Poller : public QObject
{
    Q_OBJECT

public:
    using SubmitFunction
        = std::function<void(const Request &, std::function<void(const SessionResult &)>)>;

    explicit Poller(SubmitFunction submit, QObject *parent = nullptr);

    void setProtocol(Protocol protocol);
    void setWatchList(const QList<WatchEntry> &entries);
    // Polling runs only while the link is up.
    void setLinkUp(bool up);

    // Elements remembered as refused by the PLC.
    const std::set<StationAddress> &isolated() const { return m_isolated; }

Q_SIGNALS:
    void values(const QList<Fatek::WatchValue> &values);
    void cycleCompleted(double milliseconds);

private:
    struct Group
    {
        int intervalMs = 1000;
        std::vector<WatchItem> items;
        Plan plan;
        qint64 deadline = 0; // ms on m_clock
        bool inFlight = false;
        bool replan = false;
        int outstanding = 0;
        qint64 cycleStart = 0;
        quint64 generation = 0;
        QHash<std::uint64_t, WatchValue> cycleValues;
    };

    void replan(Group &group);
    void reschedule();
    void onTimer();
    void startCycle(Group &group);
    void submitStep(Group &group, const PlanStep &step);
    void onStepDone(int intervalMs, quint64 generation, const PlanStep &step,
                    const SessionResult &result);
    void finishCycle(Group &group);

    SubmitFunction m_submit;
    std::optional<PollPlanner> m_planner;
    std::map<int, Group> m_groups;
    // Last good value of each item, for Stale reports: only what they need (16 bytes, not a
    // whole WatchValue: this is per watched item, see docs/performance.md).
    struct LastGood
    {
        std::uint32_t value = 0;
        QDateTime timestamp;
    };
    QHash<std::uint64_t, LastGood> m_lastGood;
    std::set<StationAddress> m_isolated;
    bool m_linkUp = false;
    quint64 m_generation = 0;
    QElapsedTimer m_clock;
    QTimer m_timer{this}; // a child: follows the poller to its thread
};

} // namespace Fatek
