#pragma once

#include "model/camcon/analogue_cams.h"
#include "model/camcon/programming_program.h"
#include "model/camcon/carry_over.h"

#include <QList>
#include <QMap>
#include <QObject>

#include <optional>

namespace cambench {

struct Project;

// The sections only the table interface has, beside the dead-time modes:
// analogue cams, the programming program and the EEPROM lock, each as the
// device holds it (last read or written) and, where the user or a project
// wants something else, the edit. An edit equal to the device's value is no
// edit. Their pages show and change them here; a saved project holds what is
// shown; Compare with device and the one write path take the edits from here.
class TableSectionCopies : public QObject {
    Q_OBJECT
public:
    using QObject::QObject;

    // --- Analogue cams, key = analogue output 1..14.
    // Edited, else the device's; nullopt when neither is known.
    std::optional<AnalogueCamTrack> analogueCams(int output) const;
    std::optional<AnalogueCamTrack> deviceAnalogueCams(int output) const;
    void editAnalogueCams(const AnalogueCamTrack& track);
    void setDeviceAnalogueCams(const AnalogueCamTrack& track);
    QList<int> changedAnalogueOutputs() const { return m_analogueEdits.keys(); }
    // What a project saved now holds: every output known, as shown.
    QList<AnalogueCamTrack> shownAnalogueCams() const;

    // --- Programming program.
    std::optional<ProgrammingProgram> programmingProgram() const;
    const std::optional<ProgrammingProgram>& deviceProgrammingProgram() const {
        return m_deviceProgramming;
    }
    void editProgrammingProgram(const ProgrammingProgram& programming);
    void setDeviceProgrammingProgram(const ProgrammingProgram& programming);
    bool programmingProgramChanged() const { return m_programmingEdit.has_value(); }

    // --- EEPROM lock (true: locked).
    std::optional<bool> eepromLock() const;
    const std::optional<bool>& deviceEepromLock() const { return m_deviceLock; }
    void editEepromLock(bool locked);
    void setDeviceEepromLock(bool locked);
    bool eepromLockChanged() const { return m_lockEdit.has_value(); }

    // Items that differ from the device (or whose device value is unknown).
    int changedCount() const;
    // A project's sections: edits (from a file) or device copies (from a
    // read of everything, edits stay). Sections the project lacks are left.
    void take(const Project& project, bool fromDevice);
    // Another device, or one without these sections: the device copies
    // mean nothing now; the edits `carry` says stay.
    void forgetDeviceCopies(CarryOver carry = CarryOver::Changes);
    void clear();
    // Drops the edit of one section ("Read from device" on its page).
    void dropAnalogueEdit(int output);
    void dropProgrammingEdit();

Q_SIGNALS:
    void changed();

private:
    // The rules of editAnalogueCams / setDeviceAnalogueCams, without the signal.
    void putAnalogueEdit(const AnalogueCamTrack& track);
    void putDeviceAnalogue(const AnalogueCamTrack& track);

    QMap<int, AnalogueCamTrack> m_deviceAnalogue;
    QMap<int, AnalogueCamTrack> m_analogueEdits;
    std::optional<ProgrammingProgram> m_deviceProgramming;
    std::optional<ProgrammingProgram> m_programmingEdit;
    std::optional<bool> m_deviceLock;
    std::optional<bool> m_lockEdit;
};

}  // namespace cambench
