#pragma once

#include "model/camcon/cam_axis.h"

#include <QList>
#include <QRect>
#include <QRectF>

#include <algorithm>

namespace cambench {

// Maps positions and outputs of the cam diagram to pixels: the visible
// position window (zoom and horizontal pan), the plot area and the row
// stack (vertical scroll). No painting, so it is easy to reason about.
class DiagramLayout {
public:
    void setAxis(const Axis& axis);
    const Axis& axis() const { return m_axis; }
    void setPlotArea(const QRect& plot, int rowHeight, int scrollY);
    const QRect& plotArea() const { return m_plot; }
    int rowHeight() const { return m_rowHeight; }

    // The visible window is [viewStart, viewStart + viewSpan) in positions;
    // the whole axis is [min, max + 1).
    double viewStart() const { return m_viewStart; }
    double viewSpan() const { return m_viewSpan; }
    void fit();
    // Zooms by factor (> 1 zooms in) keeping `anchor` (a position) in place.
    void zoom(double factor, double anchor);
    void setViewStart(double start);

    double xForPosition(double position) const;
    double positionAtX(double x) const;
    double positionsPerPixel() const;
    // Output under a y coordinate, 0 when none.
    int outputAtY(int y, int outputCount) const;
    // Vertical band of an output's row (1-based output), full widget width.
    QRectF rowBand(int output) const;
    // The bar(s) of a cam, two for a cam that wraps through zero.
    QList<QRectF> camRects(const Cam& cam, int output) const;
    // Pixels at the foot of every row kept for the timing strip (0: none);
    // the cam bars take the rest.
    void setStripHeight(int pixels) { m_strip = std::max(pixels, 0); }
    int stripHeight() const { return m_strip; }
    // Where an output is on electrically, [from, from + length) in
    // positions, in the row's strip; wraps round on a rotary axis.
    QList<QRectF> stripRects(double from, double length, int output) const;
    // A tick step of 1, 2 or 5 times a power of ten, about `pixels` apart.
    qint64 tickStep(double pixels) const;

private:
    void clampView();

    Axis m_axis;
    QRect m_plot;
    int m_rowHeight = 20;
    int m_strip = 0;
    int m_scrollY = 0;
    double m_viewStart = 0;
    double m_viewSpan = 360;
};

}  // namespace cambench
