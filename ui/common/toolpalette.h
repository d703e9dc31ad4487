#pragma once

#include <QColor>
#include <QPalette>

class QLabel;

namespace Fatek {

// Colours for the tools, always derived from the widget palette so light and dark themes both work
// (no hard-coded colours anywhere in the tools).
class ToolPalette
{
public:
    // Foreground for error lines: the palette's link-visited/highlight hue pushed towards red while
    // keeping the text's lightness, so it stays readable on the current base colour.
    static QColor errorText(const QPalette &palette);
    // Background tint for error rows: a light blend of errorText() into the base colour.
    static QColor errorBackground(const QPalette &palette);
    // Foreground and background of passed checks (I/O checkout): the error colours' green twin.
    static QColor passText(const QPalette &palette);
    static QColor passBackground(const QPalette &palette);
    // Indicator colour for an active ("on") flag: the palette highlight.
    static QColor activeIndicator(const QPalette &palette);
    // Indicator colour for an inactive flag: the mid tone of the palette.
    static QColor inactiveIndicator(const QPalette &palette);
    // Colour for alarm-type flags that are set (battery low, checksum error...).
    static QColor alarmIndicator(const QPalette &palette);

    // Shows `text` in `label`, in the error colour when `error` is set (the label keeps following
    // palette changes otherwise).
    static void showMessage(QLabel *label, const QString &text, bool error);

    static QColor blend(const QColor &a, const QColor &b, double ratioOfB);
};

} // namespace Fatek
