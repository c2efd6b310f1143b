#pragma once

#include "mc1_page.h"

class QLabel;
class QSpinBox;

namespace cambench {

class LedStrip;

// Flags and I/O: the controller's inputs, outputs and a range of flags as
// LEDs under their manual numbers, live while shown. Clicking an output
// or a flag sets or clears it after a confirmation; inputs only show.
class Mc1PointsPage : public Mc1Page {
    Q_OBJECT
public:
    explicit Mc1PointsPage(DeviceSession* session, QWidget* parent = nullptr);

    QString sectionTitle() const override { return tr("Flags & I/O"); }
    bool poll() override;
    void markStale() override;

    LedStrip* strip(comm::Mc1Area area) const;
    // Asks, then sets or clears `point`; the LED shows what was read back.
    void toggle(const comm::Mc1Point& point, bool on);

protected:
    void factsChanged() override;
    void freshnessChanged() override;

private:
    struct Area {
        comm::Mc1Area area;
        LedStrip* strip;
        QList<int> numbers;
    };
    void layoutFlags();

    QList<Area> m_areas;  // inputs, outputs, flags
    QSpinBox* m_flagFirst;
    QSpinBox* m_flagCount;
};

}  // namespace cambench
