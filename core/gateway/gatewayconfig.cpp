#include "gatewayconfig.h"

#include "core/mqtt/gatewaytopics.h"
#include "core/protocol/logtext.h"
#include "core/watch/jsonkeys.h"
#include "core/watch/watchmessages.h"
#include "gatewayconfigreader.h"
#include "gatewayhistoryconfig.h"
#include "gatewaymessages.h"
#include "homeassistantdiscovery.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QHash>
#include <QHostAddress>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSet>
#include <QUrl>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace Fatek {

namespace {

using GatewayConfigRead::at;
using GatewayConfigRead::Reader;
using GatewayConfigRead::resolve;
using Problem = GatewayConfigProblem;

Problem readBroker(const QJsonObject &json, const QString &baseDirectory, MqttBrokerSettings *out)
{
    Reader r(json);
    const QString url = r.string(QStringLiteral("url"), QStringLiteral("mqtt://127.0.0.1:1883"));
    if (r.problem)
        return r.problem;
    Result<MqttBrokerSettings> parsed = MqttBrokerSettings::fromUrl(url);
    if (!parsed)
        return parsed.error().message;
    MqttBrokerSettings broker = std::move(parsed).value();
    auto file = [&](const QString &key, QString *target) {
        const QString name = r.string(key);
        if (!name.isEmpty())
            *target = resolve(baseDirectory, name);
    };
    file(QStringLiteral("caFile"), &broker.caFile);
    file(QStringLiteral("certFile"), &broker.certFile);
    file(QStringLiteral("keyFile"), &broker.keyFile);
    broker.tlsInsecure = r.boolean(QStringLiteral("tlsInsecure"), false);
    if (r.has(QStringLiteral("username")))
        broker.username = r.string(QStringLiteral("username"));
    if (r.has(QStringLiteral("password")) && r.has(QStringLiteral("passwordFile")))
        return msg<MsgId::GatewayConfigPasswordTwice>("password", "passwordFile");
    if (r.has(QStringLiteral("password")))
        broker.password = r.string(QStringLiteral("password"));
    const QString passwordFile = r.string(QStringLiteral("passwordFile"));
    broker.clientId = r.string(QStringLiteral("clientId"));
    r.integerInto(QStringLiteral("keepAliveSec"), 5, 65535, &broker.keepAliveSec);
    r.rejectUnknown();
    if (r.problem)
        return r.problem;
    if (!passwordFile.isEmpty()) {
        // The first line: a password kept out of a configuration that may be shown around.
        QFile f(resolve(baseDirectory, passwordFile));
        if (!f.open(QIODevice::ReadOnly))
            return msg<MsgId::GatewayConfigCannotRead>(
                f.fileName().toStdString(), Message::text(f.errorString().toStdString()));
        broker.password = QString::fromUtf8(f.readLine(4096)).trimmed();
    }
    if (const Message m = broker.validate(); !m.empty())
        return m;
    *out = broker;
    return std::nullopt;
}

Problem readHomeAssistant(const QJsonObject &json, GatewayConfig::HomeAssistant *out)
{
    Reader r(json);
    out->discovery = r.boolean(QStringLiteral("discovery"), false);
    out->prefix = r.string(QStringLiteral("prefix"), out->prefix);
    r.rejectUnknown();
    if (r.problem)
        return r.problem;
    if (!GatewayTopics::isValidPrefix(out->prefix))
        return msg<MsgId::GatewayConfigBadPrefix>(escapedForLog(out->prefix.toStdString()));
    return std::nullopt;
}

// A host as a start would look it up: an IP address, or a DNS name of labels of letters,
// digits, '-' (and '_', which local names have), none empty or longer than 63 (issue 55: "not a
// host!" passed --check and the link retried for ever).
bool isHostSyntax(const QString &host)
{
    if (QHostAddress address; address.setAddress(host))
        return true;
    const QByteArray ace = QUrl::toAce(host);
    if (ace.isEmpty() || ace.size() > 253)
        return false;
    for (const QByteArray &label : ace.split('.')) {
        if (label.isEmpty() || label.size() > 63 || label.startsWith('-') || label.endsWith('-'))
            return false;
        for (const char c : label) {
            const bool plain = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z')
                               || (c >= '0' && c <= '9') || c == '-' || c == '_';
            if (!plain)
                return false;
        }
    }
    return true;
}

// The checks of every link, given as an object or as a URL.
Message validateLink(const LinkSettings &link)
{
    if (const Message m = link.validate(); !m.empty())
        return m;
    if (link.kind != LinkSettings::Kind::Serial && !isHostSyntax(link.host.trimmed()))
        return msg<MsgId::GatewayConfigBadHost>(escapedForLog(link.host.toStdString()));
    return {};
}

Problem readLink(const QJsonObject &json, LinkSettings *out)
{
    Reader r(json);
    const QString kind = r.string(QStringLiteral("kind"), QStringLiteral("tcp"));
    if (r.problem)
        return r.problem;
    LinkSettings link;
    if (kind == u"tcp")
        link = LinkSettings::tcp(QStringLiteral("127.0.0.1"));
    else if (kind == u"udp")
        link = LinkSettings::udp(QStringLiteral("127.0.0.1"));
    else if (kind == u"serial")
        link = LinkSettings::serial(QString());
    else
        return msg<MsgId::GatewayConfigBadKind>(kind.toStdString(), "tcp", "udp", "serial");
    link.autoReconnect = true; // a gateway never gives up on its PLC
    link.host = r.string(QStringLiteral("host"), link.host);
    r.integerInto(QStringLiteral("port"), 1, 65535, &link.port);
    link.portName = r.string(QStringLiteral("portName"), link.portName);
    r.integerInto(QStringLiteral("baud"), 1, std::numeric_limits<qint32>::max(), &link.baudRate);
    const QString format = r.string(QStringLiteral("format"));
    const QString protocol = r.string(QStringLiteral("protocol"), QStringLiteral("facon"));
    // The range of a link URL's timeout= (10 ms is already shorter than any PLC answers in).
    r.integerInto(QStringLiteral("timeoutMs"), 10, 60000, &link.timeoutMs);
    r.integerInto(QStringLiteral("retries"), 0, 10, &link.retries);
    r.rejectUnknown();
    if (r.problem)
        return r.problem;
    if (!format.isEmpty()) {
        if (const QString error = link.setSerialFormat(format); !error.isEmpty())
            return Message::text(error.toStdString());
    }
    // The one reading of a protocol name (also --protocol and a link URL's protocol=).
    const std::optional<LinkSettings::ProtocolChoice> choice = protocolChoiceFromText(protocol);
    if (!choice)
        return msg<MsgId::GatewayConfigBadProtocol>(protocol.toStdString(), "facon", "binary",
                                                    "auto");
    link.protocol = *choice;
    if (const Message m = validateLink(link); !m.empty())
        return m;
    *out = link;
    return std::nullopt;
}

Problem readWatchLists(Reader &r, const QString &baseDirectory, GatewayConnectionConfig *c)
{
    const QJsonArray lists = r.array(QStringLiteral("watchLists"));
    if (r.problem)
        return r.problem;
    for (qsizetype i = 0; i < lists.size(); ++i) {
        const Message place = msg<MsgId::GatewayPlaceWatchList>(i + 1);
        if (!lists.at(i).isObject())
            return at(place, msg<MsgId::JsonWrongType>("watchLists", msg<MsgId::JsonTypeObject>()));
        Reader lr(lists.at(i).toObject());
        GatewayConnectionConfig::WatchListFileRef ref;
        ref.file = lr.string(QStringLiteral("file"));
        if (const std::optional<qint64> interval = lr.integer(
                QStringLiteral("intervalMs"), WatchList::MinIntervalMs, WatchList::MaxIntervalMs))
            ref.intervalMs = static_cast<int>(*interval);
        lr.rejectUnknown();
        if (!lr.problem && ref.file.isEmpty())
            lr.problem = msg<MsgId::JsonKeyMissing>("file");
        if (lr.problem)
            return at(place, *lr.problem);
        const Message filePlace = msg<MsgId::GatewayPlaceWatchList>(ref.file.toStdString());
        const Result<WatchListFile> file
            = WatchList::loadFromFile(resolve(baseDirectory, ref.file));
        if (!file) {
            // The watch list names its file itself ("line1.json: table 1, ..."): once is enough.
            Message error = file.error().message;
            const std::string fileName = QFileInfo(ref.file).fileName().toStdString();
            if (error.id == MsgId::AtPlace && error.args.size() == 2 && error.args[0].message
                && error.args[1].message && english(*error.args[0].message) == fileName) {
                const Message inner = *error.args[1].message;
                error = inner;
            }
            return at(filePlace, error);
        }
        for (WatchTableSpec table : file->tables) {
            if (ref.intervalMs)
                table.intervalMs = *ref.intervalMs;
            c->tables.append(table);
        }
        c->watchLists.append(ref);
    }
    // One topic per station and address: a second item there would overwrite the first's.
    QSet<QPair<int, QString>> seen;
    for (qsizetype t = 0; t < c->tables.size(); ++t) {
        const QList<WatchItemSpec> &items = c->tables.at(t).items;
        for (qsizetype i = 0; i < items.size(); ++i) {
            const QString address = QString::fromStdString(items.at(i).address.toString());
            if (!seen.contains({items.at(i).station, address})) {
                seen.insert({items.at(i).station, address});
                continue;
            }
            return at(
                msg<MsgId::PlaceItem>(t + 1, i + 1),
                msg<MsgId::GatewayConfigDuplicateItem>(items.at(i).station, address.toStdString()));
        }
    }
    if (seen.isEmpty())
        return msg<MsgId::GatewayConfigNoItems>();
    return std::nullopt;
}

Problem readConnection(const QJsonObject &json, const QString &baseDirectory,
                       GatewayConnectionConfig *c)
{
    Reader r(json);
    c->name = r.string(QStringLiteral("name"));
    if (!r.problem && !r.has(QStringLiteral("name")))
        r.problem = msg<MsgId::JsonKeyMissing>("name");
    if (!r.problem && !GatewayTopics::isValidConnectionName(c->name))
        r.problem = msg<MsgId::GatewayConfigBadName>(c->name.toStdString());
    r.integerInto(QStringLiteral("statisticsIntervalMs"), GatewayConfig::MinStatisticsIntervalMs,
                  GatewayConfig::MaxStatisticsIntervalMs, &c->statisticsIntervalMs);
    r.integerInto(QStringLiteral("commandMaxAgeSec"), 1, 3600, &c->commandMaxAgeSec);
    // The link as an object of settings, or as the URL the other programs take
    // ("tcp://192.168.1.5?protocol=binary", "serial:///dev/ttyUSB0?baud=19200&format=7E1").
    const bool linkUrl = json.value(QStringLiteral("link")).isString();
    const QString url = linkUrl ? r.string(QStringLiteral("link")) : QString();
    const QJsonObject link = linkUrl ? QJsonObject() : r.object(QStringLiteral("link"), true);
    r.known({QStringLiteral("allow"), QStringLiteral("watchLists")}); // read below
    r.rejectUnknown();
    if (r.problem)
        return r.problem;
    if (linkUrl) {
        LinkSettings defaults;
        defaults.autoReconnect = true; // a gateway never gives up on its PLC
        Message error;
        const std::optional<LinkSettings::Parsed> parsed
            = LinkSettings::fromUrl(url, &error, defaults);
        // The station is the watch lists' (each item names its own): neither refusal lists it
        // among the settings a gateway's link takes.
        const char *takes = url.trimmed().startsWith(QLatin1String("serial:"), Qt::CaseInsensitive)
                                ? "baud, format, flow, protocol, timeout, retries"
                                : "protocol, timeout, retries";
        if (!parsed && error.id == MsgId::SettingsUrlUnknown && error.args.size() == 3)
            error = msg<MsgId::SettingsUrlUnknown>(error.args[0], error.args[1], takes);
        if (!parsed)
            return at(msg<MsgId::GatewayPlaceLink>(), error);
        if (parsed->station)
            return at(msg<MsgId::GatewayPlaceLink>(),
                      msg<MsgId::SettingsUrlUnknown>(url.toStdString(), "station", takes));
        if (const Message m = validateLink(parsed->settings); !m.empty())
            return at(msg<MsgId::GatewayPlaceLink>(), m);
        c->link = parsed->settings;
    } else if (Problem p = readLink(link, &c->link)) {
        return at(msg<MsgId::GatewayPlaceLink>(), *p);
    }
    const QJsonArray allow = r.array(QStringLiteral("allow"));
    if (r.problem)
        return r.problem;
    for (const auto &entry : allow) {
        const QString text = entry.toString();
        if (!entry.isString())
            return msg<MsgId::JsonWrongType>("allow", msg<MsgId::JsonTypeString>());
        const Result<AddressRange> range = AddressRange::parse(text.toStdString());
        if (!range)
            return at(msg<MsgId::GatewayPlaceAllow>(text.toStdString()), range.error().message);
        c->allow.push_back(*range);
    }
    return readWatchLists(r, baseDirectory, c);
}

// Home Assistant's ids keep only letters, digits, '-' and '_' (HomeAssistantDiscovery::idLevel):
// "line.1" and "line_1" would be one device, one connection's entities lost (issue 55). Refused
// rather than made injective, so that the ids of existing entities stay as they are.
Problem checkDiscoveryIds(const GatewayConfig &config)
{
    if (!config.homeAssistant.discovery)
        return std::nullopt;
    QHash<QString, qsizetype> nodes;
    for (qsizetype i = 0; i < config.connections.size(); ++i) {
        const QString name = config.connections.at(i).name;
        const QString node = HomeAssistantDiscovery::idLevel(config.prefix + u'_' + name);
        const auto other = nodes.constFind(node);
        if (other == nodes.cend()) {
            nodes.insert(node, i);
            continue;
        }
        return at(msg<MsgId::GatewayPlaceConnection>(i + 1, name.toStdString()),
                  msg<MsgId::GatewayConfigDiscoveryIdTwice>(
                      config.connections.at(*other).name.toStdString(), name.toStdString(),
                      node.toStdString()));
    }
    return std::nullopt;
}

} // namespace

