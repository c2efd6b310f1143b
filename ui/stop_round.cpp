#include "stop_round.h"

#include "stop_control.h"

namespace cambench {

StopRound::StopRound(QObject* parent, Finished finished)
    : QObject(parent), m_finished(std::move(finished)) {}

StopRound* StopRound::start(QObject* parent, const QList<Member>& members, Finished finished) {
    auto* round = new StopRound(parent, std::move(finished));
    for (const Member& member : members)
        round->m_answers.append({member.name, member.reached, false, {}});
    // Every answer is listened for before the first STOP goes: a member
    // that reaches nothing answers at once.
    for (int at = 0; at < members.size(); ++at) {
        if (!members.at(at).reached) continue;
        connect(members.at(at).control, &StopControl::stopFinished, round,
                [round, at](const comm::MotionStopReport& report) {
                    Answer& answer = round->m_answers[at];
                    if (answer.answered) return;
                    answer.answered = true;
                    answer.report = report;
                    round->finishIfAllAnswered();
                });
    }
    for (const Member& member : members)
        if (member.reached) member.start();
    round->finishIfAllAnswered();
    return round;
}

void StopRound::finishIfAllAnswered() {
    if (m_done) return;
    for (const Answer& answer : m_answers)
        if (answer.reached && !answer.answered) return;
    m_done = true;
    m_finished(m_answers);
    deleteLater();
}

}  // namespace cambench
