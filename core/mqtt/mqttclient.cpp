#include "mqttclient.h"

#include "core/session/crossthreadcall.h"
#include "mqttmessages.h"
#include "mqttpacket.h"
#include "wakesocket.h"

#include <QCoreApplication>
#include <QHash>
#include <QMetaObject>
#include <QRandomGenerator>

#include <mosquitto.h>

#ifdef _WIN32
#include <winsock2.h>
#else
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/socket.h>
#endif

#include <atomic>
#include <cerrno>
#include <chrono>
#include <condition_variable>
#include <cstring>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace Fatek {

namespace {

void initLibrary()
{
    static std::once_flag once;
    std::call_once(once, [] { mosquitto_lib_init(); });
}

// The library's socket as poll() takes it (a SOCKET on Windows, which libmosquitto hands out as
// an int).
WakeSocket::Handle socketOf(struct mosquitto *mosq)
{
    return static_cast<WakeSocket::Handle>(mosquitto_socket(mosq));
}

void setCork(int sock, bool on)
{
#ifdef TCP_CORK
    const int value = on ? 1 : 0;
    ::setsockopt(sock, IPPROTO_TCP, TCP_CORK, &value, sizeof value);
#else
    Q_UNUSED(sock);
    Q_UNUSED(on);
#endif
}

std::string libraryError(int rc)
{
    if (rc == MOSQ_ERR_ERRNO) {
#ifdef _WIN32
        // libmosquitto puts WSAGetLastError() into errno on Windows: Winsock codes from 10000.
        if (errno >= WSABASEERR)
            return WakeSocket::errorText(errno);
#endif
        return std::strerror(errno);
    }
    return mosquitto_strerror(rc);
}

// The backoff spread over 75..125 %: the links of a gateway (and gateways) that lost the same
// broker at the same instant do not all try again in the same instant (issue 33).
int jittered(int delayMs)
{
    return delayMs * 3 / 4 + static_cast<int>(QRandomGenerator::global()->bounded(delayMs / 2 + 1));
}

QString madeUpClientId(const MqttBrokerSettings &settings)
{
    static std::atomic<int> counter{0};
    return QStringLiteral("fatek-%1-%2-%3")
        .arg(settings.host)
        .arg(QCoreApplication::applicationPid())
        .arg(++counter);
}

} // namespace

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

    void run();
    bool serve();
    void linkDown(int rc);
    void handOver(bool *stopping);
    bool writeRaw();
    void deliverInbox();
    Message attemptMessage(const Message &general) const;
};

namespace {

MqttClientShared *sharedOf(void *userdata)
{
    return static_cast<MqttClientShared *>(userdata);
}

void onConnect(struct mosquitto *mosq, void *userdata, int rc, int flags)
{
    MqttClientShared *shared = sharedOf(userdata);
    shared->resumed = rc == 0 && (flags & 1) != 0; // CONNACK's "session present"
    if (rc != 0) {
        shared->attemptReported = true;
        const Message reason
            = msg<MsgId::MqttRefused>(shared->url, Message::text(mosquitto_connack_string(rc)));
        shared->post([reason](MqttClient *client) { Q_EMIT client->disconnected(reason); });
        return;
    }
    std::vector<std::pair<std::string, int>> subscriptions;
    {
        std::lock_guard lock(shared->mutex);
        subscriptions = shared->subscriptions;
        shared->newSubscriptions.clear(); // all of them go now
        shared->connected = true;
    }
    for (const auto &[filter, qos] : subscriptions)
        mosquitto_subscribe(mosq, nullptr, filter.c_str(), qos);
#ifndef _WIN32
    // Issue 35: what the socket holds is a queue no newer state can replace; Linux grows it to
    // 4 MB (seconds of small messages behind a slow broker). Bounded, the rest waits in the
    // outbox, where it is coalesced. 256 KB still fills a 100 ms round trip at 2.5 MB/s.
    if (const int sock = mosquitto_socket(mosq); sock >= 0) {
        const int bytes = 256 * 1024;
        ::setsockopt(sock, SOL_SOCKET, SO_SNDBUF, &bytes, sizeof bytes);
    }
#endif
    shared->connackSeen = true;
    shared->post([](MqttClient *client) { Q_EMIT client->connected(); });
}

void onLog(struct mosquitto *, void *userdata, int level, const char *text)
{
    if (level != MOSQ_LOG_ERR || !text)
        return;
    std::string line(text);
    // "OpenSSL Error[0]: error:0A000086:SSL routines::certificate verify failed"
    if (const auto routines = line.find("routines::"); routines != std::string::npos)
        line = line.substr(routines + 10);
    else if (const auto colon = line.find("]: "); colon != std::string::npos)
        line = line.substr(colon + 3);
    std::vector<std::string> &errors = sharedOf(userdata)->attemptErrors;
    if (errors.size() < 3 && std::find(errors.begin(), errors.end(), line) == errors.end())
        errors.push_back(line);
}

void onSubscribe(struct mosquitto *, void *userdata, int, int, const int *)
{
    sharedOf(userdata)->resumed = false; // queued messages came before this answer
}

void onDisconnect(struct mosquitto *, void *userdata, int rc)
{
    sharedOf(userdata)->linkDown(rc);
}

void onPublish(struct mosquitto *, void *userdata, int)
{
    MqttClientShared *shared = sharedOf(userdata);
    if (shared->outstanding > 0)
        --shared->outstanding;
}

void onMessage(struct mosquitto *, void *userdata, const struct mosquitto_message *message)
{
    MqttClientShared *shared = sharedOf(userdata);
    shared->inbox.push_back(
        {QString::fromUtf8(message->topic),
         QByteArray(static_cast<const char *>(message->payload), message->payloadlen),
         message->retain, shared->resumed});
}

} // namespace

