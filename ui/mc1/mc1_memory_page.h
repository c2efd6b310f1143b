#pragma once

#include "mc1_page.h"

class QLineEdit;
class QPlainTextEdit;
class QSpinBox;

namespace cambench {

// Memory (MC200): a range read into a hex view, and bytes written at an
// address after a confirmation (MC200 V2), then read back.
class Mc1MemoryPage : public Mc1Page {
    Q_OBJECT
public:
    explicit Mc1MemoryPage(DeviceSession* session, QWidget* parent = nullptr);

    QString sectionTitle() const override { return tr("Memory"); }
    QPlainTextEdit* hexView() const { return m_view; }
    void read(int address, int length);
    void write(int address, const QByteArray& bytes);

protected:
    void factsChanged() override;

private:
    QSpinBox* m_address;
    QSpinBox* m_length;
    QSpinBox* m_writeAddress;
    QLineEdit* m_bytes;
    QPlainTextEdit* m_view;
    QList<QWidget*> m_readWidgets;
    QList<QWidget*> m_writeWidgets;
};

}  // namespace cambench
