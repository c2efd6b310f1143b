#pragma once

#include <QChartView>

class QLineSeries;
class QValueAxis;

namespace cambench {

// Live trend of position and speed over the last minute, each on its own
// axis. Follows the palette (light or dark).
class TrendChart : public QChartView {
    Q_OBJECT
public:
    explicit TrendChart(QWidget* parent = nullptr);

    void addSample(double seconds, double position, double speed);
    void clear();
    int sampleCount() const;

protected:
    void changeEvent(QEvent* event) override;

private:
    void applyPalette();

    QLineSeries* m_position;
    QLineSeries* m_speed;
    QValueAxis* m_time;
    QValueAxis* m_positionAxis;
    QValueAxis* m_speedAxis;
};

}  // namespace cambench
