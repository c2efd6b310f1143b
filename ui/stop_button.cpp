#include "stop_button.h"

#include "motion_stop.h"

#include <QPushButton>

namespace cambench {

void styleAsStop(QPushButton* button) {
    button->setStyleSheet(QStringLiteral(
        "QPushButton { background: #c62828; color: white; font-weight: bold; font-size: 16pt; }"
        "QPushButton:disabled { background: palette(mid); color: palette(dark); }"));
}

void routeToShellStop(QPushButton* button, MotionStop* stop, QObject* context,
                      std::function<void(const QString& text, bool ok)> showResult,
                      std::function<void()> armedChanged) {
    styleAsStop(button);
    button->setMinimumHeight(56);
    const auto update = [button, stop] { button->setEnabled(stop->armed()); };
    update();
    QObject::connect(stop, &MotionStop::availabilityChanged, button, update);
    QObject::connect(stop, &MotionStop::availabilityChanged, context, std::move(armedChanged));
    QObject::connect(button, &QPushButton::clicked, stop, &MotionStop::stopAll);
    QObject::connect(stop, &MotionStop::stopFinished, context,
                     [showResult](const comm::MotionStopReport& report) {
                         showResult(MotionStop::reportSummary(report) + QLatin1Char('\n') +
                                        MotionStop::reportText(report),
                                    report.allAcknowledged());
                     });
}

}  // namespace cambench
