// libFuzzer target for the Cam-BUS receiver: whatever bytes the bus carries
// (breaks in P12's encoding among them), fed in random chunks at random
// times to the PC's station with a block waiting, and every block the
// station takes read as a CamCon frame. The station must never crash or
// hang, must hand up only blocks whose checksum held, and must report each
// of its blocks at most once. The same function runs in normal builds
// through fuzz_cambus_station_replay_main.cpp (fuzz_cambus_station_replay).
#include "comm/camcon/cambus/cambus_payload.h"
#include "comm/camcon/cambus/cambus_station.h"
#include "fuzz_check.h"

#include <QSet>

#include <cstdint>

using namespace cambench::comm;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size < 2) return 0;
    CamBusStationConfig config;
    config.number = data[0] & 0x3F;
    config.joinBeforeFirstBlock = (data[1] & 1) != 0;
    qint64 now = 0;
    CamBusStation station(config, now);
    const quint64 first = station.send(3, camBusPayload('?', "GNR"));
    const quint64 second = station.send(7, camBusPayload('!', "GNR05"));
    QSet<quint64> reported;
    std::size_t at = 2;
    while (at < size) {
        // A chunk of 1..8 bytes, then 0..15 ms of time.
        const std::size_t chunk = std::min<std::size_t>(size - at, 1 + data[at] % 8);
        now += data[at] >> 4;
        station.feed(QByteArrayView(reinterpret_cast<const char*>(data + at), qsizetype(chunk)),
                     now);
        at += chunk;
        station.poll(now);
        for (const CamBusStation::Delivery& delivery : station.takeDeliveries()) {
            FUZZ_CHECK(delivery.id == first || delivery.id == second);
            FUZZ_CHECK(!reported.contains(delivery.id));
            reported.insert(delivery.id);
        }
        for (const CamBusStation::Received& block : station.takeReceived()) {
            FUZZ_CHECK(!block.data.isEmpty() && block.data.size() <= kCamBusMaxData);
            FUZZ_CHECK(block.source >= 0 && block.source <= kCamBusLastUser);
            (void)parseCamBusPayload(block.data);
        }
        // What the station writes is well-formed P12: it decodes completely.
        QByteArray written = station.takeOutput();
        (void)takeBreakMarked(written);
        FUZZ_CHECK(written.isEmpty());
    }
    return 0;
}
