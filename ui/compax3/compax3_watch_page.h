#pragma once

#include "compax3_page.h"

#include <QDateTime>

class QLineEdit;
class QTableWidget;

namespace cambench {

namespace usecases {
struct Compax3Reading;
}

class Compax3Gui;
class MultiTrendChart;

// Watch: any objects polled live while the page is shown, a table with
// their values and when they were read (grey when stale), and the numeric
// ones on a trend over the last minute.
class Compax3WatchPage : public Compax3Page {
    Q_OBJECT
public:
    Compax3WatchPage(DeviceSession* session, Compax3Gui* gui, QWidget* parent = nullptr);

    QString sectionTitle() const override { return tr("Watch"); }
    bool poll() override;
    // "680.5" or "O 680,5"; false with a message when it is no object.
    bool addObject(const QString& text);
    QTableWidget* table() const { return m_table; }
    MultiTrendChart* chart() const { return m_chart; }

protected:
    void freshnessChanged() override;
    // Another connect, maybe another device: its trend starts anew.
    void forgetDevice() override;

private:
    void rebuildTable();
    // Greys the values read and says why in their tooltips.
    void greyOut(const QString& why);
    void show(const QList<usecases::Compax3Reading>& values);

    Compax3Gui* m_gui;
    QLineEdit* m_add;
    QTableWidget* m_table;
    MultiTrendChart* m_chart;
};

}  // namespace cambench
