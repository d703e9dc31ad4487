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
    // Every result names who recorded it: a record signed by nobody is refused.
    if (m_engineer.trimmed().isEmpty() && m_plan.info.engineer.trimmed().isEmpty()) {
        fail(makeError(ErrorKind::InvalidRequest, msg<MsgId::CheckoutNoEngineer>()));
        return;
    }
    m_running = true;
    m_starting = true;
    m_inputs.clear();
    m_pollError.reset();
    m_refused.clear();
    m_refusal.reset();
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
    probePoints();
}

void CheckoutRunner::probePoints()
{
    // One read of every run: X9999 on a small model is said now, by name, not as polls that fail
    // for ever or a force the PLC refuses.
    std::vector<Address> all;
    for (const CheckoutPoint &p : m_plan.points)
        all.push_back(p.address);
    std::sort(all.begin(), all.end());
    const std::uint8_t station = stationOf(m_plan);
    const auto readOf = [station](const Address &start, std::uint32_t count) {
        return isDiscrete(start.type) ? Request::readDiscretes(station, start, count)
                                      : Request::readRegisters(station, start, count);
    };
    const auto submit = [this](const Request &request, auto onRefused) {
        ++m_probesInFlight;
        m_actions.submit(request, [this, onRefused](const SessionResult &r) {
            if (!r.ok() && r.error().kind == ErrorKind::PlcError) {
                if (!m_refusal)
                    m_refusal = r.error().message;
                onRefused();
            } else if (!r.ok()) {
                fail(r.error()); // a timeout: said, and the polls go on
            }
            probeDone();
        });
    };
    for (const AddressRange &range : Snapshot::rangesOf(all)) {
        const std::uint32_t chunk
            = isDiscrete(range.start.type)
                  ? Limits::maxDiscretes
                  : Limits::maxRegisterWords
                        / static_cast<std::uint32_t>(wordCount(range.start.type));
        for (std::uint32_t done = 0; done < range.count; done += chunk) {
            const Address start = range.start.advanced(done);
            const std::uint32_t count = std::min(chunk, range.count - done);
            // Refused as a whole: each point alone says which.
            submit(readOf(start, count), [this, start, count, readOf, submit] {
                if (count == 1)
                    return m_refused.push_back(start);
                for (std::uint32_t i = 0; i < count; ++i) {
                    const Address one = start.advanced(i);
                    submit(readOf(one, 1), [this, one] { m_refused.push_back(one); });
                }
            });
        }
    }
    if (m_probesInFlight == 0)
        probeDone();
}

