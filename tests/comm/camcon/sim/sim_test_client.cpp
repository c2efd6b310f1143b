#include "sim_test_client.h"

namespace cambench::comm::test {

SimTestClient::SimTestClient(SimLine& line, int pcNumber)
    : m_line(line), m_decoder(line.framing(), QByteArrayLiteral(":")), m_pc(pcNumber) {}

QByteArray SimTestClient::rawRequest(char lead, const QByteArray& body, int block) const {
    Frame frame;
    frame.lead = lead;
    frame.body = body;
    if (m_line.framing() == Framing::Multiuser)
        frame.address = MultiuserAddress{m_pc, m_device, block};
    return encodeFrame(frame);
}

QByteArray SimTestClient::requestBytes(char kind, const char* name, const Fields& fields,
                                       int block) const {
    const CommandSpec* spec = findCommand(kind, name);
    if (!spec) return {};
    const Result<QByteArray> body = encodeRequestBody(*spec, fields);
    return body ? rawRequest(kind, *body, block) : QByteArray();
}

QList<Frame> SimTestClient::replies(const QList<SimOutput>& outputs) {
    QList<Frame> frames;
    for (const SimOutput& output : outputs) {
        for (const DecodeEvent& event : m_decoder.feed(output.bytes)) {
            if (event.kind == DecodeEvent::FrameOk) frames.append(event.frame);
        }
    }
    return frames;
}

ReplyMatch SimTestClient::call(char kind, const char* name, const Fields& fields) {
    m_block = (m_block + 1) % 64;
    const QList<Frame> frames = replies(m_line.feed(requestBytes(kind, name, fields, m_block)));
    const CommandSpec* spec = findCommand(kind, name);
    if (frames.isEmpty() || !spec) return {};
    return matchReply(*spec, frames.first());
}

ReplyMatch SimTestClient::writeBlock(int block, const QByteArray& data) {
    Fields fields;
    fields.set("block", block).setBytes("data", data);
    return call(kCommand, "EE", fields);
}

QList<QByteArray> SimTestClient::backup() {
    QList<QByteArray> blocks;
    for (int number = 0; number < 0xFFFF; ++number) {
        Fields request;
        request.set("block", number);
        const ReplyMatch reply = call(kQuery, "EE", request);
        if (reply.kind != ReplyMatch::Matches || reply.fields.num("block") == 0xFFFF) break;
        blocks.append(reply.fields.bytes("data"));
    }
    return blocks;
}

}  // namespace cambench::comm::test
