// fatek-cli checkout.
#include "clicheckoutcommand.h"

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

QString pointText(const CheckoutPoint &p)
{
    const QString a = QString::fromStdString(p.address.toString());
    return p.name.isEmpty() ? a : QStringLiteral("%1 (%2)").arg(a, p.name);
}

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
    // The report is written at the end: a place that cannot take it is said before anything is
    // forced, not after the whole checkout.
    if (const QString &report = options().checkoutReport; !report.isEmpty()) {
        if (const QString reason = SafeFile::checkWritable(report); !reason.isEmpty()) {
            out().error(englishText(msg<MsgId::ReportCannotWrite>(
                            report.toStdString(), Message::text(reason.toStdString())))
                            + QStringLiteral(" Nothing was forced."),
                        ExitCode::Internal);
            return m_context.finish(ExitCode::Internal);
        }
    }
    CheckoutPlan p = std::move(plan).value();
    p.info.station = m_context.station();
    if (!options().checkoutProject.isEmpty())
        p.info.project = options().checkoutProject;
    if (!options().checkoutCustomer.isEmpty())
        p.info.customer = options().checkoutCustomer;
    if (!options().checkoutEngineer.isEmpty())
        p.info.engineer = options().checkoutEngineer;
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
    connect(r, &CheckoutRunner::pointChanged, this, [this, r](int index) {
        const CheckoutPoint &pt = r->plan().points[static_cast<std::size_t>(index)];
        if (pt.kind == CheckoutKind::Input && pt.result == CheckoutResult::Passed
            && !m_inputsDone) {
            out().note(QStringLiteral("%1: %2").arg(pointText(pt), englishText(pt.measured())));
            const auto inputs = r->plan().indexesOf(CheckoutKind::Input);
            if (std::all_of(inputs.begin(), inputs.end(), [r](int i) {
                    return r->plan().points[static_cast<std::size_t>(i)].result
                           != CheckoutResult::Untested;
                }))
                inputsDone();
        }
    });
    connect(r, &CheckoutRunner::runConfirmationNeeded, this,
            [this, r](int index, const Message &question) {
                const auto yes = [r, index] {
                    r->allowOutputsInRun(true);
                    r->forceOutput(index);
                };
                if (options().assumeYes) {
                    out().note(
                        QStringLiteral("The PLC is in RUN: %1 is forced on all the same "
                                       "(--yes).")
                            .arg(pointText(r->plan().points[static_cast<std::size_t>(index)])));
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
        out().note(QStringLiteral("%1: %2, released")
                       .arg(pointText(pt), englishText(checkoutResultMessage(pt.result))));
        nextOutput();
    });
    connect(r, &CheckoutRunner::started, this, [this, r] {
        const auto inputs = r->plan().indexesOf(CheckoutKind::Input);
        const bool open = std::any_of(inputs.begin(), inputs.end(), [r](int i) {
            return r->plan().points[static_cast<std::size_t>(i)].result == CheckoutResult::Untested;
        });
        if (open)
            out().note(QStringLiteral("Actuate each input in the field (on, then off); any "
                                      "order. Ctrl-C ends the checkout and writes the report."));
        else
            inputsDone();
    });
    r->start();
}

void CliCheckoutCommand::inputsDone()
{
    if (m_inputsDone)
        return;
    m_inputsDone = true;
    nextOutput();
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
        QStringLiteral("%1 is ON now. Seen in the field? [y/n/comment]").arg(pointText(pt)),
        [this, index](const QString &a) {
            // An empty line is no answer: asked again.
            if (a.isEmpty())
                return askSeen(index);
            const bool seen = isYes(a);
            const bool plain = seen || a.compare(QLatin1String("n"), Qt::CaseInsensitive) == 0
                               || a.compare(QLatin1String("no"), Qt::CaseInsensitive) == 0;
            m_runner->answerOutput(seen, plain ? QString() : a);
        },
        [this, index] {
            out().note(
                QStringLiteral("No answer (end of input): %1 is released and stays "
                               "untested.")
                    .arg(pointText(m_runner->plan().points[static_cast<std::size_t>(index)])));
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
        out().note(QStringLiteral("%1: %2 (%3)")
                       .arg(pointText(pt), englishText(checkoutResultMessage(pt.result)),
                            englishText(pt.measured())));
        return nextAnalog();
    }
    const double percent = pt.analog.checks[static_cast<std::size_t>(check)];
    ask(
        QStringLiteral("Set %1 to %2 % (%3), then Enter.")
            .arg(pointText(pt), QString::number(percent, 'g', 4),
                 QString::fromStdString(pt.analog.text(pt.analog.expected(percent)))),
        [this, index, check](const QString &) {
            // The next question once this reading is in the point, not before: one reading at
            // a time, each on its own point and check.
            auto *connection = new QMetaObject::Connection;
            *connection = connect(m_runner.get(), &CheckoutRunner::analogRecorded, this,
                                  [this, index, check, connection](int i, int c) {
                                      if (i != index || c != check)
                                          return;
                                      disconnect(*connection);
                                      delete connection;
                                      askAnalog(index, check + 1);
                                  });
            if (const Status s = m_runner->recordAnalog(index, check); !s) {
                disconnect(*connection);
                delete connection;
                out().error(englishText(s.error().message), ExitCode::Differ);
                nextAnalog();
            }
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
    const QString path = options().checkoutReport;
    if (!path.isEmpty()) {
        Status s = Ok{};
        if (path.endsWith(QLatin1String(".pdf"), Qt::CaseInsensitive)) {
            s = CheckoutPdf::write(report, path, text);
        } else {
            const QString reason = SafeFile::write(path, report.toCsv(text));
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
    out().note(englishText(report.summary));
    if (m_exitCode != ExitCode::Ok)
        return m_context.finish(m_exitCode);
    const bool failed
        = plan.count(CheckoutResult::Failed) > 0 || plan.count(CheckoutResult::Untested) > 0;
    if (failed)
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