void MqttClientShared::linkDown(int rc)
{
    bool wasConnected = false;
    {
        // The library drops what was queued and not written, and so do we: those messages are
        // gone (retained state is published again on the next connect).
        std::lock_guard lock(mutex);
        outbox.clear();
        outboxIndex.clear();
        outstanding = 0;
        wasConnected = connected.exchange(false);
    }
    if (!wasConnected)
        return;
    const Message why = rc == MOSQ_ERR_KEEPALIVE
                            ? msg<MsgId::MqttKeepaliveTimeout>(settings.keepAliveSec)
                            : Message::text(libraryError(rc));
    const Message reason
        = rc == 0 ? msg<MsgId::MqttClosed>(url) : msg<MsgId::MqttLinkLost>(url, why);
    post([reason](MqttClient *client) { Q_EMIT client->disconnected(reason); });
}

Message MqttClientShared::attemptMessage(const Message &general) const
{
    // "A TLS error occurred." alone does not say which check failed: the library's own lines do
    // ("certificate verify failed", "tlsv13 alert certificate required").
    if (attemptErrors.empty()) {
        // The library said nothing more (its alert came on a path that does not log it): on TLS
        // without a client certificate, the likeliest cause is the one to name.
        if (settings.tls && settings.certFile.isEmpty())
            return msg<MsgId::MqttMaybeNeedsCertificate>(general);
        return general;
    }
    std::string detail;
    for (const std::string &error : attemptErrors)
        detail += (detail.empty() ? "" : "; ") + error;
    return msg<MsgId::MqttErrorDetail>(general, detail);
}

void MqttClientShared::deliverInbox()
{
    if (inbox.empty())
        return;
    // One queued call per batch of received messages, not one per message.
    ++batchesOnTheirWay;
    // (The owner holds this object: it is there while the call runs.)
    post([batch = std::move(inbox), shared = this](MqttClient *client) {
        for (const Incoming &in : batch)
            Q_EMIT client->messageReceived(in.topic, in.payload, in.retained, in.queued);
        // The network thread may read again (setReceiveWindow()).
        if (--shared->batchesOnTheirWay < shared->receiveWindow) {
            std::lock_guard lock(shared->mutex);
            shared->wakeUp();
        }
    });
    inbox.clear();
}

