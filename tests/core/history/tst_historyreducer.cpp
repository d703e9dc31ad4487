// What a trend draws of a range (HistoryReducer, issue 51): per pixel column the first, minimum,
// maximum and last value so that peaks survive, every sample when there are fewer than columns,
// gaps where a sample has no value and where nothing was recorded for longer than the heartbeat
// allows, the value the line enters the range with, and a day of 1 s values in a few ms.

#include "core/history/historyreducer.h"

#include <QElapsedTimer>
#include <QTest>

#include <cmath>
#include <limits>

using namespace Fatek;

namespace {

HistorySample good(qint64 timeMs, double value)
{
    return HistorySample{timeMs, value, 0, HistoryQuality::Good};
}

HistorySample without(qint64 timeMs, HistoryQuality quality)
{
    return HistorySample{timeMs, std::numeric_limits<double>::quiet_NaN(), 0, quality};
}

HistoryPoint at(qint64 timeMs, double value)
{
    return HistoryPoint{timeMs, value, false};
}

HistoryPoint gapAt(qint64 timeMs)
{
    return HistoryPoint{timeMs, 0, true};
}

constexpr qint64 NoSilence = 0;

} // namespace

class TestHistoryReducer : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void bucketsKeepTheirPeaks()
    {
        // 1,000 samples into 10 columns of 100: a spike up and one down in column 3.
        std::vector<HistorySample> samples;
        for (qint64 t = 0; t < 1000; ++t)
            samples.push_back(good(t, 10));
        samples[345].value = 99;
        samples[367].value = -5;
        const std::vector<HistoryPoint> points
            = HistoryReducer::reduce(samples, 0, 1000, 10, NoSilence);
        // Flat columns: their first and last; column 3: first, max, min, last in time order.
        QCOMPARE(points.size(), std::size_t(9 * 2 + 4));
        const std::vector<HistoryPoint> third(points.begin() + 6, points.begin() + 10);
        QCOMPARE(third,
                 (std::vector<HistoryPoint>{at(300, 10), at(345, 99), at(367, -5), at(399, 10)}));
        for (std::size_t i = 1; i < points.size(); ++i)
            QVERIFY(points[i - 1].timeMs < points[i].timeMs);
        QCOMPARE(points.front(), at(0, 10));
        QCOMPARE(points.back(), at(999, 10));
    }

    void fewerSamplesThanBucketsKeepAll()
    {
        // Five samples crowded into one column of 100: all kept, in order.
        std::vector<HistorySample> samples{good(10, 1), good(11, 5), good(12, 3), good(13, 4),
                                           good(14, 2)};
        const std::vector<HistoryPoint> points
            = HistoryReducer::reduce(samples, 0, 10'000, 100, NoSilence);
        QCOMPARE(points, (std::vector<HistoryPoint>{at(10, 1), at(11, 5), at(12, 3), at(13, 4),
                                                    at(14, 2)}));
    }

    void sampleWithoutValueIsAGap()
    {
        const std::vector<HistorySample> samples{good(0, 1),
                                                 good(100, 2),
                                                 without(200, HistoryQuality::Stale),
                                                 without(300, HistoryQuality::Error),
                                                 good(400, 4),
                                                 without(500, HistoryQuality::Off),
                                                 HistorySample{600, 6, 0, HistoryQuality::Late}};
        const std::vector<HistoryPoint> points
            = HistoryReducer::reduce(samples, 0, 1000, 100, NoSilence);
        // One gap for the two without a value in a row; Late has a value.
        QCOMPARE(points, (std::vector<HistoryPoint>{at(0, 1), at(100, 2), gapAt(200), at(400, 4),
                                                    gapAt(500), at(600, 6)}));
        // A good sample without a number (an ASCII item): nothing to draw either.
        const std::vector<HistorySample> text{good(0, 1), without(100, HistoryQuality::Good),
                                              good(200, 2)};
        QCOMPARE(HistoryReducer::reduce(text, 0, 1000, 100, NoSilence),
                 (std::vector<HistoryPoint>{at(0, 1), gapAt(100), at(200, 2)}));
        // Reduced too: a gap survives its column.
        std::vector<HistorySample> many;
        for (qint64 t = 0; t < 1000; ++t)
            many.push_back(t == 500 ? without(t, HistoryQuality::Stale) : good(t, double(t % 7)));
        const std::vector<HistoryPoint> reduced
            = HistoryReducer::reduce(many, 0, 1000, 10, NoSilence);
        QCOMPARE(std::count_if(reduced.begin(), reduced.end(),
                               [](const HistoryPoint &p) { return p.gap; }),
                 1);
        const auto gap = std::find_if(reduced.begin(), reduced.end(),
                                      [](const HistoryPoint &p) { return p.gap; });
        QCOMPARE(gap->timeMs, qint64(500));
        QVERIFY((gap - 1)->timeMs < 500 && (gap + 1)->timeMs > 500);
        // A column that flaps keeps at most one gap inside and one at its end.
        std::vector<HistorySample> flapping;
        for (qint64 t = 0; t < 100; ++t)
            flapping.push_back(t % 2 ? without(t, HistoryQuality::Stale) : good(t, 1));
        QVERIFY(HistoryReducer::reduce(flapping, 0, 100, 1, NoSilence).size() <= 10);
    }

    void silenceLongerThanTheHeartbeatIsAGap()
    {
        // Heartbeat 10 s: a value holds for 25 s; 100 s of nothing is a gap from 25 s after.
        const qint64 silence = History::maxSilenceMs(10);
        QCOMPARE(silence, qint64(25'000));
        const std::vector<HistorySample> samples{good(0, 1), good(10'000, 1), good(110'000, 2),
                                                 good(120'000, 2)};
        QCOMPARE(HistoryReducer::reduce(samples, 0, 130'000, 1000, silence),
                 (std::vector<HistoryPoint>{at(0, 1), at(10'000, 1), gapAt(35'000), at(110'000, 2),
                                            at(120'000, 2)}));
        // The last value holds until its silence ends, then the line ends (the program stopped).
        QCOMPARE(HistoryReducer::reduce(samples, 0, 200'000, 1000, silence).back(), gapAt(145'000));
        // Within the heartbeat: no gap.
        QCOMPARE(
            HistoryReducer::reduce(samples, 0, 100'000, 1000, History::maxSilenceMs(600)).size(),
            std::size_t(2));
    }

    void valueBeforeTheRangeEntersAtItsStart()
    {
        const std::vector<HistorySample> samples{good(500, 7), good(1500, 8)};
        QCOMPARE(HistoryReducer::reduce(samples, 1000, 2000, 100, NoSilence),
                 (std::vector<HistoryPoint>{at(1000, 7), at(1500, 8)}));
        // Reduced alike.
        std::vector<HistorySample> many{good(-1, 3)};
        for (qint64 t = 0; t < 1000; ++t)
            many.push_back(good(t + 1000, 5));
        QCOMPARE(HistoryReducer::reduce(many, 0, 2000, 2, NoSilence).front(), at(0, 3));
        // Too old to still hold at the range's start: no line until the next sample.
        const std::vector<HistorySample> old{good(0, 7), good(100'000, 8)};
        QCOMPARE(HistoryReducer::reduce(old, 50'000, 200'000, 100, History::maxSilenceMs(10)),
                 (std::vector<HistoryPoint>{at(100'000, 8), gapAt(125'000)}));
        // Still holding, then silent: the gap where it stops holding.
        const std::vector<HistorySample> holding{good(40'000, 7), good(100'000, 8)};
        QCOMPARE(HistoryReducer::reduce(holding, 50'000, 110'000, 100, History::maxSilenceMs(10)),
                 (std::vector<HistoryPoint>{at(50'000, 7), gapAt(65'000), at(100'000, 8)}));
        // Entering without a value: no line.
        const std::vector<HistorySample> stale{without(10, HistoryQuality::Stale), good(1500, 8)};
        QCOMPARE(HistoryReducer::reduce(stale, 1000, 2000, 100, NoSilence),
                 (std::vector<HistoryPoint>{at(1500, 8)}));
    }

    void emptyInput()
    {
        QVERIFY(HistoryReducer::reduce({}, 0, 1000, 100, NoSilence).empty());
        QVERIFY(HistoryReducer::reduce({good(10, 1)}, 1000, 1000, 100, NoSilence).empty());
        QCOMPARE(HistoryReducer::reduce({good(10, 1)}, 0, 1000, 0, NoSilence),
                 std::vector<HistoryPoint>{at(10, 1)});
    }

    void aDayOfSecondsInAFewMilliseconds()
    {
        std::vector<HistorySample> samples;
        const qint64 start = 1'800'000'000'000;
        for (qint64 i = 0; i < 86'400; ++i)
            samples.push_back(good(start + i * 1000, std::sin(double(i) / 500.0) * 100));
        QElapsedTimer timer;
        timer.start();
        const std::vector<HistoryPoint> points = HistoryReducer::reduce(
            samples, start, start + 86'400'000, 1000, History::maxSilenceMs(600));
        const qint64 ns = timer.nsecsElapsed();
        qDebug("reduce: 86,400 samples into 1,000 columns: %.2f ms, %zu points", double(ns) / 1e6,
               points.size());
        QVERIFY(points.size() <= 4000);
        QVERIFY(points.size() >= 1000);
        QVERIFY(std::none_of(points.begin(), points.end(),
                             [](const HistoryPoint &p) { return p.gap; }));
        // The peaks are there.
        const auto [low, high] = std::minmax_element(
            points.begin(), points.end(),
            [](const HistoryPoint &a, const HistoryPoint &b) { return a.value < b.value; });
        QVERIFY(high->value > 99.99);
        QVERIFY(low->value < -99.99);
    }
};

QTEST_GUILESS_MAIN(TestHistoryReducer)

#include "tst_historyreducer.moc"
