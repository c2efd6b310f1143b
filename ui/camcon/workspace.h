#pragma once

#include "model/camcon/device_workspace.h"

namespace cambench {

class CamDocument;

// The workspace of model/camcon/device_workspace.h with its cam section:
// the cam editor's document, whose edits are undo commands (QUndoStack is
// QtGui, so the document is the GUI's).
class Workspace : public DeviceWorkspace {
    Q_OBJECT
public:
    explicit Workspace(QObject* parent = nullptr);
    ~Workspace() override;

    CamDocument* cams() const { return m_cams; }

private:
    CamDocument* m_cams;
};

}  // namespace cambench
