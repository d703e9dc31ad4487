// The kill -9 test's child (tst_historywriter): records one value every 50 ms through a
// HistoryWriter into the file it is given and prints each value's time once it was handed over,
// until it is killed.

#include "core/history/historywriter.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QTimer>

#include <cstdio>

using namespace Fatek;

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    if (argc != 2) {
        std::fprintf(stderr, "usage: historykillchild FILE\n");
        return 2;
    }
    HistoryWriter writer(QString::fromLocal8Bit(argv[1]), HistoryRetention{});
    QObject::connect(&writer, &HistoryWriter::failed, &app, [](const Message &reason) {
        std::fprintf(stderr, "%s\n", english(reason).c_str());
        QCoreApplication::exit(1);
    });
    HistorySeries series;
    series.source = QStringLiteral("line1");
    series.item = QStringLiteral("1-R100");
    const qint64 handle = writer.addSeries(series);
    QTimer timer;
    double value = 0;
    QObject::connect(&timer, &QTimer::timeout, &app, [&] {
        const qint64 now = QDateTime::currentMSecsSinceEpoch();
        value += 1;
        writer.record({HistoryRecord{handle, HistorySample{now, value, 0, HistoryQuality::Good}}});
        std::printf("%lld\n", static_cast<long long>(now));
        std::fflush(stdout);
    });
    timer.start(50);
    return QCoreApplication::exec();
}
