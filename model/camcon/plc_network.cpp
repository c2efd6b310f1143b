#include "plc_network.h"

#include <algorithm>

namespace cambench {

bool PlcNetwork::isEmpty() const {
    return value == 0 && reset == 0 &&
           std::all_of(symbols.begin(), symbols.end(), [](quint16 s) { return s == 0; });
}

}  // namespace cambench
