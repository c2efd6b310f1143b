#include "multi_trend_chart.h"

#include <QChart>
#include <QEvent>
#include <QLegendMarker>
#include <QLineSeries>
#include <QValueAxis>

namespace cambench {

namespace {
constexpr double kWindowSeconds = 60;

// Told apart on a light and a dark background (the chart theme's own
// colours repeat after five, and a line after a gap took the next one).
const QList<QColor>& distinctColours() {
    static const QList<QColor> colours{QColor(0x1f, 0x77, 0xb4), QColor(0xff, 0x7f, 0x0e),
                                       QColor(0x2c, 0xa0, 0x2c), QColor(0xd6, 0x27, 0x28),
                                       QColor(0x94, 0x67, 0xbd), QColor(0x8c, 0x56, 0x4b),
                                       QColor(0xe3, 0x77, 0xc2), QColor(0x7f, 0x7f, 0x7f),
                                       QColor(0xbc, 0xbd, 0x22), QColor(0x17, 0xbe, 0xcf)};
    return colours;
}
}  // namespace

MultiTrendChart::MultiTrendChart(QWidget* parent)
    : QChartView(parent), m_time(new QValueAxis), m_values(new QValueAxis) {
    auto* chart = new QChart;
    chart->addAxis(m_time, Qt::AlignBottom);
    chart->addAxis(m_values, Qt::AlignLeft);
    m_time->setTitleText(tr("seconds"));
    m_time->setRange(0, kWindowSeconds);
    setChart(chart);
    setRenderHint(QPainter::Antialiasing);
    applyPalette();
}

int MultiTrendChart::pointCount() const {
    int count = 0;
    for (const auto& [key, series] : m_series) count += int(series->count());
    return count;
}

void MultiTrendChart::clear() {
    for (const auto& [key, series] : m_series) {
        chart()->removeSeries(series);
        delete series;
    }
    m_series.clear();
    m_origin = QDateTime();
}

QStringList MultiTrendChart::legendNames() const {
    // A value's first line carries its marker; the markers of the lines
    // after a gap are hidden.
    QStringList names;
    QStringList seen;
    for (const auto& [key, line] : m_series) {
        if (seen.contains(key)) continue;
        seen << key;
        const QLegendMarker* marker = chart()->legend()->markers(line).value(0);
        if (marker) names << marker->label();
    }
    return names;
}

QList<QColor> MultiTrendChart::valueColours() const {
    QList<QColor> colours;
    QStringList seen;
    for (const auto& [key, line] : m_series) {
        if (seen.contains(key)) continue;
        seen << key;
        colours << line->color();
    }
    return colours;
}

QColor MultiTrendChart::unusedColour() const {
    const QList<QColor> used = valueColours();
    for (const QColor& colour : distinctColours())
        if (!used.contains(colour)) return colour;
    // More values than colours: hues spread by the golden angle.
    return QColor::fromHsv(int(used.size() * 137.508) % 360, 200, 220);
}

QLineSeries* MultiTrendChart::seriesFor(const Sample& sample) {
    QLineSeries* last = nullptr;
    for (const auto& [key, line] : m_series) {
        if (key != sample.key) continue;
        last = line;
        // Renamed meanwhile: the legend says the name it has now.
        if (line->name() != sample.name) line->setName(sample.name);
    }
    if (last && !m_gap) return last;
    // A new value, or the first answer after a gap: a new line (none
    // drawn across the time without answers), in the old line's colour.
    auto* series = new QLineSeries;
    series->setName(sample.name);
    chart()->addSeries(series);
    series->attachAxis(m_time);
    series->attachAxis(m_values);
    if (last) {
        series->setColor(last->color());
        chart()->legend()->markers(series).value(0)->setVisible(false);
    } else {
        series->setColor(unusedColour());
    }
    m_series << std::pair<QString, QLineSeries*>{sample.key, series};
    return series;
}

void MultiTrendChart::addSamples(const QDateTime& at, const QList<Sample>& samples) {
    if (samples.isEmpty()) return;
    if (!m_origin.isValid()) m_origin = at;
    const double t = m_origin.msecsTo(at) / 1000.0;
    QList<QLineSeries*> lines;
    for (const Sample& sample : samples) lines << seriesFor(sample);
    for (int i = 0; i < samples.size(); ++i) lines.at(i)->append(t, samples.at(i).value);
    m_gap = false;
    double low = 0;
    double high = 1;
    bool first = true;
    for (const auto& [key, series] : m_series) {
        while (series->count() > 0 && series->at(0).x() < t - kWindowSeconds) series->remove(0);
        for (const QPointF& p : series->points()) {
            low = first ? p.y() : std::min(low, p.y());
            high = first ? p.y() : std::max(high, p.y());
            first = false;
        }
    }
    if (high - low < 1) high = low + 1;
    const double margin = (high - low) * 0.05;
    m_values->setRange(low - margin, high + margin);
    m_time->setRange(std::max(0.0, t - kWindowSeconds), std::max(kWindowSeconds, t));
}

void MultiTrendChart::changeEvent(QEvent* event) {
    QChartView::changeEvent(event);
    if (event->type() == QEvent::PaletteChange) applyPalette();
}

void MultiTrendChart::applyPalette() {
    const QPalette pal = palette();
    chart()->setBackgroundBrush(pal.color(QPalette::Base));
    chart()->legend()->setLabelColor(pal.color(QPalette::Text));
    for (QValueAxis* axis : {m_time, m_values}) {
        axis->setLabelsColor(pal.color(QPalette::Text));
        axis->setTitleBrush(pal.color(QPalette::Text));
        axis->setGridLineColor(pal.color(QPalette::Mid));
    }
}

}  // namespace cambench
