#include "watchdelegate.h"

#include "coretext.h"
#include "watchtablemodel.h"

#include <QComboBox>

namespace Fatek {

QWidget *WatchDelegate::createEditor(QWidget *parent, const QStyleOptionViewItem &option,
                                     const QModelIndex &index) const
{
    const auto *model = qobject_cast<const WatchTableModel *>(index.model());
    if (!model || index.column() != WatchTableModel::FormatColumn)
        return QStyledItemDelegate::createEditor(parent, option, index);
    auto *combo = new QComboBox(parent);
    for (DisplayFormat f : model->availableFormats(index.row()))
        combo->addItem(CoreText::format(f), static_cast<int>(f));
    return combo;
}

void WatchDelegate::setEditorData(QWidget *editor, const QModelIndex &index) const
{
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
        model->setData(index, combo->currentData().toInt(), Qt::EditRole);
        return;
    }
    QStyledItemDelegate::setModelData(editor, model, index);
}

} // namespace Fatek
