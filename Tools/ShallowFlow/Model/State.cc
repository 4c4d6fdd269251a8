#include "Model/State.h"

#include <algorithm>

namespace talus::shallow {

Primitive toPrimitive(const Conserved& s, double dryHeight) {
    if (s.h <= 0) return {0, 0, 0};
    if (s.h >= dryHeight) return {s.h, s.hu / s.h, std::clamp(s.hphi / s.h, 0.0, 1.0)};
    const double perHeight = 2 * s.h / (s.h * s.h + dryHeight * dryHeight);
    return {s.h, s.hu * perHeight, std::clamp(s.hphi * perHeight, 0.0, 1.0)};
}

}  // namespace talus::shallow
