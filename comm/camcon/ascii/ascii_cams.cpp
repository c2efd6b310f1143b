#include "ascii_camcon.h"
#include "ascii_support.h"

#include "model/camcon/cam_validation.h"

#include <algorithm>
#include <optional>

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
    return writeTrackFrom(program, track, *current);
}

namespace {

// One track edit as a sequence of !NINS / !NDEL that can be undone.
class TrackEdit {
public:
    TrackEdit(AsciiLink& link, int program, int output)
        : m_link(link), m_program(program), m_output(output) {}

    std::optional<Error> insert(const Cam& cam) {
        const Result<Fields> reply = m_link.call('!', "NINS",
                                                 Fields{{"program", qint64(m_program)},
                                                        {"output", wireOutput(m_output)},
                                                        {"on", qint64(cam.on)},
                                                        {"off", qint64(cam.off)}});
        m_repeated |= m_link.lastAttempts() > 1;
        if (!reply && !repeatedAfterLostReply(reply.error())) {
            Error error = inContext(QStringLiteral("inserting the cam %1..%2 on %3 (!NINS)")
                                        .arg(cam.on)
                                        .arg(cam.off)
                                        .arg(trackText(m_program, m_output)),
                                    reply.error());
            if (error.kind == ErrorKind::DeviceError && error.deviceCode == -1) {
                error.message += QStringLiteral(
                    " On an insert the usual cause is a cam that overlaps another cam of the track "
                    "or lies outside the device's range.");
            }
            return error;
        }
        m_inserted.append(cam);
        return std::nullopt;
    }

    std::optional<Error> remove(const Cam& cam) {
        const Result<Fields> reply = m_link.call('!', "NDEL",
                                                 Fields{{"program", qint64(m_program)},
                                                        {"output", wireOutput(m_output)},
                                                        {"on", qint64(cam.on)}});
        m_repeated |= m_link.lastAttempts() > 1;
        if (!reply && !repeatedAfterLostReply(reply.error())) {
            return inContext(QStringLiteral("deleting the cam at %1 on %2 (!NDEL)")
                                 .arg(cam.on)
                                 .arg(trackText(m_program, m_output)),
                             reply.error());
        }
        m_deleted.append(cam);
        return std::nullopt;
    }

    // Undoes what was done, latest first, and says how that went. A refused
    // step is not undone: it did not happen.
    Error undo(Error cause) {
        bool back = true;
        const QList<Cam> inserted = m_inserted;
        const QList<Cam> deleted = m_deleted;
        for (auto it = inserted.crbegin(); it != inserted.crend(); ++it) back &= !remove(*it);
        for (auto it = deleted.crbegin(); it != deleted.crend(); ++it) back &= !insert(*it);
        if (inserted.isEmpty() && deleted.isEmpty()) {
            cause.message += QStringLiteral(" Nothing had been changed on the track yet.");
        } else if (back) {
            cause.message +=
                QStringLiteral(" The cams already changed were put back: the track is as it was.");
        } else {
            cause.message += QStringLiteral(
                " Putting the track back failed too: it may now hold other cams than before; "
                "read it to see.");
        }
        return cause;
    }

    bool repeated() const { return m_repeated; }

private:
    // A retry of an edit whose reply was lost may be refused because the
    // first attempt was executed: the read-back at the end decides.
    bool repeatedAfterLostReply(const Error& error) const {
        return error.kind == ErrorKind::DeviceError && m_link.lastAttempts() > 1;
    }

    AsciiLink& m_link;
    int m_program;
    int m_output;
    QList<Cam> m_inserted;
    QList<Cam> m_deleted;
    bool m_repeated = false;
};

bool isEepromFull(const Error& error) {
    return error.kind == ErrorKind::DeviceError && error.deviceCode <= -21 &&
           error.deviceCode >= -39;
}

bool overlapsAny(const Cam& cam, const QList<Cam>& cams) {
    return std::any_of(cams.cbegin(), cams.cend(),
                       [&cam](const Cam& other) { return camsOverlap(cam, other); });
}

}  // namespace

Status AsciiCamCon::writeTrackFrom(int program, const Track& track, const Track& onDevice) {
    const QString where = trackText(program, track.output);
    QList<Cam> toInsert;
    for (const Cam& cam : track.cams) {
        if (!onDevice.cams.contains(cam)) toInsert.append(cam);
    }
    QList<Cam> toDelete;
    for (const Cam& cam : onDevice.cams) {
        if (!track.cams.contains(cam)) toDelete.append(cam);
    }
    TrackEdit edit(m_link, program, track.output);
    // Cams that overlap nothing on the track go in first: if the device
    // refuses one, no old cam has been deleted yet. When the EEPROM is full
    // the rest waits until the deletes have made room.
    QList<Cam> later;
    bool full = false;
    for (const Cam& cam : toInsert) {
        if (full || overlapsAny(cam, onDevice.cams)) {
            later.append(cam);
            continue;
        }
        if (const std::optional<Error> refused = edit.insert(cam)) {
            if (!isEepromFull(*refused)) return edit.undo(*refused);
            full = true;
            later.append(cam);
        }
    }
    for (const Cam& cam : toDelete) {
        if (const std::optional<Error> refused = edit.remove(cam)) return edit.undo(*refused);
    }
    for (const Cam& cam : later) {
        if (const std::optional<Error> refused = edit.insert(cam)) return edit.undo(*refused);
    }
    if (!edit.repeated()) return success();
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
