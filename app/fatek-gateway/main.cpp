// fatek-gateway: publishes FATEK PLC values to an MQTT broker and takes allowlisted writes back
// (docs/gateway.md). One GatewayLink per connection of the configuration file.

#include "app/common/quitsignal.h"
#include "core/gateway/gatewayconfig.h"
#include "core/gateway/gatewaylink.h"
#include "core/gateway/gatewaymessages.h"
#include "core/protocol/logtext.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QDateTime>
#include <QTextStream>

#include <algorithm>
#include <memory>
#include <vector>

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
    out() << "broker     " << config.broker.toUrl() << Qt::endl;
    out() << "prefix     " << config.prefix << Qt::endl;
    out() << "read-only  " << (config.readOnly ? "yes" : "no") << Qt::endl;
    for (const GatewayConnectionConfig &c : config.connections) {
        out() << "connection " << c.name << ": " << c.link.toString() << ", " << c.itemCount()
              << " items in " << c.tables.size() << " tables, writes allowed: "
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
                       "event on standard error."));
    parser.addHelpOption();
    parser.addVersionOption();
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
    parser.process(app);

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

    // Link i of n opens i/n of the shortest interval (at most 1 s) after the first, so that their
    // poll cycles, and the bursts of publications they cause, are spread over the interval.
    int shortestMs = 1000;
    for (const GatewayConnectionConfig &c : config.connections) {
        for (const WatchTableSpec &table : c.tables)
            shortestMs = std::min(shortestMs, table.intervalMs);
    }
    const auto linkCount = static_cast<int>(config.connections.size());
    std::vector<std::unique_ptr<GatewayLink>> links;
    for (const GatewayConnectionConfig &c : config.connections) {
        const int pollDelayMs = static_cast<int>(links.size()) * shortestMs / linkCount;
        auto link = std::make_unique<GatewayLink>(c, config.prefix, config.broker, config.readOnly);
        const QString name = c.name;
        QObject::connect(link.get(), &GatewayLink::logEvent,
                         [name](const Message &event) { logLine(name, event); });
        Message error;
        if (!link->start(&error, pollDelayMs)) {
            err() << "fatek-gateway: " << name << ": " << QString::fromStdString(english(error))
                  << Qt::endl;
            return 2;
        }
        logLine(name, msg<MsgId::GatewayLogStarted>(c.itemCount(), c.link.toString().toStdString(),
                                                    config.broker.toUrl().toStdString()));
        links.push_back(std::move(link));
    }
    // Every link publishes "offline" and disconnects; the program ends when all have.
    const auto quitWhenAllStopped = [&links] {
        for (const auto &link : links) {
            if (!link->isStopped())
                return;
        }
        QCoreApplication::quit();
    };
    for (const auto &link : links)
        QObject::connect(link.get(), &GatewayLink::stopped, &app, quitWhenAllStopped);
    onQuitSignal(&app, [&links] {
        for (const auto &link : links)
            link->stop();
    });
    const int rc = app.exec();
    links.clear();
    return rc;
}
