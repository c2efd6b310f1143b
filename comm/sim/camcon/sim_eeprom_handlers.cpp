#include "sim_device.h"
#include "sim_handlers.h"

namespace cambench::comm {

namespace {
constexpr qint64 kNoMoreBlocks = 0xFFFF;
}  // namespace

void registerEepromHandlers(SimDevice& d) {
    d.addHandler(kQuery, "EE", [&d](const Fields& r) {
        const std::optional<QByteArray> block = d.eeprom().read(int(r.num("block")), d.state());
        Fields reply;
        reply.set("block", block ? r.num("block") : kNoMoreBlocks)
            .setBytes("data", block.value_or(QByteArray()));
        return SimResult::data(reply);
    });
    d.addHandler(kCommand, "EE", [&d](const Fields& r) {
        SimEeprom::WriteOutcome outcome = d.eeprom().write(int(r.num("block")), r.bytes("data"));
        if (outcome.error != 0) return SimResult::error(outcome.error);
        if (outcome.erased) {
            d.erase();
            return SimResult::ok(d.profile().eraseDelayMs);
        }
        if (outcome.restored) d.start(std::move(*outcome.restored));
        return SimResult::ok();
    });
}

}  // namespace cambench::comm
