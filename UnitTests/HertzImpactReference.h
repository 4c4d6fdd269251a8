// An independent integration of one Hertz-Mindlin impact (HertzMindlinTest.cc): the equations of
// motion of the contact law of Documentation/UserGuide/ContactLaws.md, written out here from the
// published law (Tsuji et al. 1992, in the form of Antypov & Elliott 2011) and integrated with
// the classical fourth-order Runge-Kutta method with adaptive steps, far below the simulation's,
// with the switches between sticking and sliding and the separation located by bisection. Nothing
// of the kernel is used.
//
// Normal: the overlap x (x' = u > 0 while approaching) of a pair of reduced mass m* obeys
//   m* u' = -fn,  fn = K x^(3/2) + gn(x) u,  K = 4/3 E* sqrt(R*),
//   gn(x) = 2 sqrt(5/6) |beta| sqrt(Sn m*),  Sn = 2 E* sqrt(R* x),  beta = ln e / sqrt(ln^2 e + pi^2).
// Tangential, for a sphere (radius r, mass m, inertia I) on a plane wall, everything in the
// x-z plane: the wall z = 0, the centre moving along x with vx and spinning about y with wy.
// The branch vector to the contact point is -l z with the lever l = r - x/2 (the middle of the
// overlap), so the contact point slides with vtc = vx - l wy, and a tangential force ft (along
// x) gives m vx' = ft and I wy' = -l ft. Mindlin's spring xi (xi' = vtc while sticking) gives
// ft = -St xi, St = 8 G* sqrt(R* x), capped by Coulomb at |ft| = mu fn. Only undamped (e = 1)
// impacts are integrated with friction: with gt = 0 the two phases are simple.
//  - Sticking turns into sliding when St |xi| reaches mu fn.
//  - While sliding in the direction s = sign(xi), ft = -s mu fn and the spring sits at the limit,
//    xi = s mu fn/St = s mu E*/(6 G*) x (fn/St = K x^(3/2) / (8 G* sqrt(R*) x^(1/2))). It sticks
//    again when the spring, growing with vtc, would fall below that limit:
//    s vtc < mu E*/(6 G*) u.
//  - At the touch, x = vn0 t and xi = vtc0 t to first order, so St |xi| / fn tends to
//    6 G*/E* |vtc0|/vn0: the contact slides from the touch if that exceeds mu.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace talus::test {

struct HertzImpact {
    double effectiveYoungsModulus, effectiveShearModulus;  // E*, G*
    double restitution = 1, friction = 0;
    double effectiveRadius, reducedMass;                   // R*, m* (on a wall: the sphere's mass)
    double radius = 0, inertia = 1;                        // of the sphere on a wall (tangential motion)
    double normalSpeed, tangentialSpeed = 0;               // vn0 > 0, vtc0 (the sphere starts without spin)
};

struct HertzImpactOutcome {
    double normalSpeedAfter;    // the separation speed -u at x = 0 (> 0)
    double vx, wy;              // the sphere's velocity along x and spin about y after the impact
    double duration;            // from touch to separation
    bool slidAtTouch = false;
    int phaseChanges = 0;       // switches between sticking and sliding
    int steps = 0;              // accepted steps
};

class HertzImpactReference {
public:
    explicit HertzImpactReference(const HertzImpact& p) : p_(p) {
        // (The header's phases assume gt = 0: with friction, only elastic impacts.)
        if (p.friction > 0 && p.restitution != 1)
            throw std::invalid_argument("HertzImpactReference: friction only with restitution 1");
        const double logE = std::log(p.restitution);
        const double beta = logE / std::sqrt(logE * logE + std::numbers::pi * std::numbers::pi);
        dampingPrefactor_ = 2 * std::sqrt(5.0 / 6.0) * std::abs(beta);
    }

    // The elastic Hertz duration at the impact speed (HeadOnCollision's derivation in
    // ContactCollisionTest.cc): the time scale the steps are a fraction of.
    double elasticDuration() const {
        const double K = 4.0 / 3.0 * p_.effectiveYoungsModulus * std::sqrt(p_.effectiveRadius);
        const double maxOverlap = std::pow(5 * p_.reducedMass * p_.normalSpeed * p_.normalSpeed / (4 * K), 0.4);
        return 2 * maxOverlap / p_.normalSpeed * 0.4 * std::beta(0.4, 0.5);
    }