bool GatewayConnectionConfig::allows(const Address &address) const
{
    for (const AddressRange &range : allow) {
        if (range.start.type != address.type || address.number < range.start.number)
            continue;
        const std::uint32_t step = std::max<std::uint32_t>(1, range.start.info().step);
        const std::uint32_t offset = address.number - range.start.number;
        if (offset % step == 0 && offset / step < range.count)
            return true;
    }
    return false;
}

int GatewayConnectionConfig::itemCount() const
{
    int count = 0;
    for (const WatchTableSpec &table : tables)
        count += static_cast<int>(table.items.size());
    return count;
}

int GatewayConnectionConfig::alarmCount() const
{
    int count = 0;
    for (const WatchTableSpec &table : tables) {
        for (const WatchItemSpec &item : table.items)
            count += static_cast<int>(item.alarms.size());
    }
    return count;
}

int GatewayConnectionConfig::historyCount(bool recordAll) const
{
    int count = 0;
    for (const WatchTableSpec &table : tables) {
        for (const WatchItemSpec &item : table.items)
            count += recordAll || item.history ? 1 : 0;
    }
    return count;
}

int GatewayConfig::historyCount() const
{
    int count = 0;
    for (const GatewayConnectionConfig &connection : connections)
        count += connection.historyCount(history.recordAll.has_value());
    return count;
}

