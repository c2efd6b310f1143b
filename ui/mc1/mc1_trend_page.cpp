#include "mc1_trend_page.h"

#include "mc1_variables_page.h"
#include "mc1_watch_model.h"

#include "ui/live_freshness.h"
#include "ui/multi_trend_chart.h"

#include <QLabel>
#include <QVBoxLayout>

namespace cambench {

namespace {
constexpr int kMaxSeries = 8;
}  // namespace

Mc1TrendPage::Mc1TrendPage(DeviceSession* session, Mc1VariablesPage* variables, QWidget* parent)
    : Mc1Page(session, parent),
      m_variables(variables),
      m_model(variables->model()),
      m_chart(new MultiTrendChart),
      m_freshness(new QLabel) {
    setObjectName(QStringLiteral("mc1TrendPage"));
    m_chart->setObjectName(QStringLiteral("mc1TrendChart"));
    auto* note =
        new QLabel(tr("The first eight variables of the Variables page's watch list, "
                      "read while this page or that one is shown."));
    note->setWordWrap(true);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(note);
    layout->addWidget(m_chart, 1);
    m_freshness->setObjectName(QStringLiteral("pageFreshness"));
    layout->addWidget(m_freshness);
    connect(m_model, &Mc1WatchModel::sampled, this, &Mc1TrendPage::sample);
    // The values drawn are the Variables page's: so is their freshness.
    LiveFreshness* freshness = m_variables->freshness();
    const auto showFreshness = [this, freshness] {
        m_freshness->setText(freshness->describe());
        if (!freshness->isLive()) m_chart->breakLine();
    };
    connect(freshness, &LiveFreshness::changed, this, showFreshness);
    showFreshness();
}

LiveDevicePage* Mc1TrendPage::polledPage() {
    return m_variables;
}

bool Mc1TrendPage::poll() {
    return m_variables->poll();
}

void Mc1TrendPage::markStale() {
    m_chart->breakLine();
}

int Mc1TrendPage::seriesCount() const {
    return m_chart->seriesCount();
}

int Mc1TrendPage::pointCount() const {
    return m_chart->pointCount();
}

void Mc1TrendPage::sample(const QDateTime& at) {
    QList<MultiTrendChart::Sample> samples;
    const QList<Mc1WatchModel::Entry>& entries = m_model->entries();
    for (int i = 0; i < entries.size() && i < kMaxSeries; ++i) {
        const Mc1WatchModel::Entry& entry = entries.at(i);
        if (!entry.value) continue;
        const QString key = QStringLiteral("V%1").arg(entry.number);
        samples << MultiTrendChart::Sample{
            key, entry.name.isEmpty() ? key : QStringLiteral("%1 %2").arg(key, entry.name),
            double(*entry.value)};
    }
    m_chart->addSamples(at, samples);
}

void Mc1TrendPage::forgetDevice() {
    LiveDevicePage::forgetDevice();
    m_chart->clear();
}

}  // namespace cambench