void MqttClientShared::handOver(bool *stopping)
{
    std::vector<Outgoing> batch;
    std::vector<std::pair<std::string, int>> subscribe;
    // While the socket has not taken what the library holds, the messages wait in the outbox,
    // where a newer state of a topic replaces the older: the library's own queue (one packet
    // after another, nothing replaced) holds at most one batch.
    const bool libraryBusy = mosquitto_want_write(mosq) || !raw.isEmpty();
    {
        std::lock_guard lock(mutex);
        *stopping = stop;
        // (Stopping, the rest goes through the library, after its own queue; not while our
        // packets are half written: the DISCONNECT waits for them, the rest is dropped.)
        if (!libraryBusy || (stop && raw.isEmpty())) {
            batch.swap(outbox);
            outboxIndex.clear();
        }
        if (raw.isEmpty()) // the library writes a SUBSCRIBE at once
            subscribe.swap(newSubscriptions);
    }
    for (const auto &[filter, qos] : subscribe)
        mosquitto_subscribe(mosq, nullptr, filter.c_str(), qos);
    if (batch.empty())
        return;
    // QoS 0 only (a QoS 1 message needs the library's packet id and acknowledgement): encoded
    // here, written at once with one send().
    const bool encodeHere
        = rawWrites && !*stopping && !mosquitto_want_write(mosq)
          && std::all_of(batch.cbegin(), batch.cend(), [](const Outgoing &out) {
                 return out.qos == 0 && MqttPacket::fitsPublish(out.topic, out.payload);
             });
    if (encodeHere) {
        qsizetype bytes = 0;
        for (const Outgoing &out : batch)
            bytes += out.topic.size() + out.payload.size() + 7;
        raw.reserve(raw.size() + bytes);
        for (const Outgoing &out : batch)
            MqttPacket::appendPublishQos0(raw, out.topic, out.payload, out.retain);
        rawMessages += static_cast<int>(batch.size());
        rawProgress = std::chrono::steady_clock::now();
        writeRaw();
        return;
    }
    // One batch, few segments: corked while it is written, sent at once when uncorked (the
    // socket has TCP_NODELAY, so a lone message is not held back waiting for an ACK either).
    const int sock = mosquitto_socket(mosq);
    const bool cork = batch.size() > 1 && sock >= 0;
    if (cork)
        setCork(sock, true);
    for (const Outgoing &out : batch) {
        // Unthreaded, the library writes the packet now (or keeps it until the socket takes it).
        const int rc = mosquitto_publish(mosq, nullptr, out.topic.constData(),
                                         static_cast<int>(out.payload.size()),
                                         out.payload.constData(), out.qos, out.retain);
        if (rc != MOSQ_ERR_SUCCESS && outstanding > 0)
            --outstanding; // refused, or the link broke: lost like the rest of the queue
    }
    if (cork && mosquitto_socket(mosq) == sock)
        setCork(sock, false);
}

// What the socket takes of `raw` now; false when the link broke.
bool MqttClientShared::writeRaw()
{
#ifdef _WIN32
    return true; // rawWrites is never set
#else
    const int sock = mosquitto_socket(mosq);
    if (sock < 0)
        return false;
    while (rawSent < raw.size()) {
        const ssize_t sent
            = ::send(sock, raw.constData() + rawSent,
                     static_cast<std::size_t>(raw.size() - rawSent), MSG_NOSIGNAL | MSG_DONTWAIT);
        if (sent > 0) {
            rawSent += sent;
            rawProgress = std::chrono::steady_clock::now();
            continue;
        }
        if (sent < 0 && errno == EINTR)
            continue;
        if (sent < 0 && (errno == EAGAIN || errno == EWOULDBLOCK))
            return true;
        return false;
    }
    // All written: the messages are out of this client, as the library's onPublish() says.
    outstanding -= rawMessages;
    raw.clear();
    rawSent = 0;
    rawMessages = 0;
    return true;
#endif
}

