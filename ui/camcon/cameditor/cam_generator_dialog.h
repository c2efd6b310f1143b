#pragma once

#include "model/camcon/cam_program.h"
#include "ui/camcon/cameditor/cam_generator.h"

#include <QDialog>

class QDialogButtonBox;
class QDoubleSpinBox;
class QLabel;
class QRadioButton;
class QSpinBox;

namespace cambench {

class CamDocument;

// The multi-cam generator: the user picks a start and either length and
// pitch or count and duty; the preview shows what will be made. accept()
// replaces the track through one undo command on the document.
class CamGeneratorDialog : public QDialog {
    Q_OBJECT

public:
    CamGeneratorDialog(CamDocument* document, int program, int output, QWidget* parent = nullptr);

    CamGeneratorSettings settings() const;
    void setSettings(const CamGeneratorSettings& settings);
    // The track the current settings produce, or why there is none.
    Result<Track> generatedTrack() const;

public Q_SLOTS:
    void accept() override;

private:
    void updatePreview();

    CamDocument* m_document;
    int m_program;
    int m_output;
    QSpinBox* m_start;
    QRadioButton* m_byLength;
    QRadioButton* m_byCount;
    QSpinBox* m_length;
    QSpinBox* m_pitch;
    QSpinBox* m_count;
    QDoubleSpinBox* m_duty;
    QLabel* m_preview;
    QDialogButtonBox* m_buttons;
};

}  // namespace cambench
