// fatek-cli snapshot.
#include "clisnapshotcommand.h"

#include "clicontext.h"
#include "core/commission/snapshotfile.h"
#include "core/commission/snapshotreader.h"
#include "core/qtbridge/qtmessage.h"

namespace Fatek {

void CliSnapshotCommand::run()
{
    readSnapshot(step().ranges, [this](const SnapshotReader &reader) {
        const MemorySnapshot &s = reader.snapshot();
        if (const auto problem = SnapshotFile::saveToFile(
                s, step().file, options().crlf ? CsvFile::LineEnd::CrLf : CsvFile::LineEnd::Lf)) {
            out().error(englishText(problem->message), ExitCode::Internal);
            return m_context.finish(ExitCode::Internal);
        }
        OutputBlock block;
        block.columns = {QStringLiteral("field"), QStringLiteral("value")};
        block.tableHeader = false;
        block.rows << QStringList{QStringLiteral("file"), step().file}
                   << QStringList{QStringLiteral("values"), QString::number(s.values.size())}
                   << QStringList{QStringLiteral("requests"),
                                  QString::number(reader.requestsTotal())}
                   << QStringList{QStringLiteral("model"), s.info.model};
        QJsonObject json;
        json.insert(QStringLiteral("file"), step().file);
        json.insert(QStringLiteral("station"), m_context.station());
        json.insert(QStringLiteral("values"), static_cast<qint64>(s.values.size()));
        json.insert(QStringLiteral("requests"), reader.requestsTotal());
        json.insert(QStringLiteral("model"), s.info.model);
        block.json << json;
        succeedWith(block);
    });
}

} // namespace Fatek
