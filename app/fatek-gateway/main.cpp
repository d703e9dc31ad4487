// fatek-gateway: publishes FATEK PLC values to an MQTT broker and takes allowlisted writes back
// (docs/gateway.md). One GatewayLink per connection of the configuration file (Gateway); SIGHUP
// reloads the file.

#include "app/common/programoptions.h"
#include "app/common/quitsignal.h"
#include "core/gateway/gateway.h"
#include "core/gateway/gatewayconfig.h"
#include "core/gateway/gatewaymessages.h"
#include "core/protocol/logtext.h"
#include "core/qtbridge/secrets.h"
#include "systemdnotifier.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QDateTime>
#include <QTextStream>

using namespace Fatek;

namespace {

QTextStream &out()
{
    static QTextStream stream(stdout);
    return stream;
}

QTextStream &err()
{
    static QTextStream stream(stderr);
    return stream;
}

// One line per event: UTC time, connection, what happened (a command's value may hold a
// newline: escapedForLog keeps it on this line).
void logLine(const QString &connection, const Message &event)
{
    err() << QDateTime::currentDateTimeUtc().toString(Qt::ISODateWithMs) << ' ' << connection
          << ": " << QString::fromStdString(escapedForLog(english(event))) << Qt::endl;
}

QString allowText(const GatewayConnectionConfig &connection)
{
    if (connection.allow.empty())
        return QStringLiteral("none (no writes)");
    QStringList ranges;
    for (const AddressRange &range : connection.allow)
        ranges << QString::fromStdString(range.toString());
    return ranges.join(QStringLiteral(", "));
}

void printSummary(const QString &path, const GatewayConfig &config)
{
    out() << path << ": OK" << Qt::endl;
    // Never a password (issue 55): toUrl() leaves it out, the history store's is refused and
    // masked all the same.
    out() << "broker     " << config.broker.toUrl() << Qt::endl;
    out() << "prefix     " << config.prefix << Qt::endl;
    out() << "read-only  " << (config.readOnly ? "yes" : "no") << Qt::endl;
    out() << "discovery  "
          << (config.homeAssistant.discovery
                  ? QStringLiteral("Home Assistant, under %1/").arg(config.homeAssistant.prefix)
                  : QStringLiteral("off"))
          << Qt::endl;
    out() << "alarms     "
          << (config.alarmCount() == 0 ? QStringLiteral("none")
                                       : QStringLiteral("%1, journal %2")
                                             .arg(config.alarmCount())
                                             .arg(config.alarmJournal))
          << Qt::endl;
    const auto retentionText = [](const HistoryRetention &r) {
        QStringList parts;
        if (r.maxAgeS > 0)
            parts << QStringLiteral("%1 days").arg(r.maxAgeS / (24 * 3600));
        if (r.maxBytes > 0)
            parts << QStringLiteral("%1 MB").arg(r.maxBytes / (1024 * 1024));
        return parts.isEmpty() ? QStringLiteral("kept for ever") : parts.join(QStringLiteral(", "));
    };
    out() << "history    "
          << (config.historyCount() == 0
                  ? QStringLiteral("none")
                  : QStringLiteral("%1 items%2, store %3, %4")
                        .arg(config.historyCount())
                        .arg(config.history.recordAll ? QStringLiteral(" (all)") : QString())
                        .arg(Secrets::maskUrl(config.history.store),
                             retentionText(config.history.retention)))
          << Qt::endl;
    for (const GatewayConnectionConfig &c : config.connections) {
        const auto counted = [](qsizetype n, const char *one, const char *many) {
            return QStringLiteral("%1 %2").arg(n).arg(QLatin1String(n == 1 ? one : many));
        };
        out() << "connection " << c.name << ": " << c.link.toString() << ", "
              << counted(c.itemCount(), "item", "items") << " in "
              << counted(c.tables.size(), "table", "tables") << ", writes allowed: "
              << (config.readOnly ? QStringLiteral("none (read-only)") : allowText(c)) << Qt::endl;
    }
}

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("fatek-gateway"));
    QCoreApplication::setApplicationVersion(QStringLiteral(PROJECT_VERSION_TEXT));

    QCommandLineParser parser;
    parser.setApplicationDescription(
        QStringLiteral("Publishes the values of FATEK PLCs to an MQTT broker and carries out "
                       "allowlisted writes.\nRuns until SIGINT or SIGTERM; logs one line per "
                       "event on standard error; SIGHUP reloads the configuration."));
    ProgramOptions::addHelpAndVersion(parser);
    const QCommandLineOption checkOpt(
        QStringLiteral("check"),
        QStringLiteral("Check the configuration, print a summary and exit (0: usable, 2: not)."));
    const QCommandLineOption readOnlyOpt(
        QStringLiteral("read-only"),
        QStringLiteral("Refuse every write, whatever the configuration says."));
    parser.addOption(checkOpt);
    parser.addOption(readOnlyOpt);
    parser.addPositionalArgument(QStringLiteral("config"),
                                 QStringLiteral("The configuration file (JSON)."));
    // Usage errors exit 2, as in the other programs (process() would exit 1).
    if (!parser.parse(QCoreApplication::arguments())) {
        err() << "fatek-gateway: " << ProgramOptions::errorText(parser) << Qt::endl;
        return 2;
    }
    if (parser.isSet(QStringLiteral("help")))
        return ProgramOptions::printHelp(parser);
    if (parser.isSet(QStringLiteral("version")))
        return ProgramOptions::printVersion();

    const QStringList positional = parser.positionalArguments();
    if (positional.size() != 1) {
        err() << "fatek-gateway: give one configuration file (see --help)." << Qt::endl;
        return 2;
    }
    const QString &path = positional.first();
    Result<GatewayConfig> loaded = GatewayConfig::loadFromFile(path);
    if (!loaded) {
        err() << "fatek-gateway: " << path << ": " << QString::fromStdString(loaded.error().text())
              << Qt::endl;
        return 2;
    }
    GatewayConfig config = std::move(loaded).value();
    if (parser.isSet(readOnlyOpt))
        config.readOnly = true;
    if (parser.isSet(checkOpt)) {
        printSummary(path, config);
        return 0;
    }

    Gateway gateway;
    QObject::connect(&gateway, &Gateway::logEvent, &logLine);
    QString failed;
    Message error;
    if (!gateway.start(config, &failed, &error)) {
        err() << "fatek-gateway: " << failed << ": " << QString::fromStdString(english(error))
              << Qt::endl;
        return 2;
    }
    // Under systemd (Type=notify): ready once the links run, alive while the loop turns.
    SystemdNotifier systemd;
    systemd.notify("READY=1");
    systemd.startWatchdog();
    // Every link publishes "offline" and disconnects; the program ends when all have.
    QObject::connect(&gateway, &Gateway::stopped, &app, &QCoreApplication::quit);
    onQuitSignal(&app, [&gateway, &systemd] {
        systemd.notify("STOPPING=1");
        gateway.stop();
    });
    // SIGHUP: the file again; one that does not load leaves the running configuration as it is.
    const QString self = QStringLiteral("fatek-gateway");
    const bool forceReadOnly = parser.isSet(readOnlyOpt);
    onReloadSignal(&app, [&gateway, &systemd, &path, &self, forceReadOnly] {
        systemd.reloading();
        logLine(self, msg<MsgId::GatewayLogReloading>(path.toStdString()));
        Result<GatewayConfig> reloaded = GatewayConfig::loadFromFile(path);
        if (!reloaded) {
            logLine(self, msg<MsgId::GatewayLogReloadFailed>(path.toStdString(),
                                                             reloaded.error().message));
            systemd.notify("READY=1");
            return;
        }
        if (forceReadOnly)
            reloaded.value().readOnly = true;
        gateway.reload(reloaded.value());
    });
    QObject::connect(&gateway, &Gateway::reloaded, &app, [&self, &systemd] {
        logLine(self, msg<MsgId::GatewayLogReloaded>());
        systemd.notify("READY=1");
    });
    return app.exec();
}
