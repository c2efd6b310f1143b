#include "sim_handler_util.h"
#include "sim_handlers.h"

namespace cambench::comm {

namespace {

using sim_util::validOutput;
using sim_util::validProgram;

Fields camFields(const SimCamCursor::Answer& answer) {
    Fields fields;
    fields.set("on", answer.found ? answer.cam.on : sim_util::kNoCam);
    fields.set("off", answer.found ? answer.cam.off : sim_util::kNoCam);
    fields.set("earlier", answer.earlier ? 1 : 0);
    fields.set("more", answer.more ? 1 : 0);
    return fields;
}

bool validTrack(const SimDevice& device, const Fields& request) {
    return validProgram(device, request.num("program")) &&
           validOutput(device, request.num("output"));
}

Cam requestCam(const Fields& request) {
    return {qint32(request.num("on")), qint32(request.num("off"))};
}

// !PT: 0 = running light (one cam per output, one after the other),
// 1 = every output on from the minimum to half the maximum.
void testProgram(SimDevice& device, int program, int type) {
    const SimProfile& profile = device.profile();
    SimCamStore& cams = device.state().cams;
    cams.removeProgram(program);
    const qint64 span = qint64(profile.maxPosition) - profile.minPosition + 1;
    for (int output = 0; output < profile.outputs; ++output) {
        if (type == 0) {
            const qint64 width = std::max<qint64>(1, span / profile.outputs);
            const auto on = qint32(profile.minPosition + (output * width) % span);
            cams.insert(program, output,
                        {on, qint32(std::min<qint64>(on + width, profile.maxPosition))});
        } else {
            cams.insert(program, output, {profile.minPosition, profile.maxPosition / 2});
        }
    }
}

void registerSearch(SimDevice& d) {
    d.addHandler(kQuery, "NF", [&d](const Fields& r) {
        if (!validTrack(d, r)) return SimResult::error(sim_errors::kUnknown);
        return SimResult::data(camFields(
            d.cursor().first(d.state().cams, int(r.num("program")), int(r.num("output")))));
    });
    const auto moving = [&d](SimCamCursor::Answer (SimCamCursor::*move)(const SimCamStore&)) {
        return [&d, move](const Fields&) {
            if (!d.cursor().hasTrack()) return SimResult::error(sim_errors::kUnknown);
            return SimResult::data(camFields((d.cursor().*move)(d.state().cams)));
        };
    };
    d.addHandler(kQuery, "NL", moving(&SimCamCursor::last));
    d.addHandler(kQuery, "NN", moving(&SimCamCursor::next));
    d.addHandler(kQuery, "NP", moving(&SimCamCursor::previous));
    d.addHandler(kQuery, "NS", [&d](const Fields& r) {
        if (!d.cursor().hasTrack()) return SimResult::error(sim_errors::kUnknown);
        return SimResult::data(camFields(d.cursor().search(d.state().cams, qint32(r.num("on")))));
    });
}

void registerEditing(SimDevice& d) {
    d.addHandler(kCommand, "NINS", [&d](const Fields& r) {
        if (!validTrack(d, r)) return SimResult::error(sim_errors::kUnknown);
        return SimResult::okOr(
            d.state().cams.insert(int(r.num("program")), int(r.num("output")), requestCam(r)));
    });
    d.addHandler(kCommand, "NDEL", [&d](const Fields& r) {
        if (!validTrack(d, r)) return SimResult::error(sim_errors::kUnknown);
        return SimResult::okOr(d.state().cams.remove(int(r.num("program")), int(r.num("output")),
                                                     qint32(r.num("on"))));
    });
    d.addHandler(kCommand, "NC", [&d](const Fields& r) {
        if (!validTrack(d, r)) return SimResult::error(sim_errors::kUnknown);
        return SimResult::okOr(d.state().cams.change(int(r.num("program")), int(r.num("output")),
                                                     qint32(r.num("oldOn")), requestCam(r)));
    });
    d.addHandler(kCommand, "PDEL", [&d](const Fields& r) {
        if (!validProgram(d, r.num("program"))) return SimResult::error(sim_errors::kUnknown);
        d.state().cams.removeProgram(int(r.num("program")));
        return SimResult::ok();
    });
    d.addHandler(kCommand, "PCPY", [&d](const Fields& r) {
        if (!validProgram(d, r.num("target")) || !validProgram(d, r.num("source"))) {
            return SimResult::error(sim_errors::kUnknown);
        }
        d.state().cams.copyProgram(int(r.num("source")), int(r.num("target")));
        return SimResult::ok();
    });
    d.addHandler(kCommand, "PACPY", [&d](const Fields& r) {
        if (!validProgram(d, r.num("program")) || !validOutput(d, r.num("target")) ||
            !validOutput(d, r.num("source"))) {
            return SimResult::error(sim_errors::kUnknown);
        }
        d.state().cams.copyTrack(int(r.num("program")), int(r.num("source")), int(r.num("target")));
        return SimResult::ok();
    });
    d.addHandler(kCommand, "PT", [&d](const Fields& r) {
        if (!validProgram(d, r.num("program")) || r.num("type") > 1)
            return SimResult::error(sim_errors::kUnknown);
        testProgram(d, int(r.num("program")), int(r.num("type")));
        return SimResult::ok();
    });
}

// Dead times belong to an output, not to a program (notes 3).
void registerDeadTimes(SimDevice& d) {
    d.addHandler(kQuery, "TZK", [&d](const Fields& r) {
        const qint64 output = r.num("output");
        if (!validOutput(d, output)) return SimResult::error(sim_errors::kUnknown);
        Fields reply;
        reply.set("output", output).set("value", d.state().deadTimes.value(int(output)));
        return SimResult::data(reply);
    });
    d.addHandler(kCommand, "TZK", [&d](const Fields& r) {
        const qint64 output = r.num("output");
        const qint64 value = r.num("value");
        if (!validOutput(d, output)) return SimResult::error(sim_errors::kUnknown);
        if (value > d.profile().maxDeadTime) return SimResult::error(sim_errors::kDeadTimeTooLarge);
        if (value == 0) {
            d.state().deadTimes.remove(int(output));
        } else {
            d.state().deadTimes.insert(int(output), qint32(value));
        }
        return SimResult::ok();
    });
}

}  // namespace

void registerCamHandlers(SimDevice& device) {
    registerSearch(device);
    registerEditing(device);
    registerDeadTimes(device);
}

}  // namespace cambench::comm
