#include "mqttclient.h"

#include "core/session/crossthreadcall.h"

#include <QCoreApplication>
#include <QMetaObject>

#include <mosquitto.h>

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

std::string libraryError(int rc)
{
    if (rc == MOSQ_ERR_ERRNO)
        return std::strerror(errno);
    return mosquitto_strerror(rc);
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
    mutable std::mutex mutex;
    std::condition_variable wake;
    MqttBrokerSettings settings;
    std::string url;
    struct mosquitto *mosq = nullptr;
    std::thread thread;
    bool stop = false;
    bool running = false;
    // Under its own lock, never held while calling the library: onConnect() takes it inside the
    // library's callback lock, and `mutex` is held around library calls (a lock-order cycle).
    std::mutex subscriptionsMutex;
    std::vector<std::pair<std::string, int>> subscriptions;
    struct Will
    {
        std::string topic;
        QByteArray payload;
        int qos = 1;
        bool retain = true;
    };
    std::optional<Will> will;
    Message openError;
    std::atomic<bool> connected{false};
    std::atomic<bool> connackSeen{false};
    std::atomic<int> outstanding{0};

    // CrossThreadCall: a queued call with the marks ThreadSanitizer needs to see the hand-over
    // (Debian's Qt is not built with TSan; a plain invokeMethod reads as a race).
    void post(std::function<void(MqttClient *)> call)
    {
        MqttClient *target = owner;
        CrossThreadCall::invoke(target, [target, call = std::move(call)] { call(target); });
    }

    void run();
};

namespace {

MqttClientShared *sharedOf(void *userdata)
{
    return static_cast<MqttClientShared *>(userdata);
}

void onConnect(struct mosquitto *mosq, void *userdata, int rc)
{
    MqttClientShared *shared = sharedOf(userdata);
    if (rc != 0) {
        const Message reason
            = msg<MsgId::MqttRefused>(shared->url, Message::text(mosquitto_connack_string(rc)));
        shared->post([reason](MqttClient *client) { Q_EMIT client->disconnected(reason); });
        return;
    }
    std::vector<std::pair<std::string, int>> subscriptions;
    {
        std::lock_guard lock(shared->subscriptionsMutex);
        subscriptions = shared->subscriptions;
    }
    for (const auto &[filter, qos] : subscriptions)
        mosquitto_subscribe(mosq, nullptr, filter.c_str(), qos);
    shared->connackSeen = true;
    shared->connected = true;
    shared->post([](MqttClient *client) { Q_EMIT client->connected(); });
}

void onDisconnect(struct mosquitto *, void *userdata, int rc)
{
    MqttClientShared *shared = sharedOf(userdata);
    // The library drops what was queued and not written: those messages are gone.
    shared->outstanding = 0;
    if (!shared->connected.exchange(false))
        return;
    const Message reason
        = rc == 0 ? msg<MsgId::MqttClosed>(shared->url)
                  : msg<MsgId::MqttLinkLost>(shared->url, Message::text(libraryError(rc)));
    shared->post([reason](MqttClient *client) { Q_EMIT client->disconnected(reason); });
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
    const QString topic = QString::fromUtf8(message->topic);
    const QByteArray payload(static_cast<const char *>(message->payload), message->payloadlen);
    const bool retained = message->retain;
    shared->post([topic, payload, retained](MqttClient *client) {
        Q_EMIT client->messageReceived(topic, payload, retained);
    });
}

} // namespace

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
        const int rc = first ? mosquitto_connect(mosq, settings.host.toUtf8().constData(),
                                                 settings.port, settings.keepAliveSec)
                             : mosquitto_reconnect(mosq);
        first = false;
        if (rc == MOSQ_ERR_SUCCESS) {
            for (;;) {
                {
                    std::lock_guard lock(mutex);
                    if (stop)
                        break;
                }
                if (mosquitto_loop(mosq, 100, 1) != MOSQ_ERR_SUCCESS)
                    break;
            }
            bool stopping = false;
            {
                std::lock_guard lock(mutex);
                stopping = stop;
            }
            if (stopping) {
                // A clean DISCONNECT, so that the broker does not publish the will.
                if (connected) {
                    mosquitto_disconnect(mosq);
                    for (int i = 0; i < 10 && mosquitto_loop(mosq, 50, 1) == MOSQ_ERR_SUCCESS;
                         ++i) {
                    }
                }
                connected = false;
                break;
            }
            if (connackSeen.exchange(false))
                delayMs = settings.reconnectMinMs;
        } else {
            const Message reason
                = msg<MsgId::MqttConnectFailed>(url, Message::text(libraryError(rc)));
            post([reason](MqttClient *client) { Q_EMIT client->disconnected(reason); });
        }
        std::unique_lock lock(mutex);
        wake.wait_for(lock, std::chrono::milliseconds(delayMs), [this] { return stop; });
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
    m_shared->will = MqttClientShared::Will{topic.toStdString(), payload, qos, retain};
}

