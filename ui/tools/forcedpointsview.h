#pragma once

#include "core/protocol/address.h"
#include "discretescan.h"
#include "ui/common/toolconfirmation.h"

#include <QPointer>
#include <QWidget>

#include <optional>

class QLabel;
class QLineEdit;
class QListWidget;
class QPushButton;

namespace Fatek {

class RequestTracker;
class SymbolNames;

// Scans with 43 and lists every disabled (forced) point, with a confirmed "Enable all" so nothing
// stays forced when the engineer leaves the site. With no ranges typed it scans every discrete the
// PLC has (sizes from its detail status, 53), and it always says what it scanned.
class ForcedPointsView : public QWidget
{
    Q_OBJECT

public:
    explicit ForcedPointsView(QWidget *parent = nullptr);

    void setTarget(const PlcTarget &target);
    void setConfirmer(Confirmer confirmer) { m_confirmer = std::move(confirmer); }
    void setRanges(const QString &ranges);
    // The window's names (not owned): each forced point is listed with its name, "Y0 Pump run".
    void setSymbols(const SymbolNames *symbols);
    // The list as shown, one line per forced point.
    QStringList listedTexts() const;

    QList<Address> forcedPoints() const { return m_forced; }
    bool isScanning() const { return m_scanning; }
    // Completed scans since the target was set (tests wait for the next one).
    int scanCount() const { return m_scans; }
    QString messageText() const;
    // The ranges the last scan covered, "X0-255, Y0-255, M0-2001, ...".
    QString scannedText() const { return m_scanned; }

public Q_SLOTS:
    void scan();
    void enableAll();

Q_SIGNALS:
    // After an Enable all, so the discrete table can re-read.
    void pointsChanged();

private:
    void scanRanges(const QList<AddressRange> &ranges, const QString &note);
    void showList();
    void updateEnabled();

    RequestTracker *m_requests;
    PlcTarget m_target;
    Confirmer m_confirmer;
    QPointer<const SymbolNames> m_symbols;
    QList<Address> m_forced;
    bool m_scanning = false;
    bool m_enabling = false;
    int m_scans = 0;
    QString m_scanned;
    std::optional<QList<AddressRange>> m_plcRanges; // every point of the target, once known
    QString m_plcNote;                              // what of it is a guess
    QString m_prefix; // outcome of the last Enable all, shown with the next scan result
    bool m_prefixIsError = false;
    quint64 m_generation = 0; // answers of an older scan are ignored

    QLineEdit *m_ranges;
    QPushButton *m_scanButton;
    QPushButton *m_enableAllButton;
    QListWidget *m_list;
    class MessageLine *m_message;
};

} // namespace Fatek