// Serves one connected link until it drops (false) or close() asks to stop (true).
bool MqttClientShared::serve()
{
    raw.clear(); // what a broken link did not take is gone, as the library's queue is
    rawSent = 0;
    rawMessages = 0;
    for (;;) {
        bool stopping = false;
        handOver(&stopping);
        const int sock = mosquitto_socket(mosq);
        if (stopping) {
            // A clean DISCONNECT after what was handed over, so that the broker does not
            // publish the will.
            for (int i = 0; i < 10 && !raw.isEmpty() && sock >= 0; ++i) {
                pollfd out{socketOf(mosq), POLLOUT, 0};
                WakeSocket::poll(&out, 1, 50);
                if (!writeRaw())
                    break;
            }
            // (A DISCONNECT inside a packet not all written would be garbage: the broker drops
            // the link, and publishes the will.)
            if (connected && sock >= 0 && raw.isEmpty()) {
                mosquitto_disconnect(mosq);
                for (int i = 0; i < 10 && mosquitto_socket(mosq) >= 0; ++i) {
                    pollfd out{socketOf(mosq), POLLOUT, 0};
                    WakeSocket::poll(&out, 1, 50);
                    if (mosquitto_loop_write(mosq, 1) != MOSQ_ERR_SUCCESS)
                        break;
                }
            }
            connected = false;
            return true;
        }
        if (sock < 0)
            return false;
        // While our packets are not all written: they first, nothing of the library's in between
        // (no reading either: an answer it reads may make it write). Otherwise not reading while
        // the owner's thread has a full window of batches still to take.
        const bool ours = !raw.isEmpty();
        const bool reading = !ours && (receiveWindow <= 0 || batchesOnTheirWay < receiveWindow);
        const bool writing = ours || mosquitto_want_write(mosq);
        pollfd fds[2] = {{socketOf(mosq),
                          static_cast<short>((reading ? POLLIN : 0) | (writing ? POLLOUT : 0)), 0},
                         {waker.handle(), POLLIN, 0}};
        // Keep-alive has a resolution of seconds: loop_misc() once a second is enough.
        if (WakeSocket::poll(fds, 2, 1000) < 0 && errno != EINTR)
            return false;
        if (fds[1].revents & POLLIN) {
            std::lock_guard lock(mutex);
            waker.drain();
            wakePending = false;
        }
        if (ours) {
            if ((fds[0].revents & (POLLOUT | POLLERR | POLLHUP)) && !writeRaw())
                return false;
            // A broker that takes nothing for longer than the keep-alive allows is gone, as the
            // library would decide without an answer to its PINGREQ.
            if (!raw.isEmpty()
                && std::chrono::steady_clock::now() - rawProgress
                       > std::chrono::milliseconds(settings.keepAliveSec * 1500))
                return false;
            continue;
        }
        if (fds[0].revents & (POLLIN | POLLERR | POLLHUP)) {
            // Everything the socket holds now (bounded), then one hand-over to the owner.
            for (int i = 0; i < 1000; ++i) {
                if (mosquitto_loop_read(mosq, 1) != MOSQ_ERR_SUCCESS)
                    break;
                if (mosquitto_socket(mosq) < 0)
                    break;
                pollfd more{socketOf(mosq), POLLIN, 0};
                if (WakeSocket::poll(&more, 1, 0) <= 0)
                    break;
            }
            deliverInbox();
            if (mosquitto_socket(mosq) < 0)
                return false;
        }
        if ((fds[0].revents & POLLOUT) && mosquitto_loop_write(mosq, 1) != MOSQ_ERR_SUCCESS)
            return false;
        if (mosquitto_loop_misc(mosq) != MOSQ_ERR_SUCCESS || mosquitto_socket(mosq) < 0)
            return false;
    }
}

void MqttClientShared::run()
{
    int delayMs = settings.reconnectMinMs;
    bool first = true;
    for (;;) {
        {
            std::lock_guard lock(mutex);
            if (stop)
                break;
        }
        attemptErrors.clear();
        attemptReported = false;
        const int rc = first ? mosquitto_connect(mosq, settings.host.toUtf8().constData(),
                                                 settings.port, settings.keepAliveSec)
                             : mosquitto_reconnect(mosq);
        first = false;
        if (rc == MOSQ_ERR_SUCCESS) {
            const bool stopping = serve();
            deliverInbox();
            if (stopping)
                break;
            // Normally the library reported the loss already (onDisconnect()); if it did not,
            // the owner must still learn that the link is down.
            linkDown(MOSQ_ERR_CONN_LOST);
            if (connackSeen.exchange(false)) {
                delayMs = settings.reconnectMinMs;
            } else if (!attemptReported) {
                // Connected, then dropped before the broker accepted us: a TLS handshake the
                // broker failed (no client certificate), or a broker closing at once. Every
                // such attempt is reported (the backoff paces them), with what the library saw.
                const Message reason = msg<MsgId::MqttConnectFailed>(
                    url,
                    attemptMessage(attemptErrors.empty() ? msg<MsgId::MqttClosedBeforeAccepting>()
                                                         : msg<MsgId::MqttTlsFailed>()));
                post([reason](MqttClient *client) { Q_EMIT client->disconnected(reason); });
            }
        } else {
            const Message reason = msg<MsgId::MqttConnectFailed>(
                url, attemptMessage(Message::text(libraryError(rc))));
            post([reason](MqttClient *client) { Q_EMIT client->disconnected(reason); });
        }
        std::unique_lock lock(mutex);
        wake.wait_for(lock, std::chrono::milliseconds(jittered(delayMs)), [this] { return stop; });
        delayMs = std::min(delayMs * 2, settings.reconnectMaxMs);
    }
}

