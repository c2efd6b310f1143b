#include "replace_edits_dialog.h"

#include <QButtonGroup>
#include <QDialogButtonBox>
#include <QGridLayout>
#include <QLabel>
#include <QPushButton>
#include <QRadioButton>
#include <QVBoxLayout>

namespace cambench {

QString ReplaceEditsDialog::sectionName(EditSection section) {
    switch (section) {
        case EditSection::Cams:
            return tr("Cam programs");
        case EditSection::OutputSettings:
            return tr("Output names and dead times");
        case EditSection::Settings:
            return tr("Encoder and system settings");
        case EditSection::Users:
            return tr("Users");
        case EditSection::Plc:
            return tr("PLC networks");
    }
    return {};
}

ReplaceEditsDialog::ReplaceEditsDialog(const QMap<EditSection, int>& edits, ValueSource source,
                                       QWidget* parent)
    : QDialog(parent) {
    setObjectName(QStringLiteral("replaceEditsDialog"));
    const bool device = source == ValueSource::Device;
    setWindowTitle(device ? tr("Values read from the device") : tr("Values from the project file"));
    auto* intro =
        new QLabel(device ? tr("The device's values would replace edits that are not written yet. "
                               "For each section: keep your edits, or take the device's values?")
                          : tr("The project's values would replace edits that are not written yet. "
                               "For each section: keep your edits, or take the project's values?"));
    intro->setWordWrap(true);
    auto* grid = new QGridLayout;
    int row = 0;
    for (auto it = edits.cbegin(); it != edits.cend(); ++it, ++row) {
        auto* label =
            new QLabel(tr("%1: %n edit(s)", nullptr, it.value()).arg(sectionName(it.key())));
        auto* keep = new QRadioButton(tr("Keep my edits"));
        auto* take = new QRadioButton(device ? tr("Take the device's values")
                                             : tr("Take the project's values"));
        keep->setChecked(true);
        auto* group = new QButtonGroup(this);
        group->addButton(keep);
        group->addButton(take);
        grid->addWidget(label, row, 0);
        grid->addWidget(keep, row, 1);
        grid->addWidget(take, row, 2);
        auto* details = new QLabel;
        details->setWordWrap(true);
        details->setTextInteractionFlags(Qt::TextSelectableByMouse);
        details->setContentsMargins(16, 0, 0, 6);
        details->hide();
        grid->addWidget(details, ++row, 0, 1, 3);
        m_details.insert(it.key(), details);
        m_keep.insert(it.key(), keep);
        m_take.insert(it.key(), take);
    }
    auto* note =
        new QLabel(device ? tr("Items you did not edit take the device's values either way. "
                               "Taking the device's cam programs can be undone (Edit → Undo).")
                          : tr("Items you did not edit take the project's values either way."));
    note->setWordWrap(true);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
    buttons->button(QDialogButtonBox::Ok)->setText(tr("Apply"));
    buttons->button(QDialogButtonBox::Cancel)->setText(tr("Cancel: change nothing"));
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(intro);
    layout->addLayout(grid);
    layout->addWidget(note);
    layout->addWidget(buttons);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
}

void ReplaceEditsDialog::setDetails(const QMap<EditSection, QStringList>& items) {
    constexpr int kShown = 8;
    for (auto it = items.cbegin(); it != items.cend(); ++it) {
        QLabel* label = m_details.value(it.key());
        if (!label || it.value().isEmpty()) continue;
        QStringList lines = it.value().mid(0, kShown);
        if (it.value().size() > kShown)
            lines << tr("… and %n more", nullptr, int(it.value().size()) - kShown);
        label->setText(lines.join(QLatin1Char('\n')));
        label->show();
    }
}

QString ReplaceEditsDialog::detailsText(EditSection section) const {
    const QLabel* label = m_details.value(section);
    return label ? label->text() : QString();
}

QSet<EditSection> ReplaceEditsDialog::keptSections() const {
    QSet<EditSection> kept;
    for (auto it = m_keep.cbegin(); it != m_keep.cend(); ++it) {
        if (it.value()->isChecked()) kept.insert(it.key());
    }
    return kept;
}

void ReplaceEditsDialog::choose(EditSection section, bool keepEdits) {
    if (QRadioButton* button = (keepEdits ? m_keep : m_take).value(section))
        button->setChecked(true);
}

}  // namespace cambench
