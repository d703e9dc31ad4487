#include "sessionlink.h"

#include "core/session/changeverifier.h"
#include "core/session/session.h"

namespace Fatek {

SessionLink::SessionLink(const LinkSettings &settings, QObject *parent)
    : PlcLink(parent)
    , m_session(new Session(settings, this))
{
    connect(m_session, &Session::linkStateChanged, this, &PlcLink::linkStateChanged);
    connect(m_session, &Session::statisticsChanged, this, &PlcLink::statisticsChanged);
    connect(m_session, &Session::values, this, [this](const QList<WatchValue> &values) {
        const QList<WatchItemValue> items = m_assembler.assemble(values);
        if (!items.isEmpty())
            Q_EMIT itemValues(items);
    });
}

SessionLink::~SessionLink()
{
    // The session's destructor stops its thread; nothing may arrive in a half-destroyed object.
    disconnect(m_session, nullptr, this, nullptr);
}

void SessionLink::open()
{
    m_session->open();
}

void SessionLink::close(CloseMode mode)
{
    m_session->close(mode);
}

void SessionLink::reconnectNow()
{
    m_session->open(); // during a backoff the worker connects at once
}

LinkState SessionLink::linkState() const
{
    return m_session->linkState();
}

void SessionLink::setItems(const QList<WatchedItem> &items)
{
    m_assembler.setItems(items);
    m_session->setWatchList(m_assembler.pollEntries());
}

void SessionLink::setReadOnly(bool readOnly)
{
    m_session->setReadOnly(readOnly);
}

bool SessionLink::isReadOnly() const
{
    return m_session->isReadOnly();
}

void SessionLink::dropTrafficLog()
{
    m_session->trafficLog()->setCapacity(0);
}

void SessionLink::writeItem(const WatchItemSpec &item, std::uint64_t raw,
                            const std::optional<QDeadlineTimer> &deadline, QObject *context,
                            WriteCompletion completion)
{
    RequestOptions options = ChangeVerifier::confirmedNow(m_session);
    if (deadline)
        options.deadline = *deadline;
    ChangeVerifier::submit(
        m_session, ItemValues(item).writeRequest(raw), context,
        [completion = std::move(completion)](const ChangeReport &report) {
            if (!completion)
                return;
            const bool done = report.outcome == ChangeOutcome::Done;
            completion({done, report.message, report.outcome, report.final});
        },
        options);
}

int SessionLink::pendingWrites() const
{
    return m_session->pendingWrites();
}

int SessionLink::closeDrainMs() const
{
    return m_session->closeDrainMs();
}

} // namespace Fatek
