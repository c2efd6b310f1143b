#include "stop_bar.h"

#include "clock_time.h"
#include "motion_stop.h"
#include "stop_button.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QScrollArea>

namespace cambench {

namespace {

// The bar's height, whatever its report says.
constexpr int kBarHeight = 48;

}  // namespace

StopBar::StopBar(StopControl* stop, const QString& shortcutText, QWidget* parent)
    : QFrame(parent),
      m_stop(stop),
      m_button(new QPushButton(tr("STOP (%1)").arg(shortcutText))),
      m_report(new QLabel) {
    setObjectName(QStringLiteral("stopBar"));
    m_button->setObjectName(QStringLiteral("shellStop"));
    m_button->setFixedHeight(kBarHeight);
    m_button->setMinimumWidth(200);
    styleAsStop(m_button);
    m_button->setToolTip(tr("Stops every axis and drive of the device, without a question, "
                            "ahead of everything waiting for the line. %1 stops it too, from "
                            "every window, dialog and menu of CamBench.")
                             .arg(shortcutText));
    m_button->setFocusPolicy(Qt::NoFocus);  // a click leaves the focus where the work is
    m_report->setObjectName(QStringLiteral("shellStopReport"));
    m_report->setWordWrap(true);
    m_report->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_report->setAlignment(Qt::AlignLeft | Qt::AlignTop);
    // The report (one line per axis, ten and more in a machine) scrolls in
    // a place of its own, as high as the button: the bar never grows, and
    // the page below never moves under the pointer.
    auto* scroll = new QScrollArea;
    scroll->setObjectName(QStringLiteral("shellStopReportArea"));
    scroll->setWidget(m_report);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    scroll->setFixedHeight(kBarHeight);
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_button);
    layout->addWidget(scroll, 1);
    setFixedHeight(kBarHeight);
    connect(m_button, &QPushButton::clicked, stop, &StopControl::stopAll);
    connect(stop, &StopControl::availabilityChanged, this, &StopBar::update);
    connect(stop, &StopControl::stopStarted, this, [this] {
        m_report->setText(tr("STOP sent…"));
        m_report->setStyleSheet(QString());
    });
    connect(stop, &StopControl::stopFinished, this, &StopBar::showReport);
    update();
    if (!stop->lastReport().lines.isEmpty()) showReport();  // a window rebuilt keeps it
}

QString StopBar::reportText() const {
    return m_report->text();
}

void StopBar::update() {
    setVisible(m_stop->available());
    m_button->setEnabled(m_stop->armed());
}

void StopBar::showReport() {
    const comm::MotionStopReport& report = m_stop->lastReport();
    m_report->setText(tr("%1 %2\n%3")
                          .arg(clockTime(m_stop->lastStopTime().time()),
                               MotionStop::reportSummary(report), MotionStop::reportText(report)));
    m_report->setStyleSheet(report.allAcknowledged() ? QString()
                                                     : QStringLiteral("color: #c62828;"));
}

}  // namespace cambench