MqttClient::MqttClient(const MqttBrokerSettings &settings, QObject *parent)
    : QObject(parent)
    , m_shared(std::make_shared<MqttClientShared>())
{
    initLibrary();
    m_shared->owner = this;
    m_shared->settings = settings;
    if (m_shared->settings.clientId.isEmpty())
        m_shared->settings.clientId = madeUpClientId(settings);
    m_shared->url = settings.toUrl().toStdString();
}

MqttClient::~MqttClient()
{
    close();
}

MqttBrokerSettings MqttClient::settings() const
{
    return m_shared->settings;
}

void MqttClient::setWill(const QString &topic, const QByteArray &payload, int qos, bool retain)
{
    std::lock_guard lock(m_shared->mutex);
    m_shared->will = MqttClientShared::Outgoing{topic.toUtf8(), payload, qos, retain};
}

void MqttClient::subscribe(const QString &filter, int qos)
{
    std::lock_guard lock(m_shared->mutex);
    m_shared->subscriptions.emplace_back(filter.toStdString(), qos);
    // A (re)connect in between subscribes too: twice does no harm.
    if (m_shared->connected) {
        m_shared->newSubscriptions.push_back(m_shared->subscriptions.back());
        m_shared->wakeUp();
    }
}

bool MqttClient::open()
{
    // `mutex` is never held around a library call: the library takes its callback lock inside,
    // and onConnect()/onDisconnect() take `mutex` inside that lock (an inverted order otherwise).
    std::lock_guard openLock(m_shared->openMutex);
    MqttBrokerSettings s;
    std::optional<MqttClientShared::Outgoing> will;
    {
        std::lock_guard lock(m_shared->mutex);
        if (m_shared->running)
            return true;
        s = m_shared->settings;
        will = m_shared->will;
    }
    auto failWith = [this](const Message &error) {
        std::lock_guard lock(m_shared->mutex);
        m_shared->openError = error;
        return false;
    };
    if (const Message invalid = s.validate(); !invalid.empty())
        return failWith(invalid);
    std::string wakerError;
    {
        std::lock_guard lock(m_shared->mutex);
        if (!m_shared->waker.open())
            wakerError = m_shared->waker.error();
    }
    if (!wakerError.empty())
        return failWith(msg<MsgId::MqttLibraryError>(Message::text(wakerError)));
    struct mosquitto *mosq
        = mosquitto_new(s.clientId.toUtf8().constData(), s.cleanSession, m_shared.get());
    if (!mosq)
        return failWith(msg<MsgId::MqttLibraryError>(Message::text(libraryError(MOSQ_ERR_ERRNO))));
    auto fail = [&](int rc) {
        mosquitto_destroy(mosq);
        return failWith(msg<MsgId::MqttLibraryError>(Message::text(libraryError(rc))));
    };
    mosquitto_int_option(mosq, MOSQ_OPT_PROTOCOL_VERSION, MQTT_PROTOCOL_V311);
    // Nagle's algorithm held a message back until the broker's delayed ACK (40 ms on Linux):
    // batches are corked instead (handOver()).
    mosquitto_int_option(mosq, MOSQ_OPT_TCP_NODELAY, 1);
    mosquitto_connect_with_flags_callback_set(mosq, onConnect);
    mosquitto_subscribe_callback_set(mosq, onSubscribe);
    mosquitto_disconnect_callback_set(mosq, onDisconnect);
    mosquitto_publish_callback_set(mosq, onPublish);
    mosquitto_message_callback_set(mosq, onMessage);
    mosquitto_log_callback_set(mosq, onLog);
    if (!s.username.isEmpty()) {
        const QByteArray user = s.username.toUtf8();
        const QByteArray password = s.password.toUtf8();
        if (const int rc = mosquitto_username_pw_set(
                mosq, user.constData(), s.password.isEmpty() ? nullptr : password.constData());
            rc != MOSQ_ERR_SUCCESS)
            return fail(rc);
    }
    if (s.tls) {
        const QByteArray ca = s.caFile.toUtf8();
        const QByteArray cert = s.certFile.toUtf8();
        const QByteArray key = s.keyFile.toUtf8();
        const int rc = mosquitto_tls_set(mosq, ca.isEmpty() ? nullptr : ca.constData(),
                                         ca.isEmpty() ? "/etc/ssl/certs" : nullptr,
                                         cert.isEmpty() ? nullptr : cert.constData(),
                                         key.isEmpty() ? nullptr : key.constData(), nullptr);
        if (rc != MOSQ_ERR_SUCCESS)
            return fail(rc);
        if (s.tlsInsecure)
            mosquitto_tls_insecure_set(mosq, true);
    }
    if (will) {
        if (const int rc = mosquitto_will_set(mosq, will->topic.constData(),
                                              static_cast<int>(will->payload.size()),
                                              will->payload.constData(), will->qos, will->retain);
            rc != MOSQ_ERR_SUCCESS)
            return fail(rc);
    }
    {
        std::lock_guard lock(m_shared->mutex);
        m_shared->openError = {};
        m_shared->mosq = mosq;
#ifndef _WIN32
        m_shared->rawWrites = !s.tls; // with TLS only the library may write to the socket
#endif
        m_shared->stop = false;
        m_shared->running = true;
    }
    m_shared->thread = std::thread([shared = m_shared] { shared->run(); });
    return true;
}

