#pragma once

#include "core/session/sessionresult.h"
#include "core/session/sessionstatistics.h"
#include "core/session/sessiontypes.h"
#include "core/watch/itemassembler.h"

#include <QDeadlineTimer>
#include <QList>
#include <QObject>
#include <QString>

#include <cstdint>
#include <functional>
#include <optional>

namespace Fatek {

class Session;

// Makes the link's signal types known to queued connections and QSignalSpy (PlcLink's
// constructor calls it).
void registerLinkMetaTypes();

// What a write through a link came to: done; refused (operator mode, the PLC or the gateway said
// no, not sent); or unknown (sent, not answered: it may have been carried out). An unknown outcome
// is reported first with final = false, and again, final, once the value was read back (done or
// not done) or could no longer be (still unknown).
struct LinkWriteResult
{
    bool ok = false; // outcome == Done
    Message error;   // why not done; with ok, what confirmed it (a read-back), or empty
    ChangeOutcome outcome = ChangeOutcome::Refused;
    bool final = true;
};

// A place that holds the values of PLCs: watch items in, item values and the link's state out,
// one write call with one result. The GUI and its tables talk only to this; a direct link
// (SessionLink: a Session on a serial, TCP or UDP line) and a gateway's connection watched
// through the broker (GatewayWatch) implement it. Lives in the thread that uses it; what it
// reports arrives there.
class PlcLink : public QObject
{
    Q_OBJECT

public:
    enum class Kind {
        Direct,  // this program talks to the PLCs itself
        Gateway, // fatek-gateway does, and this program watches it through an MQTT broker
    };
    using WriteCompletion = std::function<void(const LinkWriteResult &result)>;

    explicit PlcLink(QObject *parent = nullptr);

    virtual Kind kind() const = 0;
    virtual void open() = 0;
    // Drain: accepted writes finish first (bounded by closeDrainMs()); Discard: they are dropped.
    virtual void close(CloseMode mode = CloseMode::Drain) = 0;
    // Connects at once when the link is down (skips the reconnect backoff).
    virtual void reconnectNow() = 0;
    virtual LinkState linkState() const = 0;

    // Replaces the watched items (keys unique in the process, WatchedItem::newKey()); their values
    // come in itemValues().
    virtual void setItems(const QList<WatchedItem> &items) = 0;
    // Whether the items are read at the intervals they carry; false when the far end's own
    // configuration decides (a gateway).
    virtual bool takesIntervals() const { return true; }

    // Operator mode, enforced here: write() refuses before anything reaches a wire or a broker.
    virtual void setReadOnly(bool readOnly) = 0;
    virtual bool isReadOnly() const = 0;
    // Writes `raw` (ItemValues's raw value of `item`, in its format) into the item's elements;
    // `completion` is called on `context`'s thread with the outcome, never inside this call: once,
    // or twice for an unknown outcome (LinkWriteResult::final); dropped if `context` is destroyed
    // first. The write is not sent later than the link's timeout after this call (the person
    // confirmed it now, not whenever the line is free).
    void write(const WatchItemSpec &item, std::uint64_t raw, QObject *context,
               WriteCompletion completion)
    {
        writeItem(item, raw, std::nullopt, context, std::move(completion));
    }
    // The same, not sent after `deadline` (a command's own age limit).
    void write(const WatchItemSpec &item, std::uint64_t raw, const QDeadlineTimer &deadline,
               QObject *context, WriteCompletion completion)
    {
        writeItem(item, raw, deadline, context, std::move(completion));
    }
    // Writes accepted and not finished, and how long a close waits for them.
    virtual int pendingWrites() const = 0;
    virtual int closeDrainMs() const = 0;

    // The session of a direct link, for the tools that talk to the PLC itself (control, forcing,
    // program, snapshots, the raw console); nullptr when another program owns the PLC link.
    virtual Session *session() const { return nullptr; }
    // What the far end says it talks to ("TCP 10.0.0.7:500, FACON"); empty for a direct link.
    virtual QString peerText() const { return {}; }

protected:
    // write(): `deadline` unset means the link's timeout from now.
    virtual void writeItem(const WatchItemSpec &item, std::uint64_t raw,
                           const std::optional<QDeadlineTimer> &deadline, QObject *context,
                           WriteCompletion completion)
        = 0;

Q_SIGNALS:
    void linkStateChanged(Fatek::LinkState state, const Fatek::Message &reason);
    // The items whose values were reported (one batch per poll cycle or per burst of messages);
    // only items of the last setItems() (a cycle under way when they changed reports none of the
    // items that went).
    void itemValues(const QList<Fatek::WatchItemValue> &values);
    // A direct link's counters (at most 4 times a second).
    void statisticsChanged(const Fatek::SessionStatistics &statistics);
};

} // namespace Fatek

Q_DECLARE_METATYPE(Fatek::WatchItemValue)
