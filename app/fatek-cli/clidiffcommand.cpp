// fatek-cli diff.
#include "clidiffcommand.h"

#include "clicommands.h"
#include "clicontext.h"
#include "core/commission/snapshotreader.h"
#include "core/qtbridge/qtmessage.h"

namespace Fatek {

// diff FILE [FILE2] [RANGES]: the second argument is a file when it names one (or has a
// snapshot's extension), else the first range.
QString CliDiffCommand::parse(CliStepArgs &a)
{
    if (QString err = snapshotFileArg(a, a.positional.at(0), &a.step.file); !err.isEmpty())
        return err;
    qsizetype next = 1;
    if (a.positional.size() > 1 && isSnapshotFileName(a.positional.at(1))) {
        if (QString err = snapshotFileArg(a, a.positional.at(1), &a.step.file2); !err.isEmpty())
            return err;
        next = 2;
    }
    return rangesArg(a, next);
}

void CliDiffCommand::run()
{
    std::optional<MemorySnapshot> before = loadSnapshot(step().file);
    if (!before)
        return;
    // Only the elements in the ranges given (all without ranges), on both sides.
    const std::vector<AddressRange> ranges = step().ranges;
    before->values = before->select(ranges);
    // Differences end with exit 6 (like diff(1) ends with 1): scripts test for equality.
    auto report = [this, ranges](const MemorySnapshot &a, MemorySnapshot b) {
        b.values = b.select(ranges);
        std::size_t compared = 0;
        const auto differences = SnapshotDiff::compare(a, b, &compared);
        printDifferences(differences, false);
        out().note(englishText(SnapshotDiff::summary(differences.size(), compared)));
        if (!differences.empty())
            return m_context.finish(ExitCode::Differ);
        succeed();
    };
    if (!step().file2.isEmpty()) {
        const std::optional<MemorySnapshot> after = loadSnapshot(step().file2);
        if (after)
            report(*before, *after);
        return;
    }
    std::vector<Address> addresses;
    addresses.reserve(before->values.size());
    for (const SnapshotValue &v : before->values)
        addresses.push_back(v.address);
    readSnapshot(Snapshot::rangesOf(addresses),
                 [report, file = *before](const SnapshotReader &reader) {
                     report(file, reader.snapshot());
                 });
}

} // namespace Fatek
