#include "toolpalette.h"

#include <QLabel>

namespace Fatek {

QColor ToolPalette::blend(const QColor &a, const QColor &b, double ratioOfB)
{
    const double r = qBound(0.0, ratioOfB, 1.0);
    return QColor::fromRgbF(static_cast<float>(a.redF() * (1.0 - r) + b.redF() * r),
                            static_cast<float>(a.greenF() * (1.0 - r) + b.greenF() * r),
                            static_cast<float>(a.blueF() * (1.0 - r) + b.blueF() * r));
}

QColor ToolPalette::errorText(const QPalette &palette)
{
    // Keep the text's lightness (readable on Base) but give it the red hue of "negative" text;
    // the hue is the only thing not taken from the palette, saturation/value follow the theme.
    const QColor text = palette.color(QPalette::Text);
    const QColor highlight = palette.color(QPalette::Highlight);
    const float lightness = static_cast<float>(text.lightnessF());
    const float saturation = static_cast<float>(qMax(0.6, highlight.hslSaturationF()));
    const float l = lightness < 0.5f ? 0.40f : 0.70f;
    return QColor::fromHslF(0.0f, saturation, l);
}

QColor ToolPalette::errorBackground(const QPalette &palette)
{
    return blend(palette.color(QPalette::Base), errorText(palette), 0.18);
}

QColor ToolPalette::passText(const QPalette &palette)
{
    // As errorText(), with the hue of "positive" text.
    const QColor text = palette.color(QPalette::Text);
    const QColor highlight = palette.color(QPalette::Highlight);
    const float saturation = static_cast<float>(qMax(0.6, highlight.hslSaturationF()));
    const float l = text.lightnessF() < 0.5 ? 0.30f : 0.65f;
    return QColor::fromHslF(1.0f / 3.0f, saturation, l);
}

QColor ToolPalette::passBackground(const QPalette &palette)
{
    return blend(palette.color(QPalette::Base), passText(palette), 0.22);
}

QColor ToolPalette::activeIndicator(const QPalette &palette)
{
    return palette.color(QPalette::Highlight);
}

QColor ToolPalette::inactiveIndicator(const QPalette &palette)
{
    return palette.color(QPalette::Mid);
}

QColor ToolPalette::alarmIndicator(const QPalette &palette)
{
    return errorText(palette);
}

void ToolPalette::showMessage(QLabel *label, const QString &text, bool error)
{
    label->setText(text);
    // Only the text role is set, and only for errors: everything else keeps following the theme.
    QPalette pal;
    if (error) {
        const QPalette base
            = label->parentWidget() ? label->parentWidget()->palette() : label->palette();
        pal.setColor(QPalette::WindowText, errorText(base));
    }
    label->setPalette(pal);
    label->setProperty("error", error);
    // An empty message takes no room (word-wrapped labels keep a line otherwise).
    label->setVisible(!text.isEmpty());
}

} // namespace Fatek
