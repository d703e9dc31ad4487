#pragma once

#include "core/protocol/request.h"
#include "core/session/loopbackstats.h"
#include "tooldialogframe.h"

#include <QDialog>
#include <QElapsedTimer>
#include <QTimer>

class QComboBox;
class QLabel;
class QLineEdit;
class QPlainTextEdit;
class QPushButton;
class QSpinBox;

namespace Fatek {

class RequestTracker;
class SessionResult;

// Loopback test (4E) for checking a link and its cabling: sends test data a number of times at an
// interval, keeps going after errors, and shows each run and the totals (outcomes, round trips).
class LoopbackDialog : public QDialog
{
    Q_OBJECT

public:
    enum class DataMode { Text, Hex, Pattern };

    explicit LoopbackDialog(QWidget *parent = nullptr);

    // Without a direct link the dialog shows "no connection" and cannot start.
    void setTarget(const PlcTarget &target);

    void setDataMode(DataMode mode);
    void setData(const QString &text);
    void setPatternLength(int bytes);
    void setRepeatCount(int runs);
    void setIntervalMs(int ms);

    bool isRunning() const { return m_running; }
    const LoopbackStats &stats() const { return m_stats; }
    QString messageText() const;
    // "100 runs: 100 OK, 0 mismatch, … — round trip min … ms"
    QString totalsText() const;

public Q_SLOTS:
    void start();
    void stop();

private:
    // The test data as configured, or an error sentence.
    Result<Bytes> testData() const;
    void runNext();
    void onAnswer(int run, const SessionResult &result, double rttMs);
    void appendLine(const QString &line, bool error);
    void finish(const QString &why);
    void updateControls();

    RequestTracker *m_requests;
    ToolDialogFrame *m_frame;
    bool m_running = false;
    int m_run = 0;
    Bytes m_data;
    LoopbackStats m_stats;
    QTimer m_intervalTimer;

    QComboBox *m_mode;
    QLineEdit *m_text;
    QSpinBox *m_length;
    QSpinBox *m_repeat;
    QSpinBox *m_interval;
    QPushButton *m_start;
    QPushButton *m_stop;
    QPlainTextEdit *m_runs;
    QLabel *m_totals;
};

} // namespace Fatek
