#pragma once

#include "model/camcon/cam_axis.h"
#include "model/camcon/cam_program.h"
#include "model/camcon/cam_section.h"
#include "model/camcon/cam_validation.h"
#include "model/camcon/carry_over.h"
#include "model/camcon/dead_times.h"
#include "model/camcon/device_info.h"

#include <QList>
#include <QMap>
#include <QObject>
#include <QSet>
#include <QString>

#include <optional>

class QUndoStack;

namespace cambench {

// Where an edited item stands relative to the device.
enum class ChangeState {
    Unchanged,  // equal to what was last read from or written to the device
    Edited,     // differs from the device copy, not yet written
    NotRead,    // the device copy of this program is unknown (never read)
};

// One line of "Compare with device".
struct TrackDifference {
    int program = 0;
    int output = 1;
    bool deviceKnown = false;  // false: the program was never read from the device
    Track deviceTrack;
    Track editedTrack;
};

// The edited state of one device's cam programs, beside the device copy (what
// was last read from or written to the device). Every user change goes
// through undo commands on undoStack(); the apply*() setters are for those
// commands only. Nothing here talks to the device: the shell reads and
// writes, then calls loadProgramFromDevice(), setDeviceProgram() or setDeviceTrack().
class CamDocument : public QObject, public CamSection {
    Q_OBJECT

public:
    explicit CamDocument(QObject* parent = nullptr);
    ~CamDocument() override;

    // Limits of the device (IMIN..IMAX, outputs, programs) and the axis kind.
    void setLimits(const DeviceInfo& info, bool rotary) override;
    const DeviceInfo& deviceInfo() const { return m_info; }
    bool isRotary() const override { return m_rotary; }
    qint32 minPosition() const { return m_info.minPosition; }
    qint32 maxPosition() const { return m_info.maxPosition; }
    Axis axis() const { return {m_info.minPosition, m_info.maxPosition, m_rotary}; }
    int outputCount() const { return m_info.outputs; }
    int programCount() const { return m_info.programs; }

    CamProgram program(int number) const;
    Track track(int program, int output) const;
    QString programName(int program) const;
    QString outputName(int output) const;
    qint32 deadTime(int output) const;  // 0.1 ms steps
    const Names& names() const override { return m_names; }
    const DeadTimes& deadTimes() const override { return m_deadTimes; }
    // The user's minimum pulse per output (0.1 ms) for the timing check:
    // kept on this PC and in the project file, never written to a device.
    const MinimumPulses& minimumPulses() const { return m_minimumPulses; }
    void setMinimumPulse(int output, qint32 tenths);
    void setMinimumPulses(const MinimumPulses& pulses);

    // Values that arrive: from the device (also the new device copy) or
    // from a file (edited state only). With `keepEdits` a track, name or
    // dead time the user edited keeps the edit and the rest takes the new
    // value; without, everything does. Edits replaced are one undo step.
    void mergeProgram(const CamProgram& program, bool fromDevice, bool keepEdits);
    // Forgets everything: edits, device copies, undo history (a new project).
    void clear() override;
    void mergeOutputSettings(const QMap<int, QString>& outputNames, const DeadTimes& deadTimes,
                             bool fromDevice, bool keepEdits) override;
    void mergeDeadTime(int output, qint32 deadTime, bool fromDevice, bool keepEdits) override;
    // Takes the device's program / output settings as device copy and
    // edited state (mergeProgram from the device, not keeping edits).
    void loadProgramFromDevice(const CamProgram& program) { mergeProgram(program, true, false); }
    void loadOutputSettingsFromDevice(const QMap<int, QString>& outputNames,
                                      const DeadTimes& deadTimes) {
        mergeOutputSettings(outputNames, deadTimes, true, false);
    }
    // Whether the program holds anything not on the device (edits, or
    // content of a program not read).
    bool programEdited(int program) const;
    int outputSettingsEditCount() const override;
    // Only the device copy ("keep mine"): edits stay and now compare with it.
    void setDeviceProgram(const CamProgram& program);
    // After a write: what the device holds now, item by item. A track or a
    // program name of a program whose device copy is unknown stays unknown.
    void setDeviceTrack(int program, const Track& track);
    void setDeviceProgramName(int program, const QString& name);
    void setDeviceDeadTime(int output, qint32 deadTime) override;
    void setDeviceOutputName(int output, const QString& name);
    // One track's state on the device is no longer known (its write was cut
    // off): that output shows "not read" and is written again; the rest of
    // the program keeps what the device was seen to hold.
    void forgetDeviceTrack(int program, int output);
    bool deviceTrackKnown(int program, int output) const;
    // Another device is on the line: no device copy is the device's state
    // any more, and what was only shown as read from the old device is not
    // the person's: it goes, so that it is neither shown nor written as this
    // device's values or as an edit. What stays (`carry`) is "carried": each
    // such track, program name, output name and dead time, and only those,
    // keeps its value over the new device's when that is read (mergeProgram,
    // mergeOutputSettings with keepEdits). The undo history goes with the
    // values it was made on.
    void forgetDeviceCopies(CarryOver carry = CarryOver::Changes) override;
    std::optional<CamProgram> deviceProgram(int program) const;
    std::optional<Track> deviceTrack(int program, int output) const;
    bool outputSettingsKnown() const override { return m_outputSettingsKnown; }
    std::optional<qint32> deviceDeadTime(int output) const override;
    std::optional<QString> deviceOutputName(int output) const override;
    bool hasDeviceCopy(int program) const { return m_device.contains(program); }
    QList<int> editedPrograms() const { return m_edited.keys(); }

