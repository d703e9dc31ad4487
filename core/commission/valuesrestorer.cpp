#include "valuesrestorer.h"

#include "commissionmessages.h"
#include "core/protocol/plcmodel.h"
#include "core/session/session.h"

#include <QTimer>

#include <algorithm>

namespace Fatek {

namespace {

std::uint32_t runLimit(ElementType type)
{
    return isDiscrete(type)
               ? Limits::maxDiscretes
               : Limits::maxRegisterWords / static_cast<std::uint32_t>(wordCount(type));
}

Request runWrite(std::uint8_t station, const Address &start, std::vector<std::uint32_t> values)
{
    return isDiscrete(start.type) ? Request::writeDiscretes(station, start, std::move(values))
                                  : Request::writeRegisters(station, start, std::move(values));
}

// The plain kind an element counts in (WY0 in Y, DR0 in R).
ElementType plainKind(const Address &a)
{
    const ElementInfo &info = a.info();
    return info.discrete ? *info.discrete : info.word ? *info.word : a.type;
}

std::size_t wordsOf(std::span<const SnapshotValue> chunk)
{
    std::size_t w = 0;
    for (const SnapshotValue &v : chunk)
        w += static_cast<std::size_t>(v.address.words());
    return w;
}

} // namespace

std::vector<Request> ValuesRestorer::writeRequests(std::uint8_t station,
                                                   std::span<const SnapshotValue> values)
{
    std::vector<SnapshotValue> sorted(values.begin(), values.end());
    std::sort(sorted.begin(), sorted.end(),
              [](const SnapshotValue &a, const SnapshotValue &b) { return a.address < b.address; });
    // Runs of consecutive elements, cut at the frame limits.
    std::vector<std::vector<SnapshotValue>> chunks;
    for (const SnapshotValue &v : sorted) {
        if (!chunks.empty()) {
            std::vector<SnapshotValue> &c = chunks.back();
            if (c.back().address.type == v.address.type && c.back().address.advanced(1) == v.address
                && c.size() < runLimit(v.address.type)) {
                c.push_back(v);
                continue;
            }
        }
        chunks.push_back({v});
    }
    // The k smallest runs go to the mixed-write pool, k chosen for the fewest frames: the other
    // runs take one frame each, a pool of W words ceil(W / 32) frames (49 takes any addresses, so
    // the pool splits anywhere). Ties keep more runs as plain consecutive writes.
    std::vector<std::size_t> order(chunks.size());
    for (std::size_t i = 0; i < order.size(); ++i)
        order[i] = i;
    std::stable_sort(order.begin(), order.end(), [&chunks](std::size_t a, std::size_t b) {
        return wordsOf(chunks[a]) < wordsOf(chunks[b]);
    });
    const std::size_t cap = Limits::maxMixedWriteWords;
    std::size_t bestK = 0;
    std::size_t bestFrames = chunks.size();
    std::size_t poolWords = 0;
    for (std::size_t k = 1; k <= order.size(); ++k) {
        poolWords += wordsOf(chunks[order[k - 1]]);
        const std::size_t frames = (chunks.size() - k) + (poolWords + cap - 1) / cap;
        if (frames < bestFrames) {
            bestFrames = frames;
            bestK = k;
        }
    }
    std::vector<bool> pooled(chunks.size(), false);
    for (std::size_t k = 0; k < bestK; ++k)
        pooled[order[k]] = true;
    std::vector<Request> out;
    std::vector<SnapshotValue> pool;
    for (std::size_t i = 0; i < chunks.size(); ++i) {
        if (pooled[i]) {
            pool.insert(pool.end(), chunks[i].begin(), chunks[i].end());
            continue;
        }
        std::vector<std::uint32_t> v;
        for (const SnapshotValue &sv : chunks[i])
            v.push_back(sv.value);
        out.push_back(runWrite(station, chunks[i].front().address, std::move(v)));
    }
    // The pool in ceil(words / 32) frames: 32-bit elements first, then the 1-word ones fill up.
    std::stable_partition(pool.begin(), pool.end(),
                          [](const SnapshotValue &v) { return v.address.words() == 2; });
    std::vector<std::vector<SnapshotValue>> packs;
    std::vector<std::size_t> used;
    for (const SnapshotValue &v : pool) {
        const auto w = static_cast<std::size_t>(v.address.words());
        std::size_t p = 0;
        while (p < packs.size() && used[p] + w > cap)
            ++p;
        if (p == packs.size()) {
            packs.emplace_back();
            used.push_back(0);
        }
        packs[p].push_back(v);
        used[p] += w;
    }
    for (std::vector<SnapshotValue> &pack : packs) {
        std::sort(pack.begin(), pack.end(), [](const SnapshotValue &a, const SnapshotValue &b) {
            return a.address < b.address;
        });
        if (pack.size() == 1) {
            out.push_back(runWrite(station, pack.front().address, {pack.front().value}));
            continue;
        }
        std::vector<Address> addresses;
        std::vector<std::uint32_t> v;
        for (const SnapshotValue &sv : pack) {
            addresses.push_back(sv.address);
            v.push_back(sv.value);
        }
        out.push_back(Request::mixedWrite(station, std::move(addresses), std::move(v)));
    }
    return out;
}

ValuesRestorer::ValuesRestorer(QObject *parent)
    : QObject(parent)
{
    connect(&m_reader, &SnapshotReader::progress, this,
            [this] { Q_EMIT progress(requestsDone(), requestsTotal()); });
    connect(&m_reader, &SnapshotReader::finished, this, &ValuesRestorer::verify);
}

void ValuesRestorer::setSession(Session *session)
{
    if (m_running)
        cancel();
    m_tracker.setSession(session);
    m_reader.setSession(session);
}

int ValuesRestorer::requestsDone() const
{
    return (m_checked ? 1 : 0) + m_written + m_reader.requestsDone();
}

int ValuesRestorer::valuesWritten() const
{
    std::size_t values = 0;
    for (int i = 0; i < m_written && i < static_cast<int>(m_writes.size()); ++i)
        values += m_writes[static_cast<std::size_t>(i)].values.size();
    return static_cast<int>(values);
}

int ValuesRestorer::requestsTotal() const
{
    // The 53, the writes, the read-back.
    return 1 + static_cast<int>(m_writes.size()) + std::max(1, m_reader.requestsTotal());
}

void ValuesRestorer::start(std::uint8_t station, std::vector<SnapshotValue> values,
                           const QString &snapshotModel)
{
    if (m_running)
        return;
    m_running = true;
    m_station = station;
    m_values = std::move(values);
    m_snapshotModel = snapshotModel;
    m_plcModel.clear();
    m_refusedForModel = false;
    m_checked = false;
    std::sort(m_values.begin(), m_values.end(),
              [](const SnapshotValue &a, const SnapshotValue &b) { return a.address < b.address; });
    m_writes.clear();
    m_nextWrite = 0;
    m_written = 0;
    m_error.reset();
    m_mismatches.clear();
    Session *s = m_tracker.session();
    std::optional<ProtocolError> refusal;
    if (!s)
        refusal = makeError(ErrorKind::LinkError, msg<MsgId::SnapshotNoSession>());
    else if (s->isReadOnly())
        refusal = makeError(ErrorKind::ReadOnly, msg<MsgId::RestoreReadOnly>());
    else if (m_values.empty())
        refusal = makeError(ErrorKind::InvalidRequest, msg<MsgId::RestoreNothing>());
    if (refusal) {
        // Nothing is sent; the answer comes from the event loop like every other outcome.
        QTimer::singleShot(0, this, [this, e = *refusal] { fail(e); });
        return;
    }
    m_writes = writeRequests(station, m_values);
    Q_EMIT progress(requestsDone(), requestsTotal());
    // The model and ranges first: a value the PLC lacks would fail its whole write request
    // half-way through the restore.
    m_tracker.submit(Request::detailStatus(station),
                     [this](const SessionResult &r) { onDetailStatus(r); });
}

void ValuesRestorer::onDetailStatus(const SessionResult &result)
{
    if (!m_running)
        return;
    if (!result.ok() && result.errorKind() != ErrorKind::PlcError
        && result.errorKind() != ErrorKind::Unsupported
        && result.errorKind() != ErrorKind::MalformedResponse) {
        // The link itself failed: nothing else would come through either.
        ProtocolError e = result.error();
        e.message = msg<MsgId::RestoreCheckFailed>(result.error().message);
        return fail(std::move(e));
    }
    m_checked = true;
    Q_EMIT progress(requestsDone(), requestsTotal());
    if (result.ok()) {
        if (std::optional<ProtocolError> refusal
            = checkModel(DetailStatus::decode(result.response().data)))
            return fail(std::move(*refusal));
    }
    submitNext();
}

std::optional<ProtocolError> ValuesRestorer::checkModel(const DetailStatus &status)
{
    const std::optional<PlcModel> plc = PlcModel::fromDetailStatus(status);
    m_plcModel = QString::fromStdString(PlcModel::modelText(status));
    if (!plc)
        return std::nullopt;
    const std::optional<PlcModel::Family> family
        = PlcModel::familyOfText(m_snapshotModel.toStdString());
    if (family && plc->family != PlcModel::Family::Reported && *family != plc->family
        && !m_allowOtherModel) {
        m_refusedForModel = true;
        return makeError(
            ErrorKind::InvalidRequest,
            msg<MsgId::RestoreOtherModel>(m_snapshotModel.toStdString(), m_plcModel.toStdString()));
    }
    // Every element the PLC lacks, by name, and what it has of those kinds.
    std::vector<Address> outside;
    std::vector<ElementType> kinds;
    for (const SnapshotValue &v : m_values) {
        if (plc->contains(v.address))
            continue;
        outside.push_back(v.address);
        if (std::find(kinds.begin(), kinds.end(), plainKind(v.address)) == kinds.end())
            kinds.push_back(plainKind(v.address));
    }
    if (outside.empty())
        return std::nullopt;
    std::string has;
    for (ElementType t : kinds)
        has += (has.empty() ? "" : ", ") + plc->rangeText(t);
    return makeError(ErrorKind::InvalidAddress,
                     msg<MsgId::RestoreOutOfRange>(Snapshot::rangesText(outside, 8), outside.size(),
                                                   m_plcModel.toStdString(), has));
}

void ValuesRestorer::cancel()
{
    if (!m_running)
        return;
    m_tracker.cancelPending();
    fail(makeError(ErrorKind::Cancelled, msg<MsgId::SnapshotCancelled>()));
    m_reader.cancel(); // its finished() finds us stopped: verify() does nothing
}

void ValuesRestorer::submitNext()
{
    if (!m_running)
        return;
    if (m_nextWrite >= m_writes.size()) {
        std::vector<Address> addresses;
        addresses.reserve(m_values.size());
        for (const SnapshotValue &v : m_values)
            addresses.push_back(v.address);
        m_reader.start(m_station, Snapshot::rangesOf(addresses));
        return;
    }
    const Request request = m_writes[m_nextWrite++];
    // One write at a time, each under the one rule for changes: sent once, not later than a
    // timeout from now, and an unanswered one read back before the next goes.
    m_tracker.submitChange(
        request, [this, request](const ChangeReport &r) { onWritten(request, r); },
        ChangeVerifier::confirmedNow(m_tracker.session()));
}

void ValuesRestorer::onWritten(const Request &request, const ChangeReport &report)
{
    if (!m_running || !report.final)
        return;
    if (report.outcome != ChangeOutcome::Done) {
        // Not done means the write's own result was an error (a refusal, or no answer that the
        // read-back then settled): its kind stays, the message says what became of it.
        ProtocolError e = report.result.error();
        e.message = report.outcome == ChangeOutcome::Unknown
                        ? msg<MsgId::RestoreWriteUnknown>(request.target(), report.message)
                        : msg<MsgId::RestoreWriteFailed>(request.target(), report.message);
        return fail(std::move(e));
    }
    ++m_written;
    Q_EMIT progress(requestsDone(), requestsTotal());
    submitNext();
}

void ValuesRestorer::verify()
{
    if (!m_running)
        return;
    if (!m_reader.ok()) {
        ProtocolError e = m_reader.error();
        e.message = msg<MsgId::RestoreVerifyFailed>(m_reader.error().message);
        return fail(std::move(e));
    }
    MemorySnapshot expected;
    expected.values = m_values;
    m_mismatches = SnapshotDiff::compare(expected, m_reader.snapshot());
    m_running = false;
    Q_EMIT finished();
}

void ValuesRestorer::fail(ProtocolError error)
{
    if (!m_running)
        return;
    m_running = false;
    // Stopped while writing: some values are new, some old. Say how many were written.
    if (m_nextWrite > 0 && m_written < static_cast<int>(m_writes.size()))
        error.message = msg<MsgId::RestoreInterrupted>(std::move(error.message), valuesWritten(),
                                                       m_values.size());
    m_error = std::move(error);
    m_tracker.forgetPending();
    Q_EMIT finished();
}

Message ValuesRestorer::outcome() const
{
    if (m_error)
        return m_error->message;
    if (!m_mismatches.empty())
        return msg<MsgId::RestoreDiffer>(m_mismatches.size(), m_values.size());
    return msg<MsgId::RestoreDone>(m_values.size(), m_writes.size());
}

} // namespace Fatek
