#pragma once

#include "workspace.h"

#include "model/camcon/project_file.h"

#include <QList>
#include <QMap>
#include <QSet>

class QWidget;

namespace cambench {

// Sections of the workspace a read or an opened project can replace; the
// user decides for each with edits whether the edits stay.
enum class EditSection { Cams, OutputSettings, Settings, Users, Plc };

// What a project that arrives carries. From the device: the parts and
// programs it has read times for; from a file: everything it names.
struct IncomingParts {
    QList<int> programs;
    bool outputSettings = false;
    bool settings = false;
    bool users = false;
    bool plc = false;
};
IncomingParts partsOf(const Project& incoming, ValueSource source);

// Per section, how many edits the incoming values would replace (sections
// without edits, or not carried, are absent).
QMap<EditSection, int> editsReplacedBy(const Workspace& workspace, const IncomingParts& parts);

// The edits the incoming values would replace, one line per item, naming
// the item, the edit and what arrives ("Program 0, output 3: yours 10–90;
// the device now 10–80, 200–260"), for the sections where items can be
// told: cam programs and output names and dead times.
QMap<EditSection, QStringList> editedItemsReplacedBy(const Workspace& workspace,
                                                     const Project& incoming, ValueSource source);

// Puts the incoming values into the workspace: sections in `keepEdits`
// keep the user's edits, the others take the incoming values (see
// Workspace). From the device, the device copy and its read times follow.
void mergeIncoming(Workspace& workspace, const Project& incoming, ValueSource source,
                   const QSet<EditSection>& keepEdits);

// Where values read from the device differ from the device copy the
// workspace had: one line per item ("Program 0, output 5: 10–90 → 10–80").
// Parts the workspace had not read are not listed.
QStringList deviceChanges(const Workspace& workspace, const Project& incoming);

// Sections of a device read that keep what the person carried from another
// device without asking (read the first time since; see Workspace::carriedFrom).
QSet<EditSection> sectionsAwaitingCarried(const Workspace& workspace, const Project& incoming);

// mergeIncoming, after asking (ReplaceEditsDialog) when edits would be
// replaced. False: the user cancelled, and nothing changed.
bool takeIncoming(QWidget* parent, Workspace& workspace, const Project& incoming,
                  ValueSource source);

}  // namespace cambench
