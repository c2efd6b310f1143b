#pragma once

#include "catalogue.h"
#include "fields.h"
#include "frame.h"

#include "model/result.h"

namespace cambench::comm {

// Encoding and decoding driven only by the catalogue: no per-command code.

// Data part of a list of fields (no name). Values missing from `fields`
// encode as 0 / empty. Fails with InvalidData when a value does not fit.
Result<QByteArray> encodeFields(const QList<FieldSpec>& specs, const Fields& fields);

// Inverse of encodeFields. Fails with Communication ("malformed reply") when
// `data` does not have the expected length or digits.
Result<Fields> decodeFields(const QList<FieldSpec>& specs, QByteArrayView data);

// Frame body of a request: name + encoded request fields.
Result<QByteArray> encodeRequestBody(const CommandSpec& spec, const Fields& fields);

// The outcome of checking a reply frame against the request it answers.
struct ReplyMatch {
    enum Kind {
        Matches,        // the reply to this command; `fields` holds its data
        DeviceError,    // ':' name "ERR" + 8 hex: `errorCode`
        NotUnderstood,  // ":Z" + EPROM date: `eprom`
        Unrelated,      // a reply to something else (keep waiting)
        Malformed,      // right name, wrong data: `detail`
    };
    Kind kind = Unrelated;
    Fields fields;
    qint32 errorCode = 0;
    QByteArray eprom;
    QString detail;
};

ReplyMatch matchReply(const CommandSpec& spec, const Frame& reply);

// Device side (simulator): decode a request body, encode a reply body.
Result<Fields> decodeRequestFields(const CommandSpec& spec, QByteArrayView body);
Result<QByteArray> encodeReplyBody(const CommandSpec& spec, const Fields& fields);  // Data kind
QByteArray okReplyBody(const CommandSpec& spec);                                    // name + "OK"
QByteArray errorReplyBody(const CommandSpec& spec, qint32 code);  // name + "ERR" + 8 hex
QByteArray notUnderstoodBody(QByteArrayView epromDate);           // "Z" + date + NUL

}  // namespace cambench::comm