QString GatewayConfig::defaultHistoryStore(const QString &baseDirectory)
{
    return QFileInfo(defaultAlarmJournal(baseDirectory))
        .dir()
        .filePath(QStringLiteral("history.db"));
}

int GatewayConfig::alarmCount() const
{
    int count = 0;
    for (const GatewayConnectionConfig &connection : connections)
        count += connection.alarmCount();
    return count;
}

QString GatewayConfig::defaultAlarmJournal(const QString &baseDirectory)
{
    // systemd gives every directory of StateDirectory=, separated by ':'; ours is the first.
    const QString state = qEnvironmentVariable("STATE_DIRECTORY").section(u':', 0, 0);
    return resolve(state.isEmpty() ? baseDirectory : state, QStringLiteral("alarms.db"));
}

Result<GatewayConfig> GatewayConfig::load(const QByteArray &json, const QString &baseDirectory)
{
    const auto fail = [](Message m) {
        return makeError(ErrorKind::InvalidRequest, std::move(m));
    };
    QJsonParseError parseError{};
    const QJsonDocument document = QJsonDocument::fromJson(json, &parseError);
    if (parseError.error != QJsonParseError::NoError || !document.isObject())
        return fail(msg<MsgId::GatewayConfigNotJson>(Message::text(
            parseError.error != QJsonParseError::NoError ? parseError.errorString().toStdString()
                                                         : std::string("{ ... } expected"))));
    // Reader refuses a key it does not know, this one a key given twice (QJsonObject keeps only
    // the last: "readOnly":true,...,"readOnly":false would quietly allow writes).
    if (std::optional<Message> twice = JsonKeys::firstDuplicate(json))
        return fail(std::move(*twice));
    const QJsonObject root = document.object();
    if (root.value(QStringLiteral("format")).toString() != QLatin1StringView(FormatMarker))
        return fail(msg<MsgId::GatewayConfigWrongFormat>("format", FormatMarker));
    const QJsonValue version = root.value(QStringLiteral("version"));
    if (version.isUndefined())
        return fail(msg<MsgId::JsonKeyMissing>("version"));
    if (version.toInt(-1) != CurrentVersion)
        return fail(msg<MsgId::GatewayConfigWrongVersion>(QJsonDocument(QJsonArray{version})
                                                              .toJson(QJsonDocument::Compact)
                                                              .mid(1)
                                                              .chopped(1)
                                                              .toStdString(),
                                                          CurrentVersion));

    GatewayConfig config;
    Reader r(root);
    config.prefix = r.string(QStringLiteral("prefix"), config.prefix);
    config.readOnly = r.boolean(QStringLiteral("readOnly"), false);
    const QJsonObject broker = r.object(QStringLiteral("broker"), false);
    const QJsonObject homeAssistant = r.object(QStringLiteral("homeAssistant"), false);
    const QJsonArray connections = r.array(QStringLiteral("connections"));
    const bool journalGiven = r.has(QStringLiteral("alarmJournal"));
    const QString journal = r.string(QStringLiteral("alarmJournal"));
    const QJsonObject history = r.object(QStringLiteral("history"), false);
    r.known({QStringLiteral("format"), QStringLiteral("version")}); // checked above
    r.rejectUnknown();
    if (r.problem)
        return fail(*r.problem);
    if (!GatewayTopics::isValidPrefix(config.prefix))
        return fail(msg<MsgId::GatewayConfigBadPrefix>(escapedForLog(config.prefix.toStdString())));
    if (journalGiven && journal.trimmed().isEmpty())
        return fail(msg<MsgId::GatewayConfigEmptyFile>("alarmJournal"));
    config.alarmJournal
        = journalGiven ? resolve(baseDirectory, journal) : defaultAlarmJournal(baseDirectory);
    if (Problem p = GatewayConfigRead::readHistory(history, baseDirectory, &config.history))
        return fail(at(Message::text("history"), *p));
    if (Problem p = readBroker(broker, baseDirectory, &config.broker))
        return fail(at(msg<MsgId::GatewayPlaceBroker>(), *p));
    // The place is the key itself, as typed (not a word to translate).
    if (Problem p = readHomeAssistant(homeAssistant, &config.homeAssistant))
        return fail(at(Message::text("homeAssistant"), *p));
    if (connections.isEmpty())
        return fail(msg<MsgId::GatewayConfigNoConnections>());
    QSet<QString> names;
    for (qsizetype i = 0; i < connections.size(); ++i) {
        const QJsonObject object = connections.at(i).toObject();
        const QString name = object.value(QStringLiteral("name")).toString();
        const Message place = name.isEmpty()
                                  ? msg<MsgId::GatewayPlaceConnectionNumber>(i + 1)
                                  : msg<MsgId::GatewayPlaceConnection>(i + 1, name.toStdString());
        if (!connections.at(i).isObject())
            return fail(
                at(place, msg<MsgId::JsonWrongType>("connections", msg<MsgId::JsonTypeObject>())));
        GatewayConnectionConfig connection;
        if (Problem p = readConnection(object, baseDirectory, &connection))
            return fail(at(place, *p));
        if (names.contains(connection.name))
            return fail(at(place, msg<MsgId::GatewayConfigDuplicateName>(name.toStdString())));
        names.insert(connection.name);
        config.connections.append(connection);
    }
    if (Problem p = checkDiscoveryIds(config))
        return fail(*p);
    return config;
}

Result<GatewayConfig> GatewayConfig::loadFromFile(const QString &path)
{
    QFile file(path);
    // A configuration is small; a bound keeps a wrong path (a device, a huge log) from hanging.
    constexpr qint64 maxBytes = 4 * 1024 * 1024;
    if (!file.open(QIODevice::ReadOnly))
        return makeError(ErrorKind::InvalidRequest,
                         msg<MsgId::GatewayConfigCannotRead>(
                             path.toStdString(), Message::text(file.errorString().toStdString())));
    const QByteArray json = file.read(maxBytes + 1);
    if (json.size() > maxBytes)
        return makeError(ErrorKind::InvalidRequest,
                         msg<MsgId::GatewayConfigNotJson>(Message::text("larger than 4 MiB")));
    return load(json, QFileInfo(path).absolutePath());
}

} // namespace Fatek
