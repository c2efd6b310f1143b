#include "window_fit.h"

#include <QScreen>
#include <QWidget>

#include <algorithm>

namespace cambench {

namespace {
constexpr int kFrameAllowance = 60;  // title bar and borders of the window manager
}  // namespace

void showFitting(QWidget& window, bool restored) {
    const QScreen* screen = window.screen();
    if (!restored && screen &&
        (screen->availableGeometry().height() < window.height() + kFrameAllowance ||
         screen->availableGeometry().width() < window.width())) {
        window.showMaximized();
        return;
    }
    window.show();
}

void resizeWithinScreen(QWidget& window, int width, int height) {
    if (const QScreen* screen = window.screen()) {
        const QRect room = screen->availableGeometry();
        width = std::min(width, room.width());
        height = std::min(height, room.height() - kFrameAllowance);
    }
    window.resize(width, height);
}

}  // namespace cambench
