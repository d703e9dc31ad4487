#include "mqttclient.h"

#include "mqttclientshared.h"
#include "mqttmessages.h"

#include <QCoreApplication>

#include <mosquitto.h>

#include <atomic>
#include <mutex>

namespace Fatek {

namespace {

void initLibrary()
{
    static std::once_flag once;
    std::call_once(once, [] { mosquitto_lib_init(); });
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

void MqttClient::setWill(const QString &topic, std::function<QByteArray()> payload, int qos,
                         bool retain)
{
    setWill(topic, payload(), qos, retain);
    std::lock_guard lock(m_shared->mutex);
    m_shared->willPayload = std::move(payload);
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
        return failWith(msg<MsgId::MqttLibraryError>(
            Message::text(MqttClientShared::libraryError(MOSQ_ERR_ERRNO))));
    auto fail = [&](int rc) {
        mosquitto_destroy(mosq);
        return failWith(
            msg<MsgId::MqttLibraryError>(Message::text(MqttClientShared::libraryError(rc))));
    };
    mosquitto_int_option(mosq, MOSQ_OPT_PROTOCOL_VERSION, MQTT_PROTOCOL_V311);
    // Nagle's algorithm held a message back until the broker's delayed ACK (40 ms on Linux):
    // batches are corked instead (handOver()).
    mosquitto_int_option(mosq, MOSQ_OPT_TCP_NODELAY, 1);
    MqttClientShared::setCallbacks(mosq);
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
