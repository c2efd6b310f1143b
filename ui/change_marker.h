#pragma once

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

}  // namespace cambench
