#include "checkoutrunner.h"

#include "checkoutfile.h"
#include "commissionmessages.h"
#include "core/protocol/plcstatus.h"
#include "core/session/session.h"
#include "memorysnapshot.h"

#include <QTimer>

#include <algorithm>

namespace Fatek {

namespace {

std::uint8_t stationOf(const CheckoutPlan &plan)
{
    return static_cast<std::uint8_t>(std::clamp(plan.info.station, 1, 254));
}

bool contains(const std::vector<Address> &list, const Address &a)
{
    return std::find(list.begin(), list.end(), a) != list.end();
}

// Whether it was there.
bool erase(std::vector<Address> &list, const Address &a)
{
    return std::erase(list, a) > 0;
}

} // namespace

CheckoutRunner::CheckoutRunner(QObject *parent)
    : QObject(parent)
{
    m_pollTimer.setSingleShot(true);
    connect(&m_pollTimer, &QTimer::timeout, this, &CheckoutRunner::pollCycle);
    m_releaseRetry.setSingleShot(true);
    m_releaseRetry.setInterval(2000);
    connect(&m_releaseRetry, &QTimer::timeout, this, &CheckoutRunner::retryReleases);
}

CheckoutRunner::~CheckoutRunner()
{
    // No answer can come back to a destroyed runner: the releases are queued without a context,
    // and the session sends accepted writes before it closes. The file keeps them recorded as
    // forced until a later start has seen them released.
    Session *s = session();
    if (!s)
        return;
    const std::uint8_t station = stationOf(m_plan);
    for (const Address &a : m_plan.forced) {
        s->submit(Request::discreteControl(station, DiscreteOp::Reset, a));
        s->submit(Request::discreteControl(station, DiscreteOp::Enable, a));
    }
}

void CheckoutRunner::setSession(Session *session)
{
    if (m_linkConnection)
        disconnect(m_linkConnection);
    m_actions.setSession(session);
    m_polls.setSession(session);
    if (session)
        m_linkConnection = connect(session, &Session::linkStateChanged, this,
                                   [this](LinkState state) { onLinkState(state); });
}

void CheckoutRunner::setPlan(CheckoutPlan plan)
{
    m_plan = std::move(plan);
    m_inputs.clear();
    m_current = -1;
    m_outputUnderTest = -1;
}

void CheckoutRunner::start()
{
    if (m_running)
        return;
    Session *s = session();
    if (!s) {
        fail(makeError(ErrorKind::LinkError, msg<MsgId::CheckoutNoSession>()));
        return;
    }
    m_running = true;
    m_inputs.clear();
    // The packed reads of the inputs: consecutive runs, at most 256 points each.
    std::vector<Address> inputs;
    for (const CheckoutPoint &p : m_plan.points) {
        if (p.kind == CheckoutKind::Input)
            inputs.push_back(p.address);
    }
    std::sort(inputs.begin(), inputs.end());
    m_pollRequests.clear();
    for (const AddressRange &r : Snapshot::rangesOf(inputs)) {
        for (std::uint32_t done = 0; done < r.count; done += Limits::maxDiscretes) {
            m_pollRequests.push_back(
                Request::readDiscretes(stationOf(m_plan), r.start.advanced(done),
                                       std::min(Limits::maxDiscretes, r.count - done)));
        }
    }
    m_actions.submit(Request::detailStatus(stationOf(m_plan)),
                     [this](const SessionResult &r) { onStatus(r); });
}

void CheckoutRunner::onStatus(const SessionResult &result)
{
    if (!m_running)
        return;
    if (result.ok()) {
        const DetailStatus status = DetailStatus::decode(result.response().data);
        m_plcRunning = status.status.running;
        if (const auto model = status.modelName())
            m_plan.info.plcModel = QString::fromStdString(*model);
        if (const auto os = status.osVersionText())
            m_plan.info.osVersion = QString::fromStdString(*os);
        if (!m_plan.info.created.isValid())
            m_plan.info.created = QDateTime::currentDateTimeUtc();
        save();
    } else {
        fail(result.error());
    }
    if (hasForced())
        releaseAllForced(true);
    Q_EMIT started();
    pollCycle();
}

void CheckoutRunner::stop()
{
    if (!m_running)
        return;
    m_running = false;
    m_pollTimer.stop();
    m_polls.cancelPending();
    m_pollsInFlight = 0;
    m_outputUnderTest = -1;
    if (hasForced())
        releaseAllForced(false);
}

void CheckoutRunner::setCurrentPoint(int index)
{
    if (index < -1 || index >= static_cast<int>(m_plan.points.size()) || index == m_current)
        return;
    m_current = index;
    Q_EMIT currentPointChanged(index);
}

void CheckoutRunner::nextPoint()
{
    const int n = static_cast<int>(m_plan.points.size());
    for (int step = 1; step <= n; ++step) {
        const int i = ((m_current < 0 ? -1 : m_current) + step) % n;
        if (m_plan.points[static_cast<std::size_t>(i)].result == CheckoutResult::Untested) {
            setCurrentPoint(i);
            return;
        }
    }
    setCurrentPoint(-1);
}

void CheckoutRunner::markResult(CheckoutPoint &p, CheckoutResult result)
{
    p.result = result;
    p.time = QDateTime::currentDateTimeUtc();
    p.engineer = m_engineer.isEmpty() ? m_plan.info.engineer : m_engineer;
}

void CheckoutRunner::record(int index, CheckoutResult result, const QString &comment)
{
    if (index < 0 || index >= static_cast<int>(m_plan.points.size()))
        return;
    CheckoutPoint &p = m_plan.points[static_cast<std::size_t>(index)];
    markResult(p, result);
    if (!comment.isNull())
        p.comment = comment;
    changed(index);
}

void CheckoutRunner::setComment(int index, const QString &comment)
{
    if (index < 0 || index >= static_cast<int>(m_plan.points.size()))
        return;
    m_plan.points[static_cast<std::size_t>(index)].comment = comment;
    changed(index);
}

void CheckoutRunner::changed(int index)
{
    save();
    Q_EMIT pointChanged(index);
}

void CheckoutRunner::save()
{
    if (m_filePath.isEmpty())
        return;
    const Status s = CheckoutFile::saveToFile(m_plan, m_filePath);
    if (s) {
        m_saveError.reset();
        return;
    }
    m_saveError = s.error().message;
    Q_EMIT saveFailed(*m_saveError);
}

void CheckoutRunner::fail(ProtocolError error)
{
    Q_EMIT failed(error);
}

// Inputs.

void CheckoutRunner::pollCycle()
{
    if (!m_running || m_pollsInFlight > 0)
        return;
    std::vector<Request> requests = m_pollRequests;
    const bool analog
        = m_current >= 0
          && m_plan.points[static_cast<std::size_t>(m_current)].kind == CheckoutKind::Analog;
    if (analog)
        requests.push_back(Request::readRegisters(
            stationOf(m_plan), m_plan.points[static_cast<std::size_t>(m_current)].address, 1));
    if (requests.empty())
        return;
    m_pollsInFlight = static_cast<int>(requests.size());
    for (const Request &r : requests) {
        m_polls.submit(
            r, [this, r](const SessionResult &result) { onInputs(r, result); }, {},
            Priority::Background);
    }
}

void CheckoutRunner::onInputs(const Request &request, const SessionResult &result)
{
    if (--m_pollsInFlight <= 0) {
        m_pollsInFlight = 0;
        if (m_running)
            m_pollTimer.start(m_pollIntervalMs);
    }
    if (!m_running || !result.ok())
        return;
    const std::vector<std::uint32_t> &values = result.response().values;
    for (std::uint32_t i = 0; i < values.size() && i < request.count; ++i) {
        const Address a = request.start.advanced(i);
        const int index = m_plan.indexOf(a);
        if (index < 0)
            continue;
        Q_EMIT liveValue(index, values[i]);
        if (request.command != Command::ReadDiscretes)
            continue;
        const bool on = values[i] != 0;
        const auto last = m_inputs.find(a);
        const bool moved = last != m_inputs.end() && last->second != on;
        m_inputs[a] = on;
        if (moved)
            inputChanged(index, on);
    }
}

void CheckoutRunner::inputChanged(int index, bool on)
{
    const auto testing = [this](int i) {
        if (i < 0)
            return false;
        const CheckoutPoint &p = m_plan.points[static_cast<std::size_t>(i)];
        return p.kind == CheckoutKind::Input && p.result == CheckoutResult::Untested;
    };
    int target = index;
    if (testing(m_current) && index != m_current) {
        CheckoutPoint &underTest = m_plan.points[static_cast<std::size_t>(m_current)];
        const Address a = m_plan.points[static_cast<std::size_t>(index)].address;
        if (std::find(underTest.changedWith.begin(), underTest.changedWith.end(), a)
            == underTest.changedWith.end())
            underTest.changedWith.push_back(a);
        changed(m_current);
        Q_EMIT crossedWiring(
            index, m_current,
            msg<MsgId::CheckoutCrossedWiring>(a.toString(), underTest.address.toString()));
        return;
    }
    if (!testing(target))
        return;
    CheckoutPoint &p = m_plan.points[static_cast<std::size_t>(target)];
    (on ? p.rose : p.fell) = QDateTime::currentDateTimeUtc();
    if (p.rose.isValid() && p.fell.isValid())
        markResult(p, CheckoutResult::Passed);
    changed(target);
    if (p.result == CheckoutResult::Passed && m_autoAdvance && target == m_current) {
        // The next untested input after this one.
        const int n = static_cast<int>(m_plan.points.size());
        for (int step = 1; step < n; ++step) {
            const int i = (target + step) % n;
            if (testing(i))
                return setCurrentPoint(i);
        }
        setCurrentPoint(-1);
    }
}

// Outputs.

void CheckoutRunner::forceOutput(int index)
{
    Session *s = session();
    if (index < 0 || index >= static_cast<int>(m_plan.points.size())
        || m_plan.points[static_cast<std::size_t>(index)].kind != CheckoutKind::Output) {
        const std::string what
            = index >= 0 && index < static_cast<int>(m_plan.points.size())
                  ? m_plan.points[static_cast<std::size_t>(index)].address.toString()
                  : std::to_string(index);
        return fail(makeError(ErrorKind::InvalidRequest, msg<MsgId::CheckoutNotOutput>(what)));
    }
    if (!s)
        return fail(makeError(ErrorKind::LinkError, msg<MsgId::CheckoutNoSession>()));
    // Core refuses the writes in operator mode anyway; said here first, before anything is
    // recorded as forced.
    if (s->isReadOnly())
        return fail(makeError(ErrorKind::ReadOnly, msg<MsgId::CheckoutReadOnly>()));
    const Address address = m_plan.points[static_cast<std::size_t>(index)].address;
    // Its release not confirmed yet: a release still on the wire would undo the new force.
    if (contains(m_releasing, address) || contains(m_releaseFailed, address))
        return fail(makeError(ErrorKind::InvalidRequest,
                              msg<MsgId::CheckoutStillReleasing>(address.toString())));
    if (m_outputUnderTest >= 0)
        return fail(makeError(
            ErrorKind::InvalidRequest,
            msg<MsgId::CheckoutOutputBusy>(
                m_plan.points[static_cast<std::size_t>(m_outputUnderTest)].address.toString())));
    setCurrentPoint(index);
    m_outputUnderTest = index;
    // RUN or STOP now, not at the start: someone may have switched it meanwhile.
    m_actions.submit(
        Request::briefStatus(stationOf(m_plan)), [this, index](const SessionResult &r) {
            if (!r.ok()) {
                m_outputUnderTest = -1;
                return fail(r.error());
            }
            const auto &data = r.response().data;
            m_plcRunning = !data.empty() && PlcStatus::fromStatus1(data.front()).running;
            if (m_plcRunning && !m_allowInRun) {
                // A question, not a failure: what happens is said once it is answered.
                m_outputUnderTest = -1;
                return Q_EMIT runConfirmationNeeded(
                    index, msg<MsgId::CheckoutPlcInRun>(
                               m_plan.points[static_cast<std::size_t>(index)].address.toString()));
            }
            doForce(index);
        });
}

void CheckoutRunner::doForce(int index)
{
    const Address a = m_plan.points[static_cast<std::size_t>(index)].address;
    // Recorded before it is forced: a PC that dies now leaves a file that says what to release.
    if (std::find(m_plan.forced.begin(), m_plan.forced.end(), a) == m_plan.forced.end())
        m_plan.forced.push_back(a);
    save();
    if (m_saveError) {
        m_plan.forced.erase(std::remove(m_plan.forced.begin(), m_plan.forced.end(), a),
                            m_plan.forced.end());
        m_outputUnderTest = -1;
        return fail(makeError(ErrorKind::InvalidRequest, *m_saveError));
    }
    const std::uint8_t station = stationOf(m_plan);
    const auto failed = [this, a, index](const SessionResult &r) {
        if (m_outputUnderTest == index)
            m_outputUnderTest = -1;
        ProtocolError e = r.error();
        e.message = msg<MsgId::CheckoutForceFailed>(a.toString(), r.error().message);
        fail(std::move(e));
        // The disable may have reached the PLC: release.
        release(a, false);
    };
    // Forced now or not at all (a force that waited behind a silent line must not surprise the
    // person later): each step not sent later than a timeout after it was due. A release has no
    // deadline: it is always wanted.
    Session *session = m_actions.session();
    m_actions.submit(
        Request::discreteControl(station, DiscreteOp::Disable, a),
        [this, a, station, index, failed](const SessionResult &r) {
            if (!r.ok())
                return failed(r);
            // Stopped meanwhile (Ctrl-C): not set; the release follows the disable.
            if (m_outputUnderTest != index || !m_actions.session())
                return release(a, false);
            m_actions.submit(
                Request::discreteControl(station, DiscreteOp::Set, a),
                [this, index, failed](const SessionResult &r2) {
                    if (!r2.ok())
                        return failed(r2);
                    if (m_outputUnderTest == index)
                        Q_EMIT outputForced(index);
                },
                ChangeVerifier::confirmedNow(m_actions.session()));
        },
        ChangeVerifier::confirmedNow(session));
}

void CheckoutRunner::answerOutput(bool seen, const QString &comment)
{
    const int index = m_outputUnderTest;
    if (index < 0)
        return;
    m_outputUnderTest = -1;
    CheckoutPoint &p = m_plan.points[static_cast<std::size_t>(index)];
    p.seen = seen;
    markResult(p, seen ? CheckoutResult::Passed : CheckoutResult::Failed);
    if (!comment.isNull())
        p.comment = comment;
    changed(index);
    release(p.address, false);
}

void CheckoutRunner::release(const Address &address, bool leftover, bool checkFirst)
{
    Session *s = session();
    if (!s || contains(m_releasing, address))
        return;
    m_releasing.push_back(address);
    const std::uint8_t station = stationOf(m_plan);
    const auto resetAndEnable = [this, address, station, leftover] {
        // Off first while still forced, then back to the program.
        m_actions.submit(Request::discreteControl(station, DiscreteOp::Reset, address),
                         [this, address, station, leftover](const SessionResult &r) {
                             if (!r.ok())
                                 return releaseDone(address, leftover, r);
                             m_actions.submit(
                                 Request::discreteControl(station, DiscreteOp::Enable, address),
                                 [this, address, leftover](const SessionResult &r2) {
                                     releaseDone(address, leftover, r2);
                                 });
                         });
    };
    if (!checkFirst)
        return resetAndEnable();
    m_actions.submit(Request::readEnableFlags(station, address, 1),
                     [this, address, leftover, resetAndEnable](const SessionResult &r) {
                         const bool enabled = r.ok() && !r.response().values.empty()
                                              && r.response().values.front() == 0;
                         if (!r.ok() || enabled)
                             return releaseDone(address, leftover, r);
                         resetAndEnable();
                     });
}

void CheckoutRunner::releaseDone(const Address &address, bool leftover, const SessionResult &result)
{
    erase(m_releasing, address);
    if (!result.ok()) {
        // A timeout says nothing of what the PLC did: tried again until it confirms.
        if (!contains(m_releaseFailed, address)) {
            m_releaseFailed.push_back(address);
            ProtocolError e = result.error();
            e.message = msg<MsgId::CheckoutReleaseFailed>(address.toString(), e.message);
            fail(std::move(e));
        }
        if (!m_releaseRetry.isActive())
            m_releaseRetry.start();
        return;
    }
    const bool retried = erase(m_releaseFailed, address);
    erase(m_plan.forced, address);
    save();
    // Said before outputReleased(), which may end a program.
    if (leftover || retried)
        Q_EMIT leftoversReleased(msg<MsgId::CheckoutReleased>(address.toString()));
    Q_EMIT outputReleased(address);
}

void CheckoutRunner::releaseAllForced(bool leftover)
{
    const std::vector<Address> forced = m_plan.forced;
    for (const Address &a : forced)
        release(a, leftover, leftover);
}

void CheckoutRunner::retryReleases()
{
    Session *s = session();
    // Down: onLinkState() tries again once it is back.
    if (!s || s->linkState() != LinkState::Connected)
        return;
    const std::vector<Address> failed = m_releaseFailed;
    for (const Address &a : failed) {
        if (contains(m_plan.forced, a))
            release(a, true, true);
        else
            erase(m_releaseFailed, a);
    }
}

void CheckoutRunner::onLinkState(LinkState state)
{
    if (state == LinkState::Connected) {
        if (m_linkLost && hasForced())
            releaseAllForced(true);
        else
            retryReleases();
        m_linkLost = false;
        if (m_running && m_pollsInFlight == 0 && !m_pollTimer.isActive())
            pollCycle();
        return;
    }
    if (state == LinkState::Lost || state == LinkState::Reconnecting
        || state == LinkState::Closed) {
        if (m_linkLost)
            return;
        m_linkLost = true;
        // The requests on the wire fail; the next answers start a fresh baseline.
        m_inputs.clear();
        if (m_outputUnderTest >= 0 || hasForced()) {
            m_outputUnderTest = -1;
            fail(makeError(ErrorKind::LinkError, msg<MsgId::CheckoutLinkLost>()));
        }
    }
}

// Analog.

void CheckoutRunner::recordAnalog(int index, bool highEnd)
{
    if (index < 0 || index >= static_cast<int>(m_plan.points.size())
        || m_plan.points[static_cast<std::size_t>(index)].kind != CheckoutKind::Analog)
        return;
    const Address a = m_plan.points[static_cast<std::size_t>(index)].address;
    m_actions.submit(Request::readRegisters(stationOf(m_plan), a, 1), [this, index, highEnd,
                                                                       a](const SessionResult &r) {
        if (!r.ok() || r.response().values.empty()) {
            ProtocolError e = r.ok()
                                  ? makeError(ErrorKind::MalformedResponse, std::string("no value"))
                                  : r.error();
            e.message = msg<MsgId::CheckoutReadFailed>(a.toString(), e.message);
            return fail(std::move(e));
        }
        CheckoutPoint &p = m_plan.points[static_cast<std::size_t>(index)];
        const std::uint32_t v = r.response().values.front();
        (highEnd ? p.highValue : p.lowValue) = v;
        if (p.lowValue && p.highValue) {
            const bool ok = p.withinTolerance(*p.lowValue, p.expectedLow)
                            && p.withinTolerance(*p.highValue, p.expectedHigh);
            markResult(p, ok ? CheckoutResult::Passed : CheckoutResult::Failed);
        }
        Q_EMIT liveValue(index, v);
        changed(index);
    });
}

} // namespace Fatek
