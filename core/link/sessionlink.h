#pragma once

#include "core/transport/linksettings.h"
#include "plclink.h"

namespace Fatek {

// A direct link: a Session polling the items' elements and writing them, and the ItemAssembler
// that joins the elements' values into the items'.
class SessionLink : public PlcLink
{
    Q_OBJECT

public:
    explicit SessionLink(const LinkSettings &settings, QObject *parent = nullptr);
    ~SessionLink() override;

    Kind kind() const override { return Kind::Direct; }
    void open() override;
    void close(CloseMode mode = CloseMode::Drain) override;
    void reconnectNow() override;
    LinkState linkState() const override;
    void setItems(const QList<WatchedItem> &items) override;
    void setReadOnly(bool readOnly) override;
    bool isReadOnly() const override;
    int pendingWrites() const override;
    int closeDrainMs() const override;
    Session *session() const override { return m_session; }
    // The session keeps no traffic log (the studio's raw console shows it; a gateway link has
    // no reader for it).
    void dropTrafficLog();

protected:
    void writeItem(const WatchItemSpec &item, std::uint64_t raw,
                   const std::optional<QDeadlineTimer> &deadline, QObject *context,
                   WriteCompletion completion) override;

private:
    Session *m_session;
    ItemAssembler m_assembler;
};

} // namespace Fatek
