#include "messageline.h"

#include "toolpalette.h"

#include <QEvent>
#include <QFontMetrics>
#include <QPainter>
#include <QTextLayout>

#include <algorithm>

namespace Fatek {

namespace {
constexpr int margin = 3; // room around the text for the error tint
}

MessageLine::MessageLine(int lines, QWidget *parent)
    : QWidget(parent)
    , m_lines(std::max(1, lines))
{
    setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Fixed);
    setFixedHeight(reservedHeight());
}

void MessageLine::setMessage(const QString &text, bool error)
{
    if (text == m_text && error == m_error)
        return;
    m_text = text;
    m_error = error && !text.isEmpty();
    setToolTip(text);
    setProperty("error", m_error);
    setAccessibleName(text);
    update();
}

int MessageLine::reservedHeight() const
{
    return m_lines * fontMetrics().lineSpacing() + 2 * margin;
}

QSize MessageLine::sizeHint() const
{
    return {fontMetrics().horizontalAdvance(QLatin1Char('M')) * 30, reservedHeight()};
}

QSize MessageLine::minimumSizeHint() const
{
    // Narrow is fine: the text elides.
    return {fontMetrics().horizontalAdvance(QLatin1Char('M')) * 4, reservedHeight()};
}

QStringList MessageLine::shownLines() const
{
    QStringList shown;
    if (m_text.isEmpty())
        return shown;
    const int width = std::max(1, this->width() - 2 * margin);
    const QFontMetrics fm = fontMetrics();
    // Lay out the text as a word-wrapped paragraph; the last reserved line takes the rest, elided.
    QString rest = m_text;
    rest.replace(QLatin1Char('\n'), QChar::LineSeparator);
    for (int line = 0; line < m_lines && !rest.isEmpty(); ++line) {
        if (line == m_lines - 1) {
            QString last = rest;
            last.replace(QChar::LineSeparator, QLatin1Char(' '));
            shown << fm.elidedText(last, Qt::ElideRight, width);
            break;
        }
        QTextLayout layout(rest, font());
        layout.beginLayout();
        QTextLine textLine = layout.createLine();
        textLine.setLineWidth(width);
        layout.endLayout();
        const int length = textLine.textLength();
        shown << rest.left(length).trimmed();
        rest = rest.mid(length);
        if (rest.startsWith(QChar::LineSeparator))
            rest.remove(0, 1);
    }
    return shown;
}

void MessageLine::paintEvent(QPaintEvent *)
{
    if (m_text.isEmpty())
        return;
    QPainter painter(this);
    const QPalette pal = palette();
    if (m_error)
        painter.fillRect(rect(), ToolPalette::errorBackground(pal));
    painter.setPen(m_error ? ToolPalette::errorText(pal) : pal.color(QPalette::WindowText));
    const QFontMetrics fm = fontMetrics();
    int y = margin + fm.ascent();
    for (const QString &line : shownLines()) {
        painter.drawText(margin, y, line);
        y += fm.lineSpacing();
    }
}

void MessageLine::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::FontChange || event->type() == QEvent::StyleChange)
        setFixedHeight(reservedHeight());
    QWidget::changeEvent(event);
}

} // namespace Fatek
