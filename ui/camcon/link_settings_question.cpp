#include "link_settings_question.h"

#include "model/camcon/link_settings.h"

#include <QCheckBox>
#include <QCoreApplication>
#include <QMessageBox>
#include <QPushButton>

namespace cambench {

SystemSettings linkSettingsToAsk(const SystemSettings& wanted, const SystemSettings& onDevice) {
    SystemSettings link;
    for (const QString& key : linkSettingKeys()) {
        if (!wanted.contains(key)) continue;
        const bool same = onDevice.contains(key) &&
                          onDevice.value(key).toLongLong() == wanted.value(key).toLongLong();
        if (!same) link.insert(key, wanted.value(key));
    }
    return link;
}

std::optional<QStringList> askLinkSettings(QWidget* parent, const SystemSettings& link,
                                           const SystemSettings& onDevice) {
    SystemSettings device;
    for (auto it = link.cbegin(); it != link.cend(); ++it) {
        if (onDevice.contains(it.key())) device.insert(it.key(), onDevice.value(it.key()));
    }
    QMessageBox box(
        QMessageBox::Question,
        QCoreApplication::translate("cambench::LinkSettingsQuestion", "Communication settings"),
        QCoreApplication::translate(
            "cambench::LinkSettingsQuestion",
            "The values to write include communication settings: %1 (the device "
            "has %2).")
            .arg(linkSettingsText(link),
                 device.isEmpty()
                     ? QCoreApplication::translate("cambench::LinkSettingsQuestion", "others")
                     : linkSettingsText(device)),
        QMessageBox::NoButton, parent);
    box.setInformativeText(QCoreApplication::translate(
        "cambench::LinkSettingsQuestion",
        "They decide how the device is reached. Written, the next connection to this "
        "device needs them: change the connection settings to match afterwards. Left "
        "out, the device keeps its own and everything else is written."));
    auto* also =
        new QCheckBox(QCoreApplication::translate("cambench::LinkSettingsQuestion", "Also write %1")
                          .arg(linkSettingsText(link)),
                      &box);
    also->setChecked(false);
    box.setCheckBox(also);
    QPushButton* write =
        box.addButton(QCoreApplication::translate("cambench::LinkSettingsQuestion", "Write"),
                      QMessageBox::AcceptRole);
    box.addButton(QMessageBox::Cancel);
    box.setDefaultButton(write);
    box.exec();
    if (box.clickedButton() != write) return std::nullopt;
    return also->isChecked() ? QStringList(link.keys()) : QStringList();
}

}  // namespace cambench
