#pragma once

#include <QScrollArea>

namespace Fatek {

// The scroll area of a tool dock. In height the tool scrolls, so a dock of any height fits a
// laptop's screen; in width it should not need to: wholeWidth() is how wide the dock's contents
// must be to show the tool without a sideways scroll bar (ToolDocks opens a side dock that wide).
// With a very large font a tool may still scroll sideways rather than push the window past the
// screen.
class ToolScrollArea : public QScrollArea
{
    Q_OBJECT

public:
    explicit ToolScrollArea(QWidget *tool, QWidget *parent = nullptr);

    int wholeWidth() const;
    // How tall the dock's contents are when the tool shows at its own size hint (the raw
    // console: its controls and a few rows of traffic); ToolDocks opens a bottom dock that tall.
    int usefulHeight() const;
};

} // namespace Fatek
