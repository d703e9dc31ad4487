#pragma once

// Internal to fateksession (compiled with QT_NO_KEYWORDS: PlanStep has a member named "slots").

#include "core/planner/pollplanner.h"
#include "core/protocol/address.h"
#include "sessionresult.h"
#include "sessiontypes.h"
#include "watchvalue.h"

#include <QDateTime>
#include <QElapsedTimer>
#include <QHash>
#include <QList>
#include <QMetaType>
#include <QObject>
#include <QTimer>

#include <deque>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <vector>

namespace Fatek {

// The polling engine of a session (lives in the worker thread). Items are grouped by interval and
// station; each group is planned by PollPlanner and cycles on absolute deadlines: period
// max(interval, cycle time), no drift, never catch-up bursts. A group has one request in the queue
// at a time, so the stations of a line take turns and one-shot requests get the line between any
// two poll requests.
//
// Field faults (issue 31): a station that leaves `demoteAfter` requests in a row unanswered is
// demoted: not polled for `demotionMs`, then tried once; meanwhile its items are stale with the
// reason and the next try, and the other stations keep their rate. A batch failing with PLC
// error A or 2 is split until the bad element is found; only that element is marked, later plans
// keep it alone, and it is asked again only every refusalRecheckMs, without counting as an error.
// A group whose cycle is overdue by twice its interval reports its good values as late.
class Poller : public QObject
{
    Q_OBJECT

public:
    using SubmitFunction = std::function<void(const Request &, const RequestOptions &,
                                              std::function<void(const SessionResult &)>)>;
    static constexpr qint64 refusalRecheckMs = 60000;

    struct Policy
    {
        int demoteAfter = 3; // 0: never demote
        int demotionMs = 10000;
    };

    explicit Poller(SubmitFunction submit, Policy policy, QObject *parent = nullptr);

    void setProtocol(Protocol protocol);
    void setWatchList(const QList<WatchEntry> &entries);
    // Polling runs only while the link is up.
    void setLinkUp(bool up);

    // Elements remembered as refused by the PLC.
    const std::set<StationAddress> &isolated() const { return m_isolated; }

    // The station's health, for the session's other requests to it: a station that left a
    // request unanswered is suspect (one attempt, no retries); a demoted one rests, and its
    // routine reads are not sent (`reason` says until when).
    bool isSuspect(quint8 station) const;
    bool isResting(quint8 station, Message *reason = nullptr) const;
    // What a request of someone else told about the station (an answer ends a demotion early,
    // no answer counts towards one).
    void noteAnswer(quint8 station, const SessionResult &result);

Q_SIGNALS:
    void values(const QList<Fatek::WatchValue> &values);
    void cycleCompleted(double milliseconds);
    // A station was demoted (`demoted`, with the time of its next try) or answers again.
    void stationHealthChanged(quint8 station, bool demoted, const QDateTime &nextTry,
                              int unanswered);

private:
    using GroupKey = std::pair<int, quint8>; // interval, station
    // Last good value of an item, for Stale reports: only what they need (16 bytes, not a whole
    // WatchValue: this is per watched item, see docs/performance.md).
    struct LastGood
    {
        std::uint32_t value = 0;
        QDateTime timestamp;
    };
    struct Group
    {
        int intervalMs = 1000;
        quint8 station = 1;
        std::vector<WatchItem> items;
        Plan plan;
        qint64 deadline = 0; // ms on m_clock
        bool inFlight = false;
        bool replan = false;
        std::deque<PlanStep> pending; // steps of this cycle not submitted yet
        int outstanding = 0;          // submitted, not finished
        qint64 cycleStart = 0;
        quint64 generation = 0;
        // Per item, by position in `items` (the plan's slots name it): arrays, not hash tables
        // by id, since this is per watched item.
        std::vector<LastGood> lastGood;
        QList<WatchValue> cycleValues; // this cycle's values, where cycleFilled says
        std::vector<bool> cycleFilled;
        qint64 lastDelivery = 0; // ms on m_clock: the last batch, or the group's start
        bool lateReported = false;
        bool trial = false;                      // this cycle tries a demoted station
        bool submitting = false;                 // inside submitNext()
        std::vector<std::uint32_t> goodLastTime; // positions of the items good in the last batch
    };
    struct StationHealth
    {
        int unanswered = 0; // poll requests in a row without an answer
        bool demoted = false;
        qint64 until = 0;      // ms on m_clock: end of the demotion
        bool trialOut = false; // a group of the station is trying it
    };

    void replan(Group &group);
    void reschedule();
    void onTimer();
    void startCycle(Group &group);
    void submitNext(Group &group);
    void onStepDone(GroupKey key, quint64 generation, const PlanStep &step,
                    const SessionResult &result);
    // The station's items of `steps` are stale because it is demoted.
    void markDemoted(Group &group, const std::vector<PlanStep> &steps);
    Message demotedReason(quint8 station) const;
    void reportLate(Group &group, qint64 now);
    void finishCycle(Group &group);
    static void setCycleValue(Group &group, std::uint32_t index, WatchValue value);
    static std::set<StationAddress> elementsOf(const PlanStep &step);
    bool isRefusal(const PlanStep &step) const;

    SubmitFunction m_submit;
    Policy m_policy;
    std::optional<PollPlanner> m_planner;
    std::map<GroupKey, Group> m_groups;
    std::map<quint8, StationHealth> m_health;
    std::set<StationAddress> m_isolated;
    // Isolated elements: the refusal to show, and when to ask again (ms on m_clock).
    struct Refusal
    {
        Message reason;
        qint64 recheckAt = 0;
    };
    std::map<StationAddress, Refusal> m_refusals;
    bool m_linkUp = false;
    quint64 m_generation = 0;
    QElapsedTimer m_clock;
    QTimer m_timer{this}; // a child: follows the poller to its thread
};

} // namespace Fatek
