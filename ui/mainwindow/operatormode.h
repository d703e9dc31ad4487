#pragma once

#include <QObject>
#include <QString>

#include <functional>

class QAction;
class QLabel;
class QWidget;

namespace Fatek {

// Operator mode (read-only) as a preference, protected from casual change: switching it on is
// immediate; switching it off needs the operator-mode password when one is set (stored as a salted
// SHA-256 in QSettings), an explicit confirmation otherwise. Started with --read-only, the mode
// cannot be left in that process. The session layer enforces the mode (ConnectionManager); this
// class only decides it.
class OperatorMode : public QObject
{
    Q_OBJECT

public:
    // How the user is asked: a question, and whether a password is wanted. Returns false if the
    // user cancelled; `answer` receives the typed text. Replaceable for tests.
    using Asker = std::function<bool(const QString &question, bool password, QString *answer)>;

    // `locked`: started with --read-only (the preference is not consulted nor changed).
    OperatorMode(bool locked, QWidget *window);

    bool isActive() const { return m_active; }
    bool isLocked() const { return m_locked; }
    bool hasPassword() const;

    // Switching on never asks. Switching off asks (password or confirmation); false if refused.
    bool enable();
    bool disable();
    // Sets (or with an empty text removes) the password; only allowed while the mode is off, so
    // an operator cannot change it.
    bool setPassword(const QString &password);
    void setAsker(Asker asker) { m_asker = std::move(asker); }

    // "Operator Mode (Read-Only)" (checkable) and "Operator Mode Password…" for the menus.
    QAction *toggleAction() const { return m_toggle; }
    QAction *passwordAction() const { return m_passwordAction; }
    // "Operator mode (read-only)" for the status bar, shown while the mode is on.
    QLabel *label() const { return m_label; }

Q_SIGNALS:
    void activeChanged(bool active);
    // A refusal or a change, in words for the status bar.
    void message(const QString &text);

private:
    void setActive(bool active);
    bool checkPassword(const QString &password) const;
    void passwordDialog();
    bool ask(const QString &question, bool password, QString *answer);

    QWidget *m_window;
    bool m_locked;
    bool m_active = false;
    Asker m_asker;
    QAction *m_toggle;
    QAction *m_passwordAction;
    QLabel *m_label;
};

} // namespace Fatek
