#include "plc_coupling_page.h"
#include "ui/camcon/camcon_jobs.h"

#include "milliseconds_text.h"
#include "ui/device_session.h"
#include "ui/sentence.h"
#include "workspace.h"

#include "ui/camcon/cameditor/cam_document.h"

#include "comm/camcon/table/short_client.h"
#include "comm/camcon/usecases/short_coupling.h"

#include <QDoubleSpinBox>
#include <QFontDatabase>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QMessageBox>
#include <QPushButton>
#include <QSpinBox>
#include <QTableWidget>
#include <QTime>
#include <QVBoxLayout>

namespace cambench {

namespace {

using comm::CamConDevice;
using comm::table::ShortClient;
using comm::table::ShortStatus;

// Work for the worker thread with the device's short commands.
template <class T, class Work>
CamConWork<T> withShortCommands(Work work) {
    return comm::table::withShortCommands<T>(
        [work = std::move(work)](ShortClient& client, CamConDevice&) { return work(client); });
}

QLabel* monospaceLabel() {
    auto* label = new QLabel;
    label->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    label->setTextInteractionFlags(Qt::TextSelectableByMouse);
    return label;
}

QString outputList(const QList<bool>& bits, int first, int last) {
    QStringList on;
    for (int i = first; i <= last && i <= bits.size(); ++i)
        if (bits.at(i - 1)) on.append(QString::number(i));
    return on.isEmpty() ? QCoreApplication::translate("cambench::PlcCouplingPage", "none on")
                        : QCoreApplication::translate("cambench::PlcCouplingPage", "on: %1")
                              .arg(on.join(QStringLiteral(", ")));
}

}  // namespace

PlcCouplingPage::PlcCouplingPage(DeviceSession* session, Workspace* workspace, QWidget* parent)
    : CamConSectionPage(parent),
      m_session(session),
      m_workspace(workspace),
      m_statusArea(monospaceLabel()),
      m_statusWords(new QLabel),
      m_program(new QSpinBox),
      m_output(new QSpinBox),
      m_cams(new QTableWidget(0, 2)),
      m_deadTime(new QDoubleSpinBox),
      m_deadTimeArea(monospaceLabel()),
      m_outcome(new QLabel) {
    auto* intro = new QLabel(
        tr("An S7 with a CP340 drives the CamCon with the short commands 0x01 to 0x07. This "
           "page sends the same telegrams as the function block and shows the answers as the "
           "data block holds them. When the CamCon answers here as expected, look for the "
           "fault in the PLC program or the CP340's settings."));
    intro->setWordWrap(true);
    m_statusWords->setWordWrap(true);
    // Room for the whole area before the first read: the page does not jump.
    m_statusArea->setMinimumHeight(m_statusArea->fontMetrics().lineSpacing() * 8);
    m_statusArea->setAlignment(Qt::AlignLeft | Qt::AlignTop);
    m_outcome->setWordWrap(true);
    m_outcome->setObjectName(QStringLiteral("couplingOutcome"));
    m_statusWords->setObjectName(QStringLiteral("couplingStatusWords"));

    // Area 1: status (0x01), error reset (0x02), program change (0x03).
    auto* readStatusButton = new QPushButton(tr("Read status (0x01)"));
    auto* resetButton = new QPushButton(tr("Reset errors (0x02)"));
    auto* wantedProgram = new QSpinBox;
    wantedProgram->setRange(0, 65535);
    wantedProgram->setObjectName(QStringLiteral("couplingWantedProgram"));
    auto* changeButton = new QPushButton(tr("Change program (0x03)"));
    auto* statusButtons = new QHBoxLayout;
    statusButtons->addWidget(readStatusButton);
    statusButtons->addWidget(resetButton);
    statusButtons->addSpacing(12);
    statusButtons->addWidget(new QLabel(tr("Program:")));
    statusButtons->addWidget(wantedProgram);
    statusButtons->addWidget(changeButton);
    statusButtons->addStretch();
    auto* statusGroup = new QGroupBox(tr("Area 1: status"));
    auto* statusLayout = new QVBoxLayout(statusGroup);
    statusLayout->addLayout(statusButtons);
    statusLayout->addWidget(m_statusArea);
    statusLayout->addWidget(m_statusWords);

    // Area 2: the cam table of one output (0x04, 0x05).
    m_program->setRange(0, 65535);
    m_output->setRange(1, 255);
    m_cams->setHorizontalHeaderLabels({tr("On"), tr("Off")});
    m_cams->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    m_cams->setMinimumHeight(120);
    auto* readTrackButton = new QPushButton(tr("Read cams (0x04)"));
    auto* writeTrackButton = new QPushButton(tr("Write cams (0x05)…"));
    auto* addCam = new QPushButton(tr("Add cam"));
    auto* removeCam = new QPushButton(tr("Remove cam"));
    auto* trackButtons = new QHBoxLayout;
    trackButtons->addWidget(new QLabel(tr("Program:")));
    trackButtons->addWidget(m_program);
    trackButtons->addWidget(new QLabel(tr("Output:")));
    trackButtons->addWidget(m_output);
    trackButtons->addWidget(readTrackButton);
    trackButtons->addWidget(writeTrackButton);
    trackButtons->addStretch();
    trackButtons->addWidget(addCam);
    trackButtons->addWidget(removeCam);
    auto* trackGroup = new QGroupBox(tr("Area 2: cam table"));
    auto* trackLayout = new QVBoxLayout(trackGroup);
    trackLayout->addLayout(trackButtons);
    trackLayout->addWidget(m_cams);

    // Area 3: the dead time of the same output (0x06, 0x07).
    m_deadTime->setDecimals(1);
    // Below the range: "not read", until a value comes from the device.
    m_deadTime->setRange(-0.1, 6553.5);
    m_deadTime->setSpecialValueText(tr("not read"));
    m_deadTime->setValue(-0.1);
    m_deadTime->setSingleStep(0.1);
    m_deadTime->setSuffix(tr(" ms"));
    auto* readDeadTimeButton = new QPushButton(tr("Read dead time (0x06)"));
    auto* writeDeadTimeButton = new QPushButton(tr("Write dead time (0x07)…"));
    auto* deadTimeButtons = new QHBoxLayout;
    deadTimeButtons->addWidget(readDeadTimeButton);
    deadTimeButtons->addWidget(m_deadTime);
    deadTimeButtons->addWidget(writeDeadTimeButton);
    deadTimeButtons->addStretch();
    auto* deadTimeGroup = new QGroupBox(tr("Area 3: dead times (of the output above)"));
    auto* deadTimeLayout = new QVBoxLayout(deadTimeGroup);
    deadTimeLayout->addLayout(deadTimeButtons);
    deadTimeLayout->addWidget(m_deadTimeArea);

    auto* layout = new QVBoxLayout(this);
    layout->addWidget(intro);
    layout->addWidget(statusGroup);
    layout->addWidget(trackGroup, 1);
    layout->addWidget(deadTimeGroup);
    layout->addWidget(m_outcome);

    connect(readStatusButton, &QPushButton::clicked, this, &PlcCouplingPage::readStatus);
    connect(resetButton, &QPushButton::clicked, this, &PlcCouplingPage::resetErrors);
    connect(changeButton, &QPushButton::clicked, this,
            [this, wantedProgram] { changeProgram(wantedProgram->value()); });
    connect(readTrackButton, &QPushButton::clicked, this, &PlcCouplingPage::readTrack);
    connect(writeTrackButton, &QPushButton::clicked, this, &PlcCouplingPage::writeTrack);
    connect(readDeadTimeButton, &QPushButton::clicked, this, &PlcCouplingPage::readDeadTime);
    connect(writeDeadTimeButton, &QPushButton::clicked, this, &PlcCouplingPage::writeDeadTime);
    connect(addCam, &QPushButton::clicked, this, [this] {
        const int row = m_cams->rowCount();
        m_cams->insertRow(row);
        for (int column = 0; column < 2; ++column) {
            auto* item = new QTableWidgetItem;
            item->setData(Qt::EditRole, 0);
            m_cams->setItem(row, column, item);
        }
    });
    connect(removeCam, &QPushButton::clicked, this, [this] {
        if (m_cams->rowCount() > 0)
            m_cams->removeRow(m_cams->currentRow() >= 0 ? m_cams->currentRow()
                                                        : m_cams->rowCount() - 1);
    });
    m_statusArea->setText(tr("Not read yet."));
    m_deadTimeArea->setText(tr("Not read yet."));
}

QString PlcCouplingPage::statusInWords() const {
    return m_statusWords->text();
}

QString PlcCouplingPage::lastOutcome() const {
    return m_outcome->text();
}

void PlcCouplingPage::showFailure(const QString& what, const Error& error) {
    m_outcome->setStyleSheet(QStringLiteral("QLabel { color: #b03a2e; }"));
    m_outcome->setText(tr("%1 failed: %2").arg(what, withoutCommandNames(error.message)));
    Q_EMIT statusMessage(m_outcome->text());
}

void PlcCouplingPage::showOutcome(const usecases::OutcomeLine& line) {
    const bool ok = line.state == usecases::WriteState::Written ||
                    line.state == usecases::WriteState::Unchanged;
    m_outcome->setStyleSheet(ok ? QString() : QStringLiteral("QLabel { color: #b03a2e; }"));
    m_outcome->setText(line.text);
    Q_EMIT statusMessage(line.text);
}

void PlcCouplingPage::showStatus(const ShortStatus& status) {
    // As the function block files the reply into the data block (coupling
    // manual 3.3.8.1): DW10..DW22.
    const QString row = QStringLiteral("%1  %2  %3\n");
    QString area;
    area += row.arg(QStringLiteral("DW 10"), QStringLiteral("ISTWERT  "),
                    QString::number(status.actualValue));
    area += row.arg(QStringLiteral("DW 12"), QStringLiteral("SPEED    "),
                    QString::number(status.speed));
    area += row.arg(QStringLiteral("DW 14"), QStringLiteral("PROG     "),
                    QString::number(status.program));
    area += row.arg(QStringLiteral("DB 16"), QStringLiteral("NSWSTATUS"),
                    QStringLiteral("%1 (%2)")
                        .arg(status.deviceStatus)
                        .arg(comm::table::shortDeviceStatusText(status.deviceStatus)));
    area += row.arg(QStringLiteral("DB 17"), QStringLiteral("AUSANZIST"),
                    QString::number(status.outputCount));
    for (int word = 0; word < 3 && word * 16 < status.outputCount; ++word) {
        area += row.arg(QStringLiteral("DW %1").arg(18 + 2 * word),
                        QStringLiteral("AUSSTAT%1 ").arg(word + 1),
                        tr("outputs %1–%2: %3")
                            .arg(word * 16 + 1)
                            .arg(word * 16 + 16)
                            .arg(outputList(status.outputs, word * 16 + 1, word * 16 + 16)));
    }
    m_statusArea->setText(area.trimmed());
    QStringList on;
    for (int i = 0; i < status.outputs.size(); ++i)
        if (status.outputs.at(i)) on.append(QString::number(i + 1));
    // A snapshot, not a live value: when it was read is part of it.
    m_statusWords->setText(
        tr("Read at %1.").arg(QLocale().toString(QTime::currentTime(), QLocale::ShortFormat)) +
        QLatin1Char(' ') +
        tr("A PLC program reading the status sees: actual value %1, speed %2, program %3 "
           "active, device status %4, %5 outputs, %6. To change the program it writes the "
           "wanted number into DW 34; the function block sends 0x03 while DW 14 and DW 34 "
           "differ.")
            .arg(status.actualValue)
            .arg(status.speed)
            .arg(status.program)
            .arg(comm::table::shortDeviceStatusText(status.deviceStatus))
            .arg(status.outputCount)
            .arg(on.isEmpty() ? tr("none of them on")
                              : tr("on: %1").arg(on.join(QStringLiteral(", ")))));
}

void PlcCouplingPage::readStatus() {
    runOnCamCon<ShortStatus>(
        m_session, this, tr("Read the status (0x01)"),
        withShortCommands<ShortStatus>([](ShortClient& client) { return client.status(); }),
        [this](Result<ShortStatus> status) {
            if (!status) {
                m_statusArea->setText(tr("Not read: the status is unknown."));
                m_statusWords->clear();
                showFailure(tr("Reading the status"), status.error());
                return;
            }
            showStatus(*status);
        });
}

bool PlcCouplingPage::confirmed(const QString& question) {
    // No is the default: Enter alone must not switch a machine's outputs.
    return QMessageBox::question(this, tr("PLC coupling"), question,
                                 QMessageBox::Yes | QMessageBox::No,
                                 QMessageBox::No) == QMessageBox::Yes;
}

void PlcCouplingPage::runCheckedWrite(const QString& title,
                                      std::function<usecases::OutcomeLine(ShortClient&)> write,
                                      std::function<void()> readBack) {
    runOnCamCon<usecases::OutcomeLine>(
        m_session, this, title,
        withShortCommands<usecases::OutcomeLine>(
            [write = std::move(write)](ShortClient& client) -> Result<usecases::OutcomeLine> {
                return write(client);
            }),
        [this, title, readBack](Result<usecases::OutcomeLine> line) {
            if (!line) {
                showFailure(title, line.error());
            } else {
                showOutcome(*line);
            }
            // Written, refused or cut off: show what the device holds now.
            readBack();
        });
}

void PlcCouplingPage::resetErrors() {
    runCheckedWrite(
        tr("Reset the errors (0x02)"),
        [](ShortClient& client) { return usecases::shortResetErrors(client); },
        [this] { readStatus(); });
}

void PlcCouplingPage::changeProgram(int program) {
    if (!confirmed(tr("Switch the CamCon to program %1 (0x03)? Its outputs follow the cams of "
                      "program %1 at once.")
                       .arg(program)))
        return;
    runCheckedWrite(
        tr("Change the program (0x03)"),
        [program](ShortClient& client) { return usecases::shortChangeProgram(client, program); },
        [this] { readStatus(); });
}

Track PlcCouplingPage::trackInTable() const {
    Track track;
    track.output = m_output->value();
    for (int row = 0; row < m_cams->rowCount(); ++row) {
        const auto value = [this, row](int column) {
            const QTableWidgetItem* item = m_cams->item(row, column);
            return item ? item->data(Qt::EditRole).toInt() : 0;
        };
        track.cams.append({qint32(value(0)), qint32(value(1))});
    }
    return track;
}

void PlcCouplingPage::showTrack(const Track& track) {
    m_cams->setRowCount(0);
    for (const Cam& cam : track.cams) {
        const int row = m_cams->rowCount();
        m_cams->insertRow(row);
        for (int column = 0; column < 2; ++column) {
            auto* item = new QTableWidgetItem;
            item->setData(Qt::EditRole, column == 0 ? cam.on : cam.off);
            m_cams->setItem(row, column, item);
        }
    }
    // The rows as the cam table in the data block holds them (3.3.8.2):
    // output number and count as bytes, then on and off points as words.
    QStringList labels;
    for (int i = 1; i <= track.cams.size(); ++i)
        labels << QStringLiteral("DW+%1 EIN_%2 / DW+%3 AUS_%2")
                      .arg(4 * i - 2)
                      .arg(i, 4, 10, QLatin1Char('0'))
                      .arg(4 * i);
    m_cams->setVerticalHeaderLabels(labels);
}

void PlcCouplingPage::readTrack() {
    readTrackOf(m_program->value(), m_output->value(), true);
}

void PlcCouplingPage::readTrackOf(int program, int output, bool sayWhatWasRead) {
    runOnCamCon<Track>(
        m_session, this, tr("Read the cams (0x04)"),
        withShortCommands<Track>(
            [program, output](ShortClient& client) { return client.readTrack(program, output); }),
        [this, program, sayWhatWasRead](Result<Track> track) {
            if (!track) {
                m_cams->setRowCount(0);
                return showFailure(tr("Reading the cams"), track.error());
            }
            showTrack(*track);
            // What the device holds: the cam editor's copy of it learns it too.
            m_workspace->cams()->setDeviceTrack(program, *track);
            if (!sayWhatWasRead) return;
            m_outcome->setStyleSheet(QString());
            m_outcome->setText(tr("Program %1, output %2: %3 cams as a PLC reads them (DB+0 "
                                  "AUSG_NR %2, DB+1 ANZ_NOCKEN %3).")
                                   .arg(program)
                                   .arg(track->output)
                                   .arg(track->cams.size()));
        });
}

void PlcCouplingPage::writeTrack() {
    const int program = m_program->value();
    const Track track = trackInTable();
    if (!confirmed(tr("Replace the cams of output %1 in program %2 by the %3 cams shown "
                      "(0x05)? If program %2 runs, output %1 switches by them at once.")
                       .arg(track.output)
                       .arg(program)
                       .arg(track.cams.size())))
        return;
    runCheckedWrite(
        tr("Write the cams (0x05)"),
        [program, track](ShortClient& client) {
            return usecases::shortWriteTrack(client, program, track);
        },
        [this, program, output = track.output] { readTrackOf(program, output, false); });
}

void PlcCouplingPage::readDeadTime() {
    readDeadTimeOf(m_output->value());
}

void PlcCouplingPage::readDeadTimeOf(int output) {
    runOnCamCon<int>(
        m_session, this, tr("Read the dead time (0x06)"),
        withShortCommands<int>(
            [output](ShortClient& client) { return client.readDeadTime(output); }),
        [this, output](Result<int> tenths) {
            if (!tenths) {
                m_deadTimeArea->setText(tr("Not read: the dead time is unknown."));
                return showFailure(tr("Reading the dead time"), tenths.error());
            }
            m_deadTime->setValue(*tenths / 10.0);
            m_workspace->cams()->setDeviceDeadTime(output, *tenths);
            // Dead-time table (3.3.8.3): one word per output from the offset in
            // DW 2.
            m_deadTimeArea->setText(
                QStringLiteral("DW+%1  TZK%2  %3  (%4)  ")
                    .arg(2 * (output - 1))
                    .arg(output)
                    .arg(*tenths)
                    .arg(millisecondsText(*tenths)) +
                tr("read at %1")
                    .arg(QLocale().toString(QTime::currentTime(), QLocale::ShortFormat)));
        });
}

void PlcCouplingPage::writeDeadTime() {
    const int output = m_output->value();
    const int tenths = qRound(m_deadTime->value() * 10.0);
    if (tenths < 0) {
        m_outcome->setText(tr("Enter the dead time to write first (or read it from the device)."));
        return;
    }
    if (!confirmed(tr("Set the dead time of output %1 to %2 (0x07)? The output switches that "
                      "much earlier from now on.")
                       .arg(output)
                       .arg(millisecondsText(tenths))))
        return;
    runCheckedWrite(
        tr("Write the dead time (0x07)"),
        [output, tenths](ShortClient& client) {
            return usecases::shortWriteDeadTime(client, output, tenths);
        },
        [this, output] { readDeadTimeOf(output); });
}

}  // namespace cambench
