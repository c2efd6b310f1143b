#include "project_content.h"

#include "device_info_json.h"
#include "program_diff.h"

#include <QCoreApplication>
#include <QJsonArray>
#include <QJsonDocument>
#include <QSet>

#include <map>
#include <set>

namespace cambench {

namespace {

QString key(const char* text) {
    return QString::fromLatin1(text);
}

QString camText(const Cam& cam) {
    return QStringLiteral("%1–%2").arg(cam.on).arg(cam.off);
}

QString compact(const QJsonValue& value) {
    const QByteArray text = QJsonDocument(QJsonArray{value}).toJson(QJsonDocument::Compact);
    return QString::fromUtf8(text.mid(1, text.size() - 2));
}

BackupDifference item(const QString& label, const QString& what, ChangeKind kind,
                      const QString& before, const QString& after) {
    const QString change = changeText(kind, before, after);
    return {{},
            label,
            what,
            before,
            after,
            kind,
            what.isEmpty() ? QStringLiteral("%1: %2").arg(label, change)
                           : QStringLiteral("%1: %2 %3").arg(label, what, change)};
}

void diffProgram(const CamProgram& a, const CamProgram& b, QList<BackupDifference>& out) {
    const QString program = QCoreApplication::translate("cambench::model", "program %1");
    const ProgramDiff diff = diffPrograms(a, b);
    if (diff.nameDiffers())
        out << item(program.arg(a.number), key("name"), ChangeKind::Changed, compact(diff.nameA),
                    compact(diff.nameB));
    const QString cam = QCoreApplication::translate("cambench::model", "cam");
    for (const CamDifference& difference : diff.cams) {
        const QString where =
            QCoreApplication::translate("cambench::model", "program %1, output %2")
                .arg(a.number)
                .arg(difference.output);
        switch (difference.kind) {
            case CamDifference::Kind::OnlyInA:
                out << item(where, cam, ChangeKind::Removed, camText(difference.a), {});
                break;
            case CamDifference::Kind::OnlyInB:
                out << item(where, cam, ChangeKind::Added, {}, camText(difference.b));
                break;
            case CamDifference::Kind::Changed:
                out << item(where, cam, ChangeKind::Changed, camText(difference.a),
                            camText(difference.b));
                break;
        }
    }
}

// What names an element of a part's list: its number fields ("output 5",
// "area 3, number 2"), else its place ("user 2").
QString elementLabel(const QString& singular, const QJsonObject& element, int place) {
    QStringList ids;
    for (const char* id : {"program", "output", "area", "number"})
        if (element.contains(key(id)))
            ids << QStringLiteral("%1 %2").arg(key(id), compact(element.value(key(id))));
    return ids.isEmpty() ? QStringLiteral("%1 %2").arg(singular).arg(place + 1)
                         : ids.join(QStringLiteral(", "));
}

bool isIdField(const QString& name) {
    return name == QLatin1String("program") || name == QLatin1String("output") ||
           name == QLatin1String("area") || name == QLatin1String("number");
}

// Two objects member by member, each as one item of `label`.
void diffMembers(const QString& label, const QJsonObject& a, const QJsonObject& b,
                 QList<BackupDifference>& out) {
    std::set<QString> names;
    for (auto it = a.constBegin(); it != a.constEnd(); ++it) names.insert(it.key());
    for (auto it = b.constBegin(); it != b.constEnd(); ++it) names.insert(it.key());
    for (const QString& name : names) {
        if (isIdField(name)) continue;
        const bool inA = a.contains(name);
        const bool inB = b.contains(name);
        if (inA && inB && a.value(name) == b.value(name)) continue;
        const ChangeKind kind = !inA   ? ChangeKind::Added
                                : !inB ? ChangeKind::Removed
                                       : ChangeKind::Changed;
        out << item(label, name, kind, inA ? compact(a.value(name)) : QString(),
                    inB ? compact(b.value(name)) : QString());
    }
}

// A list of elements, matched by what names them.
void diffList(const QString& singular, const QJsonArray& a, const QJsonArray& b,
              QList<BackupDifference>& out) {
    std::map<QString, std::pair<QJsonObject, QJsonObject>> elements;
    std::map<QString, std::pair<bool, bool>> present;
    QStringList order;
    for (int i = 0; i < a.size(); ++i) {
        const QString label = elementLabel(singular, a.at(i).toObject(), i);
        elements[label].first = a.at(i).toObject();
        present[label].first = true;
        order << label;
    }
    for (int i = 0; i < b.size(); ++i) {
        const QString label = elementLabel(singular, b.at(i).toObject(), i);
        elements[label].second = b.at(i).toObject();
        present[label].second = true;
        if (!order.contains(label)) order << label;
    }
    for (const QString& label : order) {
        const auto& [inA, inB] = present[label];
        const auto& [one, two] = elements[label];
        if (inA && inB) {
            diffMembers(label, one, two, out);
        } else {
            out << item(label, {}, inA ? ChangeKind::Removed : ChangeKind::Added,
                        inA ? compact(one) : QString(), inB ? compact(two) : QString());
        }
    }
}

// A part that is not a program: a list, an object of settings, a value.
void diffPart(const QString& part, const QJsonValue& a, const QJsonValue& b,
              QList<BackupDifference>& out) {
    if (a == b) return;
    static const QHash<QString, QString> singular{
        {key("users"), key("user")},
        {key("plcNetworks"), key("PLC network")},
        {key("analogueCams"), key("analogue cam")},
    };
    if ((a.isArray() || a.isUndefined()) && (b.isArray() || b.isUndefined())) {
        diffList(singular.value(part, part), a.toArray(), b.toArray(), out);
        return;
    }
    if ((a.isObject() || a.isUndefined()) && (b.isObject() || b.isUndefined())) {
        const QString label = part == QLatin1String("settings") ? key("setting") : part;
        std::set<QString> names;
        const QJsonObject one = a.toObject();
        const QJsonObject two = b.toObject();
        for (auto it = one.constBegin(); it != one.constEnd(); ++it) names.insert(it.key());
        for (auto it = two.constBegin(); it != two.constEnd(); ++it) names.insert(it.key());
        for (const QString& name : names) {
            if (one.value(name) == two.value(name)) continue;
            const ChangeKind kind = !one.contains(name)   ? ChangeKind::Added
                                    : !two.contains(name) ? ChangeKind::Removed
                                                          : ChangeKind::Changed;
            out << item(QStringLiteral("%1 %2").arg(label, name), {}, kind,
                        one.contains(name) ? compact(one.value(name)) : QString(),
                        two.contains(name) ? compact(two.value(name)) : QString());
        }
        return;
    }
    const ChangeKind kind = a.isUndefined()   ? ChangeKind::Added
                            : b.isUndefined() ? ChangeKind::Removed
                                              : ChangeKind::Changed;
    out << item(part, {}, kind, a.isUndefined() ? QString() : compact(a),
                b.isUndefined() ? QString() : compact(b));
}

}  // namespace

QJsonObject projectContentJson(const Project& project) {
    QJsonObject content = QJsonDocument::fromJson(projectToJson(project, {})).object();
    content.remove(key("readAt"));
    content.remove(key("device"));
    content.remove(key("minimumPulses"));  // the person's, on the PC only
    return content;
}

Result<Project> projectFromContent(const QJsonObject& content, const DeviceInfo& device) {
    QJsonObject project = content;
    project.insert(key("device"), deviceInfoToJson(device));
    return projectFromJson(QJsonDocument(project).toJson(QJsonDocument::Compact));
}

QList<BackupDifference> diffProjectContent(const Project& before, const Project& after) {
    QList<BackupDifference> out;
    std::map<int, std::pair<CamProgram, CamProgram>> programs;
    for (const CamProgram& program : before.programs) programs[program.number].first = program;
    for (const CamProgram& program : after.programs) programs[program.number].second = program;
    QSet<int> inPrograms;
    for (auto& [number, pair] : programs) {
        pair.first.number = number;
        pair.second.number = number;
        inPrograms.insert(number);
        diffProgram(pair.first, pair.second, out);
    }
    const QJsonObject a = projectContentJson(before);
    const QJsonObject b = projectContentJson(after);
    std::set<QString> parts;
    for (auto it = a.constBegin(); it != a.constEnd(); ++it) parts.insert(it.key());
    for (auto it = b.constBegin(); it != b.constEnd(); ++it) parts.insert(it.key());
    for (const QString& part : parts) {
        if (part == QLatin1String("format") || part == QLatin1String("version") ||
            part == QLatin1String("family") || part == QLatin1String("programs"))
            continue;
        if (part == QLatin1String("programNames")) {
            // A program read whole said its name above.
            QJsonArray one;
            QJsonArray two;
            for (const QJsonValue& name : a.value(part).toArray())
                if (!inPrograms.contains(name.toObject().value(key("program")).toInt()))
                    one << name;
            for (const QJsonValue& name : b.value(part).toArray())
                if (!inPrograms.contains(name.toObject().value(key("program")).toInt()))
                    two << name;
            diffPart(part, one, two, out);
            continue;
        }
        diffPart(part, a.value(part), b.value(part), out);
    }
    return out;
}

}  // namespace cambench
