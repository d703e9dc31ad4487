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

    // Asks for the whole summary (at most its room) and takes less: the status bar may give it
    // less than its room (a message beside it), and what it shows is elided to what it got.
    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

protected:
    void resizeEvent(QResizeEvent *event) override;

private:
    // `whole`: the summary before anything gave way (the size the label asks for); empty: the
    // summary itself.
    void showSummary(const QString &summary, const QString &tip, const QString &whole = {});
    // The summary elided to the narrower of the room and the width the label has.
    void showElided();
    int effectiveRoom() const;

    QString m_summary;
    QString m_wanted;
    QString m_tip;
    int m_room = QWIDGETSIZE_MAX;
};

} // namespace Fatek
