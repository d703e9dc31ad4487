#include "app/common/quitsignal.h"
#include "clicompletion.h"
#include "clioptions.h"
#include "clioutput.h"
#include "clirunner.h"

#include <QCoreApplication>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTextStream>
#include <QTimer>

#include <cstdlib>

#ifdef Q_OS_UNIX
#include <csignal>
#endif

using namespace Fatek;

int main(int argc, char *argv[])
{
#ifdef Q_OS_UNIX
    // Qt ignores SIGPIPE once it opens a socket; ignored from the start, a closed stdout is always
    // EPIPE, which CliOutput turns into a quiet end with ExitCode::ClosedPipe (also for --help and
    // serial links, where no socket is opened), and the data log is closed on the way out.
    ::signal(SIGPIPE, SIG_IGN);
#endif
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("fatek-cli"));
    QCoreApplication::setApplicationVersion(QStringLiteral(PROJECT_VERSION_TEXT));

    QStringList arguments = QCoreApplication::arguments();
    arguments.removeFirst();
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
    // a second one, while that is still going on, ends the program at once.
    onQuitSignal(&runner, [&runner, asked = false]() mutable {
        if (asked)
            std::_Exit(ExitCode::Interrupted);
        asked = true;
        runner.interrupt();
    });
    QTimer::singleShot(0, &runner, &CliRunner::start);
    return app.exec();
}
