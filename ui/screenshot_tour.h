#pragma once

#include "family_gui.h"

#include <QObject>
#include <QSize>
#include <QString>

class QWidget;

namespace cambench {

class Shell;

// `cambench --screenshots DIR`: visits every screen on the simulated
// device, waits through the event loop for its data (never sleeping on the
// GUI thread), saves one PNG per screen and reports when done.
class ScreenshotTour : public QObject {
    Q_OBJECT
public:
    ScreenshotTour(Shell* shell, const QString& directory, QObject* parent = nullptr);

    void start();
    QStringList failures() const { return m_failures; }

Q_SIGNALS:
    void finished(bool ok);

private:
    void buildSteps();
    void runStep(int index);
    void waitFor(int index, int waitedMs);
    void capture(int index);

    Shell* m_shell;
    QString m_directory;
    QList<TourStop> m_steps;
    QStringList m_failures;
};

}  // namespace cambench
