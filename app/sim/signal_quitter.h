#pragma once

#include <QObject>
#include <QSocketNotifier>

#include <memory>

namespace cambench {

// Quits the application on SIGTERM and SIGINT. A signal handler may only
// write to a pipe; the notifier turns that into a call on the event loop.
class SignalQuitter : public QObject {
    Q_OBJECT

public:
    explicit SignalQuitter(QObject* parent = nullptr);
    ~SignalQuitter() override;

    bool isValid() const { return m_notifier != nullptr; }

private:
    static void onSignal(int signal);
    void onNotified();

    std::unique_ptr<QSocketNotifier> m_notifier;
};

}  // namespace cambench
