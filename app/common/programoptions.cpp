#include "programoptions.h"

#include <QCoreApplication>
#include <QStringList>
#include <QTextStream>

namespace Fatek::ProgramOptions {

void addHelpAndVersion(QCommandLineParser &parser)
{
    parser.addOption(QCommandLineOption({QStringLiteral("h"), QStringLiteral("help")},
                                        QStringLiteral("Show this help and exit.")));
    parser.addOption(QCommandLineOption({QStringLiteral("v"), QStringLiteral("version")},
                                        QStringLiteral("Show the version and exit.")));
}

QString errorText(const QCommandLineParser &parser)
{
    const QStringList unknown = parser.unknownOptionNames();
    if (!unknown.isEmpty()) {
        const QString &name = unknown.constFirst();
        return QStringLiteral("Unknown option %1%2 (see --help).")
            .arg(name.size() == 1 ? QStringLiteral("-") : QStringLiteral("--"), name);
    }
    return parser.errorText();
}

int printHelp(const QCommandLineParser &parser)
{
    // Qt's usage line names the program as it was typed ("./build/fatek-sim"): the name instead.
    QString text = parser.helpText();
    const QString usage = QStringLiteral("Usage: ");
    if (text.startsWith(usage)) {
        const qsizetype end = text.indexOf(QLatin1Char(' '), usage.size());
        if (end > 0)
            text.replace(usage.size(), end - usage.size(), QCoreApplication::applicationName());
    }
    QTextStream(stdout) << text;
    return 0;
}

int printVersion()
{
    QTextStream(stdout) << QCoreApplication::applicationName() << ' '
                        << QCoreApplication::applicationVersion() << '\n';
    return 0;
}

} // namespace Fatek::ProgramOptions
