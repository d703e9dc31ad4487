#pragma once

#include "core/watch/historysetting.h"

#include <QDialog>

class QDoubleSpinBox;
class QSpinBox;

namespace Fatek {

// How the selected watch table rows are recorded in the history: the deadband (a smaller change
// is not kept) and the heartbeat (a value is kept at least this often). OK records the rows with
// them.
class HistorySettingsDialog : public QDialog
{
    Q_OBJECT

public:
    // `rows`: how many rows it applies to (the title says so); `discreteOnly`: bits and texts,
    // which take no deadband.
    HistorySettingsDialog(const HistorySetting &setting, int rows, bool discreteOnly,
                          QWidget *parent = nullptr);

    HistorySetting setting() const;

private:
    QDoubleSpinBox *m_deadband;
    QSpinBox *m_heartbeat;
};

} // namespace Fatek
