#include "device_change_dialog.h"

#include "cam_text.h"
#include "plc_page.h"
#include "setting_field.h"
#include "workspace.h"

#include "ui/camcon/cameditor/cam_document.h"

#include <QCoreApplication>
#include <QDialogButtonBox>
#include <QLabel>
#include <QLocale>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QRadioButton>
#include <QVBoxLayout>

namespace cambench {

namespace {

QString tenths(qint32 value) {
    return QLocale().toString(value / 10.0, 'f', 1);
}

// The changed cam items: tracks, program names, output names, dead times.
void addCamChanges(const Workspace& workspace, const QString& from, QStringList& lines) {
    const CamDocument* cams = workspace.cams();
    for (const TrackDifference& d : cams->differences()) {
        lines << (d.deviceKnown
                      ? QCoreApplication::translate("cambench::DeviceChange",
                                                    "Program %1, output %2: %3 (read from %4: %5)")
                            .arg(d.program)
                            .arg(d.output)
                            .arg(camsText(d.editedTrack), from, camsText(d.deviceTrack))
                      : QCoreApplication::translate(
                            "cambench::DeviceChange",
                            "Program %1, output %2: %3 (not read from a device)")
                            .arg(d.program)
                            .arg(d.output)
                            .arg(camsText(d.editedTrack)));
    }
    for (int program : cams->editedPrograms()) {
        const std::optional<CamProgram> device = cams->deviceProgram(program);
        const QString name = cams->programName(program);
        if (device ? device->name != name : !name.isEmpty())
            lines << QCoreApplication::translate("cambench::DeviceChange",
                                                 "Program %1 name: \"%2\"")
                         .arg(program)
                         .arg(name);
    }
    for (int output = 1; output <= workspace.info().outputs; ++output) {
        const std::optional<QString> deviceName = cams->deviceOutputName(output);
        if (cams->outputName(output) != deviceName.value_or(QString()))
            lines << QCoreApplication::translate("cambench::DeviceChange", "Output %1 name: \"%2\"")
                         .arg(output)
                         .arg(cams->outputName(output));
        const std::optional<qint32> deviceTime = cams->deviceDeadTime(output);
        if (cams->deadTime(output) != deviceTime.value_or(0))
            lines << QCoreApplication::translate("cambench::DeviceChange",
                                                 "Output %1 dead time: %2 ms")
                         .arg(output)
                         .arg(tenths(cams->deadTime(output)));
    }
}

// The changed items of the other sections.
void addSectionChanges(const Workspace& workspace, QStringList& lines) {
    for (const QString& key : workspace.settings().changedKeys()) {
        const SettingSpec* spec = findSetting(key);
        lines << QCoreApplication::translate("cambench::DeviceChange", "Setting: %1")
                     .arg(spec ? SettingField::labelText(*spec) : key);
    }
    if (workspace.users().changedCount() > 0)
        lines << QCoreApplication::translate("cambench::DeviceChange", "Users: %1 changed")
                     .arg(workspace.users().changedCount());
    for (int key : workspace.plc().changedKeys())
        lines << QCoreApplication::translate("cambench::DeviceChange", "PLC network %1")
                     .arg(PlcPage::networkName(key >> 8, key & 0xFF));
    for (int output : workspace.deadTimeModes().changedKeys())
        lines << QCoreApplication::translate("cambench::DeviceChange", "Output %1 dead-time mode")
                     .arg(output);
    for (int output : workspace.analogueCams().changedKeys())
        lines << QCoreApplication::translate("cambench::DeviceChange", "Analogue output %1 cams")
                     .arg(output);
    if (workspace.programmingProgram().isChanged())
        lines << QCoreApplication::translate("cambench::DeviceChange", "Programming program");
    if (workspace.eepromLock().isChanged())
        lines << QCoreApplication::translate("cambench::DeviceChange", "EEPROM lock");
}

}  // namespace

QString deviceName(const DeviceInfo& info) {
    // The programmed cams tell apart two devices of the same firmware.
    return QCoreApplication::translate("cambench::DeviceChange",
                                       "CamCon %1, device %2, %3 cams programmed")
        .arg(info.epromDate)
        .arg(info.deviceNumber)
        .arg(info.programmedCams);
}

QStringList personsChanges(const Workspace& workspace) {
    QStringList lines;
    const QString from = workspace.copiesFrom()
                             ? deviceName(*workspace.copiesFrom())
                             : QCoreApplication::translate("cambench::DeviceChange", "the device");
    addCamChanges(workspace, from, lines);
    addSectionChanges(workspace, lines);
    return lines;
}

DeviceChangeDialog::DeviceChangeDialog(const QString& oldDevice, const QString& newDevice,
                                       const QStringList& changes, QWidget* parent)
    : QDialog(parent) {
    setObjectName(QStringLiteral("deviceChangeDialog"));
    setWindowTitle(tr("Another device answers"));
    // The two devices are named once, here; the options speak of "the new"
    // and "the old device" so that each fits on a line (a radio button's
    // text does not wrap, and the German names made the dialog wider than
    // the screen).
    auto* intro = new QLabel(
        tr("Another device answers.<br>New device, on the line now: <b>%1</b><br>Old device, "
           "the values shown were read from it: <b>%2</b><br>You changed %3 of those values. "
           "What shall the new device's values be?")
            .arg(newDevice.toHtmlEscaped(), oldDevice.toHtmlEscaped())
            .arg(changes.size()));
    intro->setTextFormat(Qt::RichText);
    intro->setWordWrap(true);
    m_options.insert(
        CarryOver::Nothing,
        new QRadioButton(tr("Take the new device's values (your changes are dropped)")));
    m_options.insert(
        CarryOver::Changes,
        new QRadioButton(tr("Keep my changes, each applied to the new device's values")));
    m_options.insert(
        CarryOver::Everything,
        new QRadioButton(tr("Copy the old device's programs and sections (with your "
                            "changes): written to the new device only when you write")));
    m_options.value(CarryOver::Nothing)->setChecked(true);
    auto* list = new QPlainTextEdit;
    list->setReadOnly(true);
    m_changesText = changes.join(QLatin1Char('\n'));
    list->setPlainText(m_changesText);
    auto* listLabel = new QLabel(tr("Your changes:"));
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(intro);
    for (QRadioButton* option : m_options) layout->addWidget(option);
    layout->addWidget(listLabel);
    layout->addWidget(list);
    layout->addWidget(buttons);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
}

CarryOver DeviceChangeDialog::choice() const {
    for (auto it = m_options.cbegin(); it != m_options.cend(); ++it) {
        if ((*it)->isChecked()) return it.key();
    }
    return CarryOver::Changes;
}

void DeviceChangeDialog::choose(CarryOver carry) {
    m_options.value(carry)->setChecked(true);
}

void DeviceChangeDialog::reject() {
    // Closed without an answer: nothing the person did is lost, and
    // nothing of the old device becomes theirs.
    choose(CarryOver::Changes);
    QDialog::reject();
}

}  // namespace cambench
