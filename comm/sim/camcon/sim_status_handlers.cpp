#include "sim_handler_util.h"
#include "sim_handlers.h"

#include <cmath>

namespace cambench::comm {

namespace {

constexpr int kFormattedWidth = 9;  // 10 characters including the NUL

Fields table(const QByteArray& bytes) {
    Fields fields;
    fields.setBytes("data", bytes);
    return fields;
}

Fields number(qint64 v) {
    Fields fields;
    fields.set("value", v);
    return fields;
}

Fields formatted(const QByteArray& text) {
    Fields fields;
    fields.setBytes("text", text.rightJustified(kFormattedWidth, ' '));
    return fields;
}

int setting(SimDevice& d, const char* name) {
    return int(d.state().settings.value({name, -1}).num("value"));
}

void registerAxis(SimDevice& d) {
    d.addHandler(kQuery, "IGWG",
                 [&d](const Fields&) { return SimResult::data(number(d.axis().position())); });
    d.addHandler(kQuery, "IREE", [&d](const Fields&) {
        return SimResult::data(number(qint64(d.axis().position()) - d.profile().minPosition));
    });
    d.addHandler(kQuery, "IFGWG", [&d](const Fields&) {
        return SimResult::data(formatted(QByteArray::number(d.axis().position())));
    });
    d.addHandler(kQuery, "BSPEED", [&d](const Fields&) {
        return SimResult::data(number(qRound64(d.axis().unitsPerSecond())));
    });
    d.addHandler(kQuery, "SPEED", [&d](const Fields&) {
        return SimResult::data(formatted(QByteArray::number(d.axis().rpm(), 'f', 1)));
    });
    // "P" + the position display (manual 5.1.3); the codec adds no NUL to a
    // text that runs up to the checksum.
    d.addHandler(kQuery, "AUTO", [&d](const Fields&) {
        Fields reply;
        reply.setBytes(
            "text",
            "P" + QByteArray::number(d.axis().position()).rightJustified(kFormattedWidth, ' '));
        return SimResult::data(reply);
    });
}

void registerTables(SimDevice& d) {
    d.addHandler(kQuery, "ATAB", [&d](const Fields&) {
        const qint32 position = d.axis().position();
        const bool running = d.axis().running();
        const int program = d.state().activeProgram;
        return SimResult::data(table(sim_util::bitTable(d.profile().outputs, [&](int output) {
            return running && d.state().cams.isOn(program, output, position);
        })));
    });
    // Input 0 reports "running", the others are open.
    d.addHandler(kQuery, "ETAB", [&d](const Fields&) {
        return SimResult::data(table(sim_util::bitTable(
            d.profile().inputs, [&](int input) { return input == 0 && d.axis().running(); })));
    });
    const QList<std::pair<const char*, const char*>> plcTables{{"GASPSTAB", "GASPSMAX"},
                                                               {"GESPSTAB", "GESPSMAX"},
                                                               {"GMPSTAB", "GMSPSMAX"},
                                                               {"GXSPSTAB", "GXSPSMAX"},
                                                               {"GSSPSTAB", "GSSPSMAX"}};
    for (const auto& [query, count] : plcTables) {
        const char* countName = count;
        d.addHandler(kQuery, query, [&d, countName](const Fields&) {
            return SimResult::data(table(QByteArray((setting(d, countName) + 7) / 8, '\0')));
        });
    }
    d.addHandler(kQuery, "GVSPSTAB", [&d](const Fields&) {
        QByteArray bytes = d.runtime().vInputs;
        bytes.resize((setting(d, "GVSPSMAX") + 7) / 8, '\0');
        return SimResult::data(table(bytes));
    });
    d.addHandler(kCommand, "GVSPSTAB", [&d](const Fields& r) {
        d.runtime().vInputs = r.bytes("data");
        return SimResult::ok();
    });
}

void registerErrorAndProgram(SimDevice& d) {
    d.addHandler(kQuery, "ERR",
                 [&d](const Fields&) { return SimResult::data(number(d.runtime().errorState)); });
    d.addHandler(kCommand, "ERR", [&d](const Fields&) {
        d.runtime().errorState = 0;
        return SimResult::ok();
    });
    d.addHandler(kQuery, "PAU",
                 [&d](const Fields&) { return SimResult::data(number(d.state().activeProgram)); });
    d.addHandler(kCommand, "PAU", [&d](const Fields& r) {
        if (!sim_util::validProgram(d, r.num("value")))
            return SimResult::error(sim_errors::kUnknown);
        d.state().activeProgram = int(r.num("value"));
        return SimResult::ok();
    });
}

}  // namespace

void registerStatusHandlers(SimDevice& device) {
    registerAxis(device);
    registerTables(device);
    registerErrorAndProgram(device);
}

}  // namespace cambench::comm
