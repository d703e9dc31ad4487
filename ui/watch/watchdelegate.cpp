#include "watchdelegate.h"

#include "ui/common/uitext.h"
#include "watchtablemodel.h"

#include <QAbstractProxyModel>
#include <QComboBox>

namespace Fatek {

QWidget *WatchDelegate::createEditor(QWidget *parent, const QStyleOptionViewItem &option,
                                     const QModelIndex &index) const
{
    QModelIndex source = index;
    if (const auto *proxy = qobject_cast<const QAbstractProxyModel *>(index.model()))
        source = proxy->mapToSource(index);
    const auto *model = qobject_cast<const WatchTableModel *>(source.model());
    if (!model || source.column() != WatchTableModel::FormatColumn)
        return QStyledItemDelegate::createEditor(parent, option, index);
    auto *combo = new QComboBox(parent);
    for (DisplayFormat f : model->availableFormats(source.row()))
        combo->addItem(UiText::format(f), static_cast<int>(f));
    // A pick (mouse or keyboard) is the whole edit: apply it now rather than when focus leaves.
    auto *self = const_cast<WatchDelegate *>(this);
    connect(combo, &QComboBox::activated, self, [self, combo] {
        Q_EMIT self->commitData(combo);
        Q_EMIT self->closeEditor(combo);
    });
    return combo;
}

void WatchDelegate::setEditorData(QWidget *editor, const QModelIndex &index) const
{
    // The view calls this again for every dataChanged over an open editor, and polls change the
    // row several times a second: only the first call fills it, later ones would overwrite what
    // the user is typing or choosing.
    static constexpr char filled[] = "fatekEditorFilled";
    if (editor->property(filled).toBool())
        return;
    editor->setProperty(filled, true);
    if (auto *combo = qobject_cast<QComboBox *>(editor)) {
        const int i = combo->findData(index.data(Qt::EditRole).toInt());
        combo->setCurrentIndex(std::max(0, i));
        return;
    }
    QStyledItemDelegate::setEditorData(editor, index);
}

void WatchDelegate::setModelData(QWidget *editor, QAbstractItemModel *model,
                                 const QModelIndex &index) const
{
    if (auto *combo = qobject_cast<QComboBox *>(editor)) {
        if (m_formatHandler)
            m_formatHandler(index, static_cast<DisplayFormat>(combo->currentData().toInt()));
        else
            model->setData(index, combo->currentData().toInt(), Qt::EditRole);
        return;
    }
    QStyledItemDelegate::setModelData(editor, model, index);
}

} // namespace Fatek
