#pragma once

#include <QString>

#include <functional>
#include <vector>

namespace Fatek::Bench {

// One line of the table: a measured figure next to what it is compared to (measured or computed
// in the same run).
struct Row
{
    QString figure;
    QString value;
    QString comparedTo;
    QString ratio;
    QString target;
};

// One RESULT line: a figure with a target, checked.
struct Outcome
{
    QString name;
    double value = 0;
    QString target;
    bool pass = false;
};

struct Report
{
    std::vector<Row> rows;
    std::vector<Outcome> results;

    void row(const QString &figure, const QString &value, const QString &comparedTo = {},
             const QString &ratio = {}, const QString &target = {})
    {
        rows.push_back({figure, value, comparedTo, ratio, target});
    }
    void result(const QString &name, double value, const QString &target, bool pass)
    {
        results.push_back({name, value, target, pass});
    }
};

struct Options
{
    bool quick = false; // shorter runs (sanitizer builds, smoke checks)
};

// The figures of the bench; each adds its rows and results.
void runPacking(const Options &options, Report &report);
void runSerialCycle(const Options &options, Report &report);
void runTcp(const Options &options, Report &report);
void runUiLoad(const Options &options, Report &report);
void runCodec(const Options &options, Report &report);
// fatek-gateway: 50 PLCs x 200 items at 1 Hz, 10 x 1000 at 10 Hz (issue 20).
void runGateway(const Options &options, Report &report);
// Planning time of a whole FBs snapshot and of the packing watch lists (issue 35).
void runPlanTime(const Options &options, Report &report);
// Alarm evaluation: 10,000 items, a high and a low alarm each, updated at 10 Hz (issue 50).
void runAlarmEvaluation(const Options &options, Report &report);
// History: 10,000 items recorded every second, a day of one item looked back at (issue 51).
void runHistory(const Options &options, Report &report);

QString fmt(double value, int decimals = 2);
QString ratioText(double value, double base);

} // namespace Fatek::Bench
