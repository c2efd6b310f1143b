#include "sim_state.h"

#include <algorithm>

namespace cambench::comm {

bool SimPlcNetwork::isEmpty() const {
    return value == 0 && reset == 0 &&
           std::all_of(symbols.begin(), symbols.end(), [](quint16 s) { return s == 0; });
}

}  // namespace cambench::comm
