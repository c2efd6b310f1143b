#include "ui/camcon/cameditor/cam_generator_dialog.h"

#include "ui/camcon/cameditor/cam_document.h"

#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QPushButton>
#include <QRadioButton>
#include <QSpinBox>
#include <QVBoxLayout>

#include <algorithm>
#include <limits>

namespace cambench {

namespace {
constexpr int kPreviewCams = 6;  // cams listed in the preview before "…"
}

CamGeneratorDialog::CamGeneratorDialog(CamDocument* document, int program, int output,
                                       QWidget* parent)
    : QDialog(parent),
      m_document(document),
      m_program(program),
      m_output(output),
      m_start(new QSpinBox(this)),
      m_byLength(new QRadioButton(tr("Fixed &length and pitch"), this)),
      m_byCount(new QRadioButton(tr("&Number of cams and duty cycle"), this)),
      m_length(new QSpinBox(this)),
      m_pitch(new QSpinBox(this)),
      m_count(new QSpinBox(this)),
      m_duty(new QDoubleSpinBox(this)),
      m_preview(new QLabel(this)),
      m_buttons(new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this)) {
    setWindowTitle(tr("Generate Cams for Output %1").arg(output));
    const Axis axis = document->axis();
    const int longest = int(std::min<qint64>(axis.span(), std::numeric_limits<int>::max()));
    m_start->setRange(axis.min, axis.max);
    m_length->setRange(1, longest);
    m_pitch->setRange(2, longest);
    m_count->setRange(1, kMaxCamsPerTrack);
    m_duty->setRange(0.1, 99.9);
    m_duty->setDecimals(1);
    m_duty->setSuffix(tr(" %"));
    m_preview->setWordWrap(true);
    m_preview->setMinimumWidth(fontMetrics().averageCharWidth() * 50);

    auto* form = new QFormLayout;
    form->addRow(tr("&Start position:"), m_start);
    form->addRow(m_byLength);
    form->addRow(tr("Cam l&ength:"), m_length);
    form->addRow(tr("&Pitch:"), m_pitch);
    form->addRow(m_byCount);
    form->addRow(tr("&Count:"), m_count);
    form->addRow(tr("&Duty cycle:"), m_duty);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(new QLabel(tr("The cams replace all cams of output %1.").arg(output), this));
    layout->addWidget(m_preview);
    layout->addWidget(m_buttons);

    const CamGeneratorSettings defaults;
    CamGeneratorSettings initial = defaults;
    initial.start = axis.min;
    // A quarter-turn pattern suits the default rotary range and scales to others.
    initial.pitch = qint32(std::max<qint64>(axis.span() / 4, 2));
    initial.length = std::max(initial.pitch / 2, 1);
    setSettings(initial);

    connect(m_buttons, &QDialogButtonBox::accepted, this, &CamGeneratorDialog::accept);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &CamGeneratorDialog::reject);
    for (QSpinBox* spin : {m_start, m_length, m_pitch, m_count}) {
        connect(spin, &QSpinBox::valueChanged, this, &CamGeneratorDialog::updatePreview);
    }
    connect(m_duty, &QDoubleSpinBox::valueChanged, this, &CamGeneratorDialog::updatePreview);
    connect(m_byLength, &QRadioButton::toggled, this, &CamGeneratorDialog::updatePreview);
    updatePreview();
}

CamGeneratorSettings CamGeneratorDialog::settings() const {
    CamGeneratorSettings settings;
    settings.mode = m_byLength->isChecked() ? CamGeneratorSettings::Mode::LengthAndPitch
                                            : CamGeneratorSettings::Mode::CountAndDuty;
    settings.start = m_start->value();
    settings.length = m_length->value();
    settings.pitch = m_pitch->value();
    settings.count = m_count->value();
    settings.dutyPercent = m_duty->value();
    return settings;
}

void CamGeneratorDialog::setSettings(const CamGeneratorSettings& settings) {
    m_byLength->setChecked(settings.mode == CamGeneratorSettings::Mode::LengthAndPitch);
    m_byCount->setChecked(settings.mode == CamGeneratorSettings::Mode::CountAndDuty);
    m_start->setValue(settings.start);
    m_length->setValue(settings.length);
    m_pitch->setValue(settings.pitch);
    m_count->setValue(settings.count);
    m_duty->setValue(settings.dutyPercent);
    updatePreview();
}

Result<Track> CamGeneratorDialog::generatedTrack() const {
    const Axis axis = m_document->axis();
    Result<QList<Cam>> cams = CamGenerator::generate(settings(), axis.min, axis.max, axis.rotary);
    if (!cams) {
        return cams.error();
    }
    return Track{m_output, cams.value()};
}

void CamGeneratorDialog::updatePreview() {
    const bool byLength = m_byLength->isChecked();
    m_length->setEnabled(byLength);
    m_pitch->setEnabled(byLength);
    m_count->setEnabled(!byLength);
    m_duty->setEnabled(!byLength);

    const Result<Track> track = generatedTrack();
    m_buttons->button(QDialogButtonBox::Ok)->setEnabled(track.ok());
    if (!track) {
        m_preview->setText(track.error().message);
        return;
    }
    QStringList cams;
    for (const Cam& cam : track->cams.mid(0, kPreviewCams)) {
        cams << tr("%1–%2").arg(cam.on).arg(cam.off);
    }
    if (track->cams.size() > kPreviewCams) {
        cams << tr("…");
    }
    m_preview->setText(
        tr("%n cam(s): %1", nullptr, int(track->cams.size())).arg(cams.join(tr(", "))));
}

void CamGeneratorDialog::accept() {
    const Result<Track> track = generatedTrack();
    if (!track) {
        return;
    }
    m_document->generateCams(m_program, track.value());
    QDialog::accept();
}

}  // namespace cambench
