// fatek-bench: the performance figures of docs/performance.md, each next to what it is compared
// to, measured in the same run. Run through tools/bench.sh; never part of CTest.
#include "bench.h"

#include "core/session/session.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QElapsedTimer>
#include <QStandardPaths>

#include <algorithm>
#include <cstdio>
#include <cstdlib>

namespace Fatek::Bench {

QString fmt(double value, int decimals)
{
    return QString::number(value, 'f', decimals);
}

QString ratioText(double value, double base)
{
    if (base <= 0)
        return QStringLiteral("-");
    return fmt(value / base, 3);
}

namespace {

void printTable(const Report &report)
{
    const QStringList headers{QStringLiteral("figure"), QStringLiteral("value"),
                              QStringLiteral("compared to"), QStringLiteral("ratio"),
                              QStringLiteral("target")};
    std::vector<qsizetype> width(5);
    for (int c = 0; c < 5; ++c)
        width[static_cast<std::size_t>(c)] = headers[c].size();
    auto cells = [](const Row &r) {
        return QStringList{r.figure, r.value, r.comparedTo, r.ratio, r.target};
    };
    for (const Row &r : report.rows) {
        const QStringList c = cells(r);
        for (int i = 0; i < 5; ++i)
            width[static_cast<std::size_t>(i)]
                = std::max(width[static_cast<std::size_t>(i)], c[i].size());
    }
    auto line = [&](const QStringList &c) {
        QString out;
        for (int i = 0; i < 5; ++i) {
            const qsizetype w = width[static_cast<std::size_t>(i)];
            out += (i == 0 ? c[i].leftJustified(w) : c[i].rightJustified(w));
            out += i < 4 ? QStringLiteral(" | ") : QString();
        }
        std::printf("%s\n", qPrintable(out.trimmed()));
    };
    line(headers);
    QString rule;
    for (int i = 0; i < 5; ++i)
        rule += QString(width[static_cast<std::size_t>(i)], QLatin1Char('-'))
                + (i < 4 ? QStringLiteral("-+-") : QString());
    std::printf("%s\n", qPrintable(rule));
    for (const Row &r : report.rows)
        line(cells(r));
}

} // namespace
} // namespace Fatek::Bench

int main(int argc, char **argv)
{
    using namespace Fatek::Bench;
    // The UI figure needs widgets but no screen.
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    QApplication::setOrganizationName(QStringLiteral("fatek-bench"));
    QApplication::setApplicationName(QStringLiteral("fatek-bench"));
    // Recent connections go to a throw-away settings file, not the user's.
    QStandardPaths::setTestModeEnabled(true);
    Fatek::registerSessionMetaTypes();

    QCommandLineParser parser;
    parser.setApplicationDescription(
        QStringLiteral("FATEK Studio performance bench (see docs/performance.md)."));
    parser.addHelpOption();
    const QCommandLineOption quick(QStringLiteral("quick"),
                                   QStringLiteral("Short runs (for sanitizer builds)."));
    const QCommandLineOption only(QStringLiteral("only"),
                                  QStringLiteral("Run only these figures (comma list of 1-9)."),
                                  QStringLiteral("list"));
    parser.addOption(quick);
    parser.addOption(only);
    parser.process(app);

    Options options;
    options.quick = parser.isSet(quick);
    QStringList figures = parser.value(only).split(QLatin1Char(','), Qt::SkipEmptyParts);
    if (figures.isEmpty())
        figures = {QStringLiteral("1"), QStringLiteral("2"), QStringLiteral("3"),
                   QStringLiteral("4"), QStringLiteral("5"), QStringLiteral("6"),
                   QStringLiteral("7"), QStringLiteral("8"), QStringLiteral("9")};

    Report report;
    QElapsedTimer total;
    total.start();
    const std::vector<std::pair<QString, void (*)(const Options &, Report &)>> runs{
        {QStringLiteral("1"), &runPacking},  {QStringLiteral("2"), &runSerialCycle},
        {QStringLiteral("3"), &runTcp},      {QStringLiteral("4"), &runUiLoad},
        {QStringLiteral("5"), &runCodec},    {QStringLiteral("6"), &runGateway},
        {QStringLiteral("7"), &runPlanTime}, {QStringLiteral("8"), &runAlarmEvaluation},
        {QStringLiteral("9"), &runHistory},
    };
    for (const auto &[key, run] : runs) {
        if (!figures.contains(key))
            continue;
        QElapsedTimer clock;
        clock.start();
        run(options, report);
        std::fprintf(stderr, "figure %s done in %.1f s\n", qPrintable(key),
                     static_cast<double>(clock.elapsed()) / 1000.0);
    }

    std::printf("\n");
    printTable(report);
    std::printf("\nbench time: %.1f s%s\n", static_cast<double>(total.elapsed()) / 1000.0,
                options.quick ? " (--quick)" : "");
    bool allPass = true;
    for (const Outcome &r : report.results) {
        std::printf("RESULT %s %s %s %s\n", qPrintable(r.name),
                    qPrintable(QString::number(r.value, 'g', 6)), qPrintable(r.target),
                    r.pass ? "PASS" : "FAIL");
        allPass = allPass && r.pass;
    }
    std::fflush(stdout);
    return allPass ? EXIT_SUCCESS : EXIT_FAILURE;
}
