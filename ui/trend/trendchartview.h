#pragma once

#include "trendbuffer.h"

#include <QColor>
#include <QString>
#include <QtCharts/QChartView>
#include <QtCharts/QDateTimeAxis>

#include <functional>
#include <optional>
#include <vector>

class QGraphicsLineItem;
class QGraphicsRectItem;
class QGraphicsTextItem;

namespace Fatek {

// The trend's chart on screen: rubber band zoom from Qt Charts plus wheel zoom on the time axis
// around the mouse and Shift+wheel scrolling it (each stops the window from following the
// present: userZoomed()), and
// the cursor: moving the mouse over the plot shows a vertical line and a read-out of the time and
// each line's value there.
class TrendChartView : public QChartView
{
    Q_OBJECT

public:
    // What the read-out shows of one line.
    struct CursorLine
    {
        QString name;
        QColor color;
        const TrendBuffer *buffer = nullptr;
        // The recorded part before the buffer: true when it holds the time, with the value
        // there (NaN in a gap).
        std::function<bool(qint64 timeMs, double *value)> recorded;
    };
    using LinesSource = std::function<std::vector<CursorLine>()>;

    // `lines` lists the lines for the read-out whenever it is drawn; `timeAxis` (of `chart`) gives
    // the time under the mouse.
    TrendChartView(QChart *chart, QDateTimeAxis *timeAxis, LinesSource lines,
                   QWidget *parent = nullptr);

    // The read-out's text: one line for the time and one per line ("Sine (R1): -309"); empty
    // while hidden.
    QString readoutText() const { return m_readoutText; }
    // Draws the cursor and read-out again (the axes moved under the mouse).
    void updateReadout();

Q_SIGNALS:
    void userZoomed();

protected:
    void mouseMoveEvent(QMouseEvent *event) override;
    void leaveEvent(QEvent *event) override;
    void wheelEvent(QWheelEvent *event) override;
    void mouseReleaseEvent(QMouseEvent *event) override;

private:
    // The mouse over the chart (viewport coordinates); nothing: it left.
    void hoverAt(std::optional<QPointF> viewportPos);

    QDateTimeAxis *m_timeAxis;
    LinesSource m_lines;
    QGraphicsLineItem *m_cursorLine;
    QGraphicsRectItem *m_readoutBox;
    QGraphicsTextItem *m_readout;
    std::optional<QPointF> m_hoverPos;
    QString m_readoutText;
};

} // namespace Fatek
