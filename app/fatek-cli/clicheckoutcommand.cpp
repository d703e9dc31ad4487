// fatek-cli checkout.
#include "clicheckoutcommand.h"

#include "clicommands.h"
#include "clicontext.h"
#include "clitext.h"
#include "core/commission/checkoutfile.h"
#include "core/commission/checkoutreport.h"
#include "core/commission/checkoutrunner.h"
#include "core/commission/commissionmessages.h"
#include "core/qtbridge/qtmessage.h"
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

QString CliCheckoutCommand::ask(const QString &question)
{
    QTextStream err(stderr);
    err << question << QLatin1Char(' ') << Qt::flush;
    // Blocking on purpose: the output stays forced until the person answers.
    static QTextStream in(stdin);
    return in.readLine().trimmed().toLower();
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
    CheckoutPlan p = std::move(plan).value();
    p.info.station = m_context.station();
    if (!options().checkoutProject.isEmpty())
        p.info.project = options().checkoutProject;
    if (!options().checkoutCustomer.isEmpty())
        p.info.customer = options().checkoutCustomer;
    if (!options().checkoutEngineer.isEmpty())
        p.info.engineer = options().checkoutEngineer;
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
        if (m_finishing)
            return;
        out().error(englishText(e.message), CliContext::exitCodeFor(e.kind));
        if (e.kind == ErrorKind::ReadOnly || e.kind == ErrorKind::LinkError
            || e.kind == ErrorKind::Timeout)
            finishCheckout(CliContext::exitCodeFor(e.kind));
    });
    connect(r, &CheckoutRunner::saveFailed, this, [this](const Message &m) {
        out().error(englishText(m), ExitCode::Internal);
        finishCheckout(ExitCode::Internal);
    });
    connect(r, &CheckoutRunner::leftoversReleased, this,
            [this](const Message &m) { out().note(englishText(m)); });
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
                const QString a = options().assumeYes
                                      ? QStringLiteral("y")
                                      : ask(englishText(question) + QStringLiteral(" [y/N]"));
                if (a != QLatin1String("y") && a != QLatin1String("yes"))
                    return finishCheckout(ExitCode::Usage);
                r->allowOutputsInRun(true);
                r->forceOutput(index);
            });
    connect(r, &CheckoutRunner::outputForced, this, [this, r](int index) {
        const CheckoutPoint &pt = r->plan().points[static_cast<std::size_t>(index)];
        const QString a = ask(
            QStringLiteral("%1 is ON now. Seen in the field? [y/n/comment]").arg(pointText(pt)));
        const bool seen = a == QLatin1String("y") || a == QLatin1String("yes");
        const bool plain = seen || a == QLatin1String("n") || a == QLatin1String("no");
        r->answerOutput(seen, plain ? QString() : a);
    });
    connect(r, &CheckoutRunner::outputReleased, this, [this, r](const Address &) {
        if (m_finishing || r->outputUnderTest() >= 0 || m_nextOutput == 0)
            return;
        const CheckoutPoint &pt
            = r->plan().points[static_cast<std::size_t>(m_outputs[m_nextOutput - 1])];
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

void CliCheckoutCommand::nextAnalog()
{
    if (m_finishing)
        return;
    if (m_nextAnalog >= m_analogs.size() || !canAsk())
        return finishCheckout(ExitCode::Ok);
    const int index = m_analogs[m_nextAnalog++];
    const CheckoutPoint &pt = m_runner->plan().points[static_cast<std::size_t>(index)];
    ask(QStringLiteral("Set %1 to its low end (%2), then Enter.")
            .arg(pointText(pt))
            .arg(pt.expectedLow));
    m_runner->recordAnalog(index, false);
    ask(QStringLiteral("Set %1 to its high end (%2), then Enter.")
            .arg(pointText(pt))
            .arg(pt.expectedHigh));
    m_runner->recordAnalog(index, true);
    // The readings come back in order: the next point after this one's high end.
    connect(
        m_runner.get(), &CheckoutRunner::pointChanged, this,
        [this, index](int changed) {
            const CheckoutPoint &p = m_runner->plan().points[static_cast<std::size_t>(changed)];
            if (changed == index && p.highValue) {
                disconnect(m_runner.get(), &CheckoutRunner::pointChanged, this, nullptr);
                out().note(QStringLiteral("%1: %2 (%3)")
                               .arg(pointText(p), englishText(checkoutResultMessage(p.result)),
                                    englishText(p.measured())));
                nextAnalog();
            }
        },
        Qt::QueuedConnection);
}

void CliCheckoutCommand::finishCheckout(int exitCode)
{
    if (m_finishing)
        return;
    m_finishing = true;
    m_exitCode = exitCode;
    m_runner->stop();
    const auto writeReport = [this] {
        if (m_reported)
            return;
        m_reported = true;
        const CheckoutPlan &plan = m_runner->plan();
        const CheckoutReport report = CheckoutReport::of(plan);
        ReportTranslator translator;
        if (!translator.setLanguage(options().checkoutLanguage)) {
            out().error(QStringLiteral("--lang takes en or zh_TW, not \"%1\".")
                            .arg(options().checkoutLanguage),
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
                                  msg<MsgId::ReportCannotWrite>(
                                      path.toStdString(), Message::text(reason.toStdString())));
            }
            if (!s) {
                out().error(englishText(s.error().message), ExitCode::Internal);
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
    };
    if (!m_runner->hasForced())
        return writeReport();
    // Released first (reset, enable): the report is written once nothing stays forced, or the
    // release failed (said on stderr; the file keeps it recorded).
    connect(m_runner.get(), &CheckoutRunner::outputReleased, this, [this, writeReport] {
        if (!m_runner->hasForced())
            writeReport();
    });
    connect(m_runner.get(), &CheckoutRunner::failed, this, [writeReport] { writeReport(); });
}

void CliCheckoutCommand::interrupt()
{
    if (m_runner && !m_finishing) {
        out().error(QStringLiteral("Interrupted: releasing what is forced and writing the report."),
                    ExitCode::Interrupted);
        finishCheckout(ExitCode::Interrupted);
        return;
    }
    CliCommand::interrupt();
}

void CliCheckoutCommand::abandon()
{
    if (m_runner)
        m_runner->stop();
}

} // namespace Fatek
