#pragma once

#include "alarmpayload.h"
#include "core/alarm/alarmtypes.h"
#include "core/mqtt/gatewaytopics.h"
#include "gatewayconfig.h"

#include <QByteArray>
#include <QDateTime>
#include <QHash>
#include <QObject>
#include <QPointer>
#include <QSet>
#include <QString>

namespace Fatek {

class AlarmEngine;
class GatewayPublisher;
class MqttClient;

// The MQTT side of one connection's alarms (issue 50): publishes each alarm's state, retained
// (QoS 1), on <prefix>/<conn>/alarms/<id> and every event of the connection's AlarmEngine on
// <prefix>/<conn>/alarms/events, and takes the operators' acknowledge, shelve and unshelve
// commands on <alarm>/ack, /shelve, /unshelve with the checks of a write command (size, strict
// JSON, retained, age) and one reply each on <alarm>/reply. Read-only mode does not stop them:
// an operator who may not write may still acknowledge. Shares its link's broker connection and
// publisher with MqttNorth; lives in the link's thread.
class AlarmNorth : public QObject
{
    Q_OBJECT

public:
    static constexpr int MaxCommandBytes = 4096;
    // Command topics whose last payload is remembered (to know the broker's retained copy of one
    // already answered); beyond it the memory starts again.
    static constexpr int MaxRememberedCommands = 256;
    // Who the journal names for a command without "user": it came through the broker.
    static inline const QString DefaultUser = QStringLiteral("mqtt");

    AlarmNorth(const GatewayConnectionConfig &config, const QString &prefix, AlarmEngine *engine,
               MqttClient *client, GatewayPublisher *publisher, QObject *parent = nullptr);

    // The journal restores the engine's states (AlarmJournalWriter::attach, asynchronous): the
    // states are first published after that (the engine's alarmsReset), not as normal before.
    void awaitRestore() { m_awaitRestore = true; }
    // Publishes every alarm's state (unless awaiting the restore) and takes commands from now on.
    void start();
    // Commands that arrive from now on are ignored; nothing more is published.
    void stop() { m_stopping = true; }
    // Publishes an empty retained payload on the state topics `keep` does not hold (a reload
    // removed those alarms: the broker forgets them), before the link stops.
    void clearStates(const QSet<QString> &keep);

    // The state topics of the alarms `connection` defines.
    static QSet<QString> stateTopics(const QString &prefix,
                                     const GatewayConnectionConfig &connection);

Q_SIGNALS:
    // Raises, returns, operator actions and refused commands, one log line each.
    void logEvent(const Fatek::Message &event);

private:
    void onEvent(const AlarmEvent &event, const AlarmRecord &record);
    void onReset();
    void publishAll();
    void publishState(const QString &alarmId);
    void onMessage(const QString &topic, const QByteArray &payload, bool retained, bool queued);
    // What the command did (empty) or why not; `reply` gets its id and the alarm's state.
    Message carryOut(const GatewayTopics::AlarmCommandTopic &target, const QByteArray &payload,
                     bool queued, AlarmPayload::Reply &reply);
    void answer(const AlarmPayload::Reply &reply);

    GatewayConnectionConfig m_config;
    QString m_prefix;
    QPointer<AlarmEngine> m_engine;
    GatewayPublisher *m_publisher;
    QSet<QString> m_published; // alarm ids with a state on the broker
    bool m_started = false;
    bool m_awaitRestore = false;
    bool m_stopping = false;
    QDateTime m_brokerDownAt; // when the link to the broker last went down (invalid: never)
    bool m_brokerDown = true;
    QHash<QString, QByteArray> m_lastCommand; // per command topic, for retained copies
};

} // namespace Fatek
