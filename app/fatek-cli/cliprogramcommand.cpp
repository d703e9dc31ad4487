// fatek-cli commands that carry the PLC's program: backup FILE, restore FILE (core's
// ProgramTransfer over 4F/50; the file is core's ProgramImage).
#include "cliprogramcommand.h"

#include "clicommands.h"
#include "clicontext.h"
#include "clitext.h"
#include "core/qtbridge/qtmessage.h"

#include <QFileInfo>
#include <QJsonArray>
#include <QTextStream>

#include <algorithm>

namespace Fatek {

using namespace CliText;

namespace {

QString crcText(std::uint32_t crc)
{
    return QStringLiteral("%1").arg(crc, 8, 16, QLatin1Char('0')).toUpper();
}

QJsonArray pagesJson(const std::vector<std::uint16_t> &pages)
{
    QJsonArray all;
    for (const std::uint16_t p : pages)
        all.append(p);
    return all;
}

// Ends the progress line on stderr, if one is shown.
void endProgressLine(bool *shown)
{
    if (*shown) {
        QTextStream err(stderr);
        err << Qt::endl;
    }
    *shown = false;
}

} // namespace

// backup FILE, restore FILE
QString CliProgramCommand::parse(CliStepArgs &a)
{
    a.step.file = a.positional.at(0);
    if (a.step.file.trimmed().isEmpty())
        return QStringLiteral("%1 needs a file name.").arg(a.cmd());
    return {};
}

void CliProgramCommand::run()
{
    if (step().command == CliCommandKind::Backup)
        runBackup();
    else
        runRestore();
}

void CliProgramCommand::interrupt()
{
    if (!m_program || !m_program->isRunning())
        return CliCommand::interrupt();
    m_interrupted = true;
    m_program->cancel();
}

void CliProgramCommand::startTransfer()
{
    m_program = std::make_unique<ProgramTransfer>();
    m_program->setSession(m_context.session());
    m_program->setStation(m_context.station());
    m_progressShown = false;
    connect(m_program.get(), &ProgramTransfer::progress, this,
            &CliProgramCommand::showTransferProgress);
    m_context.armWatchdog(m_context.requestBudgetMs());
}

void CliProgramCommand::showTransferProgress(int done, int total)
{
    // Every page is a request: the watchdog waits for the next one.
    m_context.armWatchdog(m_context.requestBudgetMs());
    if (!stderrIsTerminal() || total <= 0)
        return;
    QTextStream err(stderr);
    err << '\r' << englishText(ProgramTransfer::phaseMessage(m_program->phase())) << ": " << done
        << '/' << total << " pages   " << Qt::flush;
    m_progressShown = true;
}

void CliProgramCommand::failTransfer(const ProgramTransferResult &result)
{
    using Problem = ProgramTransferResult::Problem;
    endProgressLine(&m_progressShown);
    m_context.stopWatchdog();
    int code = ExitCode::Link;
    QString text = englishText(result.message);
    switch (result.problem) {
    case Problem::None:
    case Problem::NoSession:
    case Problem::Busy:
    case Problem::NoSize:
    case Problem::NoHeader: code = ExitCode::Link; break;
    case Problem::ReadOnly: code = ExitCode::ReadOnly; break;
    case Problem::Running:
        code = ExitCode::Plc;
        text += QStringLiteral(" Run `fatek-cli stop` first, or `fatek-cli stop --then restore "
                               "FILE`.");
        break;
    case Problem::ModelMismatch: code = ExitCode::Usage; break;
    case Problem::Request: code = CliContext::exitCodeFor(result.errorKind); break;
    case Problem::VerifyFailed: code = ExitCode::Plc; break;
    case Problem::Cancelled: code = ExitCode::Interrupted; break;
    }
    QJsonObject extra;
    extra.insert(QStringLiteral("station"), m_context.station());
    extra.insert(QStringLiteral("file"), step().file);
    if (!result.pages.empty())
        extra.insert(QStringLiteral("pages"), pagesJson(result.pages));
    // Where a backup's reading or a restore's writing stopped; a restore stopped while it
    // compared has written nothing, and no page to name ("Cancelled before anything was
    // written.").
    const bool comparing = step().command == CliCommandKind::Restore && !m_writing;
    if (result.stoppedAtPage >= 0 && !comparing)
        extra.insert(QStringLiteral("stoppedAtPage"), result.stoppedAtPage);
    if (step().command == CliCommandKind::Restore)
        extra.insert(QStringLiteral("writeStarted"), m_writing);
    out().error(text, code, extra);
    m_context.finish(code);
}

// --- backup ---------------------------------------------------------------------------------

void CliProgramCommand::runBackup()
{
    startTransfer();
    connect(m_program.get(), &ProgramTransfer::finished, this,
            [this](const ProgramTransferResult &result) {
                if (!result.ok() || m_interrupted)
                    return failTransfer(result);
                m_context.stopWatchdog();
                endProgressLine(&m_progressShown);
                const ProgramImage &image = m_program->plcImage();
                if (const auto error = image.save(step().file)) {
                    out().error(QString::fromStdString(error->text()), ExitCode::Internal);
                    return m_context.finish(ExitCode::Internal);
                }
                OutputBlock block;
                block.columns = {QStringLiteral("station"), QStringLiteral("file"),
                                 QStringLiteral("pages"),   QStringLiteral("program words"),
                                 QStringLiteral("model"),   QStringLiteral("crc32")};
                const QString model = image.modelText().isEmpty()
                                          ? englishText(image.header().model())
                                          : image.modelText();
                block.rows << QStringList{m_context.stationText(),
                                          step().file,
                                          QString::number(image.pageCount()),
                                          QString::number(image.header().ladderSize),
                                          model,
                                          crcText(image.checksum())};
                QJsonObject json;
                json.insert(QStringLiteral("station"), m_context.station());
                json.insert(QStringLiteral("file"), step().file);
                json.insert(QStringLiteral("pages"), image.pageCount());
                json.insert(QStringLiteral("programWords"), image.header().ladderSize);
                json.insert(QStringLiteral("model"), model);
                json.insert(QStringLiteral("crc32"), crcText(image.checksum()));
                json.insert(QStringLiteral("ok"), true);
                block.json << json;
                succeedWith(block);
            });
    m_program->backup();
}

// --- restore --------------------------------------------------------------------------------

void CliProgramCommand::runRestore()
{
    m_writing = false;
    const ProgramImage::LoadResult loaded = ProgramImage::load(step().file);
    if (!loaded.ok()) {
        out().error(QString::fromStdString(loaded.error().text()), ExitCode::Usage);
        return m_context.finish(ExitCode::Usage);
    }
    const ProgramImage &image = loaded.image(); // the lambdas below keep copies
    startTransfer();
    // First the PLC's program, to compare (refused in operator mode and in RUN, and for another
    // model); then the question; then the writes.
    connect(m_program.get(), &ProgramTransfer::finished, this,
            [this, image](const ProgramTransferResult &check) {
                disconnect(m_program.get(), &ProgramTransfer::finished, this, nullptr);
                if (!check.ok() || m_interrupted)
                    return failTransfer(check);
                confirmRestore(image, check);
            });
    m_program->checkRestore(image);
}

void CliProgramCommand::confirmRestore(const ProgramImage &image,
                                       const ProgramTransferResult &check)
{
    m_context.stopWatchdog();
    endProgressLine(&m_progressShown);
    const QString model = englishText(image.header().model());
    out().note(QStringLiteral("Restore %1 to station %2: %3 (%4), %5 pages, saved %6.")
                   .arg(QFileInfo(step().file).fileName(), m_context.stationText(), model,
                        image.modelText().isEmpty() ? QStringLiteral("model not recorded")
                                                    : image.modelText())
                   .arg(image.pageCount())
                   .arg(image.date().isValid() ? image.date().toString(Qt::ISODate)
                                               : QStringLiteral("at an unknown date")));
    out().note(englishText(check.message));
    const Confirmation answer = confirm(QStringLiteral("Write %1 pages to the PLC at station %2?")
                                            .arg(image.pageCount())
                                            .arg(m_context.stationText()),
                                        options().assumeYes);
    if (answer != Confirmation::Yes) {
        const QString why = answer == Confirmation::NoTerminal
                                ? QStringLiteral("Restore writes the PLC's program: give --yes "
                                                 "when standard input is not a terminal. Nothing "
                                                 "was written.")
                                : QStringLiteral("Not confirmed: nothing was written.");
        out().error(why, ExitCode::Usage);
        return m_context.finish(ExitCode::Usage);
    }
    const std::vector<std::uint16_t> differing = check.pages;
    connect(m_program.get(), &ProgramTransfer::finished, this,
            [this, image, differing](const ProgramTransferResult &result) {
                if (!result.ok() || m_interrupted)
                    return failTransfer(result);
                m_context.stopWatchdog();
                endProgressLine(&m_progressShown);
                OutputBlock block;
                block.columns
                    = {QStringLiteral("station"), QStringLiteral("file"), QStringLiteral("pages"),
                       QStringLiteral("changed pages"), QStringLiteral("result")};
                block.rows << QStringList{
                    m_context.stationText(), step().file, QString::number(image.pageCount()),
                    differing.empty() ? QStringLiteral("none")
                                      : QString::fromStdString(pageListText(differing)),
                    QStringLiteral("written and verified")};
                QJsonObject json;
                json.insert(QStringLiteral("station"), m_context.station());
                json.insert(QStringLiteral("file"), step().file);
                json.insert(QStringLiteral("pages"), image.pageCount());
                json.insert(QStringLiteral("programWords"), image.header().ladderSize);
                json.insert(QStringLiteral("changedPages"), pagesJson(differing));
                json.insert(QStringLiteral("verified"), true);
                json.insert(QStringLiteral("ok"), true);
                block.json << json;
                // The PLC stays in STOP unless the command line goes on to RUN it.
                const QList<CliStep> &steps = options().steps;
                const auto self = std::find_if(steps.begin(), steps.end(),
                                               [this](const CliStep &s) { return &s == &step(); });
                const bool runsNext = self != steps.end()
                                      && std::any_of(self + 1, steps.end(), [](const CliStep &s) {
                                             return s.command == CliCommandKind::Run;
                                         });
                if (!runsNext)
                    out().note(QStringLiteral("The PLC stays in STOP: `fatek-cli run` starts the "
                                              "restored program (or chain it: `fatek-cli stop "
                                              "--then restore FILE --then run`)."));
                succeedWith(block);
            });
    m_context.armWatchdog(m_context.requestBudgetMs());
    m_writing = true;
    m_program->restore(image);
}

} // namespace Fatek
