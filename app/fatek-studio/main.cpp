// fatek-studio: the GUI. Options: --demo (embedded simulator and a ready watch table),
// --read-only (operator mode), --screenshot FILE (render the window to PNG after startup, exit).
#include "connectionmanager.h"
#include "mainwindow.h"

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
            // A tool opened for the picture gets a few settle ticks to show its first answers.
            QWidget *target = window;
            if (!tool.isEmpty()) {
                QWidget *toolWidget = window->openTool(tool);
                if (!toolWidget) {
                    std::fprintf(
                        stderr,
                        "fatek-studio: unknown tool %s (control, forcing, console, loopback)\n",
                        qPrintable(tool));
                    QCoreApplication::exit(2);
                    return;
                }
                if (toolWidget->isWindow())
                    target = toolWidget;
                QTimer::singleShot(3000, window, [window, target, path] {
                    const bool ok = target->grab().save(path, "PNG");
                    if (!ok)
                        std::fprintf(stderr, "fatek-studio: cannot write screenshot %s\n",
                                     qPrintable(path));
                    Q_UNUSED(window)
                    QCoreApplication::exit(ok ? 0 : 1);
                });
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

} // namespace

int main(int argc, char *argv[])
{
    QApplication app(argc, argv);
    QApplication::setOrganizationName(QStringLiteral("FATEK Studio"));
    QApplication::setApplicationName(QStringLiteral("fatek-studio"));
    QApplication::setApplicationDisplayName(QStringLiteral("FATEK Studio"));
    QApplication::setApplicationVersion(QStringLiteral(FATEK_VERSION));

    QCommandLineParser parser;
    parser.setApplicationDescription(
        QStringLiteral("Commissioning and monitoring tool for FATEK PLCs."));
    parser.addHelpOption();
    parser.addVersionOption();
    const QCommandLineOption demoOpt(
        QStringLiteral("demo"),
        QStringLiteral("Start the embedded PLC simulator (demo ladder) and watch it."));
    const QCommandLineOption readOnlyOpt(
        QStringLiteral("read-only"),
        QStringLiteral("Operator mode: no writes, RUN/STOP or forcing."));
    const QCommandLineOption screenshotOpt(
        QStringLiteral("screenshot"),
        QStringLiteral("Render the main window to a PNG file after startup "
                       "and exit."),
        QStringLiteral("file"));
    const QCommandLineOption toolOpt(
        QStringLiteral("tool"),
        QStringLiteral("With --screenshot: open a commissioning tool first "
                       "(control, forcing, console, loopback)."),
        QStringLiteral("name"));
    parser.addOptions({demoOpt, readOnlyOpt, screenshotOpt, toolOpt});
    parser.process(app);

    Fatek::MainWindow window(parser.isSet(readOnlyOpt));
    if (parser.isSet(screenshotOpt))
        window.resize(1280, 800); // the same picture whatever layout was saved last time
    window.show();
    if (parser.isSet(demoOpt))
        window.startDemo();
    else if (!parser.isSet(screenshotOpt))
        window.restoreLastWatchList();
    if (parser.isSet(screenshotOpt))
        scheduleScreenshot(&window, parser.value(screenshotOpt), parser.isSet(demoOpt),
                           parser.value(toolOpt));
    return QApplication::exec();
}
