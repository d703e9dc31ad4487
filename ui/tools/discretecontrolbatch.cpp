#include "discretecontrolbatch.h"

#include "requesttracker.h"

#include <memory>

namespace Fatek {

namespace {

QString verb(DiscreteOp op)
{
    switch (op) {
    case DiscreteOp::Disable: return QStringLiteral("Disable");
    case DiscreteOp::Enable: return QStringLiteral("Enable");
    case DiscreteOp::Set: return QStringLiteral("Set ON");
    case DiscreteOp::Reset: return QStringLiteral("Reset OFF");
    }
    return {};
}

QString pastVerb(DiscreteOp op)
{
    switch (op) {
    case DiscreteOp::Disable: return QStringLiteral("Disabled");
    case DiscreteOp::Enable: return QStringLiteral("Enabled");
    case DiscreteOp::Set: return QStringLiteral("Set ON");
    case DiscreteOp::Reset: return QStringLiteral("Reset OFF");
    }
    return {};
}

} // namespace

bool DiscreteControlBatch::run(RequestTracker *tracker, quint8 station, DiscreteOp op,
                               const QList<Address> &points, Done done)
{
    if (!tracker->session() || points.isEmpty())
        return false;
    struct State
    {
        qsizetype remaining;
        Outcome outcome;
    };
    auto state = std::make_shared<State>(State{points.size(), {}});
    for (const Address &point : points) {
        const QString name = QString::fromStdString(point.toString());
        tracker->submit(Request::discreteControl(station, op, point),
                        [state, name, done](const SessionResult &result) {
                            if (result.ok())
                                ++state->outcome.succeeded;
                            else
                                state->outcome.errors
                                    << QStringLiteral("%1: %2").arg(name, result.errorText());
                            if (--state->remaining == 0 && done)
                                done(state->outcome);
                        });
    }
    return true;
}

QString DiscreteControlBatch::describe(DiscreteOp op, const QList<Address> &points)
{
    QStringList names;
    for (const Address &a : points)
        names << QString::fromStdString(a.toString());
    if (points.size() <= 8)
        return QStringLiteral("%1 %2").arg(verb(op), names.join(QStringLiteral(", ")));
    return QStringLiteral("%1 %2 points (%3, %4 \u2026 %5)")
        .arg(verb(op))
        .arg(points.size())
        .arg(names.at(0), names.at(1), names.last());
}

QString DiscreteControlBatch::outcomeText(DiscreteOp op, const Outcome &outcome)
{
    if (outcome.errors.isEmpty()) {
        return outcome.succeeded == 1
                   ? QStringLiteral("%1 1 point.").arg(pastVerb(op))
                   : QStringLiteral("%1 %2 points.").arg(pastVerb(op)).arg(outcome.succeeded);
    }
    QString text = QStringLiteral("%1: %2 done, %3 failed \u2014 %4")
                       .arg(verb(op))
                       .arg(outcome.succeeded)
                       .arg(outcome.errors.size())
                       .arg(outcome.errors.first());
    if (outcome.errors.size() > 1)
        text += QStringLiteral(" (and %1 more)").arg(outcome.errors.size() - 1);
    return text;
}

} // namespace Fatek