    ChangeState programState(int program) const;
    ChangeState trackState(int program, int output) const;
    ChangeState camState(int program, int output, int index) const;
    // An output's name and dead time against the device's copy (NotRead
    // while the device's output settings were not read).
    ChangeState outputNameState(int output) const;
    ChangeState deadTimeState(int output) const;
    QList<TrackDifference> differences() const;
    // What is wrong with a track of the edited state (model/cam_validation.h).
    QList<CamProblem> problems(int program, int output) const;
    // A cam for "Add cam": the first gap on the track that takes a cam of
    // 1/36 of the axis without a problem, else one at IMIN (shown in error).
    Cam suggestNewCam(int program, int output) const;
    // Tracks, program names, output names and dead times that differ from
    // the device (for the window title).
    int changedCount() const override;

    QUndoStack* undoStack() const { return m_undoStack; }
    // A key no other edit uses: all setCam() calls with it merge into one
    // undo command (one per drag in the diagram).
    quint64 newDragKey();

    // User edits: each pushes one undo command.
    void setCam(int program, int output, int index, const Cam& cam, quint64 mergeKey = 0);
    void insertCam(int program, int output, const Cam& cam);
    void deleteCam(int program, int output, int index);
    void replaceTrack(int program, const Track& track, const QString& text);
    void copyTrack(int program, int fromOutput, int toProgram, int toOutput);
    void copyProgram(int from, int to);
    void generateCams(int program, const Track& track);
    // Replaces every track of a program (CSV import), keeping its name.
    void replaceTracks(int program, const QMap<int, Track>& tracks, const QString& text);
    void setProgramName(int program, const QString& name);
    void setOutputName(int output, const QString& name);
    void setDeadTime(int output, qint32 deadTime) override;

    // For the undo commands: change state without recording undo.
    void applyTrack(int program, const Track& track);
    void applyProgram(const CamProgram& program);
    void applyProgramName(int program, const QString& name);
    void applyOutputName(int output, const QString& name);
    void applyDeadTime(int output, qint32 deadTime);

    // Cams on a track are kept ordered by switch-on point.
    static Track normalized(Track track);
    static CamProgram normalized(CamProgram program);

Q_SIGNALS:
    void limitsChanged();
    void trackChanged(int program, int output);
    void programChanged(int program);  // name, or every track at once
    void outputNameChanged(int output);
    void deadTimeChanged(int output);
    void minimumPulsesChanged();
    // The device copy changed (read or written): change markers must follow.
    void deviceStateChanged();
    void changedCountChanged(int count);

private:
    void notifyChangedCount();

    DeviceInfo m_info;
    bool m_rotary = true;
    QMap<int, CamProgram> m_edited;
    QMap<int, CamProgram> m_device;
    Names m_names;  // edited output names; program names live in CamProgram
    DeadTimes m_deadTimes;
    MinimumPulses m_minimumPulses;
    QMap<int, QString> m_deviceOutputNames;
    DeadTimes m_deviceDeadTimes;
    // Tracks of read programs whose state on the device is unknown (key
    // trackKey()).
    QSet<quint32> m_unknownTracks;
    static quint32 trackKey(int program, int output) {
        return (quint32(program) << 16) | quint32(output);
    }
    void forgetUnknownTracks(int program);
    // Whether the item stays over what the device holds (see forgetDeviceCopies).
    bool carriedTrack(int program, int output) const;
    bool carryEdits(int program) const;
    // Items carried from another device (forgetDeviceCopies), dropped once
    // the new device's value of the item was read.
    QSet<quint32> m_carriedTracks;
    QSet<int> m_carriedProgramNames;
    QSet<int> m_carriedOutputNames;
    QSet<int> m_carriedDeadTimes;
    bool m_outputSettingsKnown = false;
    QUndoStack* m_undoStack = nullptr;
    quint64 m_lastDragKey = 0;
    int m_lastChangedCount = 0;
};

}  // namespace cambench
