#pragma once

#include "short_commands.h"

#include "comm/camcon/camcon_device.h"

namespace cambench::comm::table {

class TableLink;

// The short commands 0x01..0x07 as a PC (or an S7 with a CP340, through its
// function block) sends them, one call each: what the PLC coupling tools
// (`cambench-cli short ...`, the PLC coupling page) use to show what a PLC
// program would see.
//
// Retry safety: every one of them is safe to repeat. The status query goes
// without virtual inputs (which a device without the PLC logic module ANDs
// with its outputs), 0x02 resets an error state, 0x03 selects an absolute
// program, 0x05 replaces whole tracks and 0x07 sets an absolute dead time.
class ShortClient {
public:
    explicit ShortClient(TableLink& link) : m_link(link) {}

    Result<ShortStatus> status();
    Status resetErrors();
    Status changeProgram(int program);
    // The cams of `output` (from 1) in `program`.
    Result<Track> readTrack(int program, int output);
    // Replaces the cams of track.output in `program`; at most 14 cams fit
    // the telegram (a usage error beyond).
    Status writeTrack(int program, const Track& track);
    // The dead time of `output` in 0.1 ms.
    Result<int> readDeadTime(int output);
    Status writeDeadTime(int output, int tenthsMs);

private:
    // Sends `request` (or its encoding error) and returns the reply telegram;
    // errors say `what` was being done.
    Result<QByteArray> exchange(const Result<QByteArray>& request, const QString& what);
    Status acknowledged(ShortCommand command, const Result<QByteArray>& request,
                        const QString& what);

    TableLink& m_link;
};

// The short commands of `device`, or why it has none (another protocol).
Result<ShortClient*> shortCommandsOf(CamConDevice& device);

// Work for a job of the GUI or the CLI (device, job context) that needs the
// short commands: `work(client, device)` runs only where they exist.
template <class T, class Work>
auto withShortCommands(Work work) {
    return [work = std::move(work)](CamConDevice& device, auto& /*job*/) -> Result<T> {
        const Result<ShortClient*> client = shortCommandsOf(device);
        if (!client) return client.error();
        return work(**client, device);
    };
}

}  // namespace cambench::comm::table
