#pragma once

#include "mc1_page.h"

class QLabel;

namespace cambench {

class MultiTrendChart;
class Mc1VariablesPage;
class Mc1WatchModel;

// Trend: the first watched variables (up to eight) over the last minute on
// one chart, from the same reads as the Variables page. A stretch without
// answers leaves a gap.
class Mc1TrendPage : public Mc1Page {
    Q_OBJECT
public:
    Mc1TrendPage(DeviceSession* session, Mc1VariablesPage* variables, QWidget* parent = nullptr);

    QString sectionTitle() const override { return tr("Trend"); }
    bool poll() override;
    void markStale() override;
    // Another connect, maybe another device: its trend starts anew.
    void forgetDevice() override;
    // The Variables page polls what the trend draws.
    LiveDevicePage* polledPage() override;
    MultiTrendChart* chart() const { return m_chart; }
    int seriesCount() const;
    int pointCount() const;

private:
    void sample(const QDateTime& at);

    Mc1VariablesPage* m_variables;
    Mc1WatchModel* m_model;
    MultiTrendChart* m_chart;
    QLabel* m_freshness;
};

}  // namespace cambench
