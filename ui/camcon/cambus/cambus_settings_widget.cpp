#include "cambus_settings_widget.h"

#include "cambus_view_widget.h"

#include "comm/camcon/cambus/cambus_view.h"

#include <QFormLayout>
#include <QSpinBox>

namespace cambench {

CamBusSettingsWidget::CamBusSettingsWidget(QWidget* parent)
    : AsciiSettingsWidget(true, parent), m_view(new CamBusView(comm::CamBusMonitor::shared())) {
    deviceNumber()->setToolTip(tr("The number of the CamCon to talk to on the Cam-BUS (0–63)."));
    pcNumber()->setToolTip(
        tr("This PC's own number on the Cam-BUS (0–63, usually 63). No other user of the bus "
           "(CamCon, display, another PC) may have it."));
    m_view->setOwnNumber([this] { return pcNumber()->value(); });
    if (auto* form = qobject_cast<QFormLayout*>(layout())) form->addRow(m_view);
}

}  // namespace cambench
