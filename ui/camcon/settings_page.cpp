#include "settings_page.h"

#include "device_reads.h"
#include "setting_field.h"
#include "ui/device_session.h"
#include "workspace.h"

#include <QCoreApplication>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QListWidget>
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
    : CamConSectionPage(parent),
      m_session(session),
      m_workspace(workspace),
      m_groups(new QListWidget),
      m_pages(new QStackedWidget) {
    QHBoxLayout* buttons =
        readWriteBar(ReadWriteBar([this] { readFromDevice(); }, [this] { writeChanges(); }));

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
                connect(field, &SettingField::valueEdited, m_workspace,
                        [this](const QString& key, const QVariant& value) {
                            m_workspace->settings().edit(key, value);
                        });
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
    const SystemSettings settings = m_workspace->settings().shown();
    const SystemSettings& device = m_workspace->settings().device();
    for (auto it = m_fields.cbegin(); it != m_fields.cend(); ++it) {
        const QVariant value = settings.value(it.key());
        if (value.isValid() && value != it.value()->value()) it.value()->setValue(value);
        it.value()->setDeviceValue(device.value(it.key()),
                                   device.contains(it.key()) || !settings.contains(it.key()));
    }
}

void SettingsPage::readFromDevice() {
    devicereads::readSettings(this, m_session, m_workspace,
                              reportRead(
                                  tr("Reading settings…"), [] { return tr("Settings read."); },
                                  tr("Reading settings failed: %1")));
}

int SettingsPage::itemCount() const {
    return int(m_workspace->settings().shown().size());
}

QList<SectionDifference> SettingsPage::differences() const {
    QList<SectionDifference> list;
    const SystemSettings& device = m_workspace->settings().device();
    for (const QString& key : m_workspace->settings().changedKeys()) {
        const SettingSpec* spec = findSetting(key);
        if (!spec) continue;
        list.append({WorkspaceItem::setting(key), SettingField::labelText(*spec),
                     device.contains(key) ? SettingField::displayText(*spec, device.value(key))
                                          : tr("not read"),
                     SettingField::displayText(
                         *spec, m_workspace->settings().value(key).value_or(QVariant()))});
    }
    return list;
}

void SettingsPage::writeChanges(std::function<void(const WriteResult&)> done) {
    writeDifferences(m_session, m_workspace, std::move(done));
}

}  // namespace cambench
