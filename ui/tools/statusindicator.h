#pragma once

#include <QWidget>

namespace Fatek {

// A labelled lamp: filled when on, hollow when off, dashed while unknown. Colours come from the
// palette (highlight for normal flags, the palette-derived error colour for alarm flags).
class StatusIndicator : public QWidget
{
    Q_OBJECT

public:
    enum class State { Unknown, Off, On };

    explicit StatusIndicator(const QString &text, bool alarm, QWidget *parent = nullptr);

    void setState(State state);
    State state() const { return m_state; }
    bool isOn() const { return m_state == State::On; }
    QString text() const { return m_text; }

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override { return sizeHint(); }

protected:
    void paintEvent(QPaintEvent *event) override;

private:
    QString m_text;
    bool m_alarm;
    State m_state = State::Unknown;
};

} // namespace Fatek
