#include "trend_chart.h"

#include <QChart>
#include <QEvent>
#include <QLegendMarker>
#include <QLineSeries>
#include <QLocale>
#include <QValueAxis>

#include <algorithm>
#include <cmath>

namespace cambench {

namespace {
constexpr double kWindowSeconds = 60.0;

void fitAxis(QValueAxis* axis, const QList<QPointF>& points) {
    if (points.isEmpty()) return;
    const auto [lo, hi] =
        std::minmax_element(points.cbegin(), points.cend(),
                            [](const QPointF& a, const QPointF& b) { return a.y() < b.y(); });
    // A flat line (constant speed) still gets a readable, non-degenerate scale.
    const double margin = std::max(
        {1.0, (hi->y() - lo->y()) * 0.05, std::max(std::abs(hi->y()), std::abs(lo->y())) * 0.05});
    axis->setRange(lo->y() - margin, hi->y() + margin);
}
}  // namespace

TrendChart::TrendChart(QWidget* parent)
    : QChartView(parent),
      m_time(new QValueAxis),
      m_positionAxis(new QValueAxis),
      m_speedAxis(new QValueAxis) {
    auto* chart = new QChart;
    // Axis labels in the user's language: "6,0" in German, not "6.0".
    chart->setLocalizeNumbers(true);
    chart->setLocale(QLocale());
    chart->legend()->setAlignment(Qt::AlignBottom);
    m_time->setTitleText(tr("Time (s)"));
    m_time->setLabelFormat(QStringLiteral("%.0f"));
    m_time->setRange(0, kWindowSeconds);
    m_positionAxis->setTitleText(tr("Position"));
    m_positionAxis->setLabelFormat(QStringLiteral("%.0f"));
    m_speedAxis->setTitleText(tr("Speed"));
    m_speedAxis->setLabelFormat(QStringLiteral("%.1f"));
    chart->addAxis(m_time, Qt::AlignBottom);
    chart->addAxis(m_positionAxis, Qt::AlignLeft);
    chart->addAxis(m_speedAxis, Qt::AlignRight);
    setChart(chart);
    setRenderHint(QPainter::Antialiasing);
    setMinimumHeight(220);
    addSegment();  // the legend needs its two entries before the first sample
    m_broken = false;
    applyPalette();
}

TrendChart::Segment TrendChart::addSegment() {
    Segment segment{new QLineSeries, new QLineSeries};
    segment.position->setName(tr("Position"));
    segment.speed->setName(tr("Speed"));
    for (QLineSeries* series : {segment.position, segment.speed}) {
        chart()->addSeries(series);
        series->attachAxis(m_time);
    }
    segment.position->attachAxis(m_positionAxis);
    segment.speed->attachAxis(m_speedAxis);
    // One legend entry per quantity, however many segments there are.
    if (!m_segments.isEmpty()) {
        for (QLineSeries* series : {segment.position, segment.speed}) {
            for (QLegendMarker* marker : chart()->legend()->markers(series))
                marker->setVisible(false);
        }
    }
    styleSegment(segment);
    m_segments.append(segment);
    return segment;
}

void TrendChart::addSample(double seconds, double position, double speed) {
    if (m_broken && m_segments.last().position->count() > 0) addSegment();
    m_broken = false;
    m_segments.last().position->append(seconds, position);
    m_segments.last().speed->append(seconds, speed);
    dropOldSamples(seconds);
    m_time->setRange(std::max(0.0, seconds - kWindowSeconds), std::max(kWindowSeconds, seconds));
    fitAxes();
}

void TrendChart::breakLine() {
    m_broken = true;
}

void TrendChart::dropOldSamples(double now) {
    // Keep one window of samples: older points only cost time. A segment
    // left empty goes, except the first (it carries the legend).
    for (int i = 0; i < m_segments.size(); ++i) {
        const Segment& segment = m_segments[i];
        while (segment.position->count() > 0 &&
               segment.position->at(0).x() < now - kWindowSeconds) {
            segment.position->remove(0);
            segment.speed->remove(0);
        }
    }
    for (int i = int(m_segments.size()) - 1; i >= 1; --i) {
        if (m_segments.at(i).position->count() == 0) removeSegment(i);
    }
    if (m_segments.size() > 1 && m_segments.first().position->count() == 0) {
        // The first pair carries the legend: it takes over the next one's points.
        m_segments.first().position->replace(m_segments.at(1).position->points());
        m_segments.first().speed->replace(m_segments.at(1).speed->points());
        removeSegment(1);
    }
}

void TrendChart::removeSegment(int index) {
    const Segment segment = m_segments.takeAt(index);
    chart()->removeSeries(segment.position);
    chart()->removeSeries(segment.speed);
    delete segment.position;
    delete segment.speed;
}

void TrendChart::fitAxes() {
    QList<QPointF> positions;
    QList<QPointF> speeds;
    for (const Segment& segment : m_segments) {
        positions += segment.position->points();
        speeds += segment.speed->points();
    }
    fitAxis(m_positionAxis, positions);
    fitAxis(m_speedAxis, speeds);
}

void TrendChart::clear() {
    while (m_segments.size() > 1) removeSegment(int(m_segments.size()) - 1);
    m_segments.first().position->clear();
    m_segments.first().speed->clear();
    m_broken = false;
}

int TrendChart::sampleCount() const {
    int count = 0;
    for (const Segment& segment : m_segments) count += int(segment.position->count());
    return count;
}

QList<QPointF> TrendChart::speedPoints() const {
    QList<QPointF> points;
    for (const Segment& segment : m_segments) points += segment.speed->points();
    return points;
}

void TrendChart::changeEvent(QEvent* event) {
    if (event->type() == QEvent::PaletteChange) applyPalette();
    QChartView::changeEvent(event);
}

void TrendChart::styleSegment(const Segment& segment) {
    const QPalette pal = palette();
    segment.position->setPen(QPen(pal.color(QPalette::Highlight), 2));
    segment.speed->setPen(QPen(QColor(0xe0, 0x8a, 0x1e), 2));
}

void TrendChart::applyPalette() {
    const QPalette pal = palette();
    QChart* c = chart();
    c->setBackgroundBrush(pal.color(QPalette::Base));
    c->setPlotAreaBackgroundVisible(false);
    c->legend()->setLabelColor(pal.color(QPalette::Text));
    for (QValueAxis* axis : {m_time, m_positionAxis, m_speedAxis}) {
        axis->setLabelsColor(pal.color(QPalette::Text));
        axis->setTitleBrush(pal.color(QPalette::Text));
        axis->setGridLineColor(pal.color(QPalette::Mid));
        axis->setLinePenColor(pal.color(QPalette::Mid));
    }
    for (const Segment& segment : m_segments) styleSegment(segment);
}

}  // namespace cambench
