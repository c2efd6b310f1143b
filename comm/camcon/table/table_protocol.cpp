#include "table_protocol.h"

#include "table_camcon.h"

#include <QCoreApplication>

namespace cambench::comm {

namespace {

using table::Rk512Variant;

ProtocolInfo tableProtocol(Rk512Variant variant) {
    const table::Rk512VariantInfo& variantInfo = table::rk512VariantInfo(variant);
    ProtocolInfo info;
    info.id = tableProtocolId(variant);
    info.title =
        QCoreApplication::translate("cambench::comm", "CamCon table interface, %1 (%2 8%3%4)")
            .arg(QLatin1String(variantInfo.name))
            .arg(variantInfo.baudRate)
            .arg(QChar::fromLatin1(variantInfo.parity))
            .arg(1);
    info.choiceTitle =
        variant == Rk512Variant::N96
            ? QT_TRANSLATE_NOOP("cambench::comm", "Table interface, 3964R n96 (9600 8N1)")
            : QT_TRANSLATE_NOOP("cambench::comm", "Table interface, 3964R e38 (38400 8E1)");
    info.defaultSerial.baud = variantInfo.baudRate;
    info.defaultSerial.parity = variantInfo.parity;
    info.makeSettings = [variant] { return std::make_unique<TableProtocolSettings>(variant); };
    info.connect = [](Transport& transport, const ProtocolSettings& settings,
                      const LineTiming& line) -> Result<std::unique_ptr<DeviceConnection>> {
        const auto* table = dynamic_cast<const TableProtocolSettings*>(&settings);
        if (!table)
            return Error::usage(
                QCoreApplication::translate("cambench::comm",
                                            "the %1 protocol got settings of another protocol")
                    .arg(settings.protocolId()));
        return std::unique_ptr<DeviceConnection>(
            std::make_unique<table::TableCamCon>(transport, table->table, line));
    };
    return info;
}

}  // namespace

QString tableProtocolId(Rk512Variant variant) {
    return variant == Rk512Variant::E38 ? QStringLiteral("3964r-e38") : QStringLiteral("3964r-n96");
}

QString TableProtocolSettings::protocolId() const {
    return tableProtocolId(table.variant);
}

std::unique_ptr<ProtocolSettings> TableProtocolSettings::clone() const {
    return std::make_unique<TableProtocolSettings>(*this);
}

QVariantMap TableProtocolSettings::toMap() const {
    return {{QStringLiteral("timeoutMs"), table.timeoutMs},
            {QStringLiteral("retries"), table.retries}};
}

void TableProtocolSettings::fromMap(const QVariantMap& map) {
    table.timeoutMs = qMax(0, map.value(QStringLiteral("timeoutMs"), table.timeoutMs).toInt());
    table.retries = qBound(0, map.value(QStringLiteral("retries"), table.retries).toInt(), 10);
}

QList<ProtocolInfo> camconTableProtocols() {
    return {tableProtocol(Rk512Variant::N96), tableProtocol(Rk512Variant::E38)};
}

}  // namespace cambench::comm
