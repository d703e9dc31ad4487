#pragma once

#include "clicommand.h"
#include "core/watch/datalogger.h"
#include "core/watch/itemassembler.h"

#include <QSet>

namespace Fatek {

struct CliStepArgs;

// monitor ADDR[:FORMAT]... [--interval MS] [--cycles N] [--format FORMAT] [--output FILE]
// [--names LIST]: planned polling, one line per cycle, optional CSV data log.
class CliMonitorCommand : public CliCommand
{
    Q_OBJECT

public:
    explicit CliMonitorCommand(CliContext &context);

    static QString parse(CliStepArgs &args);
    // After parse and the check of the station: the step's items with their resolved formats
    // (per item, else --format, else the element's default); the usage error, or an empty text.
    static QString resolveItems(CliStep &step, const CliOptions &options);

    // A monitor ends as if its last cycle had come (exit 0, the data log closed).
    void interrupt() override;
    void abandon() override;

protected:
    void run() override;

private:
    void onValues(const QList<WatchValue> &values);
    void armForNextCycle(qsizetype elements);
    // Closes the data log; false (and finished) when it cannot be closed.
    bool closeLog();

    int m_cycle = 0;
    int m_staleCycles = 0;
    bool m_errors = false;
    QSet<QString> m_reported; // "address + reason" noted once (for every monitor step)
    QStringList m_lastLate;   // the elements said late last cycle
    DataLogger m_logger;      // --output
    ItemAssembler m_items;    // step().items (keys: their indexes), their elements joined
};

} // namespace Fatek
