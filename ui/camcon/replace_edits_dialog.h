#pragma once

#include "ui/camcon/incoming_values.h"

#include <QDialog>
#include <QMap>
#include <QSet>

class QLabel;
class QRadioButton;

namespace cambench {

// Asked before values from the device or a project replace unwritten
// edits: per section, keep the edits or take the incoming values; or
// cancel, and nothing changes. Keeping is the default: nothing the user
// did is lost by pressing Enter.
class ReplaceEditsDialog : public QDialog {
    Q_OBJECT
public:
    ReplaceEditsDialog(const QMap<EditSection, int>& edits, ValueSource source,
                       QWidget* parent = nullptr);

    QSet<EditSection> keptSections() const;
    // Names the edited items of each section, with what arrives in their
    // place, below the section (the first few; the rest counted).
    void setDetails(const QMap<EditSection, QStringList>& items);
    QString detailsText(EditSection section) const;
    // For tests and keyboard users: choose for one section.
    void choose(EditSection section, bool keepEdits);
    QList<EditSection> sections() const { return m_keep.keys(); }

    static QString sectionName(EditSection section);

private:
    QMap<EditSection, QRadioButton*> m_keep;
    QMap<EditSection, QRadioButton*> m_take;
    QMap<EditSection, QLabel*> m_details;
};

}  // namespace cambench
