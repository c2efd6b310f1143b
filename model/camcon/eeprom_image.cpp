#include "eeprom_image.h"

namespace cambench {

int EepromImage::totalBytes() const {
    int total = 0;
    for (const EepromBlock& block : blocks) total += block.data.size();
    return total;
}

}  // namespace cambench
