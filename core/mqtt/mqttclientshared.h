#pragma once

#include "core/session/crossthreadcall.h"
#include "mqttclient.h"
#include "wakesocket.h"

#include <QByteArray>
#include <QHash>
#include <QString>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <utility>
#include <vector>

struct mosquitto;

namespace Fatek {

// What an MqttClient shares with its network thread, and that thread's work (run()): it alone
// calls the library while connected, writes the outbox, hands received messages over to the
// client's thread and connects again after a loss.
struct MqttClientShared
{
    MqttClient *owner = nullptr; // lives until the network thread is joined
    // Guards every field below that other threads touch. Never held while calling the library:
    // only the network thread calls it (mosquitto_new/destroy aside, before and after the thread),
    // so libmosquitto runs unthreaded and writes each packet straight to the socket.
    mutable std::mutex mutex;
    std::mutex openMutex; // serialises open() and close(); the thread and library calls there
    std::condition_variable wake;
    std::thread thread;
    struct mosquitto *mosq = nullptr;
    MqttBrokerSettings settings;
    std::string url;
    bool stop = false;
    bool running = false;
    std::vector<std::pair<std::string, int>> subscriptions;
    std::vector<std::pair<std::string, int>> newSubscriptions; // to subscribe on this link now
    struct Outgoing
    {
        QByteArray topic; // UTF-8
        QByteArray payload;
        int qos = 0;
        bool retain = false;
    };
    // Handed over by publish(), written by the network thread in one go: one wake-up per batch,
    // not one per message (docs/performance.md). Taken only while the library has nothing left to
    // write: meanwhile a retained QoS 0 message replaces the one waiting for its topic
    // (outboxIndex: where each such topic waits in the outbox).
    std::vector<Outgoing> outbox;
    QHash<QByteArray, std::size_t> outboxIndex;
    std::atomic<quint64> superseded{0};
    std::optional<Outgoing> will;
    // Writes the will's payload again before every connect (its time: issue 55); set before
    // open(), then read by the network thread only.
    std::function<QByteArray()> willPayload;
    Message openError;
    std::atomic<bool> connected{false};
    std::atomic<bool> connackSeen{false};
    std::atomic<int> outstanding{0};
    // Wakes the network thread out of poll(): a datagram sent when the outbox turns non-empty.
    WakeSocket waker;
    bool wakePending = false; // a datagram is queued and not yet read (under mutex)
    // Network thread only: messages received since the last hand-over to the owner's thread.
    struct Incoming
    {
        QString topic;
        QByteArray payload;
        bool retained = false;
        bool queued = false;
    };
    std::vector<Incoming> inbox;
    std::atomic<int> receiveWindow{0};     // setReceiveWindow()
    std::atomic<int> batchesOnTheirWay{0}; // posted by deliverInbox(), not yet emitted
    // Network thread only: what the library said went wrong in this connection attempt (its
    // TLS errors name the check that failed, "certificate verify failed"), and whether the
    // attempt's failure was reported already (a refusing CONNACK).
    std::vector<std::string> attemptErrors;
    bool attemptReported = false;
    // Network thread only: sessions the broker ended right after accepting them, in a row (another
    // client with the same id taking over: issue 55), when the last one began, and the backoff.
    int shortSessions = 0;
    std::chrono::steady_clock::time_point connackAt;
    int delayMs = 0;
    // A session the broker ends sooner than this after its CONNACK is "right after".
    std::chrono::milliseconds shortSession() const
    {
        return std::chrono::milliseconds(std::max(5000, 2 * delayMs));
    }
    // Network thread only: the broker resumed a persistent session; what it sends before the
    // answer to our SUBSCRIBE waited at the broker while this client was away.
    bool resumed = false;
    // Network thread only: a batch of QoS 0 messages encoded here (MqttPacket) and written with
    // one send() per batch, not one per message as the library does (issue 35: that send() was
    // the gateway's largest cost per message). Only over plain TCP, and only while the library
    // has nothing to write; while `raw` is not all written the library neither reads nor writes
    // (its packets would land inside ours).
    bool rawWrites = false;
    QByteArray raw;
    qsizetype rawSent = 0;
    int rawMessages = 0;
    std::chrono::steady_clock::time_point rawProgress;

    // CrossThreadCall: a queued call with the marks ThreadSanitizer needs to see the hand-over
    // (Debian's Qt is not built with TSan; a plain invokeMethod reads as a race).
    void post(std::function<void(MqttClient *)> call)
    {
        MqttClient *target = owner;
        CrossThreadCall::invoke(target, [target, call = std::move(call)] { call(target); });
    }
    // Under mutex.
    void wakeUp()
    {
        if (wakePending || !waker.isOpen())
            return;
        wakePending = true;
        waker.wake();
    }

    // The library's callbacks on `mosq`, each handed the shared state as its user data.
    static void setCallbacks(struct mosquitto *mosq);
    // The library's error text (errno's for MOSQ_ERR_ERRNO).
    static std::string libraryError(int rc);

    void run();
    bool serve();
    void linkDown(int rc);
    void handOver(bool *stopping);
    bool writeRaw();
    void deliverInbox();
    Message attemptMessage(const Message &general) const;
};

} // namespace Fatek
