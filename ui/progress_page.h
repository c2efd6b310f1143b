#pragma once

#include <QElapsedTimer>
#include <QWizardPage>

class QLabel;
class QProgressBar;

namespace cambench {

// The last page of the backup wizard: a progress bar with an estimate of
// the time left, then the honest result. Complete only when the work ended.
class ProgressPage : public QWizardPage {
    Q_OBJECT
public:
    explicit ProgressPage(QWidget* parent = nullptr);

    // Whether the total of the progress is the real amount (a restore's
    // image) or only a bound (a backup: the device does not say how much
    // it holds). Only a real total gives a time left.
    enum class Total { Exact, UpperBound };

    void start(const QString& what, Total total = Total::Exact);
    void setProgress(qint64 done, qint64 total);
    void finish(bool ok, const QString& report);
    bool isComplete() const override { return m_finished; }
    bool isRunning() const { return m_running; }
    QString reportText() const;
    QString etaLabelText() const;

    // "about 1 min 20 s left", from the rate measured so far.
    static QString etaText(qint64 elapsedMs, qint64 done, qint64 total);

private:
    QLabel* m_what;
    QProgressBar* m_bar;
    QLabel* m_eta;
    QLabel* m_report;
    QElapsedTimer m_clock;
    Total m_total = Total::Exact;
    bool m_running = false;
    bool m_finished = false;
};

}  // namespace cambench
