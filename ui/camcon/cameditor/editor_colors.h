#pragma once

#include <QColor>

namespace cambench {

// Background of an invalid cam or cell: a red that stays readable with white
// text on light and dark palettes alike.
inline QColor errorColor() {
    return QColor(200, 40, 40);
}

}  // namespace cambench
