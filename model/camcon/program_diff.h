#pragma once

#include "cam_program.h"

#include <QList>
#include <QMap>
#include <QString>
#include <QStringList>

namespace cambench {

// One difference between the cams of an output in two programs A and B.
struct CamDifference {
    enum class Kind {
        OnlyInA,  // a cam of A that no cam of B overlaps
        OnlyInB,
        Changed,  // a cam of A and the cam of B it overlaps most, edges moved
    };
    Kind kind = Kind::Changed;
    int output = 1;  // counts from 1
    int camA = 0;    // its number in A's track (from 1); 0 = none
    int camB = 0;
    Cam a;  // valid where camA > 0
    Cam b;  // valid where camB > 0

    friend bool operator==(const CamDifference& x, const CamDifference& y) {
        return x.kind == y.kind && x.output == y.output && x.camA == y.camA && x.camB == y.camB &&
               x.a == y.a && x.b == y.b;
    }
};

// What differs between two cam programs: their names and their cams, output
// by output in ascending order. Equal cams pair first; of the rest, a cam
// of A and the cam of B it overlaps most are one changed cam; what is left
// is only in A or only in B. A cam with off < on wraps through zero.
struct ProgramDiff {
    QString nameA;
    QString nameB;
    QList<CamDifference> cams;

    bool nameDiffers() const { return nameA != nameB; }
    bool isEmpty() const { return !nameDiffers() && cams.isEmpty(); }
};

ProgramDiff diffPrograms(const CamProgram& a, const CamProgram& b);

// Which program of a comparison receives the differences.
enum class DiffSide { A, B };

// The tracks of `target` (the program on side `side`) with `selected`
// differences applied towards the other side: a cam only on the other side
// is added, one only on this side removed, a changed cam takes the other
// side's extent. Only outputs a difference touches are returned, each
// whole (key = output); a cam that is not in `target` as the difference
// says (the program changed since) makes that output fail with a sentence.
struct AppliedDifferences {
    QMap<int, Track> tracks;
    QStringList problems;
};
AppliedDifferences applyDifferences(const CamProgram& target, DiffSide side,
                                    const QList<CamDifference>& selected);

// "output 3, cam 2: 10..20 → 12..20", "output 4: cam 100..120 only in B".
QString describeDifference(const CamDifference& difference);

}  // namespace cambench
