#include "statusindicator.h"

#include "ui/common/toolpalette.h"

#include <QPainter>

namespace Fatek {

StatusIndicator::StatusIndicator(const QString &text, bool alarm, QWidget *parent)
    : QWidget(parent)
    , m_text(text)
    , m_alarm(alarm)
{
    setAccessibleName(text);
    setToolTip(text);
}

void StatusIndicator::setState(State state)
{
    if (m_state == state)
        return;
    m_state = state;
    const QString stateText = state == State::On    ? tr("on")
                              : state == State::Off ? tr("off")
                                                    : tr("unknown");
    setAccessibleDescription(stateText);
    setToolTip(tr("%1: %2").arg(m_text, stateText));
    update();
}

QSize StatusIndicator::sizeHint() const
{
    const QFontMetrics fm = fontMetrics();
    const int lamp = fm.height();
    return {lamp + fm.horizontalAdvance(QLatin1Char(' ')) * 2 + fm.horizontalAdvance(m_text) + 4,
            lamp + 4};
}

void StatusIndicator::paintEvent(QPaintEvent *)
{
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    const QPalette pal = palette();
    const int lamp = fontMetrics().height() - 2;
    const QRectF circle(2, (height() - lamp) / 2.0, lamp, lamp);

    QColor fill = Qt::transparent;
    QPen pen(pal.color(QPalette::WindowText), 1);
    switch (m_state) {
    case State::On:
        fill = m_alarm ? ToolPalette::alarmIndicator(pal) : ToolPalette::activeIndicator(pal);
        pen.setColor(fill.darker(130));
        break;
    case State::Off:
        fill = pal.color(QPalette::Base);
        pen.setColor(ToolPalette::inactiveIndicator(pal));
        break;
    case State::Unknown:
        pen.setColor(ToolPalette::inactiveIndicator(pal));
        pen.setStyle(Qt::DotLine);
        break;
    }
    p.setPen(pen);
    p.setBrush(fill);
    p.drawEllipse(circle);

    p.setPen(
        pal.color(m_state == State::Unknown ? QPalette::PlaceholderText : QPalette::WindowText));
    const int x = lamp + 4 + fontMetrics().horizontalAdvance(QLatin1Char(' '));
    p.drawText(QRect(x, 0, width() - x, height()), Qt::AlignVCenter | Qt::AlignLeft, m_text);
}

} // namespace Fatek
