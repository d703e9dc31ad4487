// fatek-cli diff.
#include "clidiffcommand.h"

#include "clicommands.h"
#include "clicontext.h"
#include "core/commission/snapshotreader.h"
#include "core/qtbridge/qtmessage.h"

namespace Fatek {

// diff FILE [FILE2]
QString CliDiffCommand::parse(CliStepArgs &a)
{
    if (QString err = snapshotFileArg(a, a.positional.at(0), &a.step.file); !err.isEmpty())
        return err;
    if (a.positional.size() > 1)
        return snapshotFileArg(a, a.positional.at(1), &a.step.file2);
    return {};
}

void CliDiffCommand::run()
{
    const std::optional<MemorySnapshot> before = loadSnapshot(step().file);
    if (!before)
        return;
    // Differences end with exit 6 (like diff(1) ends with 1): scripts test for equality.
    auto report = [this](const MemorySnapshot &a, const MemorySnapshot &b) {
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
