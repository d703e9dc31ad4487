#pragma once

#include "clicommand.h"
#include "clicontext.h"
#include "core/commission/memorysnapshot.h"
#include "core/commission/snapshotdiff.h"

#include <functional>
#include <memory>
#include <optional>
#include <vector>

namespace Fatek {

class SnapshotReader;
struct CliStepArgs;

// What the commands on memory snapshots (snapshot, diff, restore-values; core/commission) share:
// the parsing of their files and ranges, the loading of a file, a reader on the session and the
// printing of differences.
class CliSnapshotFileCommand : public CliCommand
{
    Q_OBJECT

public:
    // Whether `path` names a snapshot file (.json or .csv), not a range.
    static bool isSnapshotFileName(const QString &path);

    explicit CliSnapshotFileCommand(CliContext &context);
    ~CliSnapshotFileCommand() override;

    // snapshot FILE [RANGES], restore-values FILE [RANGES]
    static QString parseFileAndRanges(CliStepArgs &args);
    void abandon() override;

protected:
    // The command's reader or restorer (core/commission) on the session, made once, the watchdog
    // re-armed on its progress; nothing connected to its finished() any more.
    template<class Worker>
    Worker *worker(std::unique_ptr<Worker> &owned)
    {
        if (!owned) {
            owned = std::make_unique<Worker>();
            owned->setSession(m_context.session());
            connect(owned.get(), &Worker::progress, this, &CliSnapshotFileCommand::rearmWatchdog);
        }
        disconnect(owned.get(), &Worker::finished, this, nullptr);
        return owned.get();
    }
    void rearmWatchdog();
    // RANGES from the argument `from` on (none: every element).
    static QString rangesArg(CliStepArgs &args, qsizetype from);
    // A snapshot file name: .json or .csv.
    static QString snapshotFileArg(CliStepArgs &args, const QString &path, QString *out);
    using ReadHandler = std::function<void(const SnapshotReader &reader)>;
    // Reads `ranges` from the PLC (the watchdog re-armed on progress): `onRead` gets the reader
    // once it has read them all; a failure ends the program.
    void readSnapshot(std::vector<AddressRange> ranges, ReadHandler onRead);
    // A snapshot file, or nothing after reporting why not (exit 2).
    std::optional<MemorySnapshot> loadSnapshot(const QString &path);
    // One line (table, CSV row, JSON object) per difference.
    void printDifferences(const std::vector<SnapshotDifference> &differences, bool readBack);

private:
    std::unique_ptr<SnapshotReader> m_reader;
};

} // namespace Fatek
