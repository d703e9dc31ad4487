#pragma once

#include "core/plant/plctarget.h"
#include "core/protocol/address.h"
#include "core/protocol/request.h"

#include <QList>
#include <QString>
#include <QStringList>

#include <functional>

namespace Fatek {

class RequestTracker;

// Sends one 42 (disable / enable / set / reset) per point and reports once every answer is in.
// All requests are queued at once: the session serves its user queue in order, one at a time.
class DiscreteControlBatch
{
public:
    struct Outcome
    {
        int succeeded = 0;
        QStringList errors; // "Y3: PLC error A: illegal address Y3"
    };
    using Done = std::function<void(const Outcome &)>;

    // Sends through `tracker` (aimed at `target`) to the target's station. Returns false (and
    // calls nothing) without a direct link or without a point.
    static bool run(RequestTracker *tracker, const PlcTarget &target, DiscreteOp op,
                    const QList<Address> &points, Done done);

    // "Disable Y0, Y1, Y2" / "Enable 40 points (M0 … M39)" for questions and messages.
    static QString describe(DiscreteOp op, const QList<Address> &points);
    // "Disabled 3 points." or "Disable: 2 done, 1 failed — Y3: PLC error A: illegal address Y3".
    static QString outcomeText(DiscreteOp op, const Outcome &outcome);
};

} // namespace Fatek
