#include "mc1_trend_page.h"

#include "mc1_variables_page.h"
#include "mc1_watch_model.h"

#include <QChart>
#include <QChartView>
#include <QEvent>
#include <QLabel>
#include <QLegendMarker>
#include <QLineSeries>
#include <QVBoxLayout>
#include <QValueAxis>

namespace cambench {

namespace {
constexpr int kMaxSeries = 8;
constexpr double kWindowSeconds = 60;
}  // namespace

Mc1TrendPage::Mc1TrendPage(DeviceSession* session, Mc1VariablesPage* variables, QWidget* parent)
    : Mc1Page(session, parent),
      m_variables(variables),
      m_model(variables->model()),
      m_view(new QChartView),
      m_time(new QValueAxis),
      m_values(new QValueAxis) {
    setObjectName(QStringLiteral("mc1TrendPage"));
    auto* chart = new QChart;
    chart->addAxis(m_time, Qt::AlignBottom);
    chart->addAxis(m_values, Qt::AlignLeft);
    m_time->setTitleText(tr("seconds"));
    m_time->setRange(0, kWindowSeconds);
    m_view->setChart(chart);
    m_view->setRenderHint(QPainter::Antialiasing);
    m_view->setObjectName(QStringLiteral("mc1TrendChart"));
    auto* note =
        new QLabel(tr("The first eight variables of the Variables page's watch list, "
                      "read while this page or that one is shown."));
    note->setWordWrap(true);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(note);
    layout->addWidget(m_view, 1);
    connect(m_model, &Mc1WatchModel::sampled, this, &Mc1TrendPage::sample);
    applyPalette();
}

bool Mc1TrendPage::poll() {
    return m_variables->poll();
}

void Mc1TrendPage::markStale() {
    m_gap = true;
}

int Mc1TrendPage::pointCount() const {
    int count = 0;
    for (const auto& [number, series] : m_series) count += int(series->count());
    return count;
}

void Mc1TrendPage::sample(const QDateTime& at) {
    if (!m_start.isValid()) m_start = at;
    const double t = m_start.msecsTo(at) / 1000.0;
    const QList<Mc1WatchModel::Entry>& entries = m_model->entries();
    QChart* chart = m_view->chart();
    double low = 0;
    double high = 1;
    bool first = true;
    for (int i = 0; i < entries.size() && i < kMaxSeries; ++i) {
        const Mc1WatchModel::Entry& entry = entries.at(i);
        if (!entry.value) continue;
        QLineSeries* series = nullptr;
        for (const auto& [number, line] : m_series)
            if (number == entry.number && !m_gap) series = line;
        if (!series) {
            // A new variable, or the first answer after a gap: a new line
            // (no line drawn across the time without answers).
            series = new QLineSeries;
            const QString name = entry.name.isEmpty()
                                     ? QStringLiteral("V%1").arg(entry.number)
                                     : QStringLiteral("V%1 %2").arg(entry.number).arg(entry.name);
            series->setName(name);
            chart->addSeries(series);
            series->attachAxis(m_time);
            series->attachAxis(m_values);
            for (const auto& [number, line] : m_series) {
                if (number != entry.number) continue;
                series->setColor(line->color());
                chart->legend()->markers(series).value(0)->setVisible(false);
                break;
            }
            m_series << std::pair<int, QLineSeries*>{entry.number, series};
        }
        series->append(t, double(*entry.value));
    }
    m_gap = false;
    for (const auto& [number, series] : m_series) {
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

void Mc1TrendPage::changeEvent(QEvent* event) {
    Mc1Page::changeEvent(event);
    if (event->type() == QEvent::PaletteChange) applyPalette();
}

void Mc1TrendPage::applyPalette() {
    const QPalette pal = palette();
    QChart* chart = m_view->chart();
    chart->setBackgroundBrush(pal.color(QPalette::Base));
    chart->legend()->setLabelColor(pal.color(QPalette::Text));
    for (QValueAxis* axis : {m_time, m_values}) {
        axis->setLabelsColor(pal.color(QPalette::Text));
        axis->setTitleBrush(pal.color(QPalette::Text));
        axis->setGridLineColor(pal.color(QPalette::Mid));
    }
}

}  // namespace cambench
