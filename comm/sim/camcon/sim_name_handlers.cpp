#include "sim_handler_util.h"
#include "sim_handlers.h"

namespace cambench::comm {

namespace {

// A numbered text (output name, program name, user text line): the query
// echoes the number with the text, the command stores it; an empty text is
// not kept.
void registerNumberedText(SimDevice& d, const char* name, const char* numberField,
                          QMap<int, QByteArray>& texts, std::function<bool(qint64)> valid) {
    d.addHandler(kQuery, name, [&texts, numberField, valid](const Fields& r) {
        const qint64 number = r.num(numberField);
        if (!valid(number)) return SimResult::error(sim_errors::kUnknown);
        Fields reply;
        reply.set(numberField, number).setBytes("text", texts.value(int(number)));
        return SimResult::data(reply);
    });
    d.addHandler(kCommand, name, [&texts, numberField, valid](const Fields& r) {
        const qint64 number = r.num(numberField);
        if (!valid(number)) return SimResult::error(sim_errors::kUnknown);
        const QByteArray text = r.bytes("text");
        if (text.isEmpty()) {
            texts.remove(int(number));
        } else {
            texts.insert(int(number), text);
        }
        return SimResult::ok();
    });
}

const char* const kPlcTextFields[SimState::kPlcTextLines] = {"text1", "text2", "text3", "text4"};

void registerPlcTexts(SimDevice& d) {
    const auto valid = [&d](qint64 message) {
        return message >= 0 && message < d.profile().plcTexts;
    };
    d.addHandler(kQuery, "ETXT", [&d, valid](const Fields& r) {
        const qint64 message = r.num("message");
        if (!valid(message)) return SimResult::error(sim_errors::kUnknown);
        const auto lines = d.state().plcTexts.value(int(message));
        Fields reply;
        reply.set("message", message);
        for (int i = 0; i < SimState::kPlcTextLines; ++i)
            reply.setBytes(kPlcTextFields[i], lines[i]);
        return SimResult::data(reply);
    });
    d.addHandler(kCommand, "ETXT", [&d, valid](const Fields& r) {
        const qint64 message = r.num("message");
        if (!valid(message)) return SimResult::error(sim_errors::kUnknown);
        std::array<QByteArray, SimState::kPlcTextLines> lines;
        bool empty = true;
        for (int i = 0; i < SimState::kPlcTextLines; ++i) {
            lines[i] = r.bytes(kPlcTextFields[i]);
            empty = empty && lines[i].isEmpty();
        }
        if (empty) {
            d.state().plcTexts.remove(int(message));
        } else {
            d.state().plcTexts.insert(int(message), lines);
        }
        return SimResult::ok();
    });
}

}  // namespace

void registerNameHandlers(SimDevice& device) {
    SimState& state = device.state();
    SimDevice& d = device;
    // The state object is replaced on restore but lives at the same address.
    registerNumberedText(d, "ANAME", "output", state.outputNames,
                         [&d](qint64 n) { return sim_util::validOutput(d, n); });
    registerNumberedText(d, "PNAME", "program", state.programNames,
                         [&d](qint64 n) { return sim_util::validProgram(d, n); });
    registerNumberedText(d, "BTXT", "line", state.userTexts,
                         [&d](qint64 n) { return n >= 0 && n < d.profile().userTextLines; });
    registerPlcTexts(d);
}

}  // namespace cambench::comm
