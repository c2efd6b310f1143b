#include "window_fit.h"

#include <QScreen>
#include <QWidget>

namespace cambench {

void showFitting(QWidget& window, bool restored) {
    const QScreen* screen = window.screen();
    constexpr int kFrameAllowance = 60;  // title bar and borders of the window manager
    if (!restored && screen &&
        (screen->availableGeometry().height() < window.height() + kFrameAllowance ||
         screen->availableGeometry().width() < window.width())) {
        window.showMaximized();
        return;
    }
    window.show();
}

}  // namespace cambench
