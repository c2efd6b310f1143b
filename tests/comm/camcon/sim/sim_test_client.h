#pragma once

#include "comm/camcon/ascii/command_codec.h"
#include "comm/camcon/ascii/stream_decoder.h"
#include "comm/sim/camcon/sim_line.h"

#include <QList>

namespace cambench::comm::test {

// Plays the PC on a SimLine: encodes requests with the catalogue, feeds
// them to the line and decodes what comes back.
class SimTestClient {
public:
    explicit SimTestClient(SimLine& line, int pcNumber = 63);

    // Multiuser destination; each request() takes the next block number.
    void setDevice(int device) { m_device = device; }
    int lastBlock() const { return m_block; }

    // The catalogue request `kind name` with `fields`; the reply checked
    // with matchReply (Unrelated when there was none).
    ReplyMatch call(char kind, const char* name, const Fields& fields = {});

    // Wire bytes of a request with the given block (Multiuser) or none.
    QByteArray requestBytes(char kind, const char* name, const Fields& fields, int block) const;
    QByteArray rawRequest(char lead, const QByteArray& body, int block) const;

    // Decodes reply wire bytes into frames.
    QList<Frame> replies(const QList<SimOutput>& outputs);

    // !EE blocks as the PC sends them.
    ReplyMatch writeBlock(int block, const QByteArray& data);
    // Every block of a backup, ?EE0000 .. until FFFF.
    QList<QByteArray> backup();

private:
    SimLine& m_line;
    StreamDecoder m_decoder;
    int m_pc;
    int m_device = 0;
    int m_block = 0;
};

}  // namespace cambench::comm::test
