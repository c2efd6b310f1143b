#include "mc1_controller.h"

#include "mc1_parameters.h"

#include <QCoreApplication>
#include <QMap>

namespace cambench::comm {

Mc1Controller::Mc1Controller(Transport& transport, const Mc1Settings& settings,
                             const LineTiming& line)
    : m_backend(settings.variant.value_or(Mc1Variant::Mc200V2)),
      m_engine(transport, m_backend, mc1EngineSettings(line, settings.retries, settings.timeoutMs)),
      m_link(m_engine, settings.variant.value_or(Mc1Variant::Mc200V2)),
      m_given(settings.variant) {
    setGivenAxes(settings.axes);
}

void Mc1Controller::use(Mc1Variant variant) {
    m_backend.setVariant(variant);
    m_link.setVariant(variant);
}

Result<Mc1Variant> Mc1Controller::probeVariant() {
    // RDVAR is the one telegram every variant answers: 24 bits on an
    // MC100, 32 on an MC200.
    use(Mc1Variant::Mc100V1);
    m_backend.setProbing(true);
    const Result<QByteArray> value = m_link.exchange(Mc1Op::ReadVariable, mc1LittleEndian(1, 2));
    m_backend.setProbing(false);
    if (!value) {
        Error error = value.error();
        error.message = QCoreApplication::translate("cambench::comm",
                                                    "no MC100/MC200 answers reading variable 1: %1")
                            .arg(error.message);
        return error;
    }
    const bool mc200 = value->size() == 4;
    // The second telegram tells V1 from V2: an MC200 V2 answers SYSDATA's
    // status, an MC100 V2 RDBLOCK; V1 NAKs them.
    use(mc200 ? Mc1Variant::Mc200V2 : Mc1Variant::Mc100V2);
    const Result<QByteArray> second =
        mc200 ? m_link.exchange(Mc1Op::ProgramStatus, {})
              : m_link.exchange(Mc1Op::ReadBlock, QByteArray(3, '\0') + mc1LittleEndian(1, 1));
    if (second) return mc200 ? Mc1Variant::Mc200V2 : Mc1Variant::Mc100V2;
    if (isMc1Refusal(second.error())) return mc200 ? Mc1Variant::Mc200V1 : Mc1Variant::Mc100V1;
    return second.error();
}

Result<Mc1Variant> Mc1Controller::ensureIdentified() {
    if (m_identified) return variant();
    const Result<Mc1Variant> found = probeVariant();
    if (!found) {
        if (m_given) use(*m_given);
        return found.error();
    }
    if (!m_given) {
        use(*found);
        m_source = QCoreApplication::translate("cambench::comm", "probed");
    } else if (isMc200(*m_given) != isMc200(*found)) {
        use(*m_given);
        return Error::unsupported(
            QCoreApplication::translate(
                "cambench::comm",
                "the connection is set to the %1, but the controller answers as "
                "an %2 (variables of %3 bits): choose %2 or automatic detection")
                .arg(mc1VariantName(*m_given), mc1VariantName(*found))
                .arg(mc1VariableBits(*found)));
    } else {
        use(*m_given);
        m_source =
            *m_given == *found
                ? QCoreApplication::translate("cambench::comm", "as given, confirmed by the probe")
                : QCoreApplication::translate("cambench::comm", "as given (the probe found the %1)")
                      .arg(mc1VariantName(*found));
    }
    m_identified = true;
    return variant();
}

bool Mc1Controller::has(Mc1Capability capability) const {
    const Mc1Variant v = variant();
    switch (capability) {
        case Mc1Capability::BlockRead:
            return v == Mc1Variant::Mc100V2;
        case Mc1Capability::MemoryRead:
            return isMc200(v);
        case Mc1Capability::MemoryWrite:
        case Mc1Capability::ProgramControl:
        case Mc1Capability::Axes:
            return v == Mc1Variant::Mc200V2;
    }
    return false;
}

Status Mc1Controller::require(Mc1Capability capability, const QString& what) {
    const Result<Mc1Variant> identified = ensureIdentified();
    if (!identified) return identified.error();
    if (has(capability)) return success();
    return Error::unsupported(
        QCoreApplication::translate("cambench::comm", "the %1 cannot %2 (%3)")
            .arg(mc1VariantName(variant()), what,
                 capability == Mc1Capability::MemoryRead
                     ? QCoreApplication::translate("cambench::comm",
                                                   "the memory telegrams need an MC200")
                     : QCoreApplication::translate("cambench::comm", "this needs an MC200 V2")));
}

Result<QString> Mc1Controller::identify() {
    const Result<Mc1Variant> identified = ensureIdentified();
    if (!identified) return identified.error();
    QString text = QCoreApplication::translate("cambench::comm", "%1 (%2)")
                       .arg(mc1VariantName(*identified), m_source);
    if (has(Mc1Capability::ProgramControl)) {
        const Result<Mc1ProgramStatus> status = programStatus();
        if (!status) return status.error();
        text +=
            QStringLiteral(", ") +
            QCoreApplication::translate("cambench::comm", "PLC program %1").arg(status->summary());
    }
    return text;
}

Result<QString> Mc1Controller::probe() {
    const EngineSettings usual = m_engine.settings();
    const Result<QString> first = Mc1Device::probe();
    if (first || !m_backend.synchronised()) return first;
    // Reading the identity is safe to ask again, with the usual retries:
    // a telegram that missed the card's few milliseconds after a 0xFF (a
    // busy PC) is lost as silently as the first.
    m_engine.setSettings(usual);
    return identify();
}

Result<Mc1Variant> Mc1Controller::identifiedFor(int variable) {
    if (variable < 0 || variable > 0xFFFF)
        return Error::usage(
            QCoreApplication::translate("cambench::comm", "variable numbers are 0 to 65535, not %1")
                .arg(variable));
    return ensureIdentified();
}

Result<qint64> Mc1Controller::readVariable(int number) {
    const Result<Mc1Variant> identified = identifiedFor(number);
    if (!identified) return identified.error();
    const Result<QByteArray> value =
        m_link.exchange(Mc1Op::ReadVariable, mc1LittleEndian(number, 2));
    if (!value) return value.error();
    return mc1FromLittleEndian(*value, true);
}

Status Mc1Controller::writeVariable(int number, qint64 value) {
    const Result<Mc1Variant> identified = identifiedFor(number);
    if (!identified) return identified.error();
    const int bits = mc1VariableBits(*identified);
    const qint64 lowest = -(qint64(1) << (bits - 1));
    const qint64 highest = (qint64(1) << (bits - 1)) - 1;
    if (value < lowest || value > highest)
        return Error::usage(QCoreApplication::translate(
                                "cambench::comm", "V%1 of the %2 holds %3 to %4 (%5 bits), not %6")
                                .arg(number)
                                .arg(mc1VariantName(*identified))
                                .arg(lowest)
                                .arg(highest)
                                .arg(bits)
                                .arg(value));
    const bool wide = isMc200(*identified);
    const Result<QByteArray> done =
        m_link.exchange(wide ? Mc1Op::WriteVariable32 : Mc1Op::WriteVariable,
                        mc1LittleEndian(number, 2) + mc1LittleEndian(value, wide ? 4 : 3));
    if (!done) return done.error();
    return success();
}

Result<QByteArray> Mc1Controller::readRam(bool external, quint8 page, int address, int count,
                                          const ProgressFn& progress) {
    QByteArray bytes;
    while (bytes.size() < count) {
        const int at = address + int(bytes.size());
        Result<QByteArray> got = QByteArray();
        if (has(Mc1Capability::BlockRead)) {
            const int n = std::min<int>(kMc1MaxBlockRead, count - int(bytes.size()));
            QByteArray parameters = mc1LittleEndian(at, 1) + mc1LittleEndian(page, 1) +
                                    mc1LittleEndian(external ? 1 : 0, 1) + mc1LittleEndian(n, 1);
            got = m_link.exchange(Mc1Op::ReadBlock, parameters);
        } else {
            got = external ? m_link.exchange(Mc1Op::ReadByteExternal,
                                             mc1LittleEndian(at, 1) + mc1LittleEndian(page, 1))
                           : m_link.exchange(Mc1Op::ReadByteInternal, mc1LittleEndian(at, 1));
        }
        if (!got) return got.error();
        bytes += *got;
        if (progress) progress(bytes.size(), count);
    }
    return bytes;
}

Result<QList<bool>> Mc1Controller::readPoints(const QList<Mc1Point>& points,
                                              const ProgressFn& progress) {
    const Result<Mc1Variant> identified = ensureIdentified();
    if (!identified) return identified.error();
    QList<Mc1BitAddress> addresses;
    for (const Mc1Point& point : points) {
        const Result<Mc1BitAddress> address = mc1BitAddress(point, isMc200(*identified));
        if (!address) return address.error();
        addresses << *address;
    }
    // Each byte once; runs of neighbouring bytes in one RDBLOCK where there is one.
    QMap<std::pair<int, int>, quint8> bytes;  // (page or -1 internal, address)
    for (const Mc1BitAddress& a : addresses) bytes.insert({a.external ? a.page : -1, a.address}, 0);
    int done = 0;
    for (auto it = bytes.begin(); it != bytes.end();) {
        auto end = std::next(it);
        int count = 1;
        if (has(Mc1Capability::BlockRead)) {
            while (end != bytes.end() && end.key().first == it.key().first &&
                   end.key().second == it.key().second + count && count < kMc1MaxBlockRead) {
                ++end;
                ++count;
            }
        }
        const bool external = it.key().first >= 0;
        const Result<QByteArray> read =
            readRam(external, quint8(std::max(0, it.key().first)), it.key().second, count, {});
        if (!read) return read.error();
        for (int i = 0; i < count; ++i, ++it) it.value() = quint8(read->at(i));
        done += count;
        if (progress) progress(done, bytes.size());
    }
    QList<bool> values;
    for (const Mc1BitAddress& a : addresses)
        values << bool(bytes.value({a.external ? a.page : -1, a.address}) & a.mask());
    return values;
}

Result<bool> Mc1Controller::writePoint(const Mc1Point& point, bool on) {
    const Result<Mc1Variant> identified = ensureIdentified();
    if (!identified) return identified.error();
    if (const Status ok = mc1CheckWritable(point, *identified); !ok) return ok.error();
    const Result<Mc1BitAddress> address = mc1BitAddress(point, isMc200(*identified));
    // 2^bit sets the bit, NOT 2^bit clears it; the page is the flags' own.
    const quint8 flag = on ? address->mask() : quint8(~address->mask());
    const Result<QByteArray> done =
        m_link.exchange(address->external ? Mc1Op::WriteBitExternal : Mc1Op::WriteBitInternal,
                        mc1LittleEndian(address->address, 1) + mc1LittleEndian(flag, 1));
    const Result<QList<bool>> readBack = readPoints({point}, {});
    if (!done) {
        if (done.error().kind != ErrorKind::Communication) return done.error();
        // WRBIT is not repeated: what the bit holds now says whether it took.
        if (readBack && readBack->first() == on) return on;
        const QString found =
            readBack
                ? QStringLiteral("%1 = %2").arg(mc1PointText(point)).arg(readBack->first() ? 1 : 0)
                : QCoreApplication::translate("cambench::comm", "reading it failed too: %1")
                      .arg(readBack.error().message);
        return mc1LostAnswer(QCoreApplication::translate("cambench::comm", "%1 %2")
                                 .arg(on ? QCoreApplication::translate("cambench::comm", "set")
                                         : QCoreApplication::translate("cambench::comm", "clear"),
                                      mc1PointText(point)),
                             done.error(), found);
    }
    if (!readBack) return readBack.error();
    return readBack->first();
}

Result<QByteArray> Mc1Controller::readExternalPage(quint8 page, const ProgressFn& progress) {
    const Result<Mc1Variant> identified = ensureIdentified();
    if (!identified) return identified.error();
    return readRam(true, page, 0, 256, progress);
}

}  // namespace cambench::comm
