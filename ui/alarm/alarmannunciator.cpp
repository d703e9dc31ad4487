#include "alarmannunciator.h"

#include "alarmcenter.h"
#include "alarmtext.h"

#include <QAction>
#include <QApplication>

namespace Fatek {

AlarmAnnunciator::AlarmAnnunciator(AlarmCenter *center, QWidget *parent)
    : QToolButton(parent)
    , m_mute(new QAction(tr("&Mute Alarm Sound"), this))
{
    setObjectName(QStringLiteral("alarmCount"));
    setIcon(QIcon(QStringLiteral(":/icons/alarm.svg")));
    setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    setAutoRaise(true);
    setToolTip(tr("Open the alarm summary"));
    // The flash colours the button itself: no frame of a pressed look.
    setAutoFillBackground(true);
    hide();
    m_mute->setObjectName(QStringLiteral("muteAlarmsAction"));
    m_mute->setCheckable(true);
    m_mute->setToolTip(tr("No sound while alarms wait for an acknowledge"));
    connect(this, &QToolButton::clicked, this, &AlarmAnnunciator::summaryRequested);
    m_flashTimer.setInterval(flashMs);
    connect(&m_flashTimer, &QTimer::timeout, this, &AlarmAnnunciator::flash);
    m_beepTimer.setInterval(beepMs);
    connect(&m_beepTimer, &QTimer::timeout, this, &AlarmAnnunciator::beep);
    connect(center, &AlarmCenter::unackedCountChanged, this, &AlarmAnnunciator::setCount);
    setCount(center->unackedCount());
}

void AlarmAnnunciator::setCount(int count)
{
    const bool more = count > m_count;
    m_count = count;
    setText(tr("%n unacknowledged alarm(s)", nullptr, count));
    setVisible(count > 0);
    if (count == 0) {
        m_flashTimer.stop();
        m_beepTimer.stop();
        m_flashOn = true; // the next flash turns it off: plain
        flash();
        return;
    }
    if (!m_flashTimer.isActive()) {
        m_flashOn = false;
        flash();
        m_flashTimer.start();
    }
    // A new alarm sounds at once (unless muted); then every few seconds.
    if (more) {
        beep();
        m_beepTimer.start();
    }
}

void AlarmAnnunciator::flash()
{
    m_flashOn = !m_flashOn;
    QPalette p = QApplication::palette(this);
    if (m_flashOn) {
        const QColor colour = AlarmText::priorityColor(AlarmPriority::Critical);
        p.setColor(QPalette::Button, colour);
        p.setColor(QPalette::Window, colour);
        p.setColor(QPalette::ButtonText, Qt::white);
        p.setColor(QPalette::WindowText, Qt::white);
    }
    setPalette(p);
}

void AlarmAnnunciator::beep()
{
    if (m_mute->isChecked() || m_count == 0)
        return;
    ++m_beeps;
    QApplication::beep();
}

} // namespace Fatek