void MqttClient::subscribe(const QString &filter, int qos)
{
    const std::string text = filter.toStdString();
    {
        std::lock_guard lock(m_shared->subscriptionsMutex);
        m_shared->subscriptions.emplace_back(text, qos);
    }
    // A (re)connect in between subscribes too: twice does no harm.
    std::lock_guard lock(m_shared->mutex);
    if (m_shared->connected && m_shared->mosq)
        mosquitto_subscribe(m_shared->mosq, nullptr, text.c_str(), qos);
}

bool MqttClient::open()
{
    std::lock_guard lock(m_shared->mutex);
    if (m_shared->running)
        return true;
    const MqttBrokerSettings &s = m_shared->settings;
    m_shared->openError = s.validate();
    if (!m_shared->openError.empty())
        return false;
    struct mosquitto *mosq = mosquitto_new(s.clientId.toUtf8().constData(), true, m_shared.get());
    if (!mosq) {
        m_shared->openError
            = msg<MsgId::MqttLibraryError>(Message::text(libraryError(MOSQ_ERR_ERRNO)));
        return false;
    }
    auto fail = [&](int rc) {
        m_shared->openError = msg<MsgId::MqttLibraryError>(Message::text(libraryError(rc)));
        mosquitto_destroy(mosq);
        return false;
    };
    mosquitto_threaded_set(mosq, true);
    mosquitto_int_option(mosq, MOSQ_OPT_PROTOCOL_VERSION, MQTT_PROTOCOL_V311);
    mosquitto_connect_callback_set(mosq, onConnect);
    mosquitto_disconnect_callback_set(mosq, onDisconnect);
    mosquitto_publish_callback_set(mosq, onPublish);
    mosquitto_message_callback_set(mosq, onMessage);
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
    if (m_shared->will) {
        const auto &will = *m_shared->will;
        if (const int rc
            = mosquitto_will_set(mosq, will.topic.c_str(), static_cast<int>(will.payload.size()),
                                 will.payload.constData(), will.qos, will.retain);
            rc != MOSQ_ERR_SUCCESS)
            return fail(rc);
    }
    m_shared->mosq = mosq;
    m_shared->stop = false;
    m_shared->running = true;
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
    {
        std::lock_guard lock(m_shared->mutex);
        if (!m_shared->running)
            return;
        m_shared->stop = true;
    }
    m_shared->wake.notify_all();
    m_shared->thread.join();
    std::lock_guard lock(m_shared->mutex);
    mosquitto_destroy(m_shared->mosq);
    m_shared->mosq = nullptr;
    m_shared->running = false;
    m_shared->connected = false;
    m_shared->outstanding = 0;
}

bool MqttClient::isConnected() const
{
    return m_shared->connected;
}

bool MqttClient::publish(const QString &topic, const QByteArray &payload, int qos, bool retain)
{
    std::lock_guard lock(m_shared->mutex);
    if (!m_shared->connected || !m_shared->mosq)
        return false;
    ++m_shared->outstanding;
    const int rc
        = mosquitto_publish(m_shared->mosq, nullptr, topic.toUtf8().constData(),
                            static_cast<int>(payload.size()), payload.constData(), qos, retain);
    if (rc != MOSQ_ERR_SUCCESS) {
        --m_shared->outstanding;
        return false;
    }
    return true;
}

int MqttClient::outstanding() const
{
    return m_shared->outstanding;
}

} // namespace Fatek