void CheckoutRunner::probeDone()
{
    if (m_probesInFlight > 0 && --m_probesInFlight > 0)
        return;
    if (!m_running)
        return;
    m_starting = false;
    if (!m_refused.empty()) {
        m_running = false;
        std::sort(m_refused.begin(), m_refused.end());
        const std::string list = Snapshot::rangesText(m_refused, 20);
        Q_EMIT refused(msg<MsgId::CheckoutPointsRefused>(list, m_refusal ? *m_refusal : Message(),
                                                         static_cast<int>(m_refused.size())));
        return;
    }
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

void CheckoutRunner::archiveAttempt(CheckoutPoint &p)
{
    if (p.result == CheckoutResult::Untested)
        return;
    p.earlier.push_back(p.attempt());
    p.attempt() = CheckoutAttempt{};
}

CheckoutPoint *CheckoutRunner::pointAt(int index)
{
    if (index < 0 || index >= static_cast<int>(m_plan.points.size()))
        return nullptr;
    return &m_plan.points[static_cast<std::size_t>(index)];
}

Status CheckoutRunner::record(int index, CheckoutResult result, const QString &comment)
{
    CheckoutPoint *p = pointAt(index);
    if (!p)
        return makeError(ErrorKind::InvalidRequest,
                         msg<MsgId::CheckoutNoSuchPoint>(std::to_string(index)));
    if (result == CheckoutResult::Untested) {
        retest(index);
        return Ok{};
    }
    const std::string name = p->address.toString();
    const QString text = comment.isNull() ? p->comment : comment;
    const auto refuse = [](Message why) {
        return makeError(ErrorKind::InvalidRequest, std::move(why));
    };
    if (result == CheckoutResult::PassedWithRemark && text.trimmed().isEmpty())
        return refuse(msg<MsgId::CheckoutNeedsRemark>(name));
    if (result == CheckoutResult::Deferred && text.trimmed().isEmpty())
        return refuse(msg<MsgId::CheckoutNeedsReason>(name));
    if (p->kind == CheckoutKind::Analog
        && (result == CheckoutResult::Passed || result == CheckoutResult::Failed))
        return refuse(msg<MsgId::CheckoutMeasuredOnly>(name));
    // The flag belongs to the attempt being recorded: a point that has a result is a new test.
    const bool retest = p->result != CheckoutResult::Untested;
    if (result == CheckoutResult::Passed && !retest && !p->changedWith.empty())
        return refuse(
            msg<MsgId::CheckoutCrossedCannotPass>(name, Snapshot::rangesText(p->changedWith)));
    // The output under test answered by hand (passed with remark, deferred, not applicable):
    // released at once, as answerOutput() does.
    const bool forced = index == m_outputUnderTest;
    if (forced)
        m_outputUnderTest = -1;
    // A new test keeps the old one; measurements of the untested attempt stay with it.
    archiveAttempt(*p);
    markResult(*p, result);
    // Seen in the field with something to note: the answer is part of the record.
    if (forced && (result == CheckoutResult::Passed || result == CheckoutResult::PassedWithRemark))
        p->seen = true;
    if (!comment.isNull())
        p->comment = comment;
    changed(index);
    if (forced)
        release(p->address, false);
    return Ok{};
}

void CheckoutRunner::retest(int index)
{
    CheckoutPoint *p = pointAt(index);
    if (!p || index == m_outputUnderTest)
        return;
    archiveAttempt(*p);
    // An untested attempt with partial measurements starts clean too.
    p->attempt() = CheckoutAttempt{};
    changed(index);
}

Status CheckoutRunner::setPunchOwner(int index, const QString &owner)
{
    CheckoutPoint *p = pointAt(index);
    if (!p || !p->onPunchList())
        return makeError(
            ErrorKind::InvalidRequest,
            msg<MsgId::CheckoutNotOnPunchList>(p ? p->address.toString() : std::to_string(index)));
    p->punch.owner = owner;
    changed(index);
    return Ok{};
}

Status CheckoutRunner::closePunch(int index, const QString &closedBy)
{
    CheckoutPoint *p = pointAt(index);
    if (!p || !p->onPunchList())
        return makeError(
            ErrorKind::InvalidRequest,
            msg<MsgId::CheckoutNotOnPunchList>(p ? p->address.toString() : std::to_string(index)));
    if (p->result == CheckoutResult::Failed || p->result == CheckoutResult::Untested)
        return makeError(ErrorKind::InvalidRequest,
                         msg<MsgId::CheckoutPunchStillFailing>(p->address.toString()));
    p->punch.closed = QDateTime::currentDateTimeUtc();
    p->punch.closedBy = closedBy.isEmpty()
                            ? (m_engineer.isEmpty() ? m_plan.info.engineer : m_engineer)
                            : closedBy;
    changed(index);
    return Ok{};
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
    if (!m_running)
        return;
    if (!result.ok()) {
        // Said once per failure, not once per poll; the values were not read, so no edge.
        if (!m_pollError || !(*m_pollError == result.error().message)) {
            m_pollError = result.error().message;
            ProtocolError e = result.error();
            e.message = msg<MsgId::CheckoutReadFailed>(
                AddressRange{request.start, request.count}.toString(), e.message);
            fail(std::move(e));
        }
        m_inputs.clear();
        return;
    }
    if (m_pollError) {
        m_pollError.reset();
        Q_EMIT readAgain(
            msg<MsgId::CheckoutReadAgain>(AddressRange{request.start, request.count}.toString()));
    }
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
    // Both edges: passed, unless another input moved with it (crossed wiring).
    if (p.rose.isValid() && p.fell.isValid())
        markResult(p, p.changedWith.empty() ? CheckoutResult::Passed : CheckoutResult::Failed);
    changed(target);
    if (p.result != CheckoutResult::Untested && m_autoAdvance && target == m_current) {
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
    // Not started, still reading every point once (the PLC may yet refuse some, and then
    // nothing may have been forced), or stopped: nothing is forced.
    if (!isStarted())
        return fail(makeError(ErrorKind::InvalidRequest, msg<MsgId::CheckoutNotRunning>()));
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
    // Forced again after a result: a new test, the old one kept.
    if (m_plan.points[static_cast<std::size_t>(index)].result != CheckoutResult::Untested) {
        archiveAttempt(m_plan.points[static_cast<std::size_t>(index)]);
        changed(index);
    }
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

Status CheckoutRunner::recordAnalog(int index, int check, bool asLeft)
{
    CheckoutPoint *p = pointAt(index);
    if (!p || p->kind != CheckoutKind::Analog)
        return makeError(
            ErrorKind::InvalidRequest,
            msg<MsgId::CheckoutNotAnalog>(p ? p->address.toString() : std::to_string(index)));
    const std::string name = p->address.toString();
    if (!p->analog.isDefined())
        return makeError(ErrorKind::InvalidRequest, msg<MsgId::CheckoutAnalogNoScale>(name));
    if (check < 0 || check >= static_cast<int>(p->analog.checks.size()))
        return makeError(ErrorKind::InvalidRequest,
                         msg<MsgId::CheckoutNoCheck>(name, std::to_string(check)));
    const double percent = p->analog.checks[static_cast<std::size_t>(check)];
    if (asLeft) {
        const auto it = std::find_if(
            p->readings.begin(), p->readings.end(),
            [percent](const AnalogReading &r) { return r.percent == percent && r.asFound; });
        if (it == p->readings.end())
            return makeError(ErrorKind::InvalidRequest,
                             msg<MsgId::CheckoutNoAsFound>(
                                 name, QString::number(percent, 'g', 4).toStdString()));
    }
    if (!session())
        return makeError(ErrorKind::LinkError, msg<MsgId::CheckoutNoSession>());
    const Address a = p->address;
    m_actions.submit(Request::readRegisters(stationOf(m_plan), a, 1),
                     [this, index, check, asLeft](const SessionResult &r) {
                         analogRead(index, check, asLeft, r);
                     });
    return Ok{};
}

void CheckoutRunner::analogRead(int index, int check, bool asLeft, const SessionResult &r)
{
    CheckoutPoint *p = pointAt(index);
    if (!p)
        return;
    if (!r.ok() || r.response().values.empty()) {
        ProtocolError e
            = r.ok() ? makeError(ErrorKind::MalformedResponse, std::string("no value")) : r.error();
        e.message = msg<MsgId::CheckoutReadFailed>(p->address.toString(), e.message);
        return fail(std::move(e));
    }
    const double percent = p->analog.checks[static_cast<std::size_t>(check)];
    const std::int64_t value = p->rawValue(r.response().values.front());
    // A reading as found on a point that has a result: a new test (as left adjusts this one).
    if (!asLeft && p->result != CheckoutResult::Untested)
        archiveAttempt(*p);
    auto it = std::find_if(
        p->readings.begin(), p->readings.end(),
        [percent](const AnalogReading &reading) { return reading.percent == percent; });
    if (it == p->readings.end()) {
        p->readings.push_back(AnalogReading{percent, {}, {}});
        it = std::prev(p->readings.end());
    }
    if (asLeft) {
        it->asLeft = value;
    } else {
        it->asFound = value;
        it->asLeft.reset();
    }
    decideAnalog(*p);
    Q_EMIT liveValue(index, r.response().values.front());
    changed(index);
    Q_EMIT analogRecorded(index, check);
}

void CheckoutRunner::decideAnalog(CheckoutPoint &p)
{
    // Decided once every check is read; the latest value of each counts.
    for (double percent : p.analog.checks) {
        const auto it
            = std::find_if(p.readings.begin(), p.readings.end(), [percent](const AnalogReading &r) {
                  return r.percent == percent && r.last();
              });
        if (it == p.readings.end())
            return;
    }
    const bool ok = std::all_of(p.readings.begin(), p.readings.end(), [&p](const AnalogReading &r) {
        return !r.last() || p.analog.within(double(*r.last()), r.percent);
    });
    markResult(p, ok ? CheckoutResult::Passed : CheckoutResult::Failed);
}

} // namespace Fatek
