#include "compax3_status_page.h"

#include "ui/device_session.h"
#include "ui/live_freshness.h"
#include "ui/sentence.h"

#include <QDateTime>
#include <QFormLayout>
#include <QGridLayout>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

namespace cambench {

Compax3StatusPage::Compax3StatusPage(DeviceSession* session, QWidget* parent)
    : Compax3Page(session, parent),
      m_error(new QLabel),
      m_axis(new QLabel),
      m_acknowledge(new QPushButton(tr("Acknowledge error…"))) {
    setObjectName(QStringLiteral("compax3StatusPage"));
    // Two columns of eight lamps, each with its bit and meaning.
    auto* lamps = new QGridLayout;
    for (int bit = 0; bit < 16; ++bit) {
        auto* lamp = new QLabel;
        lamp->setObjectName(QStringLiteral("compax3Bit%1").arg(bit));
        lamps->addWidget(lamp, bit % 8, bit / 8);
        m_lamps << lamp;
    }
    lamps->setColumnStretch(2, 1);
    paintLamps();
    m_error->setObjectName(QStringLiteral("compax3LastError"));
    QFont big = m_error->font();
    big.setPointSizeF(big.pointSizeF() * 1.3);
    big.setBold(true);
    m_error->setFont(big);
    m_axis->setObjectName(QStringLiteral("compax3AxisLine"));
    m_acknowledge->setObjectName(QStringLiteral("compax3Acknowledge"));
    m_acknowledge->setToolTip(
        tr("Switches the drive off and on again (control word 0, then 1): "
           "the rising edge acknowledges the error and powers the axis."));
    connect(m_acknowledge, &QPushButton::clicked, this, &Compax3StatusPage::acknowledge);
    auto* note =
        new QLabel(tr("Status word 1 (object 1000.3), bit 0 first. The meanings of the "
                      "bits and error numbers come from a public client, not from "
                      "Parker's manual."));
    note->setWordWrap(true);
    auto* form = new QFormLayout;
    form->addRow(tr("Last error:"), m_error);
    form->addRow(tr("Axis:"), m_axis);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(note);
    layout->addLayout(lamps);
    layout->addLayout(form);
    layout->addWidget(m_acknowledge, 0, Qt::AlignLeft);
    layout->addWidget(freshnessLine());
    layout->addWidget(resultLine());
    layout->addStretch(1);
}

QString Compax3StatusPage::errorText() const {
    return m_error->text();
}

void Compax3StatusPage::show(const comm::Compax3DriveStatus& status) {
    m_stale = false;
    m_shown = status;
    m_axis->setStyleSheet(QString());
    m_word = status.status.word;
    paintLamps();
    m_error->setText(comm::compax3LastErrorText(status.lastError));
    m_error->setStyleSheet(status.lastError == 1 ? QString() : QStringLiteral("color: #d03030;"));
    m_axis->setText(status.summary());
}

void Compax3StatusPage::paintLamps() {
    // Lit: green; off: a hollow ring; stale: all grey, lit or not.
    for (const comm::Compax3StatusBit& bit : comm::compax3StatusBits(m_word)) {
        const QString colour = m_stale  ? QStringLiteral("gray")
                               : bit.on ? QStringLiteral("#2e9d3a")
                                        : QStringLiteral("palette(mid)");
        m_lamps.at(bit.bit)->setText(
            QStringLiteral("<span style=\"color:%1; font-size:14pt\">%2</span> b%3 %4")
                .arg(colour, bit.on ? QStringLiteral("●") : QStringLiteral("○"))
                .arg(bit.bit)
                .arg(bit.name.toHtmlEscaped()));
    }
}

bool Compax3StatusPage::poll() {
    return pollStatus([this](const comm::Compax3DriveStatus& status) { show(status); });
}

void Compax3StatusPage::freshnessChanged() {
    // A missed cycle, a lost line, a backup holding the line: grey, and why.
    if (!freshness()->isLive()) greyOut(freshness()->valueNote());
}

void Compax3StatusPage::greyOut(const QString& why) {
    if (!m_shown) return;
    m_stale = true;
    paintLamps();
    m_error->setText(tr("%1 (%2)").arg(comm::compax3LastErrorText(m_shown->lastError), why));
    m_error->setStyleSheet(QStringLiteral("color: gray;"));
    m_axis->setText(tr("%1 (%2)").arg(m_shown->summary(), why));
    m_axis->setStyleSheet(QStringLiteral("color: gray;"));
}

void Compax3StatusPage::acknowledge() {
    if (!facts().known) return;
    if (!confirm(tr("Acknowledge"),
                 tr("Acknowledge the error and power the axis of drive %1?")
                     .arg(facts().identity.serial),
                 tr("A powerless drive is switched off and on again; it holds its position "
                    "with power afterwards. A powered drive is left as it is (nothing is sent). "
                    "Make sure nobody is at the axis.")))
        return;
    // It powers the drive: only when the line is free, never queued.
    session()->runMotion<comm::Compax3Device, comm::Compax3CommandResult>(
        this, tr("Acknowledge"),
        [](comm::Compax3Device& device, comm::JobContext&) {
            return device.motion(comm::Compax3Motion::Enable);
        },
        [this](Result<comm::Compax3CommandResult> result) {
            if (!result) {
                showResult(tr("Not acknowledged: %1").arg(asSentence(result.error().message)),
                           false);
                return;
            }
            if (!result->note.isEmpty()) {
                if (result->after) show(*result->after);
                showResult(capitalised(asSentence(result->note)), false);
                return;
            }
            if (!result->after) {
                showResult(tr("Acknowledged by the drive; %1").arg(asSentence(result->summary())),
                           true);
                poll();
                return;
            }
            show(*result->after);
            showResult(tr("Acknowledged; last error now: %1.")
                           .arg(comm::compax3LastErrorText(result->after->lastError)),
                       result->after->lastError == 1);
        });
}

}  // namespace cambench
