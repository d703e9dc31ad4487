#include "trendnavigation.h"

#include "trendtimeticks.h"

#include <QComboBox>
#include <QDateTimeEdit>
#include <QDialog>
#include <QDialogButtonBox>
#include <QFontMetrics>
#include <QFormLayout>
#include <QLabel>
#include <QPushButton>
#include <QScrollBar>
#include <QVBoxLayout>
#include <QtCharts/QCategoryAxis>
#include <QtCharts/QChart>
#include <QtCharts/QDateTimeAxis>

#include <algorithm>

namespace Fatek {

namespace {

constexpr qint64 hourMs = 3600 * 1000;
constexpr qint64 dayMs = 24 * hourMs;
// The scroll bar counts seconds.
constexpr qint64 unitMs = 1000;

} // namespace

QList<qint64> TrendNavigation::windowChoicesMs()
{
    return {10000, 60000, 600000, hourMs, 8 * hourMs, dayMs, 7 * dayMs};
}

TrendNavigation::TrendNavigation(QChart *chart, QDateTimeAxis *timeAxis, QWidget *parent)
    : QObject(parent)
    , m_parent(parent)
    , m_chart(chart)
    , m_timeAxis(timeAxis)
{
    m_windowBox = new QComboBox(parent);
    m_windowBox->setObjectName(QStringLiteral("trendWindow"));
    m_windowBox->setToolTip(tr("How much time the trend shows"));
    const QStringList names
        = {tr("10 s"), tr("1 min"), tr("10 min"), tr("1 h"), tr("8 h"), tr("24 h"), tr("7 days")};
    const QList<qint64> windows = windowChoicesMs();
    for (qsizetype i = 0; i < windows.size(); ++i)
        m_windowBox->addItem(names.at(i), windows.at(i));
    m_windowBox->addItem(tr("Custom…"), qint64(-1));
    m_windowBox->setCurrentIndex(m_windowIndex);
    connect(m_windowBox, &QComboBox::currentIndexChanged, this, [this](int index) {
        const qint64 ms = m_windowBox->itemData(index).toLongLong();
        if (ms < 0) {
            chooseCustomRange();
            return;
        }
        m_windowIndex = index;
        Q_EMIT windowChosen(ms);
    });
    // "Custom…" again while it is chosen: another range.
    connect(m_windowBox, &QComboBox::activated, this, [this](int index) {
        if (m_windowBox->itemData(index).toLongLong() < 0)
            chooseCustomRange();
    });

    // The labels say it is time: the title's line goes to the scroll bar, so that the plot keeps
    // its height (a short plot gets fewer value ticks). They fall on round moments.
    timeAxis->setTitleVisible(false);
    m_ticks = new TrendTimeTicks(chart, timeAxis, this);
    m_scrollBar = new QScrollBar(Qt::Horizontal, parent);
    m_scrollBar->setObjectName(QStringLiteral("trendScrollBar"));
    m_scrollBar->setToolTip(tr("Scroll back in time (Shift+wheel over the chart too); Reset Zoom "
                               "follows the present again"));
    connect(m_scrollBar, &QScrollBar::valueChanged, this, &TrendNavigation::scrolled);
    // As many time labels as fit whole: QtCharts cuts labels that do not fit their tick's width
    // to "…" (a narrow dock at 1366x768 showed "12:0…").
    connect(chart, &QChart::plotAreaChanged, this, &TrendNavigation::fitTicks);
}

void TrendNavigation::showWindow(qint64 ms)
{
    const int index = m_windowBox->findData(ms);
    if (index < 0)
        return;
    m_windowIndex = index;
    if (index != m_windowBox->currentIndex()) {
        const QSignalBlocker block(m_windowBox);
        m_windowBox->setCurrentIndex(index);
    }
}

void TrendNavigation::showRange(qint64 fromMs, qint64 toMs, qint64 nowMs)
{
    m_fromMs = fromMs;
    m_toMs = toMs;
    const qint64 span = std::max<qint64>(toMs - fromMs, unitMs);
    // The date matters once the range is longer than a day.
    const QString format = span > 2 * dayMs    ? QStringLiteral("MM-dd HH:mm")
                           : span > 2 * hourMs ? QStringLiteral("HH:mm")
                                               : QStringLiteral("HH:mm:ss");
    if (format != m_ticks->format()) {
        m_timeAxis->setFormat(format);
        m_ticks->setFormat(format);
        fitTicks();
    }
    m_baseMs = std::min(fromMs, nowMs - ScrollBackMs);
    const QSignalBlocker block(m_scrollBar);
    m_scrollBar->setRange(0, static_cast<int>((std::max(toMs, nowMs) - span - m_baseMs) / unitMs));
    m_scrollBar->setPageStep(static_cast<int>(span / unitMs));
    m_scrollBar->setSingleStep(static_cast<int>(std::max<qint64>(1, span / 8 / unitMs)));
    m_scrollBar->setValue(static_cast<int>((fromMs - m_baseMs) / unitMs));
}

void TrendNavigation::scrolled(int value)
{
    const qint64 span = m_toMs - m_fromMs;
    const qint64 fromMs = m_baseMs + qint64(value) * unitMs;
    if (span > 0 && fromMs != m_fromMs)
        Q_EMIT rangeChosen(fromMs, fromMs + span);
}

void TrendNavigation::fitTicks()
{
    const QRectF area = m_chart->plotArea();
    const QString sample
        = QDateTime(QDate(2000, 12, 28), QTime(20, 58, 58)).toString(m_ticks->format());
    const int label = QFontMetrics(m_ticks->axis()->labelsFont()).horizontalAdvance(sample);
    const int fit = static_cast<int>(area.width()) / (label + label / 2) + 1;
    m_ticks->setMaxTicks(std::clamp(fit, 2, 7));
}

QDialog *TrendNavigation::chooseCustomRange()
{
    if (m_custom) {
        m_custom->raise();
        return m_custom;
    }
    auto *dialog = new QDialog(m_parent);
    dialog->setObjectName(QStringLiteral("trendCustomRange"));
    dialog->setWindowTitle(tr("Custom Time Range"));
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    const QString format = QStringLiteral("yyyy-MM-dd HH:mm:ss");
    auto *from = new QDateTimeEdit(QDateTime::fromMSecsSinceEpoch(m_fromMs), dialog);
    from->setObjectName(QStringLiteral("customFrom"));
    auto *to = new QDateTimeEdit(QDateTime::fromMSecsSinceEpoch(m_toMs), dialog);
    to->setObjectName(QStringLiteral("customTo"));
    for (QDateTimeEdit *edit : {from, to}) {
        edit->setDisplayFormat(format);
        edit->setCalendarPopup(true);
    }
    auto *error = new QLabel(dialog);
    error->setObjectName(QStringLiteral("customError"));
    error->hide();
    auto *form = new QFormLayout;
    form->addRow(tr("&From:"), from);
    form->addRow(tr("&To:"), to);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, dialog);
    auto *layout = new QVBoxLayout(dialog);
    layout->addLayout(form);
    layout->addWidget(error);
    layout->addWidget(buttons);
    connect(buttons, &QDialogButtonBox::accepted, dialog, [dialog, from, to, error] {
        if (from->dateTime() >= to->dateTime()) {
            error->setText(tr("The end must come after the beginning."));
            error->show();
            return;
        }
        dialog->accept();
    });
    connect(buttons, &QDialogButtonBox::rejected, dialog, &QDialog::reject);
    connect(dialog, &QDialog::finished, this, [this, from, to](int result) {
        if (result == QDialog::Accepted) {
            Q_EMIT rangeChosen(from->dateTime().toMSecsSinceEpoch(),
                               to->dateTime().toMSecsSinceEpoch());
            return;
        }
        // Cancelled: the box shows what the trend still shows.
        const QSignalBlocker block(m_windowBox);
        m_windowBox->setCurrentIndex(m_windowIndex);
    });
    m_custom = dialog;
    dialog->open();
    return dialog;
}

} // namespace Fatek
