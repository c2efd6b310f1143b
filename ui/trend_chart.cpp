#include "trend_chart.h"

#include <QChart>
#include <QEvent>
#include <QLineSeries>
#include <QValueAxis>

#include <algorithm>
#include <cmath>

namespace cambench {

namespace {
constexpr double kWindowSeconds = 60.0;

void fitAxis(QValueAxis* axis, const QList<QPointF>& points) {
    if (points.isEmpty()) return;
    const auto [lo, hi] = std::minmax_element(points.cbegin(), points.cend(),
                                              [](const QPointF& a, const QPointF& b) { return a.y() < b.y(); });
    // A flat line (constant speed) still gets a readable, non-degenerate scale.
    const double margin = std::max({1.0, (hi->y() - lo->y()) * 0.05,
                                    std::max(std::abs(hi->y()), std::abs(lo->y())) * 0.05});
    axis->setRange(lo->y() - margin, hi->y() + margin);
}
}  // namespace

TrendChart::TrendChart(QWidget* parent)
    : QChartView(parent),
      m_position(new QLineSeries),
      m_speed(new QLineSeries),
      m_time(new QValueAxis),
      m_positionAxis(new QValueAxis),
      m_speedAxis(new QValueAxis) {
    auto* chart = new QChart;
    chart->legend()->setAlignment(Qt::AlignBottom);
    m_position->setName(tr("Position"));
    m_speed->setName(tr("Speed"));
    chart->addSeries(m_position);
    chart->addSeries(m_speed);
    m_time->setTitleText(tr("Time (s)"));
    m_time->setLabelFormat(QStringLiteral("%.0f"));
    m_time->setRange(0, kWindowSeconds);
    m_positionAxis->setTitleText(tr("Position"));
    m_positionAxis->setLabelFormat(QStringLiteral("%.0f"));
    m_speedAxis->setTitleText(tr("Speed"));
    m_speedAxis->setLabelFormat(QStringLiteral("%.0f"));
    chart->addAxis(m_time, Qt::AlignBottom);
    chart->addAxis(m_positionAxis, Qt::AlignLeft);
    chart->addAxis(m_speedAxis, Qt::AlignRight);
    m_position->attachAxis(m_time);
    m_position->attachAxis(m_positionAxis);
    m_speed->attachAxis(m_time);
    m_speed->attachAxis(m_speedAxis);
    setChart(chart);
    setRenderHint(QPainter::Antialiasing);
    setMinimumHeight(220);
    applyPalette();
}

void TrendChart::addSample(double seconds, double position, double speed) {
    m_position->append(seconds, position);
    m_speed->append(seconds, speed);
    // Keep one window of samples: older points only cost time.
    while (m_position->count() > 0 && m_position->at(0).x() < seconds - kWindowSeconds) {
        m_position->remove(0);
        m_speed->remove(0);
    }
    m_time->setRange(std::max(0.0, seconds - kWindowSeconds), std::max(kWindowSeconds, seconds));
    fitAxis(m_positionAxis, m_position->points());
    fitAxis(m_speedAxis, m_speed->points());
}

void TrendChart::clear() {
    m_position->clear();
    m_speed->clear();
}

int TrendChart::sampleCount() const { return int(m_position->count()); }

void TrendChart::changeEvent(QEvent* event) {
    if (event->type() == QEvent::PaletteChange) applyPalette();
    QChartView::changeEvent(event);
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
    QPen position(pal.color(QPalette::Highlight), 2);
    m_position->setPen(position);
    m_speed->setPen(QPen(QColor(0xe0, 0x8a, 0x1e), 2));
}

}  // namespace cambench
