#include "ui/camcon/cameditor/diagram_layout.h"

#include <algorithm>
#include <cmath>

namespace cambench {

namespace {
// Zoomed in further, one position would be wider than the editor is useful.
constexpr double kMinimumViewSpan = 10.0;
// Bars are drawn at least this high inside their row.
constexpr double kBarMargin = 3.0;
}  // namespace

void DiagramLayout::setAxis(const Axis& axis) {
    m_axis = axis;
    fit();
}

void DiagramLayout::setPlotArea(const QRect& plot, int rowHeight, int scrollY) {
    m_plot = plot;
    m_rowHeight = std::max(rowHeight, 1);
    m_scrollY = scrollY;
}

void DiagramLayout::fit() {
    m_viewStart = m_axis.min;
    m_viewSpan = double(m_axis.span());
}

void DiagramLayout::zoom(double factor, double anchor) {
    const double fraction = (anchor - m_viewStart) / m_viewSpan;
    const double full = double(m_axis.span());
    m_viewSpan = std::clamp(m_viewSpan / factor, std::min(kMinimumViewSpan, full), full);
    m_viewStart = anchor - fraction * m_viewSpan;
    clampView();
}

void DiagramLayout::setViewStart(double start) {
    m_viewStart = start;
    clampView();
}

void DiagramLayout::clampView() {
    const double end = double(m_axis.max) + 1.0;
    m_viewStart = std::clamp(m_viewStart, double(m_axis.min), end - m_viewSpan);
}

double DiagramLayout::positionsPerPixel() const {
    return m_viewSpan / std::max(m_plot.width(), 1);
}

double DiagramLayout::xForPosition(double position) const {
    return m_plot.left() + (position - m_viewStart) / positionsPerPixel();
}

double DiagramLayout::positionAtX(double x) const {
    return m_viewStart + (x - m_plot.left()) * positionsPerPixel();
}

int DiagramLayout::outputAtY(int y, int outputCount) const {
    if (y < m_plot.top() || y > m_plot.bottom()) {
        return 0;
    }
    const int output = (y - m_plot.top() + m_scrollY) / m_rowHeight + 1;
    return output <= outputCount ? output : 0;
}

QRectF DiagramLayout::rowBand(int output) const {
    const double top = m_plot.top() + double(output - 1) * m_rowHeight - m_scrollY;
    return {0.0, top, double(m_plot.right() + 1), double(m_rowHeight)};
}

QList<QRectF> DiagramLayout::camRects(const Cam& cam, int output) const {
    const QRectF band = rowBand(output);
    QList<QRectF> rects;
    for (const CamPiece& piece : camPieces(cam, m_axis)) {
        const double left = xForPosition(double(piece.from));
        const double right = xForPosition(double(piece.to));
        rects.append(QRectF(left, band.top() + kBarMargin, std::max(right - left, 1.0),
                            band.height() - 2 * kBarMargin - m_strip));
    }
    return rects;
}

QList<QRectF> DiagramLayout::stripRects(double from, double length, int output) const {
    const QRectF band = rowBand(output);
    const double top = band.bottom() - m_strip;
    const double height = std::max(m_strip - kBarMargin, 1.0);
    const double start = double(m_axis.min);
    const double end = double(m_axis.max) + 1.0;
    QList<QRectF> rects;
    const auto add = [&](double a, double b) {
        const double left = xForPosition(a);
        rects.append(QRectF(left, top, std::max(xForPosition(b) - left, 1.0), height));
    };
    if (!m_axis.rotary) {
        add(std::max(from, start), std::min(from + length, end));
        return rects;
    }
    const double span = end - start;
    double a = start + std::fmod(std::fmod(from - start, span) + span, span);
    double rest = std::min(length, span);
    while (rest > 0) {
        const double piece = std::min(rest, end - a);
        add(a, a + piece);
        rest -= piece;
        a = start;
    }
    return rects;
}

qint64 DiagramLayout::tickStep(double pixels) const {
    const double wanted = std::max(pixels * positionsPerPixel(), 1.0);
    const double magnitude = std::pow(10.0, std::floor(std::log10(wanted)));
    for (double factor : {1.0, 2.0, 5.0, 10.0}) {
        if (factor * magnitude >= wanted) {
            return std::max<qint64>(qint64(factor * magnitude), 1);
        }
    }
    return qint64(10 * magnitude);
}

}  // namespace cambench
