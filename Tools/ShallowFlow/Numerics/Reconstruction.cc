#include "Numerics/Reconstruction.h"

#include <algorithm>
#include <cmath>

#include "Model/InputError.h"

namespace talus::shallow {

Limiter parseLimiter(const std::string& text) {
    if (text == "first-order") return Limiter::FirstOrder;
    if (text == "minmod") return Limiter::Minmod;
    if (text == "van-leer") return Limiter::VanLeer;
    throw InputError("--limiter: unknown limiter '" + text + "' (first-order, minmod or van-leer)");
}

std::string name(Limiter limiter) {
    switch (limiter) {
        case Limiter::FirstOrder: return "first-order";
        case Limiter::Minmod: return "minmod";
        case Limiter::VanLeer: return "van-leer";
    }
    return "?";
}

double limitedDifference(Limiter limiter, double backward, double forward) {
    if (limiter == Limiter::FirstOrder || backward * forward <= 0) return 0.0;
    if (limiter == Limiter::Minmod) return std::abs(backward) < std::abs(forward) ? backward : forward;
    return 2.0 * backward * forward / (backward + forward);
}

void reconstruct(Limiter limiter, const std::vector<Primitive>& c, std::vector<Primitive>& west,
                 std::vector<Primitive>& east) {
    const std::size_t n = c.size();
    west.resize(n);
    east.resize(n);
    for (std::size_t i = 1; i + 1 < n; ++i) {
        const double sh = 0.5 * limitedDifference(limiter, c[i].h - c[i - 1].h, c[i + 1].h - c[i].h);
        const double su = 0.5 * limitedDifference(limiter, c[i].u - c[i - 1].u, c[i + 1].u - c[i].u);
        const double sp = 0.5 * limitedDifference(limiter, c[i].phi - c[i - 1].phi, c[i + 1].phi - c[i].phi);
        // The limiters keep the face values between the neighbours' in exact arithmetic; the clamps
        // remove what round-off leaves outside (a height of -1e-30 would make a wave speed NaN).
        west[i] = {std::max(c[i].h - sh, 0.0), c[i].u - su, std::clamp(c[i].phi - sp, 0.0, 1.0)};
        east[i] = {std::max(c[i].h + sh, 0.0), c[i].u + su, std::clamp(c[i].phi + sp, 0.0, 1.0)};
    }
}

}  // namespace talus::shallow
