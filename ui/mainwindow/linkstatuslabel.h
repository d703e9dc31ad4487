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
};

} // namespace Fatek
