#pragma once

#include "core/plant/plctarget.h"

#include <QDialog>

class QLabel;
class QListWidget;
class QProgressBar;
class QPushButton;
class QSpinBox;

namespace Fatek {

class StationScanner;

// Tools > Scan Stations: asks every station of a range on the current connection's link (an
// RS-485 bus, typically) who answers, lists them with RUN/STOP, and makes the chosen one the
// connection's station (stationChosen). The asking is core's StationScanner, as for
// `fatek-cli scan`.
class StationScanDialog : public QDialog
{
    Q_OBJECT

public:
    // Scans the stations behind `target`'s link; its station is the one in use.
    explicit StationScanDialog(const PlcTarget &target, QWidget *parent = nullptr);

    void start();
    bool isScanning() const;
    // Stations that answered, in order.
    QList<int> foundStations() const;

Q_SIGNALS:
    // The person chose `station` for the connection (Use Station, or a double click).
    void stationChosen(quint8 station);

private:
    void onFound(int station, bool running);
    void onFinished();
    void useSelected();
    void updateButtons();

    PlcTarget m_target;
    StationScanner *m_scanner = nullptr;
    QSpinBox *m_first;
    QSpinBox *m_last;
    QSpinBox *m_timeout;
    QPushButton *m_start;
    QPushButton *m_use;
    QProgressBar *m_progress;
    QListWidget *m_list;
    QLabel *m_status;
};

} // namespace Fatek
