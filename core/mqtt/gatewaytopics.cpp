#include "gatewaytopics.h"

#include <QStringList>

namespace Fatek {

namespace {

QString addressText(const Address &address)
{
    return QString::fromStdString(address.toString());
}

} // namespace

bool GatewayTopics::isValidConnectionName(const QString &name)
{
    if (name.isEmpty() || name.size() > 64)
        return false;
    bool digitsOnly = true;
    for (const QChar c : name) {
        if (!(c.isLetterOrNumber() || c == u'-' || c == u'_' || c == u'.'))
            return false;
        digitsOnly = digitsOnly && c.isDigit();
    }
    return !digitsOnly;
}

bool GatewayTopics::isValidPrefix(const QString &prefix)
{
    // MQTT topic levels (issue 55): a NUL ends the topic where the broker reads it (the gateway
    // then took its own values as commands); a topic starting with '$' is the broker's ($SYS),
    // which drops what a client publishes there; '+' and '#' are wildcards.
    if (prefix.isEmpty() || prefix.contains(u'+') || prefix.contains(u'#')
        || prefix.contains(QChar(0)) || prefix.startsWith(u'$'))
        return false;
    for (const QString &level : prefix.split(u'/')) {
        if (level.isEmpty())
            return false;
    }
    return true;
}

QString GatewayTopics::item(const QString &prefix, const QString &connection, int station,
                            const Address &address)
{
    return prefix + u'/' + connection + u'/' + QString::number(station) + u'/'
           + addressText(address);
}

QString GatewayTopics::itemSet(const QString &prefix, const QString &connection, int station,
                               const Address &address)
{
    return item(prefix, connection, station, address) + QStringLiteral("/set");
}

QString GatewayTopics::itemReply(const QString &prefix, const QString &connection, int station,
                                 const Address &address)
{
    return item(prefix, connection, station, address) + QStringLiteral("/reply");
}

QString GatewayTopics::status(const QString &prefix, const QString &connection)
{
    return prefix + u'/' + connection + QStringLiteral("/status");
}

QString GatewayTopics::statistics(const QString &prefix, const QString &connection)
{
    return prefix + u'/' + connection + QStringLiteral("/statistics");
}

QString GatewayTopics::itemFilter(const QString &prefix, const QString &connection)
{
    return prefix + u'/' + connection + QStringLiteral("/+/+");
}

QString GatewayTopics::setFilter(const QString &prefix, const QString &connection)
{
    return prefix + u'/' + connection + QStringLiteral("/+/+/set");
}

std::optional<GatewayTopics::Parsed> GatewayTopics::parse(const QString &prefix,
                                                          const QString &topic)
{
    if (!topic.startsWith(prefix + u'/'))
        return std::nullopt;
    const QStringList levels = topic.mid(prefix.size() + 1).split(u'/');
    if (levels.isEmpty() || !isValidConnectionName(levels[0]))
        return std::nullopt;
    Parsed parsed;
    parsed.connection = levels[0];
    if (levels.size() == 2) {
        if (levels[1] == u"status")
            parsed.kind = Kind::Status;
        else if (levels[1] == u"statistics")
            parsed.kind = Kind::Statistics;
        else
            return std::nullopt;
        return parsed;
    }
    if (levels.size() < 3 || levels.size() > 4)
        return std::nullopt;
    bool ok = false;
    parsed.station = levels[1].toInt(&ok);
    if (!ok || parsed.station < 0 || parsed.station > 255
        || levels[1] != QString::number(parsed.station))
        return std::nullopt;
    const Result<Address> address = Address::parse(levels[2].toStdString());
    if (!address || addressText(*address) != levels[2])
        return std::nullopt;
    parsed.address = *address;
    if (levels.size() == 3)
        parsed.kind = Kind::Item;
    else if (levels[3] == u"set")
        parsed.kind = Kind::Set;
    else if (levels[3] == u"reply")
        parsed.kind = Kind::Reply;
    else
        return std::nullopt;
    return parsed;
}

QString GatewayTopics::alarm(const QString &prefix, const QString &connection,
                             const QString &alarmId)
{
    return prefix + u'/' + connection + QStringLiteral("/alarms/") + alarmId;
}

QString GatewayTopics::alarmEvents(const QString &prefix, const QString &connection)
{
    return prefix + u'/' + connection + QStringLiteral("/alarms/events");
}

QString GatewayTopics::alarmReply(const QString &prefix, const QString &connection,
                                  const QString &alarmId)
{
    return alarm(prefix, connection, alarmId) + QStringLiteral("/reply");
}

QString GatewayTopics::alarmActionLevel(AlarmAction action)
{
    switch (action) {
    case AlarmAction::Acknowledge: return QStringLiteral("ack");
    case AlarmAction::Shelve: return QStringLiteral("shelve");
    case AlarmAction::Unshelve: return QStringLiteral("unshelve");
    }
    return {};
}

QString GatewayTopics::alarmCommand(const QString &prefix, const QString &connection,
                                    const QString &alarmId, AlarmAction action)
{
    return alarm(prefix, connection, alarmId) + u'/' + alarmActionLevel(action);
}

QString GatewayTopics::alarmCommandFilter(const QString &prefix, const QString &connection,
                                          AlarmAction action)
{
    return alarmCommand(prefix, connection, QStringLiteral("+"), action);
}

std::optional<GatewayTopics::AlarmCommandTopic>
GatewayTopics::parseAlarmCommand(const QString &prefix, const QString &topic)
{
    if (!topic.startsWith(prefix + u'/'))
        return std::nullopt;
    const QStringList levels = topic.mid(prefix.size() + 1).split(u'/');
    if (levels.size() != 4 || levels[1] != u"alarms" || levels[2].isEmpty()
        || !isValidConnectionName(levels[0]))
        return std::nullopt;
    AlarmCommandTopic parsed{levels[0], levels[2]};
    for (const AlarmAction action :
         {AlarmAction::Acknowledge, AlarmAction::Shelve, AlarmAction::Unshelve}) {
        if (levels[3] == alarmActionLevel(action)) {
            parsed.action = action;
            return parsed;
        }
    }
    return std::nullopt;
}

} // namespace Fatek
