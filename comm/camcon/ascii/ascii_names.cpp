#include "ascii_camcon.h"

#include <QCoreApplication>
#include "ascii_support.h"

namespace cambench::comm {

using namespace client;

Result<DeadTimes> AsciiCamCon::readDeadTimes(int outputs) {
    DeadTimes deadTimes;
    for (int output = 1; output <= outputs; ++output) {
        const Result<Fields> reply =
            m_link.call('?', "TZK", Fields{{"output", wireOutput(output)}});
        if (!reply) {
            return inContext(QCoreApplication::translate(
                                 "cambench::comm", "reading the dead time of output %1 (?TZK)")
                                 .arg(output),
                             reply.error());
        }
        deadTimes.insert(output, qint32(reply->num("value")));
    }
    return deadTimes;
}

Status AsciiCamCon::writeDeadTime(int output, qint32 tenthsMs) {
    const Result<Fields> reply = m_link.call(
        '!', "TZK", Fields{{"output", wireOutput(output)}, {"value", qint64(tenthsMs)}});
    if (!reply) {
        return inContext(QCoreApplication::translate("cambench::comm",
                                                     "writing the dead time of output %1 (!TZK)")
                             .arg(output),
                         reply.error());
    }
    return success();
}

Result<QString> AsciiCamCon::readOutputName(int output) {
    const Result<Fields> reply = m_link.call('?', "ANAME", Fields{{"output", wireOutput(output)}});
    if (!reply) {
        return inContext(
            QCoreApplication::translate("cambench::comm", "reading the name of output %1 (?ANAME)")
                .arg(output),
            reply.error());
    }
    return text(*reply, "text");
}

Status AsciiCamCon::writeOutputName(int output, const QString& name) {
    Fields fields{{"output", wireOutput(output)}};
    fields.setBytes("text", wireText(name));
    const Result<Fields> reply = m_link.call('!', "ANAME", fields);
    if (!reply) {
        return inContext(
            QCoreApplication::translate("cambench::comm", "writing the name of output %1 (!ANAME)")
                .arg(output),
            reply.error());
    }
    return success();
}

Result<QString> AsciiCamCon::readProgramName(int program) {
    const Result<Fields> reply = m_link.call('?', "PNAME", Fields{{"program", qint64(program)}});
    if (!reply) {
        return inContext(
            QCoreApplication::translate("cambench::comm", "reading the name of program %1 (?PNAME)")
                .arg(program),
            reply.error());
    }
    return text(*reply, "text");
}

Status AsciiCamCon::writeProgramName(int program, const QString& name) {
    Fields fields{{"program", qint64(program)}};
    fields.setBytes("text", wireText(name));
    const Result<Fields> reply = m_link.call('!', "PNAME", fields);
    if (!reply) {
        return inContext(
            QCoreApplication::translate("cambench::comm", "writing the name of program %1 (!PNAME)")
                .arg(program),
            reply.error());
    }
    return success();
}

}  // namespace cambench::comm