Message MqttClient::openError() const
{
    std::lock_guard lock(m_shared->mutex);
    return m_shared->openError;
}

void MqttClient::close()
{
    std::lock_guard openLock(m_shared->openMutex);
    {
        std::lock_guard lock(m_shared->mutex);
        if (!m_shared->running)
            return;
        m_shared->stop = true;
        m_shared->wakeUp();
    }
    m_shared->wake.notify_all();
    m_shared->thread.join();
    mosquitto_destroy(m_shared->mosq); // the network thread is gone: nothing else touches it
    std::lock_guard lock(m_shared->mutex);
    m_shared->mosq = nullptr;
    m_shared->running = false;
    m_shared->connected = false;
    m_shared->outstanding = 0;
    m_shared->outbox.clear();
    m_shared->outboxIndex.clear();
    m_shared->wakePending = false;
}

bool MqttClient::isConnected() const
{
    return m_shared->connected;
}

bool MqttClient::publish(const QString &topic, const QByteArray &payload, int qos, bool retain)
{
    return publishUtf8(topic.toUtf8(), payload, qos, retain);
}

bool MqttClient::publishUtf8(const QByteArray &topic, const QByteArray &payload, int qos,
                             bool retain)
{
    std::lock_guard lock(m_shared->mutex);
    if (!m_shared->connected || !m_shared->mosq)
        return false;
    std::vector<MqttClientShared::Outgoing> &outbox = m_shared->outbox;
    if (qos == 0 && retain) {
        // A newer state of a topic still waiting here replaces it (in its place in the queue).
        const auto at = m_shared->outboxIndex.constFind(topic);
        if (at != m_shared->outboxIndex.cend()) {
            outbox[at.value()].payload = payload;
            ++m_shared->superseded;
            return true;
        }
        m_shared->outboxIndex.insert(topic, outbox.size());
    }
    ++m_shared->outstanding;
    outbox.push_back({topic, payload, qos, retain});
    // One wake-up when the queue turns non-empty: the network thread takes all of it at once (or,
    // while the library is busy, comes back for it as soon as the socket took the rest).
    if (outbox.size() == 1)
        m_shared->wakeUp();
    return true;
}

int MqttClient::outstanding() const
{
    return m_shared->outstanding;
}

quint64 MqttClient::superseded() const
{
    return m_shared->superseded;
}

void MqttClient::setReceiveWindow(int batches)
{
    m_shared->receiveWindow = batches;
}

} // namespace Fatek
