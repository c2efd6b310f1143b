#pragma once

#include <QChartView>
#include <QColor>
#include <QDateTime>
#include <QList>
#include <QString>

class QLineSeries;
class QValueAxis;

namespace cambench {

// Live trend of several values (watched variables, drive objects) over the
// last minute on one value axis. A stretch without answers is a gap: after
// breakLine() each value starts a new line in the colour of its old one.
// Each value has a colour no other shown value has, and the legend names
// each value once (with its latest name). Follows the palette (light or
// dark).
class MultiTrendChart : public QChartView {
    Q_OBJECT
public:
    struct Sample {
        QString key;   // identifies the value across samples: "V12", "680.5"
        QString name;  // the legend's text: "V12 Speed"
        double value;
    };

    explicit MultiTrendChart(QWidget* parent = nullptr);

    // The values read at `at`. The time axis counts from the first call
    // with a value in it (since the last clear()): a poll that brought no
    // number does not start the clock, so the first point is at 0 s.
    void addSamples(const QDateTime& at, const QList<Sample>& samples);
    void breakLine() { m_gap = true; }
    // Forgets every line and the time origin (another device, another line).
    void clear();
    int seriesCount() const { return int(m_series.size()); }
    int pointCount() const;
    // What the legend shows: one name per value, in the order they came.
    QStringList legendNames() const;
    // The colour of each value, in the same order.
    QList<QColor> valueColours() const;

protected:
    void changeEvent(QEvent* event) override;

private:
    QLineSeries* seriesFor(const Sample& sample);
    QColor unusedColour() const;
    void applyPalette();

    QValueAxis* m_time;
    QValueAxis* m_values;
    QList<std::pair<QString, QLineSeries*>> m_series;  // key, its line (several after gaps)
    bool m_gap = false;
    QDateTime m_origin;  // the first sample's time; invalid until then
};

}  // namespace cambench
