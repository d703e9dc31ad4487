#pragma once

#include <QList>
#include <QObject>
#include <QPointer>

class QChart;
class QComboBox;
class QDateTimeAxis;
class QDialog;
class QScrollBar;
class QWidget;

namespace Fatek {

class TrendTimeTicks;

// Where the trend looks in time: the window box (10 s .. 7 days, and "Custom…", a dialog with
// the first and last moment), the scroll bar under the chart (back to 30 days, the history's
// retention; an arrow click moves an eighth of the range shown, a page the whole range) and the
// time axis' labels (seconds for short ranges, the date for long ones, as many as fit whole).
// It only tells the trend what was chosen; the trend decides what the axis shows.
class TrendNavigation : public QObject
{
    Q_OBJECT

public:
    // How far back the scroll bar reaches.
    static constexpr qint64 ScrollBackMs = 30LL * 24 * 3600 * 1000;
    // The time windows the window box offers (before "Custom…").
    static QList<qint64> windowChoicesMs();

    TrendNavigation(QChart *chart, QDateTimeAxis *timeAxis, QWidget *parent);

    QComboBox *windowBox() const { return m_windowBox; }
    QScrollBar *scrollBar() const { return m_scrollBar; }
    TrendTimeTicks *timeTicks() const { return m_ticks; }

    // The box shows this window (following the present).
    void showWindow(qint64 ms);
    // The axis shows [fromMs, toMs] at nowMs: the scroll bar and the labels follow.
    void showRange(qint64 fromMs, qint64 toMs, qint64 nowMs);
    // "Custom…": the dialog, not blocking; OK chooses its range.
    QDialog *chooseCustomRange();

Q_SIGNALS:
    // A window of the box (the trend follows the present again).
    void windowChosen(qint64 ms);
    // A range of the custom dialog or the scroll bar (the trend stops following the present).
    void rangeChosen(qint64 fromMs, qint64 toMs);

private:
    void fitTicks();
    void scrolled(int value);

    QWidget *m_parent;
    QChart *m_chart;
    QDateTimeAxis *m_timeAxis;
    QComboBox *m_windowBox;
    QScrollBar *m_scrollBar;
    TrendTimeTicks *m_ticks;
    QPointer<QDialog> m_custom;
    int m_windowIndex = 1; // the box's last window, chosen again when Custom… is cancelled
    qint64 m_fromMs = 0;
    qint64 m_toMs = 0;
    qint64 m_baseMs = 0; // the scroll bar's 0, in ms since the epoch
};

} // namespace Fatek
