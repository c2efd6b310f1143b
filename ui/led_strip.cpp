#include "led_strip.h"

#include <QMouseEvent>
#include <QPainter>

namespace cambench {

namespace {
constexpr int kCell = 30;
}

LedStrip::LedStrip(QWidget* parent) : QWidget(parent) {
    setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Preferred);
}

void LedStrip::setStates(const QList<bool>& states) {
    const bool resized = states.size() != m_states.size();
    m_states = states;
    if (resized) updateGeometry();
    update();
}

void LedStrip::setCount(int count) {
    QList<bool> states = m_states;
    states.resize(count);
    setStates(states);
}

void LedStrip::setNumbers(const QList<int>& numbers) {
    m_numbers = numbers;
    update();
}

void LedStrip::setStale(bool stale) {
    if (stale == m_stale) return;
    m_stale = stale;
    update();
}

int LedStrip::indexAt(const QPoint& point) const {
    const int cols = columns(width());
    if (point.x() < 0 || point.y() < 0 || point.x() >= cols * kCell) return -1;
    const int index = (point.y() / kCell) * cols + point.x() / kCell;
    return index < m_states.size() ? index : -1;
}

void LedStrip::mousePressEvent(QMouseEvent* event) {
    const int index = indexAt(event->position().toPoint());
    if (index >= 0) Q_EMIT ledClicked(index);
}

int LedStrip::columns(int width) const {
    return std::max(1, std::min(16, width / kCell));
}

QSize LedStrip::sizeHint() const {
    return {16 * kCell, heightForWidth(16 * kCell)};
}

int LedStrip::heightForWidth(int width) const {
    const int cols = columns(width);
    return std::max<int>(1, int((m_states.size() + cols - 1) / cols)) * kCell;
}

void LedStrip::paintEvent(QPaintEvent*) {
    QPainter painter(this);
    painter.setRenderHint(QPainter::Antialiasing);
    const int cols = columns(width());
    QFont font = painter.font();
    font.setPointSizeF(font.pointSizeF() * 0.75);
    painter.setFont(font);
    for (int i = 0; i < m_states.size(); ++i) {
        const QRect cell((i % cols) * kCell, (i / cols) * kCell, kCell, kCell);
        const QRect led = cell.adjusted(5, 3, -5, -9);
        const bool on = m_states.at(i);
        painter.setPen(palette().color(QPalette::Mid));
        const QColor lit = m_stale ? palette().color(QPalette::Mid) : QColor(0x2e, 0xcc, 0x40);
        painter.setBrush(on ? lit : palette().color(QPalette::Base));
        painter.drawEllipse(QRectF(led).adjusted(2, 0, -2, 0));
        painter.setPen(palette().color(QPalette::WindowText));
        painter.drawText(QRect(cell.left(), cell.bottom() - 10, kCell, 11), Qt::AlignCenter,
                         QString::number(i < m_numbers.size() ? m_numbers.at(i) : i + 1));
    }
}

}  // namespace cambench
