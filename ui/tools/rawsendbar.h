#pragma once

#include "ui/common/toolconfirmation.h"

#include <QPointer>
#include <QWidget>

class QCheckBox;
class QComboBox;
class QLabel;
class QLineEdit;
class QPushButton;

namespace Fatek {

class RequestTracker;
class SessionResult;

// The console's send line: a frame typed in hex or ASCII, optionally framed with the link's
// checksum (LRC for FACON, CRC for binary) by the session; shows what was sent and what came back.
class RawSendBar : public QWidget
{
    Q_OBJECT

public:
    enum class Mode { Hex, Ascii };

    explicit RawSendBar(QWidget *parent = nullptr);

    void setTarget(const PlcTarget &target);
    void setConfirmer(Confirmer confirmer) { m_confirmer = std::move(confirmer); }

    void setMode(Mode mode);
    void setText(const QString &text);
    void setAddFraming(bool on);
    bool isBusy() const { return m_busy; }
    // "Sent …  Answer …" of the last frame, or the reason nothing was sent.
    QString resultText() const;
    QByteArray lastAnswer() const { return m_lastAnswer; }
    int answersReceived() const { return m_answers; }

public Q_SLOTS:
    void send();

private:
    void onAnswer(const QByteArray &sent, const SessionResult &result);
    void updateFramingLabel();
    void updateEnabled();
    bool framingIsFacon() const;

    RequestTracker *m_requests;
    PlcTarget m_target;
    QMetaObject::Connection m_protocolDetected;
    Confirmer m_confirmer;
    bool m_busy = false;
    int m_answers = 0;
    QByteArray m_lastAnswer;

    QComboBox *m_mode;
    QLineEdit *m_input;
    QCheckBox *m_framing;
    QPushButton *m_send;
    QLabel *m_result;
};

} // namespace Fatek
