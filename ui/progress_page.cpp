#include "progress_page.h"

#include <QLabel>
#include <QProgressBar>
#include <QVBoxLayout>

namespace cambench {

ProgressPage::ProgressPage(QWidget* parent)
    : QWizardPage(parent),
      m_what(new QLabel),
      m_bar(new QProgressBar),
      m_eta(new QLabel),
      m_report(new QLabel) {
    m_report->setWordWrap(true);
    m_report->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_what->setWordWrap(true);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_what);
    layout->addWidget(m_bar);
    layout->addWidget(m_eta);
    layout->addWidget(m_report, 1);
}

void ProgressPage::start(const QString& what, Total total) {
    m_total = total;
    m_what->setText(what);
    m_bar->setRange(0, 0);
    m_eta->clear();
    m_clock.start();
    m_running = true;
    m_finished = false;
    Q_EMIT completeChanged();
}

void ProgressPage::setProgress(qint64 done, qint64 total) {
    if (total <= 0) return;
    m_bar->setRange(0, 1000);
    m_bar->setValue(int(done * 1000 / total));
    if (m_total == Total::Exact) {
        m_eta->setText(etaText(m_clock.elapsed(), done, total));
    } else {
        m_eta->setText(
            tr("%1 s so far. No time left is given: how much the device holds is not known "
               "before it is read.")
                .arg(m_clock.elapsed() / 1000));
    }
}

QString ProgressPage::etaLabelText() const {
    return m_eta->text();
}

QString ProgressPage::etaText(qint64 elapsedMs, qint64 done, qint64 total) {
    if (done <= 0 || total <= done) return {};
    const qint64 left = elapsedMs * (total - done) / done / 1000;
    if (left >= 60) return tr("about %1 min %2 s left").arg(left / 60).arg(left % 60);
    return tr("about %1 s left").arg(std::max<qint64>(1, left));
}

void ProgressPage::finish(bool ok, const QString& report) {
    m_running = false;
    m_finished = true;
    if (ok) {
        m_bar->setRange(0, 1);
        m_bar->setValue(1);
    }
    m_eta->clear();
    m_report->setText(report);
    Q_EMIT completeChanged();
}

QString ProgressPage::reportText() const {
    return m_report->text();
}

}  // namespace cambench
