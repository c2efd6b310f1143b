#include "camcon_check.h"

#include "camcon_check_parts.h"

#include "comm/camcon/ascii/ascii_camcon.h"
#include "comm/camcon/ascii/catalogue.h"
#include "comm/camcon/table/rk512.h"
#include "comm/camcon/table/table_camcon.h"

#include <QCoreApplication>

namespace cambench::usecases {

namespace {

bool isTableProtocol(const QString& protocolId) {
    return protocolId.startsWith(QLatin1String("3964r"));
}

// Only what reads: an RK512 read telegram (no data) on the table
// interface, a query the catalogue knows in the ASCII protocols (Standard,
// Multiuser, Cam-BUS). Commands, short commands and free text never pass.
QString refuses(const QString& protocolId, const comm::Request& request) {
    const QByteArray& message = request.message;
    bool reads = false;
    if (isTableProtocol(protocolId)) {
        reads = message.size() == comm::table::kRk512RequestHeaderBytes &&
                quint8(message.at(2)) == quint8(comm::table::Rk512Order::Read);
    } else {
        reads = message.startsWith('?') &&
                comm::matchRequest('?', QByteArrayView(message).sliced(1)) != nullptr;
    }
    return reads ? QString() : notReadingRequest(request);
}

Result<QList<CheckResult>> run(comm::DeviceConnection& connection,
                               const UseCaseProgress& progress) {
    if (auto* table = dynamic_cast<comm::table::TableCamCon*>(&connection))
        return camcon_check::tableAreas(*table, progress);
    auto* ascii = dynamic_cast<comm::AsciiCamCon*>(&connection);
    if (!ascii) {
        return Error::usage(QCoreApplication::translate(
                                "cambench::usecases", "There is no check for the protocol %1 yet.")
                                .arg(connection.protocolId()));
    }
    const Result<QList<CheckResult>> queries = camcon_check::catalogueQueries(*ascii, progress);
    if (!queries) return queries;
    QList<CheckResult> results = *queries;
    // Only what the connection's protocol can try: a Standard line has no
    // block numbers and no token to listen to.
    const QString protocol = connection.protocolId();
    Result<QList<CheckResult>> more = QList<CheckResult>();
    if (protocol == QLatin1String("multiuser")) more = camcon_check::multiuserNumbering(*ascii);
    if (protocol == QLatin1String("cambus")) more = camcon_check::camBusTiming(*ascii);
    if (!more) return more.error();
    results << *more;
    return results;
}

}  // namespace

FamilyCheck camconCheck() {
    FamilyCheck check;
    check.refuses = refuses;
    check.run = run;
    return check;
}

}  // namespace cambench::usecases
