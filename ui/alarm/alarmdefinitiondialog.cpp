#include "alarmdefinitiondialog.h"

#include "alarmtext.h"
#include "core/watch/itemvalues.h"
#include "ui/common/messageline.h"
#include "ui/common/uitext.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QRegularExpression>
#include <QVBoxLayout>

namespace Fatek {

namespace {

QString numberText(double value)
{
    return QString::number(value, 'g', 15);
}

// A number typed in the C locale or the system's ("1.5", "1,5" where that is the decimal sign).
std::optional<double> parseNumber(const QString &text)
{
    bool ok = false;
    double value = QLocale::c().toDouble(text.trimmed(), &ok);
    if (!ok)
        value = QLocale::system().toDouble(text.trimmed(), &ok);
    return ok ? std::optional<double>(value) : std::nullopt;
}

QDoubleSpinBox *delayBox(QWidget *parent, int ms)
{
    auto *box = new QDoubleSpinBox(parent);
    box->setRange(0, Alarms::MaxDelayMs / 1000.0);
    box->setDecimals(1);
    box->setSingleStep(1);
    box->setSuffix(AlarmDefinitionDialog::tr(" s"));
    box->setValue(ms / 1000.0);
    return box;
}

} // namespace

AlarmDefinitionDialog::AlarmDefinitionDialog(const WatchItemSpec &item, QWidget *parent)
    : QDialog(parent)
    , m_item(item)
    , m_error(new MessageLine(2, this))
{
    setObjectName(QStringLiteral("alarmDefinitionDialog"));
    const QString address = QString::fromStdString(item.address.toString());
    setWindowTitle(item.name.isEmpty() ? tr("Alarms of %1").arg(address)
                                       : tr("Alarms of %1 (%2)").arg(item.name, address));
    const ItemValues values(item);
    const bool bit = values.width() == 1;
    const bool number = !bit && item.format != DisplayFormat::Ascii;
    QList<AlarmKind> kinds;
    for (AlarmKind kind : Alarms::allKinds()) {
        if ((Alarms::isLimitKind(kind) && number) || (Alarms::isBitKind(kind) && bit)
            || kind == AlarmKind::Quality)
            kinds.append(kind);
    }

    auto *grid = new QGridLayout;
    const QStringList headers{tr("Alarm"),    tr("Limit"),     tr("Deadband"),
                              tr("On delay"), tr("Off delay"), tr("Priority"),
                              tr("Message"),  tr("Group"),     tr("In service")};
    for (int c = 0; c < headers.size(); ++c) {
        auto *label = new QLabel(QStringLiteral("<b>%1</b>").arg(headers.at(c)), this);
        grid->addWidget(label, 0, c);
    }
    int row = 1;
    for (AlarmKind kind : std::as_const(kinds)) {
        const AlarmDefinition *alarm = nullptr;
        for (const AlarmDefinition &a : item.alarms) {
            if (a.kind == kind)
                alarm = &a;
        }
        addLine(grid, row++, kind, alarm);
    }
    grid->setColumnStretch(6, 2);
    grid->setColumnStretch(7, 1);

    auto *note = new QLabel(
        number ? tr("Limits are in the item's format (%1). A high alarm clears when the value is "
                    "below its limit by the deadband; the delays say how long a condition must "
                    "hold before it raises or clears the alarm.")
                     .arg(UiText::format(item.format))
               : tr("The delays say how long a condition must hold before it raises or clears "
                    "the alarm. A bad quality alarm is raised when the item is stale or in error "
                    "for its on delay."),
        this);
    note->setWordWrap(true);
    m_error->setObjectName(QStringLiteral("alarmDefinitionError"));
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(buttons, &QDialogButtonBox::accepted, this, &AlarmDefinitionDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);

    auto *layout = new QVBoxLayout(this);
    layout->addLayout(grid);
    layout->addWidget(note);
    layout->addStretch(1);
    layout->addWidget(m_error);
    layout->addWidget(buttons);
}

void AlarmDefinitionDialog::addLine(QGridLayout *grid, int row, AlarmKind kind,
                                    const AlarmDefinition *alarm)
{
    AlarmDefinition shown;
    if (alarm)
        shown = *alarm;
    shown.kind = kind;
    const QString name = Alarms::kindName(kind);
    Line line;
    line.kind = kind;
    line.defined = new QCheckBox(AlarmText::kind(kind), this);
    line.defined->setObjectName(QStringLiteral("alarm_%1").arg(name));
    line.defined->setChecked(alarm != nullptr);
    int column = 0;
    grid->addWidget(line.defined, row, column++);
    if (Alarms::isLimitKind(kind)) {
        line.limit = new QLineEdit(alarm ? numberText(shown.limit) : QString(), this);
        line.limit->setObjectName(QStringLiteral("limit_%1").arg(name));
        line.deadband = new QLineEdit(numberText(shown.deadband), this);
        line.deadband->setObjectName(QStringLiteral("deadband_%1").arg(name));
        // Room for a float's digits ("-12345.678"), no more: the message needs the width.
        const int digit = fontMetrics().horizontalAdvance(QLatin1Char('0'));
        for (QLineEdit *edit : {line.limit, line.deadband}) {
            edit->setMinimumWidth(digit * 9);
            edit->setMaximumWidth(digit * 12);
        }
        grid->addWidget(line.limit, row, column++);
        grid->addWidget(line.deadband, row, column++);
    } else {
        column += 2;
    }
    line.onDelay = delayBox(this, shown.onDelayMs);
    line.onDelay->setObjectName(QStringLiteral("onDelay_%1").arg(name));
    line.offDelay = delayBox(this, shown.offDelayMs);
    line.offDelay->setObjectName(QStringLiteral("offDelay_%1").arg(name));
    grid->addWidget(line.onDelay, row, column++);
    grid->addWidget(line.offDelay, row, column++);
    line.priority = new QComboBox(this);
    line.priority->setObjectName(QStringLiteral("priority_%1").arg(name));
    for (AlarmPriority p :
         {AlarmPriority::Critical, AlarmPriority::High, AlarmPriority::Medium, AlarmPriority::Low})
        line.priority->addItem(AlarmText::priority(p), static_cast<int>(p));
    line.priority->setCurrentIndex(static_cast<int>(shown.priority));
    grid->addWidget(line.priority, row, column++);
    line.message = new QLineEdit(shown.message, this);
    line.message->setObjectName(QStringLiteral("message_%1").arg(name));
    line.message->setPlaceholderText(Alarms::defaultMessage(m_item, kind));
    line.message->setMinimumWidth(fontMetrics().horizontalAdvance(QLatin1Char('M')) * 12);
    grid->addWidget(line.message, row, column++);
    line.group = new QLineEdit(shown.group, this);
    line.group->setObjectName(QStringLiteral("group_%1").arg(name));
    line.group->setMinimumWidth(fontMetrics().horizontalAdvance(QLatin1Char('M')) * 6);
    grid->addWidget(line.group, row, column++);
    line.enabled = new QCheckBox(this);
    line.enabled->setObjectName(QStringLiteral("enabled_%1").arg(name));
    line.enabled->setChecked(shown.enabled);
    line.enabled->setToolTip(tr("Off: out of service, never raised (kept in the list)"));
    grid->addWidget(line.enabled, row, column++, Qt::AlignCenter);

    // The line's fields count only while it is checked: greyed otherwise.
    const QList<QWidget *> fields{line.limit,    line.deadband, line.onDelay, line.offDelay,
                                  line.priority, line.message,  line.group,   line.enabled};
    const auto follow = [fields](bool on) {
        for (QWidget *w : fields) {
            if (w)
                w->setEnabled(on);
        }
    };
    follow(alarm != nullptr);
    connect(line.defined, &QCheckBox::toggled, this, follow);
    m_lines.push_back(line);
}

std::optional<QList<AlarmDefinition>> AlarmDefinitionDialog::collect(QString *error) const
{
    QList<AlarmDefinition> alarms;
    for (const Line &line : m_lines) {
        if (!line.defined->isChecked())
            continue;
        AlarmDefinition a;
        a.kind = line.kind;
        if (line.limit) {
            const auto limit = parseNumber(line.limit->text());
            if (!limit) {
                *error = line.limit->text().trimmed().isEmpty()
                             ? tr("%1: type the limit.").arg(AlarmText::kind(line.kind))
                             : tr("%1: the limit \"%2\" is not a number.")
                                   .arg(AlarmText::kind(line.kind), line.limit->text());
                line.limit->setFocus();
                return std::nullopt;
            }
            a.limit = *limit;
            const QString deadbandText = line.deadband->text().trimmed();
            const auto deadband
                = deadbandText.isEmpty() ? std::optional<double>(0) : parseNumber(deadbandText);
            if (!deadband) {
                *error = tr("%1: the deadband \"%2\" is not a number.")
                             .arg(AlarmText::kind(line.kind), deadbandText);
                line.deadband->setFocus();
                return std::nullopt;
            }
            a.deadband = *deadband;
        }
        a.onDelayMs = static_cast<int>(std::lround(line.onDelay->value() * 1000));
        a.offDelayMs = static_cast<int>(std::lround(line.offDelay->value() * 1000));
        a.priority = static_cast<AlarmPriority>(line.priority->currentData().toInt());
        a.message = line.message->text().trimmed();
        a.group = line.group->text().trimmed();
        a.enabled = line.enabled->isChecked();
        alarms.append(a);
    }
    return alarms;
}

QString AlarmDefinitionDialog::error() const
{
    return m_error->isError() ? m_error->text() : QString();
}

void AlarmDefinitionDialog::accept()
{
    QString error;
    const auto alarms = collect(&error);
    if (!alarms) {
        m_error->setMessage(error, true);
        return;
    }
    // Each alarm alone first, so that the error names its kind; then together (low under high).
    for (const AlarmDefinition &a : *alarms) {
        WatchItemSpec one = m_item;
        one.alarms = {a};
        if (const Status s = Alarms::validate(one); !s) {
            // The line is named by its kind: the file's place ("alarm 1: ") would say nothing.
            QString reason = translated(s.error().message);
            reason.remove(QRegularExpression(QStringLiteral("^alarm 1: ")));
            m_error->setMessage(tr("%1: %2").arg(AlarmText::kind(a.kind), reason), true);
            return;
        }
    }
    WatchItemSpec all = m_item;
    all.alarms = *alarms;
    if (const Status s = Alarms::validate(all); !s) {
        m_error->setMessage(translated(s.error().message), true);
        return;
    }
    m_error->clear();
    m_result = *alarms;
    QDialog::accept();
}

} // namespace Fatek
