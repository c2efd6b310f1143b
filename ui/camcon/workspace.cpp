#include "workspace.h"

#include "ui/camcon/cameditor/cam_document.h"

namespace cambench {

Workspace::Workspace(QObject* parent) : DeviceWorkspace(parent), m_cams(new CamDocument(this)) {
    connect(m_cams, &CamDocument::changedCountChanged, this, &Workspace::notifyChanged);
    attachCams(m_cams);
}

Workspace::~Workspace() = default;

}  // namespace cambench
