#include "motion_leave_question.h"

#include "motion_stop.h"
#include "sentence.h"
#include "shell_log.h"

#include <QCoreApplication>
#include <QMessageBox>
#include <QPushButton>

namespace cambench {

namespace {

// How long the question waits for the device to say what moves, and for a
// STOP's report; then "could not tell" / "no report" is said.
constexpr int kAskMs = 3000;
constexpr int kStopMs = 10000;

}  // namespace

bool askBeforeLeavingMotion(QWidget* parent, MotionStop& stop, const QString& action) {
    const Result<QStringList> moving = stop.activeMotion(kAskMs);
    if (moving && moving->isEmpty()) return true;
    QMessageBox ask(QMessageBox::Warning, action, QString(), QMessageBox::NoButton, parent);
    ask.setObjectName(QStringLiteral("motionLeaveQuestion"));
    if (moving) {
        ask.setText(QCoreApplication::translate("cambench::MotionLeaveQuestion",
                                                "On the device something moves or is powered:"));
        ask.setInformativeText(QStringLiteral("• ") + moving->join(QStringLiteral("\n• ")));
    } else {
        ask.setText(QCoreApplication::translate(
            "cambench::MotionLeaveQuestion",
            "CamBench could not tell whether something on the device moves or is "
            "powered."));
        ask.setInformativeText(asSentence(moving.error().message));
    }
    QPushButton* stopFirst =
        ask.addButton(QCoreApplication::translate("cambench::MotionLeaveQuestion", "STOP, then %1")
                          .arg(action.toLower()),
                      QMessageBox::AcceptRole);
    stopFirst->setObjectName(QStringLiteral("stopThenLeave"));
    QPushButton* leave = ask.addButton(
        QCoreApplication::translate("cambench::MotionLeaveQuestion", "%1 without stopping")
            .arg(action),
        QMessageBox::DestructiveRole);
    leave->setObjectName(QStringLiteral("leaveWithoutStop"));
    QPushButton* cancel = ask.addButton(QMessageBox::Cancel);
    ask.setDefaultButton(stopFirst);
    ask.setEscapeButton(cancel);
    ask.exec();
    if (ask.clickedButton() == leave) {
        qCInfo(shellLog) << action << "without stopping, asked";
        return true;
    }
    if (ask.clickedButton() != stopFirst) return false;
    const Result<comm::MotionStopReport> report = stop.stopAndWait(kStopMs);
    if (report && report->allAcknowledged()) return true;
    QMessageBox::warning(
        parent, action,
        QCoreApplication::translate(
            "cambench::MotionLeaveQuestion",
            "The STOP was not acknowledged everywhere, so CamBench stays connected and STOP "
            "can be pressed again. Use the machine's emergency stop.\n\n%1")
            .arg(report ? MotionStop::reportText(*report) : asSentence(report.error().message)));
    return false;
}

}  // namespace cambench
