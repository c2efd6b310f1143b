#include "pty_device.h"

#include "comm/camcon/ascii/stream_decoder.h"

#include <fcntl.h>
#include <poll.h>
#include <pty.h>
#include <termios.h>
#include <unistd.h>

#include <chrono>

namespace cambench::comm::test {

PtyDevice::PtyDevice(Framing framing, Script script)
    : m_framing(framing), m_script(std::move(script)) {
    char name[256] = {};
    if (openpty(&m_master, &m_slave, name, nullptr, nullptr) != 0) {
        m_master = m_slave = -1;
        return;
    }
    termios raw{};
    tcgetattr(m_master, &raw);
    cfmakeraw(&raw);
    tcsetattr(m_master, TCSANOW, &raw);
    m_slavePath = QString::fromLocal8Bit(name);
    m_thread = std::thread([this] { run(); });
}

PtyDevice::~PtyDevice() {
    m_stop = true;
    if (m_thread.joinable()) m_thread.join();
    if (m_master >= 0) ::close(m_master);
    if (m_slave >= 0) ::close(m_slave);
}

QList<Frame> PtyDevice::requests() const {
    std::lock_guard lock(m_mutex);
    return m_requests;
}

int PtyDevice::requestCount() const {
    std::lock_guard lock(m_mutex);
    return int(m_requests.size());
}

void PtyDevice::writeAll(const QByteArray& bytes) {
    qsizetype done = 0;
    while (done < bytes.size()) {
        const ssize_t n = ::write(m_master, bytes.constData() + done, size_t(bytes.size() - done));
        if (n <= 0) return;
        done += n;
    }
}

void PtyDevice::run() {
    StreamDecoder decoder(m_framing, QByteArray("?!"));
    while (!m_stop) {
        pollfd pfd{m_master, POLLIN, 0};
        if (::poll(&pfd, 1, 20) <= 0 || !(pfd.revents & POLLIN)) continue;
        char buffer[512];
        const ssize_t n = ::read(m_master, buffer, sizeof buffer);
        if (n <= 0) continue;
        for (const DecodeEvent& event : decoder.feed(QByteArrayView(buffer, n))) {
            if (event.kind != DecodeEvent::FrameOk) continue;
            int index = 0;
            {
                std::lock_guard lock(m_mutex);
                index = int(m_requests.size());
                m_requests.append(event.frame);
            }
            const DeviceAction action = m_script(event.frame, index);
            for (const QByteArray& chunk : action.chunks) {
                if (action.chunkDelayMs > 0)
                    std::this_thread::sleep_for(std::chrono::milliseconds(action.chunkDelayMs));
                writeAll(chunk);
            }
            if (action.hangUp) {
                ::close(m_master);
                m_master = -1;
                m_hungUp = true;
                return;
            }
        }
    }
}

QByteArray replyFrom(const Frame& request, const QByteArray& body, int device, int block) {
    Frame reply{kReply, body, std::nullopt, true};
    if (request.address) reply.address = MultiuserAddress{device, request.address->source, block};
    return encodeFrame(reply);
}

QByteArray replyTo(const Frame& request, const QByteArray& body) {
    const int device = request.address ? request.address->destination : 0;
    const int block = request.address ? request.address->block : 0;
    return replyFrom(request, body, device, block);
}

QByteArray withBadChecksum(QByteArray wire) {
    // The checksum's last digit sits before CR LF.
    const qsizetype digit = wire.size() - 3;
    wire[digit] = wire[digit] == '0' ? '1' : '0';
    return wire;
}

}  // namespace cambench::comm::test
