#include "mqttclientshared.h"

#include "mqttmessages.h"
#include "mqttpacket.h"
#include "mqtttls.h"

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

#include <cerrno>
#include <cstring>

namespace Fatek {

namespace {

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

// The backoff spread over 75..125 %: the links of a gateway (and gateways) that lost the same
// broker at the same instant do not all try again in the same instant (issue 33).
int jittered(int delayMs)
{
    return delayMs * 3 / 4 + static_cast<int>(QRandomGenerator::global()->bounded(delayMs / 2 + 1));
}

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
    shared->connackAt = std::chrono::steady_clock::now();
    shared->post([](MqttClient *client) { Q_EMIT client->connected(); });
}

void onLog(struct mosquitto *mosq, void *userdata, int level, const char *text)
{
    if (level != MOSQ_LOG_ERR || !text)
        return;
    std::string line(text);
    // "OpenSSL Error[0]: error:0A000086:SSL routines::certificate verify failed"
    if (const auto routines = line.find("routines::"); routines != std::string::npos)
        line = line.substr(routines + 10);
    else if (const auto colon = line.find("]: "); colon != std::string::npos)
        line = line.substr(colon + 3);
    // Which check: an expired certificate, an unknown CA and a host name that does not match all
    // read "certificate verify failed" (issue 55); OpenSSL's verify result tells them apart, while
    // the handshake is still there to ask.
    if (line.find("certificate verify failed") != std::string::npos) {
        if (const std::string why = MqttTls::verifyFailure(mosq); !why.empty())
            line += ": " + why;
    }
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

void MqttClientShared::setCallbacks(struct mosquitto *mosq)
{
    mosquitto_connect_with_flags_callback_set(mosq, onConnect);
    mosquitto_subscribe_callback_set(mosq, onSubscribe);
    mosquitto_disconnect_callback_set(mosq, onDisconnect);
    mosquitto_publish_callback_set(mosq, onPublish);
    mosquitto_message_callback_set(mosq, onMessage);
    mosquitto_log_callback_set(mosq, onLog);
}

std::string MqttClientShared::libraryError(int rc)
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
    // A broker drops a client when another connects with its id (MQTT 3.1.1 says no more than
    // closing the connection): two gateways with one configuration throw each other off, each
    // right after it connected. Recognised by that, said so, and the backoff keeps growing.
    const bool dropped = rc != 0 && rc != MOSQ_ERR_KEEPALIVE;
    if (dropped && std::chrono::steady_clock::now() - connackAt < shortSession())
        ++shortSessions;
    else
        shortSessions = 0;
    Message reason = rc == 0 ? msg<MsgId::MqttClosed>(url) : msg<MsgId::MqttLinkLost>(url, why);
    if (shortSessions >= 2)
        reason = msg<MsgId::MqttTakenOver>(url, shortSessions, settings.clientId.toStdString());
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
    delayMs = settings.reconnectMinMs;
    bool first = true;
    for (;;) {
        {
            std::lock_guard lock(mutex);
            if (stop)
                break;
        }
        attemptErrors.clear();
        attemptReported = false;
        if (willPayload && will) {
            // The library sends the will with CONNECT: made now, it carries this connect's time.
            const QByteArray payload = willPayload();
            mosquitto_will_set(mosq, will->topic.constData(), static_cast<int>(payload.size()),
                               payload.constData(), will->qos, will->retain);
        }
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
                if (shortSessions < 2)
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

} // namespace Fatek
