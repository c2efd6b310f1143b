#include "settings_page.h"

#include "device_session.h"
#include "report_dialog.h"
#include "setting_field.h"
#include "workspace.h"

#include <QCoreApplication>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QListWidget>
#include <QMessageBox>
#include <QPushButton>
#include <QScrollArea>
#include <QStackedWidget>
#include <QVBoxLayout>

namespace cambench {

namespace {

// "specialEncoder.ssi.resolutionBits" -> "ssi"; plain keys have no subgroup.
QString subgroupOf(const QString& key) {
    const QStringList parts = key.split(QLatin1Char('.'));
    return parts.size() >= 3 ? parts.at(1) : QString();
}

QString subgroupTitle(const QString& subgroup) {
    static const QMap<QString, const char*> titles{
        {QStringLiteral("ssi"), QT_TRANSLATE_NOOP("cambench::SettingsPage", "SSI encoder")},
        {QStringLiteral("parallel"),
         QT_TRANSLATE_NOOP("cambench::SettingsPage", "Parallel encoder")},
        {QStringLiteral("incremental"),
         QT_TRANSLATE_NOOP("cambench::SettingsPage", "Incremental encoder")},
        {QStringLiteral("multiturn"),
         QT_TRANSLATE_NOOP("cambench::SettingsPage", "Multi-turn encoder")},
        {QStringLiteral("multi"),
         QT_TRANSLATE_NOOP("cambench::SettingsPage", "Multi-turn encoder")},
        {QStringLiteral("pll"),
         QT_TRANSLATE_NOOP("cambench::SettingsPage", "PLL (pulse multiplier)")},
        {QStringLiteral("timer"), QT_TRANSLATE_NOOP("cambench::SettingsPage", "Time-based axis")},
    };
    const auto it = titles.constFind(subgroup);
    return it == titles.cend() ? subgroup
                               : QCoreApplication::translate("cambench::SettingsPage", it.value());
}

}  // namespace

QString SettingsPage::groupTitle(const QString& group) {
    static const QMap<QString, const char*> titles{
        {QStringLiteral("encoder"), QT_TR_NOOP("Encoder")},
        {QStringLiteral("adaptation"), QT_TR_NOOP("Actual-value adaptation")},
        {QStringLiteral("speed"), QT_TR_NOOP("Speed")},
        {QStringLiteral("cycle"), QT_TR_NOOP("Cycle and timing")},
        {QStringLiteral("specialOutputs"), QT_TR_NOOP("Special outputs")},
        {QStringLiteral("configuration"), QT_TR_NOOP("Device configuration")},
        {QStringLiteral("configurationPlc"), QT_TR_NOOP("PLC configuration")},
        {QStringLiteral("specialEncoder"), QT_TR_NOOP("Special encoder")},
        {QStringLiteral("analog"), QT_TR_NOOP("Analogue outputs")},
        {QStringLiteral("analogue"), QT_TR_NOOP("Analogue outputs")},
        {QStringLiteral("programSelection"), QT_TR_NOOP("Program selection")},
        {QStringLiteral("display"), QT_TR_NOOP("Display")},
        {QStringLiteral("interface"), QT_TR_NOOP("Interface")},
        {QStringLiteral("identity"), QT_TR_NOOP("Identity")},
        {QStringLiteral("expansion"), QT_TR_NOOP("Expansion modules")},
        {QStringLiteral("language"), QT_TR_NOOP("Language")},
    };
    const auto it = titles.constFind(group);
    return it == titles.cend() ? group : tr(it.value());
}

SettingsPage::SettingsPage(DeviceSession* session, Workspace* workspace, QWidget* parent)
    : SectionPage(parent),
      m_session(session),
      m_workspace(workspace),
      m_groups(new QListWidget),
      m_pages(new QStackedWidget) {
    auto* read = new QPushButton(tr("Read from device"));
    auto* write = new QPushButton(tr("Write changes"));
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(read);
    buttons->addWidget(write);
    buttons->addStretch();

    m_groups->setMaximumWidth(220);
    auto* body = new QHBoxLayout;
    body->addWidget(m_groups);
    body->addWidget(m_pages, 1);

    auto* layout = new QVBoxLayout(this);
    layout->addLayout(buttons);
    layout->addLayout(body, 1);

    buildForm();
    connect(m_groups, &QListWidget::currentRowChanged, m_pages, &QStackedWidget::setCurrentIndex);
    m_groups->setCurrentRow(0);
    connect(read, &QPushButton::clicked, this, &SettingsPage::readFromDevice);
    connect(write, &QPushButton::clicked, this, [this] {
        writeItems({}, [this](const WriteReport& report) {
            Q_EMIT statusMessage(tr("Settings: %1").arg(report.summary()));
            if (!report.complete())
                ReportDialog::presentText(this, QMessageBox::Warning, sectionTitle(),
                                          report.details());
        });
    });
    connect(m_workspace, &Workspace::settingsChanged, this, &SettingsPage::showValues);
    showValues();
}

void SettingsPage::buildForm() {
    // group -> subgroup -> specs, in table order
    QStringList groups;
    QMap<QString, QStringList> subgroups;
    QMap<QString, QList<const SettingSpec*>> specsOf;
    for (const SettingSpec& spec : settingSpecs()) {
        const QString group = QString::fromLatin1(spec.group);
        const QString sub = subgroupOf(QString::fromLatin1(spec.key));
        if (!groups.contains(group)) groups << group;
        if (!subgroups[group].contains(sub)) subgroups[group] << sub;
        specsOf[group + QLatin1Char('/') + sub].append(&spec);
    }
    for (const QString& group : groups) {
        auto* content = new QWidget;
        auto* column = new QVBoxLayout(content);
        for (const QString& sub : subgroups.value(group)) {
            auto* box = new QGroupBox(sub.isEmpty() ? groupTitle(group) : subgroupTitle(sub));
            auto* grid = new QGridLayout(box);
            grid->setColumnStretch(1, 1);
            int row = 0;
            for (const SettingSpec* spec : specsOf.value(group + QLatin1Char('/') + sub)) {
                auto* field = new SettingField(*spec, this);
                grid->addWidget(field->label(), row, 0);
                grid->addWidget(field->editor(), row, 1);
                grid->addWidget(field->rangeLabel(), row, 2);
                ++row;
                const QString key = QString::fromLatin1(spec->key);
                m_fields.insert(key, field);
                m_pageOfKey.insert(key, m_pages->count());
                connect(field, &SettingField::valueEdited, m_workspace, &Workspace::setSetting);
            }
            column->addWidget(box);
        }
        column->addStretch();
        auto* scroll = new QScrollArea;
        scroll->setWidgetResizable(true);
        scroll->setWidget(content);
        m_pages->addWidget(scroll);
        m_groups->addItem(groupTitle(group));
    }
}

void SettingsPage::showSetting(const QString& key) {
    if (m_pageOfKey.contains(key)) m_groups->setCurrentRow(m_pageOfKey.value(key));
}

void SettingsPage::showValues() {
    const SystemSettings& settings = m_workspace->settings();
    const SystemSettings& device = m_workspace->deviceSettings();
    for (auto it = m_fields.cbegin(); it != m_fields.cend(); ++it) {
        const QVariant value = settings.value(it.key());
        if (value.isValid() && value != it.value()->value()) it.value()->setValue(value);
        it.value()->setDeviceValue(device.value(it.key()),
                                   device.contains(it.key()) || !settings.contains(it.key()));
    }
}

void SettingsPage::deviceConnected() {
    readFromDevice();
}

void SettingsPage::readFromDevice() {
    Q_EMIT statusMessage(tr("Reading settings…"));
    m_session->run<SystemSettings>(
        this, tr("Read settings"),
        [](comm::CamConDevice& client, comm::JobContext&) { return client.readSettings(); },
        [this](Result<SystemSettings> result) {
            if (!result) {
                Q_EMIT statusMessage(tr("Reading settings failed: %1").arg(result.error().message));
                return;
            }
            m_workspace->loadSettingsFromDevice(result.value());
            Q_EMIT statusMessage(tr("Settings read."));
        });
}

QList<SectionDifference> SettingsPage::differences() const {
    QList<SectionDifference> list;
    const SystemSettings& device = m_workspace->deviceSettings();
    for (const QString& key : m_workspace->changedSettings()) {
        const SettingSpec* spec = findSetting(key);
        if (!spec) continue;
        list.append({key, SettingField::labelText(*spec),
                     device.contains(key) ? SettingField::displayText(*spec, device.value(key))
                                          : tr("not read"),
                     SettingField::displayText(*spec, m_workspace->settings().value(key))});
    }
    return list;
}

void SettingsPage::writeItems(const QStringList& keys,
                              std::function<void(const WriteReport&)> done) {
    const QStringList changed = m_workspace->changedSettings();
    const QStringList selected = keys.isEmpty() ? changed : keys;
    WriteReport base;
    QList<QPair<QString, SystemSettings>> items;
    for (const QString& key : selected) {
        if (!changed.contains(key)) {
            base.addUnchanged();
            continue;
        }
        const SettingSpec* spec = findSetting(key);
        // A setting travels with its group's other values (composite device
        // commands need them); those are sent as the device has them.
        SystemSettings values;
        for (auto it = m_workspace->deviceSettings().cbegin();
             it != m_workspace->deviceSettings().cend(); ++it) {
            const SettingSpec* other = findSetting(it.key());
            if (spec && other && qstrcmp(other->group, spec->group) == 0 &&
                subgroupOf(it.key()) == subgroupOf(key))
                values.insert(it.key(), it.value());
        }
        values.insert(key, m_workspace->settings().value(key));
        items.append({key, values});
    }
    if (keys.isEmpty()) base.unchanged = int(m_fields.size() - changed.size());
    const QString label = tr("Setting %1");
    const SystemSettings onDevice = m_workspace->deviceSettings();
    m_session->run<ItemOutcomes>(
        this, tr("Write settings"),
        [items, label, onDevice](comm::CamConDevice& client,
                                 comm::JobContext& job) -> Result<ItemOutcomes> {
            ItemOutcomes outcomes;
            int n = 0;
            for (const auto& item : items) {
                job.progress(n++, items.size());
                const Status status = job.cancelled() ? Status(Error::cancelled())
                                                      : client.writeSettings(item.second, onDevice);
                outcomes.append(
                    {item.first, label.arg(item.first), status ? Error{} : status.error()});
            }
            return outcomes;
        },
        [this, base, done](Result<ItemOutcomes> outcomes) {
            WriteReport report = base;
            QStringList written;
            for (ItemOutcome outcome : outcomes.value()) {
                if (const SettingSpec* spec = findSetting(outcome.key))
                    outcome.item = SettingField::labelText(*spec);
                report.add({outcome});
                if (outcome.error.kind == ErrorKind::None) written << outcome.key;
            }
            m_workspace->markSettingsWritten(written);
            done(report);
        });
}

}  // namespace cambench
