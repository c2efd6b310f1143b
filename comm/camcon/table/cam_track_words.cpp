#include "cam_track_words.h"

#include <QCoreApplication>

namespace cambench::comm::table {

namespace {

// The message names the cam as a person counts: from 1.
std::optional<Error> checkCam(int camNumber, const Cam& cam) {
    if (cam.on == kEmptyCamWord || cam.off == kEmptyCamWord) {
        return Error::invalidData(
            QCoreApplication::translate(
                "cambench::comm",
                "Cam %1 (%2..%3): 0x80000000 marks an empty cam on the device and "
                "cannot be a switch point; move the point by one.")
                .arg(camNumber)
                .arg(cam.on)
                .arg(cam.off));
    }
    if (cam.on == cam.off) {
        return Error::invalidData(
            QCoreApplication::translate(
                "cambench::comm",
                "Cam %1 switches on and off at %2: the device would delete it. Give it "
                "a length or remove it.")
                .arg(camNumber)
                .arg(cam.on));
    }
    return std::nullopt;
}

std::optional<Error> checkCamNumber(int camNumber) {
    if (camNumber >= 1 && camNumber <= kMaxTrackCams) return std::nullopt;
    return Error::usage(
        QCoreApplication::translate("cambench::comm", "Cam %1 does not exist (1..%2).")
            .arg(camNumber)
            .arg(kMaxTrackCams));
}

}  // namespace

Result<TrackWrite> wholeTrackWrite(const QList<Cam>& cams) {
    if (cams.size() > kMaxTrackCams) {
        return Error::invalidData(
            QCoreApplication::translate(
                "cambench::comm", "A track holds at most %1 cams; this one has %2. Remove %3 cams.")
                .arg(kMaxTrackCams)
                .arg(cams.size())
                .arg(cams.size() - kMaxTrackCams));
    }
    TrackWrite write;
    for (qsizetype i = 0; i < cams.size(); ++i) {
        if (std::optional<Error> error = checkCam(int(i) + 1, cams[i])) return *error;
        write.words.append(cams[i].on);
        write.words.append(cams[i].off);
    }
    while (write.words.size() < 4) write.words.append(kRewritePaddingWord);
    return write;
}

Result<TrackWrite> singleCamWrite(int camNumber, const Cam& cam) {
    if (std::optional<Error> error = checkCamNumber(camNumber)) return *error;
    if (std::optional<Error> error = checkCam(camNumber, cam)) return *error;
    return TrackWrite{camOnWord(camNumber), {cam.on, cam.off}};
}

Result<TrackWrite> camDeleteWrite(int camNumber) {
    if (std::optional<Error> error = checkCamNumber(camNumber)) return *error;
    // Any equal pair deletes; 0 keeps it readable in a traffic log.
    return TrackWrite{camOnWord(camNumber), {0, 0}};
}

Result<QList<Cam>> camsFromTrackWords(const QList<qint32>& words) {
    if (words.size() % 2 != 0 || words.size() > 2 * kMaxTrackCams) {
        return Error::usage(
            QCoreApplication::translate("cambench::comm",
                                        "Track words must come in on/off pairs, at most %1; "
                                        "got %2 words.")
                .arg(2 * kMaxTrackCams)
                .arg(words.size()));
    }
    QList<Cam> cams;
    for (qsizetype i = 0; i < words.size(); i += 2) {
        const Cam cam{words[i], words[i + 1]};
        const int camNumber = int(i / 2) + 1;
        const bool onEmpty = cam.on == kEmptyCamWord;
        const bool offEmpty = cam.off == kEmptyCamWord;
        if (onEmpty && offEmpty) continue;
        if (onEmpty || offEmpty || cam.on == cam.off) {
            return Error::invalidData(
                QCoreApplication::translate(
                    "cambench::comm",
                    "Cam %1 reads %2..%3, which is no cam: the device's track data are "
                    "inconsistent. Read the track again.")
                    .arg(camNumber)
                    .arg(cam.on)
                    .arg(cam.off));
        }
        cams.append(cam);
    }
    return cams;
}

}  // namespace cambench::comm::table
