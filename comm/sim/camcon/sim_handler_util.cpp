#include "sim_handler_util.h"

namespace cambench::comm::sim_util {

QByteArray bitTable(int count, const std::function<bool(int)>& isSet) {
    QByteArray table((count + 7) / 8, '\0');
    for (int i = 0; i < count; ++i) {
        if (isSet(i)) table[i / 8] = char(quint8(table.at(i / 8)) | (1u << (i % 8)));
    }
    return table;
}

}  // namespace cambench::comm::sim_util
