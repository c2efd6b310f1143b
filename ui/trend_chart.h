#pragma once

#include <QChartView>

class QLineSeries;
class QValueAxis;

namespace cambench {

// Live trend of position and speed over the last minute, each on its own
// axis, plotted as the monitor's readouts show them. A stretch without
// answers is a gap, not a straight line across the outage: each run of
// answers is a segment of its own. Follows the palette (light or dark).
class TrendChart : public QChartView {
    Q_OBJECT
public:
    explicit TrendChart(QWidget* parent = nullptr);

    void addSample(double seconds, double position, double speed);
    // The next sample starts a new segment (no line across the gap).
    void breakLine();
    void clear();
    int sampleCount() const;
    int segmentCount() const { return int(m_segments.size()); }
    // The speed points of all segments, oldest first (for tests).
    QList<QPointF> speedPoints() const;

protected:
    void changeEvent(QEvent* event) override;

private:
    struct Segment {
        QLineSeries* position;
        QLineSeries* speed;
    };
    Segment addSegment();
    void removeSegment(int index);
    void dropOldSamples(double now);
    void fitAxes();
    void applyPalette();
    void styleSegment(const Segment& segment);

    QList<Segment> m_segments;
    bool m_broken = true;
    QValueAxis* m_time;
    QValueAxis* m_positionAxis;
    QValueAxis* m_speedAxis;
};

}  // namespace cambench
