// fatek-cli checkout: the inputs, one at a time.
#include "clicheckoutinputs.h"

#include "clicheckoutanswer.h"
#include "clilinereader.h"
#include "clioptions.h"
#include "clioutput.h"
#include "clitext.h"
#include "core/commission/checkoutrunner.h"
#include "core/qtbridge/qtmessage.h"

#include <QStringList>
#include <QTextStream>

#include <algorithm>

namespace Fatek {

namespace {

CliLineReader &lines()
{
    return *CliLineReader::instance();
}

// A question's line is open: what is said now starts on a line of its own.
void breakQuestionLine()
{
    if (lines().isWaiting())
        QTextStream(stderr) << '\n';
}

} // namespace

CliCheckoutInputs::CliCheckoutInputs(CheckoutRunner &runner, CliOutput &out, Ask ask, bool canAsk,
                                     QObject *parent)
    : QObject(parent)
    , m_runner(runner)
    , m_out(out)
    , m_ask(std::move(ask))
    , m_canAsk(canAsk)
{
    connect(&m_runner, &CheckoutRunner::pointChanged, this, [this](int index) {
        if (index != m_underTest || m_stopped)
            return;
        const CheckoutPoint &pt = m_runner.plan().points[static_cast<std::size_t>(index)];
        if (pt.result == CheckoutResult::Untested)
            return;
        // Its result is in (its edges, or an answer): the next input, once the runner has moved
        // on (its auto-advance follows this signal).
        lines().cancel();
        m_underTest = -1;
        breakQuestionLine();
        m_out.note(CliText::checkoutResult(pt));
        QMetaObject::invokeMethod(
            this, [this, index] { next(index); }, Qt::QueuedConnection);
    });
    connect(&m_runner, &CheckoutRunner::crossedWiring, this,
            [this](int, int underTest, const Message &m) {
                if (m_stopped)
                    return;
                const bool asking = lines().isWaiting();
                breakQuestionLine();
                const CheckoutPoint &pt
                    = m_runner.plan().points[static_cast<std::size_t>(underTest)];
                m_out.error(englishText(m)
                                + QStringLiteral(" %1 cannot pass clean now: it fails when it has "
                                                 "gone on and off (r REMARK passes it with a "
                                                 "remark, t tests it again).")
                                      .arg(CliText::addressText(pt.address)),
                            ExitCode::Differ);
                if (asking && underTest == m_underTest)
                    askInput(underTest); // the question again, below what was said
            });
}

void CliCheckoutInputs::start()
{
    // A resumed checkout asks only what is untested.
    const CheckoutPlan &plan = m_runner.plan();
    m_inputs = plan.indexesOf(CheckoutKind::Input);
    std::erase_if(m_inputs, [&plan](int i) {
        return plan.points[static_cast<std::size_t>(i)].result != CheckoutResult::Untested;
    });
    if (m_inputs.empty())
        return finish();
    // One input at a time: an edge on another one is crossed wiring, recorded on the input under
    // test.
    m_runner.setAutoAdvance(true);
    m_out.note(QStringLiteral("Inputs, one at a time: actuate the input named in the field (on, "
                              "then off). Ctrl-C ends the checkout and writes the report."));
    next(-1);
}

void CliCheckoutInputs::next(int after)
{
    if (m_stopped || m_done)
        return;
    // The first input after `after` in the plan's order (wrapping) still untested and not
    // skipped in this run.
    const CheckoutPlan &plan = m_runner.plan();
    const auto open = [&](int i) {
        return plan.points[static_cast<std::size_t>(i)].result == CheckoutResult::Untested
               && !m_skipped.contains(i);
    };
    const auto from = std::upper_bound(m_inputs.begin(), m_inputs.end(), after);
    auto it = std::find_if(from, m_inputs.end(), open);
    if (it == m_inputs.end()) {
        it = std::find_if(m_inputs.begin(), from, open);
        if (it == from)
            return finish();
    }
    m_runner.setCurrentPoint(*it);
    askInput(*it);
}

void CliCheckoutInputs::askInput(int index)
{
    m_underTest = index;
    const CheckoutPoint &pt = m_runner.plan().points[static_cast<std::size_t>(index)];
    const QString actuate
        = QStringLiteral("Actuate %1 (on, then off)").arg(CliText::checkoutPoint(pt));
    if (!m_canAsk) {
        // Nothing to ask with: its edges alone move the checkout on.
        m_out.note(actuate + QLatin1Char('.'));
        return;
    }
    m_ask(
        actuate
            + QStringLiteral("; Enter: skip, f [remark]: failed, d REASON: deferred, r REMARK: "
                             "passed with remark, na: not applicable, t: test again"),
        [this, index](const QString &line) { answer(index, line); },
        [this, index] {
            m_out.note(QStringLiteral("No answer (end of input): %1 stays untested.")
                           .arg(CliText::checkoutPoint(
                               m_runner.plan().points[static_cast<std::size_t>(index)])));
            Q_EMIT noAnswer();
        });
}

void CliCheckoutInputs::answer(int index, const QString &line)
{
    const CheckoutPoint &pt = m_runner.plan().points[static_cast<std::size_t>(index)];
    const CliCheckoutAnswer a = CliCheckoutAnswer::parse(line);
    using Key = CliCheckoutAnswer::Key;
    if (a.key == Key::Empty || a.key == Key::Skip) {
        m_skipped.insert(index);
        m_underTest = -1;
        m_out.note(
            QStringLiteral("%1 skipped: it stays untested.").arg(CliText::checkoutPoint(pt)));
        return next(index);
    }
    if (a.key == Key::TestAgain) {
        m_runner.retest(index); // its edges and crossed-wiring flags so far are dropped
        m_out.note(QStringLiteral("%1 is tested again.").arg(CliText::checkoutPoint(pt)));
        return askInput(index);
    }
    const std::optional<CheckoutResult> result = a.result();
    // An input passes by its edges, not by a word.
    if (!result || a.key == Key::Yes || a.key == Key::No) {
        m_out.error(QStringLiteral("Not understood: \"%1\". An input passes by going on and off; "
                                   "the other keys are in the question.")
                        .arg(line),
                    ExitCode::Usage);
        return askInput(index);
    }
    // The result's line and the next input come from pointChanged().
    if (const Status s = m_runner.record(index, *result, a.text); !s) {
        m_out.error(englishText(s.error().message), ExitCode::Usage);
        askInput(index);
    }
}

void CliCheckoutInputs::finish()
{
    if (m_done)
        return;
    m_done = true;
    m_underTest = -1;
    m_runner.setCurrentPoint(-1);
    if (!m_skipped.empty()) {
        QStringList skipped;
        for (const int i : m_skipped)
            skipped << CliText::addressText(
                m_runner.plan().points[static_cast<std::size_t>(i)].address);
        m_out.note(
            QStringLiteral("Skipped, untested: %1.").arg(skipped.join(QStringLiteral(", "))));
    }
    Q_EMIT done();
}

} // namespace Fatek
