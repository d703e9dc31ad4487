#include "checkoutkeys.h"

#include "checkouttablemodel.h"
#include "core/commission/checkoutrunner.h"
#include "core/commission/commissionmessages.h"
#include "core/commission/memorysnapshot.h"
#include "tooldialogframe.h"
#include "ui/common/uitext.h"

#include <QApplication>
#include <QKeyEvent>
#include <QTableView>

#include <algorithm>

namespace Fatek {

CheckoutKeys::CheckoutKeys(CheckoutRunner *runner, ToolDialogFrame *frame, QTableView *table,
                           QObject *parent)
    : QObject(parent)
    , m_runner(runner)
    , m_frame(frame)
    , m_table(table)
{
    // The next check follows the reading the runner recorded, not the key pressed.
    connect(runner, &CheckoutRunner::analogRecorded, this, &CheckoutKeys::analogRecorded);
}

QString CheckoutKeys::hint()
{
    return tr("Space: passed (an output is forced first), F: failed, R: passed with remark, "
              "D: deferred, A: not applicable, T: test again, N: next point, V: read the next "
              "analog check, Shift+V: read it again as left, F2: comment");
}

QString CheckoutKeys::pointText(const CheckoutPlan &plan, int index)
{
    if (index < 0 || index >= static_cast<int>(plan.points.size()))
        return {};
    const CheckoutPoint &p = plan.points[static_cast<std::size_t>(index)];
    return p.name.isEmpty()
               ? QString::fromStdString(p.address.toString())
               : tr("%1 (%2)").arg(QString::fromStdString(p.address.toString()), p.name);
}

QString CheckoutKeys::pointText(int index) const
{
    return pointText(m_runner->plan(), index);
}

bool CheckoutKeys::handle(QKeyEvent *key)
{
    // The comment's editor has the keys: typed text is never a test key.
    const QWidget *focus = QApplication::focusWidget();
    if (focus && focus != m_table && m_table->isAncestorOf(focus))
        return false;
    const Qt::KeyboardModifiers mods
        = key->modifiers() & ~Qt::KeyboardModifiers(Qt::KeypadModifier);
    // Plain keys only (Shift+V too): Ctrl+N and the like stay the window's.
    if (mods != Qt::NoModifier && !(mods == Qt::ShiftModifier && key->key() == Qt::Key_V))
        return false;
    const int index = m_runner->currentPoint();
    switch (key->key()) {
    case Qt::Key_F2: editComment(); return true;
    case Qt::Key_N: m_runner->nextPoint(); return true;
    default: break;
    }
    if (index < 0)
        return false;
    switch (key->key()) {
    case Qt::Key_Space: pressSeen(index); return true;
    case Qt::Key_F: pressFailed(index); return true;
    case Qt::Key_R: pressWithText(index, false); return true;
    case Qt::Key_D: pressWithText(index, true); return true;
    case Qt::Key_A:
        // Also the forced output: the runner records it and releases it.
        if (const Status s = m_runner->record(index, CheckoutResult::NotApplicable); !s)
            refused(translated(s.error().message));
        return true;
    case Qt::Key_T: pressRetest(index); return true;
    case Qt::Key_V: readAnalog(index, mods == Qt::ShiftModifier); return true;
    default: return false;
    }
}

void CheckoutKeys::refused(const QString &text)
{
    m_frame->showMessage(text, true);
}

bool CheckoutKeys::refuseWhileForced(int index)
{
    if (m_runner->outputUnderTest() != index)
        return false;
    refused(tr("Answer for %1 first (Space: seen, F: not seen).").arg(pointText(index)));
    return true;
}

void CheckoutKeys::pressSeen(int index)
{
    const CheckoutPoint &p = m_runner->plan().points[static_cast<std::size_t>(index)];
    if (p.kind == CheckoutKind::Output) {
        if (m_runner->outputUnderTest() == index)
            m_runner->answerOutput(true);
        else
            force(index);
        return;
    }
    // Failed by crossed wiring: passed clean by hand it would hide what was seen; a re-test (T)
    // or a remark (R) says what happened.
    if (p.kind == CheckoutKind::Input && p.result == CheckoutResult::Failed
        && !p.changedWith.empty()) {
        std::vector<Address> crossed = p.changedWith;
        std::sort(crossed.begin(), crossed.end());
        return refused(translated(msg<MsgId::CheckoutCrossedCannotPass>(
            p.address.toString(), Snapshot::rangesText(crossed))));
    }
    if (const Status s = m_runner->record(index, CheckoutResult::Passed); !s)
        refused(translated(s.error().message));
}

void CheckoutKeys::pressFailed(int index)
{
    if (m_runner->outputUnderTest() == index)
        return m_runner->answerOutput(false);
    if (const Status s = m_runner->record(index, CheckoutResult::Failed); !s)
        refused(translated(s.error().message));
}

void CheckoutKeys::pressWithText(int index, bool deferred)
{
    // The forced output too ("seen, the lamp is dim"): recorded, then released by the runner.
    const CheckoutPoint &p = m_runner->plan().points[static_cast<std::size_t>(index)];
    const QString title = deferred ? tr("Deferred") : tr("Passed with Remark");
    const QString question
        = deferred ? tr("Why is %1 deferred (what is missing, until when)?").arg(pointText(index))
                   : tr("The remark on %1 (what was not as it should be):").arg(pointText(index));
    const std::optional<QString> text = m_frame->askText(title, question, p.comment);
    if (!text) {
        m_frame->showMessage(tr("Nothing recorded on %1.").arg(pointText(index)), false);
        return;
    }
    const Status s = m_runner->record(
        index, deferred ? CheckoutResult::Deferred : CheckoutResult::PassedWithRemark, *text);
    if (!s)
        refused(translated(s.error().message));
}

void CheckoutKeys::pressRetest(int index)
{
    if (refuseWhileForced(index))
        return;
    m_runner->retest(index);
    m_lastRead.erase(index);
    const CheckoutPoint &p = m_runner->plan().points[static_cast<std::size_t>(index)];
    QString what;
    switch (p.kind) {
    case CheckoutKind::Input:
        what = tr("%1 is tested again: actuate it in the field.").arg(pointText(index));
        break;
    case CheckoutKind::Output:
        what = tr("%1 is tested again: Space forces it.").arg(pointText(index));
        break;
    case CheckoutKind::Analog:
        what = tr("%1 is tested again: V reads its checks.").arg(pointText(index));
        break;
    }
    m_frame->showMessage(what, false);
}

void CheckoutKeys::readAnalog(int index, bool asLeft)
{
    const CheckoutPoint &p = m_runner->plan().points[static_cast<std::size_t>(index)];
    if (p.kind != CheckoutKind::Analog)
        return refused(translated(msg<MsgId::CheckoutNotAnalog>(p.address.toString())));
    int check = 0;
    if (asLeft) {
        // The check read last (its as-found value is what was adjusted).
        if (const auto last = m_lastRead.find(index); last != m_lastRead.end()) {
            check = last->second;
        } else if (!p.readings.empty()) {
            const auto &checks = p.analog.checks;
            const auto it = std::find(checks.begin(), checks.end(), p.readings.back().percent);
            check = it == checks.end() ? 0 : static_cast<int>(it - checks.begin());
        }
    } else {
        // Every check read: V starts a new test at the first.
        check = std::max(0, CheckoutTableModel::nextCheck(p));
    }
    const Status s = m_runner->recordAnalog(index, check, asLeft);
    if (!s) {
        QString text = translated(s.error().message);
        if (!p.analog.isDefined())
            text
                = tr("%1. Import a plan CSV that gives its scale (Import… > Plan CSV…).").arg(text);
        return refused(text);
    }
    m_frame->showMessage(tr("Reading %1…").arg(pointText(index)), false);
}

void CheckoutKeys::analogRecorded(int index, int check)
{
    m_lastRead[index] = check;
    const CheckoutPoint &p = m_runner->plan().points[static_cast<std::size_t>(index)];
    if (p.result != CheckoutResult::Untested) {
        m_frame->showMessage(
            tr("%1: %2.").arg(pointText(index), translated(checkoutResultMessage(p.result))),
            p.result == CheckoutResult::Failed);
        return;
    }
    m_frame->showMessage(tr("%1 read. Next: %2 (V); Shift+V reads the last check again as left.")
                             .arg(pointText(index), CheckoutTableModel::checkText(
                                                        p, CheckoutTableModel::nextCheck(p))),
                         false);
}

void CheckoutKeys::force(int index)
{
    if (!m_frame->target().isDirect() || !m_runner->isRunning())
        return refused(tr("Start the checkout first: outputs are forced only while it runs."));
    if (m_runner->outputUnderTest() >= 0) {
        refused(tr("Answer for %1 first (Space: seen, F: not seen).")
                    .arg(pointText(m_runner->outputUnderTest())));
        return;
    }
    if (m_frame->target().isReadOnly()) {
        refused(tr("Operator mode: outputs are not forced."));
        return;
    }
    const QString question
        = tr("Force %1 on at %2? It stays on until you answer, then it is released.")
              .arg(pointText(index), m_frame->targetText());
    if (!m_frame->ask(tr("Force Output"), question)) {
        m_frame->showMessage(tr("Not forced: nothing was written."), false);
        return;
    }
    m_runner->forceOutput(index);
}

void CheckoutKeys::editComment()
{
    const QModelIndex current = m_table->currentIndex();
    if (!current.isValid())
        return;
    const QModelIndex comment
        = m_table->model()->index(current.row(), CheckoutTableModel::CommentColumn);
    m_table->setCurrentIndex(comment);
    m_table->edit(comment);
}

} // namespace Fatek
