#include "mc1_parameters.h"

namespace cambench::comm {

Mc1VariableRange mc1VariableRange(Mc1Variant) {
    return {};
}

quint16 mc1AxisParameter(int axis, Mc1AxisValue value) {
    return quint16(0x1000 + 0x10 * axis + int(value));
}

}  // namespace cambench::comm
