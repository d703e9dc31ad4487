#include "historysettingsdialog.h"

#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QSpinBox>
#include <QVBoxLayout>

namespace Fatek {

HistorySettingsDialog::HistorySettingsDialog(const HistorySetting &setting, int rows,
                                             bool discreteOnly, QWidget *parent)
    : QDialog(parent)
{
    setObjectName(QStringLiteral("historySettingsDialog"));
    setWindowTitle(tr("History Settings (%n row(s))", nullptr, rows));
    m_deadband = new QDoubleSpinBox(this);
    m_deadband->setObjectName(QStringLiteral("historyDeadband"));
    m_deadband->setDecimals(3);
    m_deadband->setRange(0, 1e9);
    m_deadband->setValue(setting.deadband);
    m_deadband->setEnabled(!discreteOnly);
    m_deadband->setToolTip(discreteOnly ? tr("Bits and texts keep every change")
                                        : tr("A change smaller than this from the last value "
                                             "kept is not recorded; 0: every change"));
    m_heartbeat = new QSpinBox(this);
    m_heartbeat->setObjectName(QStringLiteral("historyHeartbeat"));
    m_heartbeat->setRange(HistorySetting::MinHeartbeatS, HistorySetting::MaxHeartbeatS);
    m_heartbeat->setSuffix(tr(" s"));
    m_heartbeat->setValue(setting.heartbeatS);
    m_heartbeat->setToolTip(tr("A value is recorded at least this often, changed or not, so that "
                               "a flat line is known to be flat"));

    auto *form = new QFormLayout;
    form->addRow(tr("&Deadband:"), m_deadband);
    form->addRow(tr("&Heartbeat:"), m_heartbeat);
    auto *note = new QLabel(tr("Recorded: the first value, every change beyond the deadband, "
                               "every change of quality, and the value once per heartbeat."),
                            this);
    note->setWordWrap(true);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(note);
    layout->addWidget(buttons);
}

HistorySetting HistorySettingsDialog::setting() const
{
    HistorySetting s;
    s.deadband = m_deadband->isEnabled() ? m_deadband->value() : 0;
    s.heartbeatS = m_heartbeat->value();
    return s;
}

} // namespace Fatek
