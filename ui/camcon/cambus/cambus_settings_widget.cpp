#include "cambus_settings_widget.h"

#include "cambus_view_widget.h"

#include "comm/camcon/cambus/cambus_protocol.h"
#include "comm/camcon/cambus/cambus_view.h"

#include <QFormLayout>
#include <QSpinBox>

namespace cambench {

CamBusSettingsWidget::CamBusSettingsWidget(QWidget* parent)
    : ProtocolOptionsForm(
          *comm::ProtocolRegistry::instance().find(comm::CamBusProtocolSettings().protocolId()),
          parent),
      m_view(new CamBusView(comm::CamBusMonitor::shared())) {
    // The bus view marks the PC's own number among the users it hears.
    QSpinBox* pcNumber = numberField(QStringLiteral("pc-number"));
    m_view->setOwnNumber([pcNumber] { return pcNumber ? pcNumber->value() : -1; });
    form()->addRow(m_view);
}

}  // namespace cambench
