#include "mc1_memory_page.h"

#include "ui/device_session.h"
#include "ui/sentence.h"

#include "comm/mc1/mc1_parameters.h"

#include <QFontDatabase>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QRegularExpression>
#include <QSpinBox>
#include <QStyle>
#include <QStyleOptionSpinBox>
#include <QVBoxLayout>

namespace cambench {

namespace {

// An address in hex ("0x1000"): never narrower than its widest address
// with the prefix, in whatever font and language it is shown (a layout
// squeezed it to "x1000").
class AddressBox : public QSpinBox {
public:
    QSize sizeHint() const override {
        const QSize hint = QSpinBox::sizeHint();
        const QString widest =
            prefix() + textFromValue(maximum()).toUpper() + QStringLiteral("0");  // a margin
        QStyleOptionSpinBox option;
        initStyleOption(&option);
        const QSize content(fontMetrics().horizontalAdvance(widest), hint.height());
        const QSize needed = style()->sizeFromContents(QStyle::CT_SpinBox, &option, content, this);
        return {std::max(hint.width(), needed.width()), hint.height()};
    }
    QSize minimumSizeHint() const override { return sizeHint(); }
};

QSpinBox* hexBox(int max) {
    auto* box = new AddressBox;
    box->setDisplayIntegerBase(16);
    box->setPrefix(QStringLiteral("0x"));
    box->setRange(0, max);
    return box;
}

}  // namespace

Mc1MemoryPage::Mc1MemoryPage(DeviceSession* session, QWidget* parent)
    : Mc1Page(session, parent),
      m_address(hexBox(comm::kMc1MemorySize - 1)),
      m_length(new QSpinBox),
      m_writeAddress(hexBox(comm::kMc1MemorySize - 1)),
      m_bytes(new QLineEdit),
      m_view(new QPlainTextEdit) {
    setObjectName(QStringLiteral("mc1MemoryPage"));
    m_address->setObjectName(QStringLiteral("mc1MemoryAddress"));
    m_length->setObjectName(QStringLiteral("mc1MemoryLength"));
    m_length->setRange(1, 4096);
    m_length->setValue(256);
    m_view->setObjectName(QStringLiteral("mc1HexView"));
    m_view->setReadOnly(true);
    m_view->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    m_bytes->setObjectName(QStringLiteral("mc1MemoryBytes"));
    m_bytes->setPlaceholderText(tr("bytes in hex, e.g. 0a 0b 0c"));
    auto* readButton = new QPushButton(tr("Read"));
    readButton->setObjectName(QStringLiteral("mc1MemoryRead"));
    auto* writeButton = new QPushButton(tr("Write…"));
    writeButton->setObjectName(QStringLiteral("mc1MemoryWrite"));
    auto* readRow = new QHBoxLayout;
    readRow->addWidget(new QLabel(tr("Address")));
    readRow->addWidget(m_address);
    readRow->addWidget(new QLabel(tr("bytes")));
    readRow->addWidget(m_length);
    readRow->addWidget(readButton);
    readRow->addStretch();
    auto* writeBox = new QGroupBox(tr("Write (MC200 V2; asks first, then reads back)"));
    auto* writeRow = new QHBoxLayout(writeBox);
    writeRow->addWidget(new QLabel(tr("Address")));
    writeRow->addWidget(m_writeAddress);
    writeRow->addWidget(m_bytes, 1);
    writeRow->addWidget(writeButton);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(readRow);
    layout->addWidget(m_view, 1);
    layout->addWidget(writeBox);
    layout->addWidget(resultLine());
    m_readWidgets = {m_address, m_length, readButton};
    m_writeWidgets = {m_writeAddress, m_bytes, writeButton};
    connect(readButton, &QPushButton::clicked, this,
            [this] { read(m_address->value(), m_length->value()); });
    connect(writeButton, &QPushButton::clicked, this, [this] {
        static const QRegularExpression hex(QStringLiteral("^([0-9a-fA-F]{2})+$"));
        const QString text = m_bytes->text().remove(QLatin1Char(' '));
        if (!hex.match(text).hasMatch()) {
            showResult(tr("Write the bytes as pairs of hex digits, e.g. 0a 0b 0c."), false);
            return;
        }
        write(m_writeAddress->value(), QByteArray::fromHex(text.toLatin1()));
    });
    factsChanged();
}

void Mc1MemoryPage::factsChanged() {
    for (QWidget* widget : m_readWidgets)
        widget->setEnabled(facts().known && facts().has(comm::Mc1Capability::MemoryRead));
    for (QWidget* widget : m_writeWidgets)
        widget->setEnabled(facts().known && facts().has(comm::Mc1Capability::MemoryWrite));
    if (facts().known && !facts().has(comm::Mc1Capability::MemoryRead))
        showResult(tr("The %1 has no memory telegrams (an MC200 has).")
                       .arg(comm::mc1VariantName(facts().variant)),
                   true);
}

void Mc1MemoryPage::read(int address, int length) {
    length = std::min(length, comm::kMc1MemorySize - address);
    session()->run<comm::Mc1Device, QByteArray>(
        this, tr("Read memory"),
        [address, length](comm::Mc1Device& device, comm::JobContext& job) {
            return device.readMemory(
                address, length, [&job](qint64 done, qint64 total) { job.progress(done, total); });
        },
        [this, address](Result<QByteArray> bytes) {
            if (!bytes) {
                showResult(asSentence(bytes.error().message), false);
                return;
            }
            m_view->setPlainText(comm::mc1HexLines(address, *bytes));
            showResult(tr("%1 bytes read from 0x%2 at %3.")
                           .arg(bytes->size())
                           .arg(QString::number(address, 16).toUpper())
                           .arg(QTime::currentTime().toString(QStringLiteral("HH:mm:ss"))),
                       true);
        });
}

void Mc1MemoryPage::write(int address, const QByteArray& bytes) {
    const QString where = QStringLiteral("0x%1").arg(QString::number(address, 16).toUpper());
    if (!confirm(tr("Write"),
                 tr("Write %n byte(s) at %1 of the %2?", nullptr, int(bytes.size()))
                     .arg(where, comm::mc1VariantName(facts().variant)),
                 tr("The controller uses its memory at once; a wrong byte can stop its program.")))
        return;
    session()->run<comm::Mc1Device, QByteArray>(
        this, tr("Write memory"),
        [address, bytes](comm::Mc1Device& device, comm::JobContext&) -> Result<QByteArray> {
            if (const Status written = device.writeMemory(address, bytes); !written)
                return written.error();
            return device.readMemory(address, int(bytes.size()));
        },
        [this, address, bytes, where](Result<QByteArray> back) {
            if (!back) {
                showResult(asSentence(back.error().message), false);
                return;
            }
            m_view->setPlainText(comm::mc1HexLines(address, *back));
            showResult(*back == bytes
                           ? tr("Written at %1 and read back.").arg(where)
                           : tr("Written at %1, but the bytes read back differ.").arg(where),
                       *back == bytes);
        });
}

}  // namespace cambench
