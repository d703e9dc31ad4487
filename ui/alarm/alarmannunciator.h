#pragma once

#include <QTimer>
#include <QToolButton>

class QAction;

namespace Fatek {

class AlarmCenter;

// The status bar's alarm count: "3 unacknowledged alarms", flashing in the alarm colour while
// any waits for an acknowledge (hidden when none does); a click opens the summary. While
// unacknowledged alarms exist it sounds every few seconds (QApplication::beep) unless muted.
class AlarmAnnunciator : public QToolButton
{
    Q_OBJECT

public:
    static constexpr int flashMs = 500;
    static constexpr int beepMs = 2000;

    AlarmAnnunciator(AlarmCenter *center, QWidget *parent = nullptr);

    // "Mute Alarm Sound" (checkable) for the summary and the View menu.
    QAction *muteAction() const { return m_mute; }
    bool isFlashOn() const { return m_flashOn; }
    int count() const { return m_count; }
    // Beeps sounded so far (tests: the sound cannot be heard offscreen).
    int beeps() const { return m_beeps; }

Q_SIGNALS:
    void summaryRequested();

private:
    void setCount(int count);
    void flash();
    void beep();

    QAction *m_mute;
    QTimer m_flashTimer;
    QTimer m_beepTimer;
    int m_count = 0;
    int m_beeps = 0;
    bool m_flashOn = false;
};

} // namespace Fatek
