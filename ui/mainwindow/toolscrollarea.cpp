#include "toolscrollarea.h"

#include <QScrollBar>

namespace Fatek {

ToolScrollArea::ToolScrollArea(QWidget *tool, QWidget *parent)
    : QScrollArea(parent)
{
    setWidgetResizable(true);
    setFrameShape(QFrame::NoFrame);
    setWidget(tool);
}

int ToolScrollArea::wholeWidth() const
{
    // Room for the vertical scroll bar too: it comes when the dock is short.
    return widget()->minimumSizeHint().width() + verticalScrollBar()->sizeHint().width()
           + 2 * frameWidth();
}

int ToolScrollArea::usefulHeight() const
{
    return widget()->sizeHint().height() + 2 * frameWidth();
}

} // namespace Fatek
