#pragma once

#include <QStyledItemDelegate>

namespace Fatek {

// Format column: a combo with the formats that fit the row's element, applied as soon as one is
// picked; other columns: default editors. An open editor is filled once and never refreshed by
// later model changes (polls).
class WatchDelegate : public QStyledItemDelegate
{
    Q_OBJECT

public:
    using QStyledItemDelegate::QStyledItemDelegate;

    QWidget *createEditor(QWidget *parent, const QStyleOptionViewItem &option,
                          const QModelIndex &index) const override;
    void setEditorData(QWidget *editor, const QModelIndex &index) const override;
    void setModelData(QWidget *editor, QAbstractItemModel *model,
                      const QModelIndex &index) const override;
};

} // namespace Fatek
