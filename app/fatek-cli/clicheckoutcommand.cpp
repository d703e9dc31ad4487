// fatek-cli checkout.
#include "clicheckoutcommand.h"

#include "clicheckoutanswer.h"
#include "clicheckoutinputs.h"
#include "clicommands.h"
#include "clicontext.h"
#include "clilinereader.h"
#include "clitext.h"
#include "core/commission/checkoutfile.h"
#include "core/commission/checkoutreport.h"
#include "core/commission/checkoutrunner.h"
#include "core/commission/commissionmessages.h"
#include "core/qtbridge/qtmessage.h"
#include "core/watch/osuser.h"
#include "core/watch/safefile.h"
#include "report/checkoutpdf.h"
#include "report/reporttranslator.h"

#include <QFile>
#include <QTextStream>

#include <cstdio>

#ifdef Q_OS_WIN
#include <io.h>
#define FATEK_ISATTY _isatty
#else
#include <unistd.h>
#define FATEK_ISATTY isatty
#endif

namespace Fatek {

namespace {

bool stdinIsTerminal()
{
    return FATEK_ISATTY(fileno(stdin)) != 0;
}

bool isYes(const QString &answer)
{
    const QString a = answer.toLower();
    return a == QLatin1String("y") || a == QLatin1String("yes");
}

CliLineReader &lines()
{
    return *CliLineReader::instance();
}

} // namespace

CliCheckoutCommand::CliCheckoutCommand(CliContext &context)
    : CliCommand(context)
{}

CliCheckoutCommand::~CliCheckoutCommand() = default;

QString CliCheckoutCommand::parse(CliStepArgs &args)
{
    args.step.file = args.positional.join(QLatin1Char(' ')).trimmed();
    return {};
}

bool CliCheckoutCommand::canAsk() const
{
    return stdinIsTerminal() || options().assumeYes;
}

void CliCheckoutCommand::ask(const QString &question, std::function<void(const QString &)> answer,
                             std::function<void()> noAnswer)
{
    QTextStream err(stderr);
    err << question << QLatin1Char(' ') << Qt::flush;
    // Not blocking: Ctrl-C and the releases go on while the person thinks.
    lines().nextLine([answer = std::move(answer),
                      noAnswer = std::move(noAnswer)](const std::optional<QString> &line) {
        if (line)
            answer(line->trimmed());
        else
            noAnswer();
    });
}

QString CliCheckoutCommand::forcedText() const
{
    QStringList forced;
    for (const Address &a : m_runner->plan().forced)
        forced << QString::fromStdString(a.toString());
    return forced.join(QStringLiteral(", "));
}

void CliCheckoutCommand::run()
{
    const QString planText = step().file;
    Result<CheckoutPlan> plan
        = makeError(ErrorKind::InvalidRequest, msg<MsgId::CheckoutPlanEmpty>());
    QString savePath = options().checkoutSave;
    if (planText.endsWith(QLatin1String(".json"), Qt::CaseInsensitive)) {
        plan = CheckoutFile::loadFromFile(planText);
        if (savePath.isEmpty())
            savePath = planText;
    } else if (planText.endsWith(QLatin1String(".csv"), Qt::CaseInsensitive)) {
        QFile f(planText);
        if (!f.open(QIODevice::ReadOnly))
            plan = makeError(
                ErrorKind::InvalidRequest,
                msg<MsgId::CheckoutFileCannotRead>(planText.toStdString(),
                                                   Message::text(f.errorString().toStdString())));
        else
            plan = CheckoutPlan::fromCsv(QString::fromUtf8(f.readAll()));
    } else {
        plan = CheckoutPlan::fromRanges(planText);
    }
    if (!plan) {
        out().error(englishText(plan.error().message), ExitCode::Usage);
        return m_context.finish(ExitCode::Usage);
    }
    // The report and the punch list are written at the end: a place that cannot take them is
    // said before anything is forced, not after the whole checkout.
    for (const QString &file : {options().checkoutReport, options().checkoutPunch}) {
        if (file.isEmpty())
            continue;
        if (const QString reason = SafeFile::checkWritable(file); !reason.isEmpty()) {
            out().error(englishText(msg<MsgId::ReportCannotWrite>(
                            file.toStdString(), Message::text(reason.toStdString())))
                            + QStringLiteral(" Nothing was forced."),
                        ExitCode::Internal);
            return m_context.finish(ExitCode::Internal);
        }
    }
    CheckoutPlan p = std::move(plan).value();
    p.info.station = m_context.station();
    // What the options say replaces what the file says; what they do not say stays.
    const auto given = [](QString &field, const QString &value) {
        if (!value.isEmpty())
            field = value;
    };
    given(p.info.project, options().checkoutProject);
    given(p.info.customer, options().checkoutCustomer);
    given(p.info.engineer, options().checkoutEngineer);
    given(p.info.documentId, options().checkoutDocument);
    given(p.info.revision, options().checkoutRevision);
    given(p.info.engineerCompany, options().checkoutCompany);
    given(p.info.witness, options().checkoutWitness);
    given(p.info.witnessCompany, options().checkoutWitnessCompany);
    given(p.info.customerSignatory, options().checkoutSignatory);
    // Every result names who recorded it: the login when no engineer is given (the core refuses
    // a checkout signed by nobody).
    if (p.info.engineer.trimmed().isEmpty())
        p.info.engineer = OsUser::name();
    m_outputs = p.indexesOf(CheckoutKind::Output);
    m_analogs = p.indexesOf(CheckoutKind::Analog);
    // Only the untested ones: a resumed checkout goes on where it stopped.
    const auto untested = [&p](std::vector<int> &v) {
        std::erase_if(v, [&p](int i) {
            return p.points[static_cast<std::size_t>(i)].result != CheckoutResult::Untested;
        });
    };
    untested(m_outputs);
    untested(m_analogs);
    if (!m_outputs.empty() && !options().readOnly && !canAsk()) {
        out().error(QStringLiteral("checkout forces outputs and asks what is seen: run it on a "
                                   "terminal, or give --yes and the answers on standard input. "
                                   "Nothing was forced."),
                    ExitCode::Usage);
        return m_context.finish(ExitCode::Usage);
    }
    m_context.stopWatchdog(); // people take their time
    m_runner = std::make_unique<CheckoutRunner>();
    CheckoutRunner *r = m_runner.get();
    r->setSession(m_context.session());
    r->setPlan(std::move(p));
    r->setFilePath(savePath);
    r->setEngineer(options().checkoutEngineer);
    connect(r, &CheckoutRunner::failed, this, [this](const ProtocolError &e) {
        // Also while finishing: a release that failed is said (once), and why the program waits.
        out().error(englishText(e.message), CliContext::exitCodeFor(e.kind));
        if (e.kind == ErrorKind::ReadOnly || e.kind == ErrorKind::LinkError
            || e.kind == ErrorKind::Timeout)
            finishCheckout(CliContext::exitCodeFor(e.kind));
    });
    connect(r, &CheckoutRunner::saveFailed, this, [this](const Message &m) {
        out().error(englishText(m), ExitCode::Internal);
        finishCheckout(ExitCode::Internal);
    });
    connect(r, &CheckoutRunner::leftoversReleased, this, [this](const Message &m) {
        if (lines().isWaiting()) // a question's line is open
            QTextStream(stderr) << '\n';
        out().note(englishText(m));
    });
    connect(r, &CheckoutRunner::refused, this, [this](const Message &m) {
        // Points the model does not have: nothing runs, nothing was forced.
        out().error(englishText(m), ExitCode::Usage);
        m_context.finish(ExitCode::Usage);
    });
    connect(r, &CheckoutRunner::readAgain, this, [this](const Message &m) {
        if (lines().isWaiting()) // a question's line is open
            QTextStream(stderr) << '\n';
        out().note(englishText(m));
    });
    connect(r, &CheckoutRunner::runConfirmationNeeded, this,
            [this, r](int index, const Message &question) {
                const auto yes = [r, index] {
                    r->allowOutputsInRun(true);
                    r->forceOutput(index);
                };
                if (options().assumeYes) {
                    out().note(QStringLiteral("The PLC is in RUN: %1 is forced on all the same "
                                              "(--yes).")
                                   .arg(CliText::checkoutPoint(
                                       r->plan().points[static_cast<std::size_t>(index)])));
                    return yes();
                }
                ask(
                    englishText(question) + QStringLiteral(" [y/N]"),
                    [this, yes](const QString &a) {
                        if (isYes(a))
                            return yes();
                        // No: the outputs stay untested; the analog points come next.
                        out().note(englishText(msg<MsgId::CheckoutRunNotConfirmed>()));
                        m_nextOutput = m_outputs.size();
                        nextOutput();
                    },
                    [this] { finishCheckout(ExitCode::Ok); });
            });
    connect(r, &CheckoutRunner::outputForced, this, &CliCheckoutCommand::askSeen);
    connect(r, &CheckoutRunner::outputReleased, this, [this, r](const Address &a) {
        if (m_finishing || r->outputUnderTest() >= 0 || m_nextOutput == 0)
            return;
        const CheckoutPoint &pt
            = r->plan().points[static_cast<std::size_t>(m_outputs[m_nextOutput - 1])];
        if (pt.address != a) // a leftover or a retried release, not the output just answered
            return;
        out().note(
            QStringLiteral("%1: %2, released")
                .arg(CliText::checkoutPoint(pt), englishText(checkoutResultMessage(pt.result))));
        nextOutput();
    });
    m_inputs = std::make_unique<CliCheckoutInputs>(
        *r, out(),
        [this](const QString &question, std::function<void(const QString &)> answer,
               std::function<void()> noAnswer) {
            ask(question, std::move(answer), std::move(noAnswer));
        },
        canAsk());
    connect(m_inputs.get(), &CliCheckoutInputs::done, this, &CliCheckoutCommand::nextOutput);
    connect(m_inputs.get(), &CliCheckoutInputs::noAnswer, this,
            [this] { finishCheckout(ExitCode::Ok); });
    connect(r, &CheckoutRunner::started, m_inputs.get(), &CliCheckoutInputs::start);
    r->start();
}

void CliCheckoutCommand::nextOutput()
{
    if (m_finishing)
        return;
    if (m_nextOutput >= m_outputs.size())
        return nextAnalog();
    m_runner->forceOutput(m_outputs[m_nextOutput++]);
}

void CliCheckoutCommand::askSeen(int index)
{
    const CheckoutPoint &pt = m_runner->plan().points[static_cast<std::size_t>(index)];
    ask(
        QStringLiteral("%1 is ON now. Seen in the field? y: yes, n [comment]: no, r REMARK: seen, "
                       "with a remark, d REASON: deferred, na: not applicable")
            .arg(CliText::checkoutPoint(pt)),
        [this, index](const QString &line) {
            const CliCheckoutAnswer answer = CliCheckoutAnswer::parse(line);
            using Key = CliCheckoutAnswer::Key;
            // An empty line is no answer: asked again.
            if (answer.key == Key::Empty)
                return askSeen(index);
            const std::optional<CheckoutResult> result = answer.result();
            if (!result) {
                out().error(QStringLiteral("Not understood: \"%1\" (y, n [comment], r REMARK, "
                                           "d REASON or na).")
                                .arg(line),
                            ExitCode::Usage);
                return askSeen(index);
            }
            if (answer.key == Key::Yes || answer.key == Key::No || answer.key == Key::Failed)
                return m_runner->answerOutput(answer.key == Key::Yes, answer.text);
            // Recorded by hand: the runner releases the output as for a yes or a no.
            if (const Status s = m_runner->record(index, *result, answer.text); !s) {
                out().error(englishText(s.error().message), ExitCode::Usage);
                askSeen(index);
            }
        },
        [this, index] {
            out().note(QStringLiteral("No answer (end of input): %1 is released and stays "
                                      "untested.")
                           .arg(CliText::checkoutPoint(
                               m_runner->plan().points[static_cast<std::size_t>(index)])));
            finishCheckout(ExitCode::Ok);
        });
}

void CliCheckoutCommand::nextAnalog()
{
    if (m_finishing)
        return;
    if (m_nextAnalog >= m_analogs.size() || !canAsk())
        return finishCheckout(ExitCode::Ok);
    const int index = m_analogs[m_nextAnalog++];
    askAnalog(index, 0);
}

void CliCheckoutCommand::askAnalog(int index, int check)
{
    const CheckoutPoint &pt = m_runner->plan().points[static_cast<std::size_t>(index)];
    if (!pt.analog.isDefined()) {
        // No expected values: it cannot pass, and is left untested.
        out().error(englishText(msg<MsgId::CheckoutAnalogNoScale>(pt.address.toString())),
                    ExitCode::Differ);
        return nextAnalog();
    }
    if (check >= static_cast<int>(pt.analog.checks.size())) {
        out().note(CliText::checkoutResult(pt));
        return nextAnalog();
    }
    const double percent = pt.analog.checks[static_cast<std::size_t>(check)];
    ask(
        QStringLiteral("Set %1 to %2 % (%3), then Enter.")
            .arg(CliText::checkoutPoint(pt), QString::number(percent, 'g', 4),
                 QString::fromStdString(pt.analog.text(pt.analog.expected(percent)))),
        [this, index, check](const QString &) { readAnalog(index, check, false); },
        [this] { finishCheckout(ExitCode::Ok); });
}

void CliCheckoutCommand::readAnalog(int index, int check, bool asLeft)
{
    // The next question once this reading is in the point, not before: one reading at a time,
    // each on its own point and check.
    auto *connection = new QMetaObject::Connection;
    *connection = connect(m_runner.get(), &CheckoutRunner::analogRecorded, this,
                          [this, index, check, connection](int i, int c) {
                              if (i != index || c != check)
                                  return;
                              disconnect(*connection);
                              delete connection;
                              sayReading(index, check);
                          });
    if (const Status s = m_runner->recordAnalog(index, check, asLeft); !s) {
        disconnect(*connection);
        delete connection;
        out().error(englishText(s.error().message), ExitCode::Differ);
        nextAnalog();
    }
}

void CliCheckoutCommand::sayReading(int index, int check)
{
    const CheckoutPoint &pt = m_runner->plan().points[static_cast<std::size_t>(index)];
    const double percent = pt.analog.checks[static_cast<std::size_t>(check)];
    const auto reading
        = std::find_if(pt.readings.begin(), pt.readings.end(), [percent](const AnalogReading &r) {
              return r.percent == percent && r.last();
          });
    if (reading == pt.readings.end())
        return askAnalog(index, check + 1);
    const double value = pt.analog.engineering(double(*reading->last()));
    const bool within = pt.analog.within(double(*reading->last()), percent);
    out().note(QStringLiteral("%1 at %2 %%3: %4 (expected %5 ± %6): %7")
                   .arg(CliText::checkoutPoint(pt), QString::number(percent, 'g', 4),
                        reading->asLeft ? QStringLiteral(", as left") : QString(),
                        QString::fromStdString(pt.analog.text(value)),
                        QString::fromStdString(pt.analog.text(pt.analog.expected(percent))),
                        QString::fromStdString(pt.analog.text(pt.analog.toleranceUnits())),
                        within ? QStringLiteral("within tolerance")
                               : QStringLiteral("OUTSIDE tolerance")));
    if (within)
        return askAnalog(index, check + 1);
    // Out of tolerance: the person may adjust the transmitter; the as-found value stays.
    ask(
        QStringLiteral("Adjust the transmitter and press Enter to read it as left, or s to go on."),
        [this, index, check](const QString &line) {
            if (CliCheckoutAnswer::parse(line).key == CliCheckoutAnswer::Key::Skip)
                return askAnalog(index, check + 1);
            readAnalog(index, check, true);
        },
        [this] { finishCheckout(ExitCode::Ok); });
}

void CliCheckoutCommand::finishCheckout(int exitCode)
{
    if (m_finishing)
        return;
    m_finishing = true;
    m_exitCode = exitCode;
    lines().cancel(); // the open question gets no answer: nothing is recorded for it
    if (m_inputs)
        m_inputs->stop();
    m_runner->stop();
    if (!m_runner->hasForced())
        return writeReport();
    // Released first (reset, enable; retried until the PLC confirms it): the report is written
    // once nothing stays forced, or once the person chose to leave it so.
    connect(m_runner.get(), &CheckoutRunner::outputReleased, this, [this] {
        if (m_runner->hasForced() || m_reported)
            return;
        lines().cancel(); // "Leave it forced?" is moot
        writeReport();
    });
    connect(m_runner.get(), &CheckoutRunner::failed, this, [this] { askLeaveForced(); });
    askLeaveForced();
}

void CliCheckoutCommand::askLeaveForced()
{
    if (m_reported || m_leftForced || !m_runner->isRetryingRelease() || lines().isWaiting())
        return;
    // No way to ask: a further Ctrl-C is the answer (interrupt()).
    if (!canAsk() || lines().atEnd()) {
        out().note(QStringLiteral("%1 is still forced: the release is tried again until the PLC "
                                  "confirms it. Ctrl-C leaves it forced and ends.")
                       .arg(forcedText()));
        return;
    }
    // Not answered by --yes: leaving an output forced is never assumed.
    ask(
        QStringLiteral("%1 is still forced in the PLC: the release is tried again until the PLC "
                       "confirms it. Leave it forced and exit? [y/N]")
            .arg(forcedText()),
        [this](const QString &a) {
            if (isYes(a))
                return leaveForced();
            out().note(QStringLiteral("Waiting for the PLC to confirm the release of %1 (Ctrl-C "
                                      "asks again).")
                           .arg(forcedText()));
        },
        [this] {
            out().note(QStringLiteral("No answer (end of input): waiting for the PLC to confirm "
                                      "the release of %1; Ctrl-C leaves it forced and ends.")
                           .arg(forcedText()));
        });
}

void CliCheckoutCommand::leaveForced()
{
    if (m_reported || m_leftForced)
        return;
    m_leftForced = true;
    lines().cancel();
    if (m_exitCode == ExitCode::Ok)
        m_exitCode = ExitCode::Link;
    out().error(QStringLiteral("Left forced in the PLC: %1. \"enable %1\" releases it, and so "
                               "does the checkout started again with its file.")
                    .arg(forcedText()),
                m_exitCode);
    writeReport();
}

void CliCheckoutCommand::writeReport()
{
    if (m_reported)
        return;
    m_reported = true;
    const CheckoutPlan &plan = m_runner->plan();
    const CheckoutReport report = CheckoutReport::of(plan);
    ReportTranslator translator;
    if (!translator.setLanguage(options().checkoutLanguage)) {
        out().error(
            QStringLiteral("--lang takes en or zh_TW, not \"%1\".").arg(options().checkoutLanguage),
            ExitCode::Usage);
        return m_context.finish(ExitCode::Usage);
    }
    const auto text = [&translator](const Message &m) {
        return translator.text(m);
    };
    const auto ends
        = options().crlf ? CheckoutReport::LineEnds::CrLf : CheckoutReport::LineEnds::Lf;
    const QString path = options().checkoutReport;
    if (!path.isEmpty()) {
        Status s = Ok{};
        if (path.endsWith(QLatin1String(".pdf"), Qt::CaseInsensitive)) {
            s = CheckoutPdf::write(report, path, text);
        } else {
            const QString reason = SafeFile::write(path, report.toCsv(text, ends));
            if (!reason.isEmpty())
                s = makeError(ErrorKind::InvalidRequest,
                              msg<MsgId::ReportCannotWrite>(path.toStdString(),
                                                            Message::text(reason.toStdString())));
        }
        if (!s) {
            out().error(englishText(s.error().message), ExitCode::Internal);
            // A device that failed (a full disk behind a link): the results are not lost.
            out().note(QStringLiteral("The report follows on standard output instead."));
            out().line(QString::fromUtf8(report.toCsv(text)).trimmed());
            out().note(englishText(report.summary));
            return m_context.finish(ExitCode::Internal);
        }
    }
    if (const QString &punch = options().checkoutPunch; !punch.isEmpty()) {
        if (const QString reason = SafeFile::write(punch, report.punchCsv(text, ends));
            !reason.isEmpty()) {
            out().error(englishText(msg<MsgId::ReportCannotWrite>(
                            punch.toStdString(), Message::text(reason.toStdString()))),
                        ExitCode::Internal);
            out().note(QStringLiteral("The punch list follows on standard output instead."));
            out().line(QString::fromUtf8(report.punchCsv(text)).trimmed());
            return m_context.finish(ExitCode::Internal);
        }
    }
    out().note(englishText(report.summary));
    if (m_exitCode != ExitCode::Ok)
        return m_context.finish(m_exitCode);
    // Failed, deferred (on the punch list) or untested: not done. Not applicable is done.
    if (std::any_of(plan.points.begin(), plan.points.end(),
                    [](const CheckoutPoint &p) { return !isCheckoutDone(p.result); }))
        return m_context.finish(ExitCode::Differ);
    succeed();
}

void CliCheckoutCommand::interrupt()
{
    if (!m_runner)
        return CliCommand::interrupt();
    if (!m_finishing) {
        out().error(QStringLiteral("Interrupted: releasing what is forced and writing the report."),
                    ExitCode::Interrupted);
        return finishCheckout(ExitCode::Interrupted);
    }
    if (!holdsInterrupts())
        return CliCommand::interrupt();
    if (!m_runner->isRetryingRelease()) {
        out().note(QStringLiteral("Releasing %1: waiting for the PLC's answer.").arg(forcedText()));
        return;
    }
    // Still forced: Ctrl-C asks whether to leave it so, or is the answer when nothing can ask.
    if (!canAsk() || lines().atEnd())
        return leaveForced();
    lines().cancel();
    QTextStream(stderr) << '\n';
    askLeaveForced();
}

bool CliCheckoutCommand::holdsInterrupts() const
{
    return m_runner && m_runner->hasForced() && !m_leftForced && !m_reported;
}

void CliCheckoutCommand::abandon()
{
    if (m_runner)
        m_runner->stop();
}

} // namespace Fatek
