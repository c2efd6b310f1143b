#pragma once

#include "compax3_page.h"

#include <optional>

class QLabel;
class QPushButton;

namespace cambench {

// Status: the status word (1000.3) as lamps with their meanings, the last
// error (550.1) in words, position and last set, polled while shown; grey
// when stale. Acknowledge powers the axis (the drive acknowledges on the
// rising edge of enable) and so asks first.
class Compax3StatusPage : public Compax3Page {
    Q_OBJECT
public:
    explicit Compax3StatusPage(DeviceSession* session, QWidget* parent = nullptr);

    QString sectionTitle() const override { return tr("Status"); }
    bool poll() override;
    void acknowledge();
    // Bit `bit` of the status word as last read.
    bool bitOn(int bit) const { return m_word & (1u << bit); }
    QString errorText() const;

protected:
    void freshnessChanged() override;

private:
    void show(const comm::Compax3DriveStatus& status);
    void paintLamps();
    // Greys lamps, error and axis with `why` after the values.
    void greyOut(const QString& why);

    QList<QLabel*> m_lamps;  // one per bit, with its name
    quint16 m_word = 0;
    QLabel* m_error;
    QLabel* m_axis;
    QPushButton* m_acknowledge;
    bool m_stale = false;
    std::optional<comm::Compax3DriveStatus> m_shown;  // as last read
};

}  // namespace cambench
