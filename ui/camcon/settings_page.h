#pragma once

#include "ui/camcon/camcon_section_page.h"

#include <QMap>

class QListWidget;
class QStackedWidget;

namespace cambench {

class DeviceSession;
class SettingField;
class Workspace;

// Encoder and system settings: a form generated from settingSpecs(), one
// page per group; dotted keys ("specialEncoder.ssi.…") get a box per
// encoder type on their group's page.
class SettingsPage : public CamConSectionPage {
    Q_OBJECT
public:
    SettingsPage(DeviceSession* session, Workspace* workspace, QWidget* parent = nullptr);

    QString sectionTitle() const override { return tr("Encoder & system"); }
    QList<SectionDifference> differences() const override;
    int itemCount() const override;
    void writeChanges(std::function<void(const WriteResult&)> done = {});

    void readFromDevice();
    SettingField* field(const QString& key) const { return m_fields.value(key); }
    // Shows the page that holds `key` (for the screenshots and tests).
    void showSetting(const QString& key);

    static QString groupTitle(const QString& group);

private:
    void buildForm();
    void showValues();

    DeviceSession* m_session;
    Workspace* m_workspace;
    QListWidget* m_groups;
    QStackedWidget* m_pages;
    QMap<QString, SettingField*> m_fields;
    QMap<QString, int> m_pageOfKey;
};

}  // namespace cambench
