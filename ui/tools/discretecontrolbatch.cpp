#include "discretecontrolbatch.h"

#include "core/session/requesttracker.h"
#include "ui/common/uitext.h"

#include <QCoreApplication>

#include <memory>

namespace Fatek {

namespace {

QString verb(DiscreteOp op)
{
    switch (op) {
    case DiscreteOp::Disable:
        return QCoreApplication::translate("Fatek::DiscreteControlBatch", "Disable");
    case DiscreteOp::Enable:
        return QCoreApplication::translate("Fatek::DiscreteControlBatch", "Enable");
    case DiscreteOp::Set:
        return QCoreApplication::translate("Fatek::DiscreteControlBatch", "Set ON");
    case DiscreteOp::Reset:
        return QCoreApplication::translate("Fatek::DiscreteControlBatch", "Reset OFF");
    }
    return {};
}

QString pastVerb(DiscreteOp op)
{
    switch (op) {
    case DiscreteOp::Disable:
        return QCoreApplication::translate("Fatek::DiscreteControlBatch", "Disabled");
    case DiscreteOp::Enable:
        return QCoreApplication::translate("Fatek::DiscreteControlBatch", "Enabled");
    //: Past tense, as in "Set ON 3 points."
    case DiscreteOp::Set:
        return QCoreApplication::translate("Fatek::DiscreteControlBatch", "Set ON", "past");
    //: Past tense, as in "Reset OFF 3 points."
    case DiscreteOp::Reset:
        return QCoreApplication::translate("Fatek::DiscreteControlBatch", "Reset OFF", "past");
    }
    return {};
}

} // namespace

bool DiscreteControlBatch::run(RequestTracker *tracker, const PlcTarget &target, DiscreteOp op,
                               const QList<Address> &points, Done done)
{
    if (!target.isDirect() || points.isEmpty())
        return false;
    struct State
    {
        qsizetype remaining;
        Outcome outcome;
    };
    auto state = std::make_shared<State>(State{points.size(), {}});
    // Confirmed now: point i may wait for the i points ahead of it, each at most one timeout (a
    // change is sent once), and not longer.
    const int timeoutMs = target.timeoutMs();
    int ahead = 0;
    for (const Address &point : points) {
        const QString name = QString::fromStdString(point.toString());
        RequestOptions options;
        options.deadline.setRemainingTime(qint64(timeoutMs) * ++ahead);
        tracker->submitChange(
            Request::discreteControl(target.station(), op, point),
            [state, name, done](const ChangeReport &report) {
                if (!report.final)
                    return; // unknown so far: counted once the read-back tells
                if (report.outcome == ChangeOutcome::Done)
                    ++state->outcome.succeeded;
                else
                    state->outcome.errors
                        << QCoreApplication::translate("Fatek::DiscreteControlBatch", "%1: %2")
                               .arg(name, translated(report.message));
                if (--state->remaining == 0 && done)
                    done(state->outcome);
            },
            options);
    }
    return true;
}

QString DiscreteControlBatch::describe(DiscreteOp op, const QList<Address> &points)
{
    QStringList names;
    for (const Address &a : points)
        names << QString::fromStdString(a.toString());
    if (points.size() <= 8)
        return QCoreApplication::translate("Fatek::DiscreteControlBatch", "%1 %2")
            .arg(verb(op), names.join(QStringLiteral(", ")));
    const int count = static_cast<int>(points.size());
    //: %1 is the action (Disable, Set ON...), %2..%4 the first, second and last point.
    return QCoreApplication::translate("Fatek::DiscreteControlBatch",
                                       "%1 %n points (%2, %3 \u2026 %4)", nullptr, count)
        .arg(verb(op), names.at(0), names.at(1), names.last());
}

QString DiscreteControlBatch::outcomeText(DiscreteOp op, const Outcome &outcome)
{
    if (outcome.errors.isEmpty()) {
        // Two texts rather than %n: the English must read right without a translator loaded.
        //: %1 is the past action (Disabled, Enabled, Set ON, Reset OFF).
        return outcome.succeeded == 1
                   ? QCoreApplication::translate("Fatek::DiscreteControlBatch", "%1 1 point.")
                         .arg(pastVerb(op))
                   : QCoreApplication::translate("Fatek::DiscreteControlBatch", "%1 %2 points.")
                         .arg(pastVerb(op))
                         .arg(outcome.succeeded);
    }
    QString text = QCoreApplication::translate("Fatek::DiscreteControlBatch",
                                               "%1: %2 done, %3 failed \u2014 %4")
                       .arg(verb(op))
                       .arg(outcome.succeeded)
                       .arg(outcome.errors.size())
                       .arg(outcome.errors.first());
    if (outcome.errors.size() > 1)
        text += QCoreApplication::translate("Fatek::DiscreteControlBatch", " (and %1 more)")
                    .arg(outcome.errors.size() - 1);
    return text;
}

} // namespace Fatek
