#pragma once

#include <QLabel>

namespace Fatek {

class Connection;

// The status bar's summary of the current connection: its state, and while connected the request
// rate, errors and round trip; while down, the failed attempts. The tooltip names the link and
// why it is down.
class LinkStatusLabel : public QLabel
{
    Q_OBJECT

public:
    explicit LinkStatusLabel(QWidget *parent = nullptr);

    // nullptr: no connection.
    void showConnection(const Connection *c);
    // The width it may take (a share of the status bar, so that the message beside it is not
    // covered); a longer summary is elided, whole in the tooltip.
    void setRoom(int px);
    QString summary() const { return m_summary; }

private:
    void showSummary(const QString &summary, const QString &tip);

    QString m_summary;
    QString m_tip;
    int m_room = QWIDGETSIZE_MAX;
};

} // namespace Fatek
