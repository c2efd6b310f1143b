#pragma once

#include "mc1_page.h"

class QChartView;
class QLineSeries;
class QValueAxis;

namespace cambench {

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
    int seriesCount() const { return int(m_series.size()); }
    int pointCount() const;

protected:
    void changeEvent(QEvent* event) override;

private:
    void sample(const QDateTime& at);
    void applyPalette();

    Mc1VariablesPage* m_variables;
    Mc1WatchModel* m_model;
    QChartView* m_view;
    QValueAxis* m_time;
    QValueAxis* m_values;
    QList<std::pair<int, QLineSeries*>> m_series;  // variable number, its line
    QDateTime m_start;
    bool m_gap = false;
};

}  // namespace cambench