    // Integrates from the touch to the separation with steps whose local error (estimated by
    // step doubling: one step against two half steps, whose difference is 15/16 of the error of
    // the single step for a fourth-order method) stays below `tolerance` times the impact speed
    // (in the speeds) or the largest overlap scale v tc (in the positions) per elastic duration
    // of steps: the steps shrink where the forces are not smooth, at the touch and the separation,
    // where gn ~ x^(1/4) has an unbounded derivative.
    HertzImpactOutcome integrate(double tolerance) {
        const double tc = elasticDuration(), v = p_.normalSpeed;
        const std::array<double, 5> scale{v * tc, v, v, v / p_.radius, v * tc};
        auto error = [&](const State& a, const State& b) {
            double worst = 0;
            for (std::size_t k = 0; k < a.size(); ++k) worst = std::max(worst, std::abs(a[k] - b[k]) / scale[k]);
            return worst;
        };
        HertzImpactOutcome out{};
        State y{0, v, p_.tangentialSpeed, 0, 0};
        sliding_ = 6 * p_.effectiveShearModulus / p_.effectiveYoungsModulus * std::abs(p_.tangentialSpeed) >
                   p_.friction * v;
        direction_ = p_.tangentialSpeed >= 0 ? 1 : -1;
        out.slidAtTouch = sliding_;
        double t = 0, h = 1e-3 * tc;
        while (t < 100 * tc) {
            const State whole = rungeKutta(y, h), halves = rungeKutta(rungeKutta(y, h / 2), h / 2);
            // (plus round-off, which no step size can lower)
            const double stepError = error(whole, halves) / 15, allowed = tolerance * h / tc + 1e-15;
            if (stepError > allowed && h > 1e-14 * tc) {
                h *= std::max(0.2, 0.9 * std::pow(allowed / stepError, 0.2));
                continue;
            }
            // Which event ends this step first: the separation or a change of phase.
            const bool separates = halves[0] <= 0;
            const bool switches = phaseEnds(halves);
            if (!separates && !switches) {
                y = keepSpringAtLimit(halves), t += h;
                ++out.steps;
                h *= std::min(2.0, 0.9 * std::pow(allowed / std::max(stepError, 1e-300), 0.2));
                continue;
            }
            double low = 0, high = h;  // the earliest event lies in (low, high]
            auto at = [&](double tau) { return rungeKutta(rungeKutta(y, tau / 2), tau / 2); };
            for (int k = 0; k < 80; ++k) {
                const double middle = 0.5 * (low + high);
                const State there = at(middle);
                ((separates && there[0] <= 0) || (switches && phaseEnds(there)) ? high : low) = middle;
            }
            const State there = at(high);
            t += high;
            if (there[0] <= 0) {  // separated (the forces are zero from x = 0 on)
                out.normalSpeedAfter = -there[1];
                out.vx = there[2], out.wy = there[3], out.duration = t;
                return out;
            }
            y = keepSpringAtLimit(there);
            sliding_ = !sliding_;
            if (sliding_) direction_ = y[4] >= 0 ? 1 : -1;
            ++out.phaseChanges;
        }
        out.normalSpeedAfter = NAN;  // never separated: the caller's parameters are wrong
        return out;
    }

private:
    using State = std::array<double, 5>;  // x, u, vx, wy, xi

    double normalForce(double x, double u) const {
        if (x <= 0) return 0;
        const double normalStiffness = 2 * p_.effectiveYoungsModulus * std::sqrt(p_.effectiveRadius * x);  // Sn
        return 4.0 / 3.0 * p_.effectiveYoungsModulus * std::sqrt(p_.effectiveRadius) * std::pow(x, 1.5) +
               dampingPrefactor_ * std::sqrt(normalStiffness * p_.reducedMass) * u;
    }
    double tangentialStiffness(double x) const {
        return x <= 0 ? 0 : 8 * p_.effectiveShearModulus * std::sqrt(p_.effectiveRadius * x);
    }
    double contactPointSpeed(const State& y) const { return y[2] - (p_.radius - 0.5 * y[0]) * y[3]; }

    State rate(const State& y) const {
        const double fn = normalForce(y[0], y[1]);
        const double ft = sliding_ ? -direction_ * p_.friction * fn : -tangentialStiffness(y[0]) * y[4];
        const double lever = p_.radius - 0.5 * y[0];
        return {y[1], -fn / p_.reducedMass, ft / p_.reducedMass, -lever * ft / p_.inertia,
                sliding_ ? 0.0 : contactPointSpeed(y)};
    }

    State rungeKutta(const State& y, double h) const {
        auto plus = [](const State& a, double c, const State& b) {
            State r;
            for (std::size_t k = 0; k < a.size(); ++k) r[k] = a[k] + c * b[k];
            return r;
        };
        const State k1 = rate(y), k2 = rate(plus(y, h / 2, k1)), k3 = rate(plus(y, h / 2, k2)), k4 = rate(plus(y, h, k3));
        State r;
        for (std::size_t k = 0; k < y.size(); ++k) r[k] = y[k] + h / 6 * (k1[k] + 2 * k2[k] + 2 * k3[k] + k4[k]);
        return r;
    }

    // The header's switching rules, with the phase as it is now.
    bool phaseEnds(const State& y) const {
        if (y[0] <= 0 || p_.friction <= 0) return false;
        if (!sliding_) return tangentialStiffness(y[0]) * std::abs(y[4]) > p_.friction * normalForce(y[0], y[1]);
        return direction_ * contactPointSpeed(y) <
               p_.friction * p_.effectiveYoungsModulus / (6 * p_.effectiveShearModulus) * y[1];
    }
    State keepSpringAtLimit(State y) const {
        if (sliding_) y[4] = direction_ * p_.friction * p_.effectiveYoungsModulus / (6 * p_.effectiveShearModulus) * y[0];
        return y;
    }

    HertzImpact p_;
    double dampingPrefactor_;
    bool sliding_ = false;  // the phase of the step being integrated
    double direction_ = 1;  // s: the sign of the sliding spring
};

}  // namespace talus::test
