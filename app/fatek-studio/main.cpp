// fatek-studio: the GUI. Options: --demo (embedded simulator and a ready watch table),
// --read-only (operator mode), --screenshot FILE (render the window to PNG after startup, exit),
// --language CODE (en, zh_TW: overrides the system locale and the View > Language choice), the
// link options of fatek-cli (--tcp, --udp, --serial, ... : open that connection at start) and a
// watch-list FILE (opened at start, its tables bound to that connection).
#include "app/common/linkarguments.h"
#include "ui/connection/connectionmanager.h"
#include "ui/mainwindow/languagemenu.h"
#include "ui/mainwindow/mainwindow.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QDeadlineTimer>
#include <QTimer>

#include <cstdio>
#include <memory>

namespace {

// Waits (without blocking the event loop) for the first values, then grabs the window.
void scheduleScreenshot(Fatek::MainWindow *window, const QString &path, bool demo,
                        const QString &tool)
{
    auto *timer = new QTimer(window);
    auto deadline = std::make_shared<QDeadlineTimer>(15000);
    // Values move in the demo; give the table a moment after the first batch so it fills in.
    auto settle = std::make_shared<int>(demo ? 6 : 0);
    QObject::connect(
        timer, &QTimer::timeout, window, [window, path, timer, deadline, settle, tool] {
            if (!deadline->hasExpired() && !window->hasValues()
                && !window->connections()->connections().isEmpty())
                return;
            if (!deadline->hasExpired() && (*settle)-- > 0)
                return;
            timer->stop();
            if (!window->hasValues() && !window->connections()->connections().isEmpty())
                std::fprintf(stderr,
                             "fatek-studio: no values arrived within 15 s; the screenshot shows "
                             "the table without them\n");
            // A tool opened for the picture gets a few settle ticks to show its first answers.
            QWidget *target = window;
            if (!tool.isEmpty()) {
                QWidget *toolWidget = window->openTool(tool);
                if (!toolWidget) {
                    std::fprintf(
                        stderr,
                        "fatek-studio: unknown tool %s (connection, control, forcing, console, "
                        "loopback, program, snapshot, trend)\n",
                        qPrintable(tool));
                    QCoreApplication::exit(2);
                    return;
                }
                if (toolWidget->isWindow())
                    target = toolWidget;
                auto grab = [target, path] {
                    const bool ok = target->grab().save(path, "PNG");
                    if (!ok)
                        std::fprintf(stderr, "fatek-studio: cannot write screenshot %s\n",
                                     qPrintable(path));
                    QCoreApplication::exit(ok ? 0 : 1);
                };
                if (tool == QLatin1String("trend")) {
                    // The trend shows its wave once it holds a whole demo sine period (10 s).
                    auto *wait = new QTimer(window);
                    auto trendDeadline = std::make_shared<QDeadlineTimer>(40000);
                    QObject::connect(wait, &QTimer::timeout, window,
                                     [wait, toolWidget, trendDeadline, grab] {
                                         if (toolWidget->property("spanMs").toLongLong() < 12000
                                             && !trendDeadline->hasExpired())
                                             return;
                                         wait->stop();
                                         grab();
                                     });
                    wait->start(250);
                    return;
                }
                QTimer::singleShot(3000, window, grab);
                return;
            }
            const bool saved = target->grab().save(path, "PNG");
            if (!saved)
                std::fprintf(stderr, "fatek-studio: cannot write screenshot %s\n",
                             qPrintable(path));
            QCoreApplication::exit(saved ? 0 : 1);
        });
    timer->start(250);
}

// --language must be known before the parser's own texts are built (they are translated too).
QString languageArgument(const QStringList &arguments)
{
    for (qsizetype i = 1; i < arguments.size(); ++i) {
        const QString &a = arguments.at(i);
        if ((a == QLatin1String("--language") || a == QLatin1String("-language"))
            && i + 1 < arguments.size())
            return arguments.at(i + 1);
        if (a.startsWith(QLatin1String("--language=")))
            return a.mid(11);
    }
    return {};
}

// The name a connection opened from the command line gets: "plc1:500", "plc1:500 (UDP)",
// "/dev/ttyUSB0".
QString connectionName(const Fatek::LinkSettings &link)
{
    switch (link.kind) {
    case Fatek::LinkSettings::Kind::Tcp:
        return QStringLiteral("%1:%2").arg(link.host).arg(link.port);
    case Fatek::LinkSettings::Kind::Udp:
        return QStringLiteral("%1:%2 (UDP)").arg(link.host).arg(link.port);
    case Fatek::LinkSettings::Kind::Serial: break;
    }
    return link.portName;
}

int usageError(const QString &message)
{
    std::fprintf(stderr, "fatek-studio: %s\n", qPrintable(message));
    std::fprintf(stderr, "Try 'fatek-studio --help' for more information.\n");
    return 2;
}

// --help, --help-all and --version print text and end: they need no display (an engineer on an
// SSH session reads the options), so they are answered before any GUI application exists.
bool asksForText(int argc, char *argv[])
{
    for (int i = 1; i < argc; ++i) {
        const QLatin1String a(argv[i]);
        if (a == QLatin1String("--help") || a == QLatin1String("-h") || a == QLatin1String("-?")
            || a == QLatin1String("--help-all") || a == QLatin1String("--version")
            || a == QLatin1String("-v"))
            return true;
    }
    return false;
}

// Returned by run() under a QCoreApplication when the command line wants the window after all
// ("--screenshot --help" names a file called --help).
constexpr int needsWindow = -1;

int run(QCoreApplication &app)
{
    auto *gui = qobject_cast<QApplication *>(&app);
    QCoreApplication::setOrganizationName(QStringLiteral("FATEK Studio"));
    QCoreApplication::setApplicationName(QStringLiteral("fatek-studio"));
    QCoreApplication::setApplicationVersion(QStringLiteral(FATEK_VERSION));
    if (gui) {
        QGuiApplication::setApplicationDisplayName(QStringLiteral("FATEK Studio"));
        // Wayland and the task bar match the window to packaging/linux/fatek-studio.desktop.
        QGuiApplication::setDesktopFileName(QStringLiteral("fatek-studio"));
    }
    const QString language = languageArgument(QCoreApplication::arguments());
    if (!language.isEmpty() && !Fatek::Language::isKnown(language)) {
        std::fprintf(stderr, "fatek-studio: unknown language %s (%s)\n", qPrintable(language),
                     qPrintable(Fatek::Language::available().join(QStringLiteral(", "))));
        return 2;
    }
    Fatek::Language::install(&app, Fatek::Language::effectiveLocale(language));

    QCommandLineParser parser;
    parser.setApplicationDescription(
        QCoreApplication::translate("main", "Commissioning and monitoring tool for FATEK PLCs."));
    parser.addHelpOption();
    parser.addVersionOption();
    const QCommandLineOption demoOpt(
        QStringLiteral("demo"),
        QCoreApplication::translate(
            "main", "Start the embedded PLC simulator (demo ladder) and watch it."));
    const QCommandLineOption readOnlyOpt(
        QStringLiteral("read-only"),
        QCoreApplication::translate("main", "Operator mode: no writes, RUN/STOP or forcing."));
    const QCommandLineOption screenshotOpt(
        QStringLiteral("screenshot"),
        QCoreApplication::translate("main", "Render the main window to a PNG file after startup "
                                            "and exit."),
        QCoreApplication::translate("main", "file"));
    const QCommandLineOption toolOpt(
        QStringLiteral("tool"),
        QCoreApplication::translate("main", "With --screenshot: open a commissioning tool first "
                                            "(connection, control, forcing, console, loopback, "
                                            "program, snapshot, trend)."),
        QCoreApplication::translate("main", "name"));
    const QCommandLineOption languageOpt(
        QStringLiteral("language"),
        QCoreApplication::translate("main", "User interface language for this run: en or zh_TW "
                                            "(default: the View > Language choice, else the "
                                            "system's)."),
        QCoreApplication::translate("main", "code"));
    parser.addOptions({demoOpt, readOnlyOpt, screenshotOpt, toolOpt, languageOpt});
    // The link options of fatek-cli: the same names, texts and checks (app/common).
    parser.addOptions(Fatek::LinkArguments::commandLineOptions());
    parser.addPositionalArgument(
        QStringLiteral("file"),
        QCoreApplication::translate("main", "Watch list to open (.json); with a link option its "
                                            "tables watch that connection."),
        QStringLiteral("[file]"));
    // A bad command line is a usage error (exit 2) before any window shows; process() then only
    // handles --help, --help-all and --version.
    if (!parser.parse(QCoreApplication::arguments()))
        return usageError(parser.errorText());
    parser.process(app);
    if (!gui)
        return needsWindow;

    const QStringList files = parser.positionalArguments();
    if (files.size() > 1)
        return usageError(QStringLiteral("give at most one watch-list file, not %1 (\"%2\").")
                              .arg(files.size())
                              .arg(files.join(QStringLiteral("\", \""))));
    const bool demo = parser.isSet(demoOpt);
    const Fatek::LinkArguments linkArguments = Fatek::LinkArguments::fromParser(parser);
    Fatek::LinkArgumentRules rules;
    rules.alternative = QStringLiteral("--demo");
    rules.alternativeGiven = demo;
    rules.linkRequired = false;
    rules.minStation = 1; // a window watches values: station 0 (broadcast) never answers
    rules.defaultProtocol = Fatek::LinkSettings::ProtocolChoice::Auto; // as fatek-cli
    const Fatek::LinkArgumentsResult link = Fatek::resolveLinkArguments(linkArguments, rules);
    if (!link.error.isEmpty())
        return usageError(link.error);
    if (demo && linkArguments.any())
        return usageError(QStringLiteral("--demo runs its own simulator: the link options "
                                         "(--protocol, --station, --timeout, --retries) do not "
                                         "apply to it."));
    std::optional<Fatek::SavedConnection> connection;
    if (link.hasLink) {
        connection = Fatek::SavedConnection{};
        connection->name = connectionName(link.link);
        connection->settings = link.link; // autoReconnect on, as in File > New Connection
        connection->station = link.station;
    }
    const QString file = files.value(0);

    Fatek::MainWindow window(parser.isSet(readOnlyOpt));
    if (parser.isSet(screenshotOpt))
        window.resize(1280, 800); // the same picture whatever layout was saved last time
    window.show();
    if (file.isEmpty() && !demo && !parser.isSet(screenshotOpt))
        window.restoreLastWatchList();
    if (connection || !file.isEmpty()) {
        if (const Fatek::Status s = window.openAtStartup(connection, file); !s)
            std::fprintf(stderr, "fatek-studio: %s cannot be loaded: %s\n", qPrintable(file),
                         s.error().text().c_str());
    }
    if (demo)
        window.startDemo();
    if (parser.isSet(screenshotOpt))
        scheduleScreenshot(&window, parser.value(screenshotOpt), parser.isSet(demoOpt),
                           parser.value(toolOpt));
    return QApplication::exec();
}

} // namespace

int main(int argc, char *argv[])
{
    if (asksForText(argc, argv)) {
        QCoreApplication app(argc, argv);
        if (const int code = run(app); code != needsWindow)
            return code;
    }
    QApplication app(argc, argv);
    return run(app);
}
