#include "operatormode.h"

#include <QAction>
#include <QCryptographicHash>
#include <QFont>
#include <QInputDialog>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QMessageBox>
#include <QPalette>
#include <QRandomGenerator>
#include <QSettings>

namespace Fatek {

namespace {

const QString enabledKey = QStringLiteral("operatorMode/enabled");
const QString saltKey = QStringLiteral("operatorMode/salt");
const QString hashKey = QStringLiteral("operatorMode/passwordSha256");

QByteArray hashOf(const QByteArray &salt, const QString &password)
{
    return QCryptographicHash::hash(salt + password.toUtf8(), QCryptographicHash::Sha256).toHex();
}

} // namespace

OperatorMode::OperatorMode(bool locked, QWidget *window)
    : QObject(window)
    , m_window(window)
    , m_locked(locked)
    , m_toggle(new QAction(tr("&Operator Mode (Read-Only)"), this))
    , m_passwordAction(new QAction(tr("Operator Mode Pass&word…"), this))
{
    setObjectName(QStringLiteral("operatorMode"));
    m_toggle->setObjectName(QStringLiteral("operatorModeAction"));
    m_toggle->setCheckable(true);
    m_passwordAction->setObjectName(QStringLiteral("operatorModePasswordAction"));
    // Anything but an explicit "false" (a damaged settings file) counts as on: the safe reading.
    const QVariant stored = QSettings().value(enabledKey);
    m_active = locked || (stored.isValid() && stored.toString() != QStringLiteral("false"));
    m_toggle->setChecked(m_active);
    m_passwordAction->setEnabled(!m_active);
    connect(m_toggle, &QAction::triggered, this, [this](bool checked) {
        if (checked)
            enable();
        else
            disable();
        m_toggle->setChecked(m_active); // a refused change flips the check mark back
    });
    connect(m_passwordAction, &QAction::triggered, this, &OperatorMode::passwordDialog);

    m_label = new QLabel(tr("Operator mode (read-only)"), window);
    m_label->setObjectName(QStringLiteral("modeLabel"));
    QFont bold = m_label->font();
    bold.setBold(true);
    m_label->setFont(bold);
    // Highlight colours of the palette: visible in light and dark themes alike.
    m_label->setAutoFillBackground(true);
    m_label->setBackgroundRole(QPalette::Highlight);
    m_label->setForegroundRole(QPalette::HighlightedText);
    m_label->setContentsMargins(6, 0, 6, 0);
    m_label->setVisible(m_active);
}

bool OperatorMode::hasPassword() const
{
    return !QSettings().value(hashKey).toByteArray().isEmpty();
}

bool OperatorMode::enable()
{
    if (!m_locked)
        QSettings().setValue(enabledKey, true);
    setActive(true);
    return true;
}

bool OperatorMode::disable()
{
    if (!m_active)
        return true;
    if (m_locked) {
        Q_EMIT message(tr("Started with --read-only: operator mode stays on until the program is "
                          "restarted without it."));
        return false;
    }
    QString answer;
    if (hasPassword()) {
        if (!ask(tr("Operator-mode password:"), true, &answer))
            return false;
        if (!checkPassword(answer)) {
            Q_EMIT message(tr("Wrong operator-mode password: operator mode stays on."));
            return false;
        }
    } else if (!ask(tr("Leave operator mode? Writes, forcing, RUN/STOP and raw frames will reach "
                       "the PLC again."),
                    false, &answer)) {
        return false;
    }
    QSettings().setValue(enabledKey, false);
    setActive(false);
    return true;
}

bool OperatorMode::setPassword(const QString &password)
{
    if (m_active)
        return false;
    QSettings settings;
    if (password.isEmpty()) {
        settings.remove(saltKey);
        settings.remove(hashKey);
        return true;
    }
    QByteArray salt(16, Qt::Uninitialized);
    for (char &c : salt)
        c = static_cast<char>(QRandomGenerator::system()->bounded(256));
    settings.setValue(saltKey, salt.toHex());
    settings.setValue(hashKey, hashOf(salt, password));
    return true;
}

bool OperatorMode::checkPassword(const QString &password) const
{
    QSettings settings;
    const QByteArray salt = QByteArray::fromHex(settings.value(saltKey).toByteArray());
    const QByteArray stored = settings.value(hashKey).toByteArray();
    return !stored.isEmpty() && hashOf(salt, password) == stored;
}

void OperatorMode::setActive(bool active)
{
    const bool changed = active != m_active;
    m_active = active;
    m_toggle->setChecked(active);
    m_passwordAction->setEnabled(!active);
    m_label->setVisible(active);
    if (changed) {
        Q_EMIT message(active ? tr("Operator mode on: the PLC is read-only.")
                              : tr("Operator mode off."));
        Q_EMIT activeChanged(active);
    }
}

bool OperatorMode::ask(const QString &question, bool password, QString *answer)
{
    if (m_asker)
        return m_asker(question, password, answer);
    if (password) {
        bool ok = false;
        *answer = QInputDialog::getText(m_window, tr("Operator Mode"), question,
                                        QLineEdit::Password, {}, &ok);
        return ok;
    }
    return QMessageBox::question(m_window, tr("Operator Mode"), question,
                                 QMessageBox::Yes | QMessageBox::Cancel, QMessageBox::Cancel)
           == QMessageBox::Yes;
}

void OperatorMode::passwordDialog()
{
    if (m_active)
        return;
    QString first;
    if (!ask(tr("New operator-mode password (empty: none):"), true, &first))
        return;
    if (!first.isEmpty()) {
        QString second;
        if (!ask(tr("Repeat the password:"), true, &second))
            return;
        if (first != second) {
            Q_EMIT message(tr("The passwords differ: nothing changed."));
            return;
        }
    }
    setPassword(first);
    Q_EMIT message(first.isEmpty() ? tr("Operator-mode password removed.")
                                   : tr("Operator-mode password set."));
}

} // namespace Fatek
