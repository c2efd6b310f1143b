#include "ascii_camcon.h"
#include "ascii_support.h"

#include "model/camcon/cam_validation.h"

namespace cambench::comm {

using namespace client;

namespace {

// More cams than any device holds on one track (125, notes 3): a device
// that keeps answering "more" is broken, not full.
constexpr int kMaxCamsPerTrack = 1024;

QString trackText(int program, int output) {
    return QStringLiteral("program %1, output %2").arg(program).arg(output);
}

}  // namespace

Result<Track> AsciiCamCon::readTrack(int program, int output) {
    Track track;
    track.output = output;
    const QString where = trackText(program, output);
    Result<Fields> reply = m_link.call(
        '?', "NF", Fields{{"program", qint64(program)}, {"output", wireOutput(output)}});
    if (!reply) return inContext(QStringLiteral("reading %1 (?NF)").arg(where), reply.error());
    while (true) {
        const qint64 on = reply->num("on");
        const qint64 off = reply->num("off");
        if (isNoCamPoint(on) && isNoCamPoint(off)) break;  // empty track or past the end
        track.cams.append(Cam{qint32(on), qint32(off)});
        if (reply->num("more") == 0) break;
        if (track.cams.size() >= kMaxCamsPerTrack) {
            return Error::communication(
                QStringLiteral("reading %1: the device reports more than %2 cams on one track; "
                               "check the device")
                    .arg(where)
                    .arg(kMaxCamsPerTrack));
        }
        reply = m_link.call('?', "NN");
        if (!reply) return inContext(QStringLiteral("reading %1 (?NN)").arg(where), reply.error());
        if (m_link.lastAttempts() > 1) {
            // A lost reply may hide an executed ?NN: the cursor could have
            // stepped twice. ?NS from just past the last cam read is
            // idempotent and lands on the right cam either way.
            reply = m_link.call('?', "NS", Fields{{"on", qint64(track.cams.last().on) + 1}});
            if (!reply) {
                return inContext(QStringLiteral("reading %1 (?NS)").arg(where), reply.error());
            }
        }
    }
    return track;
}

Result<CamProgram> AsciiCamCon::readProgram(int program, int outputs, const ProgressFn& progress) {
    CamProgram result;
    result.number = program;
    const Result<QString> name = readProgramName(program);
    if (name) {
        result.name = *name;
    } else if (!isNotUnderstood(name.error())) {
        return name.error();
    }
    for (int output = 1; output <= outputs; ++output) {
        if (progress) progress(output - 1, outputs);
        Result<Track> track = readTrack(program, output);
        if (!track) return track.error();
        if (!track->cams.isEmpty()) result.tracks.insert(output, std::move(track).value());
    }
    if (progress) progress(outputs, outputs);
    return result;
}

Status AsciiCamCon::writeTrack(int program, const Track& track) {
    const Result<Track> current = readTrack(program, track.output);
    if (!current) return current.error();
    const QString where = trackText(program, track.output);
    const auto repeatedAfterLostReply = [this](const Error& error) {
        return error.kind == ErrorKind::DeviceError && m_link.lastAttempts() > 1;
    };
    bool needsReadBack = false;
    // Deleting first means every intermediate track is a subset of the
    // target plus cams that stay: nothing the device could reject as overlap.
    for (const Cam& cam : current->cams) {
        if (track.cams.contains(cam)) continue;
        const Result<Fields> reply = m_link.call('!', "NDEL",
                                                 Fields{{"program", qint64(program)},
                                                        {"output", wireOutput(track.output)},
                                                        {"on", qint64(cam.on)}});
        if (!reply && !repeatedAfterLostReply(reply.error())) {
            return inContext(
                QStringLiteral("deleting the cam at %1 on %2 (!NDEL)").arg(cam.on).arg(where),
                reply.error());
        }
        needsReadBack |= m_link.lastAttempts() > 1;
    }
    for (const Cam& cam : track.cams) {
        if (current->cams.contains(cam)) continue;
        const Result<Fields> reply = m_link.call('!', "NINS",
                                                 Fields{{"program", qint64(program)},
                                                        {"output", wireOutput(track.output)},
                                                        {"on", qint64(cam.on)},
                                                        {"off", qint64(cam.off)}});
        if (!reply && !repeatedAfterLostReply(reply.error())) {
            return inContext(QStringLiteral("inserting the cam %1..%2 on %3 (!NINS)")
                                 .arg(cam.on)
                                 .arg(cam.off)
                                 .arg(where),
                             reply.error());
        }
        needsReadBack |= m_link.lastAttempts() > 1;
    }
    if (!needsReadBack) return success();
    // An edit was sent more than once: make sure the device holds exactly
    // the target track rather than trusting the replies.
    const Result<Track> written = readTrack(program, track.output);
    if (!written) return written.error();
    Track expected = track;
    normaliseTrack(expected);
    if (written->cams != expected.cams) {
        return Error::communication(
            QStringLiteral("writing %1: after lost replies the device holds %2 cams instead of "
                           "the %3 written; write the track again")
                .arg(where)
                .arg(written->cams.size())
                .arg(track.cams.size()));
    }
    return success();
}

Status AsciiCamCon::deleteProgram(int program) {
    const Result<Fields> reply = m_link.call('!', "PDEL", Fields{{"program", qint64(program)}});
    if (!reply) {
        return inContext(QStringLiteral("deleting program %1 (!PDEL)").arg(program), reply.error());
    }
    return success();
}

Status AsciiCamCon::copyProgram(int from, int to) {
    const Result<Fields> reply =
        m_link.call('!', "PCPY", Fields{{"target", qint64(to)}, {"source", qint64(from)}});
    if (!reply) {
        return inContext(
            QStringLiteral("copying program %1 to program %2 (!PCPY)").arg(from).arg(to),
            reply.error());
    }
    return success();
}

Status AsciiCamCon::copyTrack(int program, int fromOutput, int toOutput) {
    const Result<Fields> reply = m_link.call('!', "PACPY",
                                             Fields{{"program", qint64(program)},
                                                    {"target", wireOutput(toOutput)},
                                                    {"source", wireOutput(fromOutput)}});
    if (!reply) {
        return inContext(QStringLiteral("copying output %1 to output %2 in program %3 (!PACPY)")
                             .arg(fromOutput)
                             .arg(toOutput)
                             .arg(program),
                         reply.error());
    }
    return success();
}

}  // namespace cambench::comm
