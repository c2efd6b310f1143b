#pragma once

#include <QCoreApplication>
#include <QFont>
#include <QString>

namespace cambench {

// How every editor marks an item that differs from the device: a dot in
// front of the text and a bold font, readable in both palettes.
inline QString changedMarker() {
    return QStringLiteral("● ");
}

inline QFont changedFont(QFont font = {}) {
    font.setBold(true);
    return font;
}

// Marks `item` (a table cell) as edited or not, with the device's value as
// its tooltip; returns whether it is edited.
template <class Item>
bool markEdited(Item* item, bool edited, const QString& onDevice) {
    if (!item) return edited;
    QFont font = item->font();
    font.setBold(edited);
    item->setFont(font);
    item->setToolTip(
        edited ? QCoreApplication::translate("cambench", "On the device: %1").arg(onDevice)
               : QString());
    return edited;
}

}  // namespace cambench
