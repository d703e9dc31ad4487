#include "programtransfer.h"

#include "commissionmessages.h"
#include "core/protocol/plcstatus.h"
#include "core/session/session.h"

namespace Fatek {

namespace {

using Problem = ProgramTransferResult::Problem;
using TransferStatus = ProgramTransferResult::Status;

// The model a backup records: the detail status's summary when it names the model ("FBs-28MC,
// OS V3.1, program 13184 words"). Its main-unit bytes are documented for the FB series only, so
// for any other PLC the family comes from the program header ("M series, OS V3.1, ...").
QString modelTextOf(const DetailStatus &detail, const std::optional<ProgramHeader> &header)
{
    if (detail.modelName() || !header)
        return QString::fromStdString(detail.summary());
    return QString::fromStdString(detail.summaryNamed(header->familyName() + " series"));
}

ProgramPage toPage(const std::vector<std::uint32_t> &values)
{
    ProgramPage page{};
    for (std::size_t i = 0; i < page.size() && i < values.size(); ++i)
        page[i] = static_cast<std::uint16_t>(values[i] & 0xFFFFu);
    return page;
}

} // namespace

void registerProgramTransferMetaTypes()
{
    qRegisterMetaType<Fatek::ProgramTransferResult>();
    qRegisterMetaType<Fatek::ProgramTransfer::Phase>();
}

ProgramTransfer::ProgramTransfer(QObject *parent)
    : QObject(parent)
{
    registerProgramTransferMetaTypes();
    connect(&m_tracker, &RequestTracker::sessionDestroyed, this, [this] {
        if (isRunning())
            fail(Problem::NoSession, msg<MsgId::ProgramNoConnection>(), ErrorKind::LinkError);
    });
}

ProgramTransfer::~ProgramTransfer() = default;

void ProgramTransfer::setSession(Session *session)
{
    if (isRunning() && session != m_tracker.session())
        fail(Problem::NoSession, msg<MsgId::ProgramNoConnection>(), ErrorKind::LinkError);
    m_tracker.setSession(session);
}

Message ProgramTransfer::phaseMessage(Phase phase)
{
    switch (phase) {
    case Phase::Idle: return {};
    case Phase::Checking:
    case Phase::Reading: return msg<MsgId::ProgramPhaseReading>();
    case Phase::Writing: return msg<MsgId::ProgramPhaseWriting>();
    case Phase::Verifying: return msg<MsgId::ProgramPhaseVerifying>();
    }
    return {};
}

bool ProgramTransfer::backup()
{
    return start(Job::Backup);
}

bool ProgramTransfer::checkRestore(const ProgramImage &image)
{
    if (isRunning())
        return false;
    m_image = image;
    return start(Job::Check);
}

bool ProgramTransfer::restore(const ProgramImage &image)
{
    if (isRunning())
        return false;
    m_image = image;
    return start(Job::Restore);
}

void ProgramTransfer::cancel()
{
    if (isRunning())
        m_cancel = true;
}

bool ProgramTransfer::start(Job job)
{
    if (isRunning())
        return false;
    m_job = job;
    m_cancel = false;
    m_pages.clear();
    m_badPages.clear();
    m_pageCount = 0;
    m_done = 0;
    m_total = 0;
    m_plcModelName.reset();
    m_detail = {};
    m_running = false;
    m_result = {};
    setPhase(Phase::Checking);
    Session *session = m_tracker.session();
    if (!session) {
        fail(Problem::NoSession, msg<MsgId::ProgramNoConnection>(), ErrorKind::LinkError);
        return true;
    }
    if (job == Job::Backup) {
        readSize();
        return true;
    }
    // Operator mode refuses the writes anyway; a restore refuses before its first request, so
    // that nothing at all is written.
    if (session->isReadOnly()) {
        fail(Problem::ReadOnly, msg<MsgId::ProgramReadOnly>(), ErrorKind::ReadOnly);
        return true;
    }
    readStatus();
    return true;
}

void ProgramTransfer::setPhase(Phase phase)
{
    if (m_phase == phase)
        return;
    m_phase = phase;
    Q_EMIT phaseChanged(phase);
}

void ProgramTransfer::submit(const Request &request, RequestTracker::Callback callback)
{
    if (m_tracker.submit(request, std::move(callback)) == 0)
        fail(Problem::NoSession, msg<MsgId::ProgramNoConnection>(), ErrorKind::LinkError);
}

void ProgramTransfer::readStatus()
{
    submit(Request::briefStatus(m_station), [this](const SessionResult &r) {
        if (!r.ok())
            return failRequest(r, -1, false);
        if (stopIfCancelled(-1))
            return;
        // RUN is reported only after the model and size checks: a restore that would be refused
        // for another model must not have the PLC stopped for it first.
        const Bytes &status = r.response().data;
        m_running = !status.empty() && PlcStatus::fromStatus1(status.front()).running;
        readSize();
    });
}

void ProgramTransfer::readSize()
{
    submit(Request::detailStatus(m_station), [this](const SessionResult &r) {
        if (!r.ok())
            return failRequest(r, -1, false);
        if (stopIfCancelled(-1))
            return;
        const DetailStatus detail = DetailStatus::decode(r.response().data);
        if (!detail.ladderSize || *detail.ladderSize == 0)
            return fail(Problem::NoSize, msg<MsgId::ProgramNoSize>());
        m_detail = detail;
        m_plcModelName = detail.modelName();
        ProgramHeader size;
        size.ladderSize = *detail.ladderSize;
        m_pageCount = size.pageCount();
        switch (m_job) {
        case Job::Backup:
        case Job::Check: m_total = m_pageCount; break;
        case Job::Restore: m_total = 2 * m_pageCount; break;
        }
        if (m_job != Job::Backup && m_image.header().ladderSize != size.ladderSize) {
            // The PLC's page 0 is not read yet: its model as the detail status names it.
            const Message plcModel
                = m_plcModelName ? msg<MsgId::ProgramPlcModelSize>(*m_plcModelName, size.ladderSize)
                                 : msg<MsgId::ProgramPlcUnknownModelSize>(size.ladderSize);
            return fail(Problem::ModelMismatch,
                        msg<MsgId::ProgramModelMismatch>(m_image.header().model(), plcModel));
        }
        setPhase(m_job == Job::Restore ? Phase::Checking : Phase::Reading);
        emitProgress();
        readPage(0);
    });
}

void ProgramTransfer::readPage(std::uint16_t page)
{
    submit(Request::readProgram(m_station, page), [this, page](const SessionResult &r) {
        if (!r.ok())
            return failRequest(r, page, false);
        m_pages.push_back(toPage(r.response().values));
        if (m_job != Job::Restore) {
            ++m_done;
            emitProgress();
        }
        // In RUN only page 0 is read: the model check, before the PLC is asked to stop.
        if (m_job == Job::Restore || m_running || m_pages.size() == m_pageCount)
            return afterRead();
        if (stopIfCancelled(page + 1))
            return;
        readPage(static_cast<std::uint16_t>(page + 1));
    });
}

void ProgramTransfer::afterRead()
{
    const std::optional<ProgramHeader> plcHeader
        = ProgramHeader::decode(std::span<const std::uint16_t>(m_pages.front()));
    if (m_job == Job::Backup) {
        auto image = ProgramImage::fromPages(std::move(m_pages));
        m_pages.clear();
        if (!image)
            return fail(Problem::NoHeader, msg<MsgId::ProgramPlcNoHeader>());
        image->setModelText(modelTextOf(m_detail, plcHeader));
        image->setStation(m_station);
        image->setDate(QDateTime::currentDateTimeUtc());
        m_plcImage = std::move(*image);
        ProgramTransferResult result;
        result.message
            = msg<MsgId::ProgramBackupDone>(m_plcImage.pageCount(), m_plcImage.header().model());
        result.pagesDone = m_done;
        result.pagesTotal = m_pageCount;
        return finish(std::move(result));
    }
    // A restore: the PLC's family must be the backup's (a PLC without a header, such as one
    // whose memory was cleared, is judged by its size alone).
    if (plcHeader && !plcHeader->sameModel(m_image.header()))
        return fail(Problem::ModelMismatch,
                    msg<MsgId::ProgramModelMismatch>(m_image.header().model(), plcHeader->model()));
    // The backup fits this PLC: only now is RUN a reason to stop (and to ask for STOP).
    if (m_running)
        return fail(Problem::Running, msg<MsgId::ProgramNotStopped>());
    if (m_job == Job::Check) {
        ProgramImage plc;
        if (auto read = ProgramImage::fromPages(m_pages))
            plc = std::move(*read);
        plc.setModelText(modelTextOf(m_detail, plcHeader));
        plc.setStation(m_station);
        plc.setDate(QDateTime::currentDateTimeUtc());
        // Compared page by page (a PLC without a header has no image: every page compared).
        std::vector<std::uint16_t> differ;
        for (std::size_t i = 0; i < m_pages.size(); ++i) {
            if (i >= m_image.pages().size() || m_pages[i] != m_image.pages()[i])
                differ.push_back(static_cast<std::uint16_t>(i));
        }
        m_plcImage = std::move(plc);
        ProgramTransferResult result;
        result.message = differ.empty()
                             ? msg<MsgId::ProgramSameAsPlc>()
                             : msg<MsgId::ProgramPagesDiffer>(differ.size(), pageListText(differ));
        result.pages = std::move(differ);
        result.pagesDone = m_done;
        result.pagesTotal = m_pageCount;
        return finish(std::move(result));
    }
    if (stopIfCancelled(0))
        return;
    setPhase(Phase::Writing);
    writePage(0);
}

void ProgramTransfer::writePage(std::uint16_t page)
{
    submit(Request::writeProgram(m_station, page, m_image.pageValues(page)),
           [this, page](const SessionResult &r) {
               if (!r.ok())
                   return failRequest(r, page, true);
               ++m_done;
               emitProgress();
               const auto next = static_cast<std::uint16_t>(page + 1);
               if (stopIfCancelled(next < m_pageCount ? next : 0))
                   return;
               if (next < m_pageCount)
                   return writePage(next);
               setPhase(Phase::Verifying);
               verifyPage(0);
           });
}

void ProgramTransfer::verifyPage(std::uint16_t page)
{
    submit(Request::readProgram(m_station, page), [this, page](const SessionResult &r) {
        if (!r.ok())
            return failRequest(r, page, false);
        if (toPage(r.response().values) != m_image.pages()[page])
            m_badPages.push_back(page);
        ++m_done;
        emitProgress();
        const auto next = static_cast<std::uint16_t>(page + 1);
        if (next >= m_pageCount)
            return verified();
        if (stopIfCancelled(next))
            return;
        verifyPage(next);
    });
}

void ProgramTransfer::verified()
{
    if (!m_badPages.empty()) {
        ProgramTransferResult result;
        result.status = TransferStatus::Failed;
        result.problem = Problem::VerifyFailed;
        result.message
            = msg<MsgId::ProgramVerifyFailed>(m_badPages.size(), pageListText(m_badPages));
        result.pages = m_badPages;
        result.pagesDone = m_pageCount;
        result.pagesTotal = m_pageCount;
        return finish(std::move(result));
    }
    ProgramTransferResult result;
    result.message = msg<MsgId::ProgramRestoreDone>(m_pageCount);
    result.pagesDone = m_pageCount;
    result.pagesTotal = m_pageCount;
    finish(std::move(result));
}

void ProgramTransfer::emitProgress()
{
    Q_EMIT progress(m_done, m_total);
}

void ProgramTransfer::failRequest(const SessionResult &r, int page, bool writing)
{
    const Message why = r.errorMessage();
    Message message = why;
    if (page >= 0) {
        message = writing ? msg<MsgId::ProgramWritePageFailed>(page, why)
                          : msg<MsgId::ProgramReadPageFailed>(page, why);
    }
    if (writing && m_job == Job::Restore)
        message = msg<MsgId::ProgramRestoreInterrupted>(message, m_done, m_pageCount);
    ProgramTransferResult result;
    result.status = TransferStatus::Failed;
    result.problem = r.errorKind() == ErrorKind::ReadOnly ? Problem::ReadOnly : Problem::Request;
    result.errorKind = r.errorKind();
    result.message = std::move(message);
    result.stoppedAtPage = page;
    result.pagesTotal = m_pageCount;
    result.pagesDone = m_job != Job::Restore         ? m_done
                       : m_phase == Phase::Writing   ? m_done
                       : m_phase == Phase::Verifying ? m_pageCount
                                                     : 0;
    finish(std::move(result));
}

void ProgramTransfer::fail(Problem problem, Message message, ErrorKind kind)
{
    ProgramTransferResult result;
    result.status = TransferStatus::Failed;
    result.problem = problem;
    result.errorKind = kind;
    const bool writing = m_job == Job::Restore && m_phase == Phase::Writing;
    // The connection went away half-way through writing: the program is mixed.
    result.message
        = writing ? msg<MsgId::ProgramRestoreInterrupted>(std::move(message), m_done, m_pageCount)
                  : std::move(message);
    result.pagesDone = m_job == Job::Restore
                           ? (writing ? m_done : (m_phase == Phase::Verifying ? m_pageCount : 0))
                           : m_done;
    result.pagesTotal = m_pageCount;
    finish(std::move(result));
}

bool ProgramTransfer::stopIfCancelled(int page)
{
    if (!m_cancel)
        return false;
    ProgramTransferResult result;
    result.status = TransferStatus::Cancelled;
    result.problem = Problem::Cancelled;
    result.errorKind = ErrorKind::Cancelled;
    result.stoppedAtPage = page;
    result.pagesTotal = m_pageCount;
    if (m_job == Job::Backup) {
        result.pagesDone = m_done;
        result.message = msg<MsgId::ProgramBackupCancelled>(page, m_done, m_pageCount);
    } else if (m_job == Job::Restore && m_phase == Phase::Writing) {
        result.pagesDone = m_done;
        result.message = msg<MsgId::ProgramRestoreCancelled>(page, m_done, m_pageCount);
    } else if (m_job == Job::Restore && m_phase == Phase::Verifying) {
        result.pagesDone = m_pageCount;
        result.message
            = msg<MsgId::ProgramVerifyCancelled>(page, m_done - m_pageCount, m_pageCount);
    } else {
        result.pagesDone = 0;
        result.message = msg<MsgId::ProgramCompareCancelled>();
    }
    finish(std::move(result));
    return true;
}

void ProgramTransfer::finish(ProgramTransferResult result)
{
    m_tracker.forgetPending();
    m_pages.clear();
    m_cancel = false;
    m_result = std::move(result);
    setPhase(Phase::Idle);
    Q_EMIT finished(m_result);
}

} // namespace Fatek
