#pragma once

#include "core/watch/watchlist.h"

#include <QDialog>
#include <QList>

#include <vector>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QGridLayout;
class QLineEdit;

namespace Fatek {

class MessageLine;

// The alarms of one watch table row: one line per kind that fits the item (high-high, high, low,
// low-low for a number; bit on and bit off for a discrete; bad quality for every item), each with
// its limit and deadband in the item's format, on- and off-delay, priority, message, group and
// whether it is in service. OK checks them as a watch list file is checked (Alarms::validate) and
// names what is wrong in words; the dialog stays open until it is right or cancelled.
class AlarmDefinitionDialog : public QDialog
{
    Q_OBJECT

public:
    AlarmDefinitionDialog(const WatchItemSpec &item, QWidget *parent = nullptr);

    // The alarms as the dialog holds them (valid after accept()).
    QList<AlarmDefinition> alarms() const { return m_result; }
    // The reason the last OK was refused (empty when it was not).
    QString error() const;

    void accept() override;

private:
    struct Line
    {
        AlarmKind kind = AlarmKind::High;
        QCheckBox *defined = nullptr;
        QLineEdit *limit = nullptr; // limit kinds only
        QLineEdit *deadband = nullptr;
        QDoubleSpinBox *onDelay = nullptr;
        QDoubleSpinBox *offDelay = nullptr;
        QComboBox *priority = nullptr;
        QLineEdit *message = nullptr;
        QLineEdit *group = nullptr;
        QCheckBox *enabled = nullptr;
    };

    void addLine(QGridLayout *grid, int row, AlarmKind kind, const AlarmDefinition *alarm);
    // The lines checked as definitions; the first text that is not a number stops it.
    std::optional<QList<AlarmDefinition>> collect(QString *error) const;

    WatchItemSpec m_item;
    std::vector<Line> m_lines;
    MessageLine *m_error;
    QList<AlarmDefinition> m_result;
};

} // namespace Fatek
