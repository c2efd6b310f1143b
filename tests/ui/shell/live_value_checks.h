#pragma once

#include <QPalette>
#include <QWidget>

namespace cambench::test {

// A live value shown greyed (LiveDevicePage::addLiveValue): its text in
// the palette's disabled colour while the widget itself stays enabled.
inline bool greyed(const QWidget* widget) {
    return widget->palette().color(QPalette::WindowText) ==
           widget->palette().color(QPalette::Disabled, QPalette::WindowText);
}

}  // namespace cambench::test
