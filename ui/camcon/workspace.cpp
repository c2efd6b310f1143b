#include "workspace.h"

#include "ui/camcon/cameditor/cam_document.h"

namespace cambench {

Workspace::Workspace(QObject* parent) : DeviceWorkspace(parent), m_cams(new CamDocument(this)) {
    connect(m_cams, &CamDocument::changedCountChanged, this, &Workspace::notifyChanged);
    // Word 0 of a dead-time mode is the plain dead time the cam section
    // holds: the Dead-time modes page follows it.
    connect(m_cams, &CamDocument::deadTimeChanged, this, &Workspace::deadTimeModesChanged);
    connect(m_cams, &CamDocument::deviceStateChanged, this, &Workspace::deadTimeModesChanged);
    attachCams(m_cams);
}

Workspace::~Workspace() = default;

}  // namespace cambench
