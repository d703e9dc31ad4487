#pragma once

#include <QString>
#include <QWidget>

namespace Fatek {

// The outcome line of a table or tool. Its height is reserved whether or not it shows a message,
// so a message that comes or goes never moves the rows and buttons around it (a click aimed at a
// coil must land on that coil). Text that does not fit is elided on the last line; the tooltip
// holds it all.
class MessageLine : public QWidget
{
    Q_OBJECT

public:
    explicit MessageLine(int lines = 1, QWidget *parent = nullptr);

    void setMessage(const QString &text, bool error);
    void clear() { setMessage({}, false); }
    QString text() const { return m_text; }
    bool isError() const { return m_error; }
    // The lines actually drawn (elided), for tests and accessibility.
    QStringList shownLines() const;

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

protected:
    void paintEvent(QPaintEvent *event) override;
    void changeEvent(QEvent *event) override;

private:
    int reservedHeight() const;

    int m_lines;
    QString m_text;
    bool m_error = false;
};

} // namespace Fatek
