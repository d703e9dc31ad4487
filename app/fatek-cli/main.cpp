#include "app/common/quitsignal.h"
#include "clialarms.h"
#include "clicompletion.h"
#include "clihistory.h"
#include "clioptions.h"
#include "clioutput.h"
#include "clirunner.h"

#include <QCoreApplication>
#include <QGuiApplication>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTextStream>
#include <QTimer>

#include <cstdlib>
#include <cstring>
#include <memory>

#ifdef Q_OS_UNIX
#include <csignal>
#endif

using namespace Fatek;

namespace {

QtMessageHandler qtHandler = nullptr;

// The offscreen platform of a checkout's PDF asks for the runtime folder, and Qt warns on stderr
// when the environment has none (cron, a service, su): nothing the person can act on, so that
// one warning is dropped; every other message goes through.
void withoutRuntimeDirWarning(QtMsgType type, const QMessageLogContext &context,
                              const QString &message)
{
    if (message.startsWith(QLatin1String("QStandardPaths: XDG_RUNTIME_DIR not set")))
        return;
    qtHandler(type, context, message);
}

} // namespace

int main(int argc, char *argv[])
{
#ifdef Q_OS_UNIX
    // Qt ignores SIGPIPE once it opens a socket; ignored from the start, a closed stdout is always
    // EPIPE, which CliOutput turns into a quiet end with ExitCode::ClosedPipe (also for --help and
    // serial links, where no socket is opened), and the data log is closed on the way out.
    ::signal(SIGPIPE, SIG_IGN);
#endif
    // A checkout's PDF report lays out text (QPdfWriter): that needs a QGuiApplication, on the
    // offscreen platform so that no display is needed. Every other command stays Qt Core.
    bool checkout = false;
    for (int i = 1; i < argc; ++i)
        checkout = checkout || std::strcmp(argv[i], "checkout") == 0;
    if (checkout && qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    if (checkout)
        qtHandler = qInstallMessageHandler(withoutRuntimeDirWarning);
    const std::unique_ptr<QCoreApplication> application
        = checkout ? std::make_unique<QGuiApplication>(argc, argv)
                   : std::make_unique<QCoreApplication>(argc, argv);
    QCoreApplication &app = *application;
    QCoreApplication::setApplicationName(QStringLiteral("fatek-cli"));
    QCoreApplication::setApplicationVersion(QStringLiteral(PROJECT_VERSION_TEXT));

    QStringList arguments = QCoreApplication::arguments();
    arguments.removeFirst();
    // alarms runs a plant connection and an alarm engine, not the runner's steps.
    if (const qsizetype at = arguments.indexOf(QLatin1String("alarms"));
        at >= 0 && !arguments.contains(QLatin1String("--help"))) {
        arguments.removeAt(at);
        return runAlarms(arguments);
    }
    // history reads a store, not a PLC.
    if (!arguments.isEmpty() && arguments.first() == QLatin1String("history")
        && !arguments.contains(QLatin1String("--help"))) {
        arguments.removeFirst();
        return runHistory(arguments);
    }
    const CliParseResult parsed = parseCommandLine(arguments);
    if (!parsed.options) {
        QTextStream(stderr) << "fatek-cli: " << parsed.error << "\nTry 'fatek-cli --help'.\n";
        if (arguments.contains(QLatin1String("--json"))) {
            // Scripts parsing stdout get the error in their format too.
            const QJsonObject error{{QStringLiteral("error"), parsed.error},
                                    {QStringLiteral("code"), ExitCode::Usage}};
            CliOutput::printStdout(
                QString::fromUtf8(QJsonDocument(error).toJson(QJsonDocument::Compact)) + '\n');
        }
        return ExitCode::Usage;
    }
    if (parsed.options->help)
        return CliOutput::printStdout(usageText());
    if (!parsed.options->completion.isEmpty())
        return CliOutput::printStdout(completionScript(parsed.options->completion));
    if (parsed.options->version)
        return CliOutput::printStdout(
            QStringLiteral("fatek-cli %1\n").arg(QCoreApplication::applicationVersion()));

    CliRunner runner(*parsed.options);
    QObject::connect(
        &runner, &CliRunner::done, &app, [](int code) { QCoreApplication::exit(code); },
        Qt::QueuedConnection);
    // The first Ctrl-C ends the command cleanly (a monitor keeps its log, queued writes are sent);
    // a second one, while that is still going on, ends the program at once, unless the command
    // holds it: a checkout with an output still forced asks first.
    onQuitSignal(&runner, [&runner, asked = false]() mutable {
        if (asked && !runner.holdsInterrupts())
            std::_Exit(ExitCode::Interrupted);
        asked = true;
        runner.interrupt();
    });
    QTimer::singleShot(0, &runner, &CliRunner::start);
    return app.exec();
}
