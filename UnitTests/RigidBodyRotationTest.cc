// The rotation of non-spherical rigid bodies, Particles/RigidBodyRotation.h: conservation laws,
// the analytic solutions of Euler's equations (stable and unstable axes with the elliptic flip
// period, the symmetric top, uniform angular acceleration), second-order convergence to an
// independent fine Runge-Kutta solution, time reversibility, and refused input.
//
// Conventions (as in the header): q turns body into lab vectors, L is the lab angular momentum,
// M = A^T L its body components, omega_body = M / I componentwise.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <random>
#include <vector>

#include "Particles/RigidBodyRotation.h"
#include "TestHelpers.h"

using namespace talus;

namespace {

// Moments of inertia used throughout (mass 1). A solid ellipsoid with semi-axes (a, b, c) has
// I = (b^2 + c^2, a^2 + c^2, a^2 + b^2) / 5.
const Vec3 textbookBody(1, 2, 3);
// Triaxial ellipsoid, semi-axes (0.75, 0.5, 1.0) (longest : shortest = 2 : 1): the intermediate
// axis is x, the major (largest I) y and the minor z, so no axis order is assumed.
const Vec3 triaxialEllipsoid((0.25 + 1.0) / 5, (0.5625 + 1.0) / 5, (0.5625 + 0.25) / 5);
// Prolate spheroid of aspect ratio 2, semi-axes (0.5, 0.5, 1): a symmetric top, I1 = I2 != I3.
const Vec3 prolateSpheroid((0.25 + 1.0) / 5, (0.25 + 1.0) / 5, (0.25 + 0.25) / 5);

// Some orientation that is not special.
Quat genericOrientation() {
    return Quat(Eigen::AngleAxisd(0.7, Vec3(1, -2, 0.5).normalized()) * Eigen::AngleAxisd(2.1, Vec3(0.3, 1, 1).normalized()));
}

// The angle of the rotation that takes a to b (quaternions up to sign).
double angleBetween(const Quat& a, const Quat& b) {
    const Quat d = a.conjugate() * b;
    return 2 * std::atan2(d.vec().norm(), std::abs(d.w()));
}

// One body: orientation, lab angular momentum, principal inertia; it starts turning at the body
// angular velocity omegaBody.
struct Body {
    Quat q;
    Vec3 L;
    Vec3 I;

    Body(const Vec3& inertia, const Vec3& omegaBody, const Quat& orientation = genericOrientation())
        : q(orientation), L(orientation * inertia.cwiseProduct(omegaBody).eval()), I(inertia) {}

    // One kick-drift-kick step; torque(q) is the lab torque at orientation q.
    void step(double dt, const std::function<Vec3(const Quat&)>& torque) {
        kickAngularMomentum(L, torque(q), dt / 2);
        driftOrientation(q, L, I, dt);
        kickAngularMomentum(L, torque(q), dt / 2);
    }
    void step(double dt) { driftOrientation(q, L, I, dt); }  // torque-free: the kicks add zero

    Vec3 bodyMomentum() const { return q.conjugate() * L; }
    Vec3 bodyOmega() const { return bodyMomentum().cwiseQuotient(I); }
};

// Energy and momentum of the initial state, from the definitions (not from the code under test).
double energyOf(const Vec3& I, const Vec3& omegaBody) { return 0.5 * omegaBody.dot(I.cwiseProduct(omegaBody)); }

// Starts near each principal axis (0.01 off) and in a generic direction, |omega| = 1.
std::vector<Vec3> startingAngularVelocities() {
    return {Vec3(1, 0.01, -0.01).normalized(), Vec3(0.01, 1, 0.01).normalized(), Vec3(-0.01, 0.01, 1).normalized(),
            Vec3(0.6, -0.5, 0.62).normalized()};
}

// Period of the torque-free motion of an asymmetric body (Landau & Lifshitz, Mechanics, 37).
// Sort the moments I1 < I2 < I3, with invariants M^2 = sum I_i^2 w_i^2 and 2E = sum I_i w_i^2.
// Eliminating w1^2 and w3^2 with the invariants,
//     I1 (I3 - I1) w1^2 = (2E I3 - M^2) - I2 (I3 - I2) w2^2,
//     I3 (I3 - I1) w3^2 = (M^2 - 2E I1) - I2 (I2 - I1) w2^2,
// and squaring Euler's I2 dw2/dt = (I3 - I1) w3 w1 gives, with w2 = sqrt((2E I3 - M^2) / (I2
// (I3 - I2))) s,
//     (ds/dt)^2 = lambda^2 (1 - s^2)(1 - k^2 s^2),
//     lambda^2 = (I3 - I2)(M^2 - 2E I1) / (I1 I2 I3),  k^2 = (I2 - I1)(2E I3 - M^2) / ((I3 - I2)(M^2 - 2E I1)),
// so s = sn(lambda t, k), whose period is 4 K(k) (K the complete elliptic integral of the first
// kind): w2 changes sign twice per period T = 4 K(k) / lambda. This holds for M^2 > 2E I2
// (k < 1); for M^2 < 2E I2 the same follows with I1 and I3 exchanged.
double eulerPeriod(Vec3 I, const Vec3& omegaBody) {
    const double M2 = I.cwiseProduct(omegaBody).squaredNorm(), twoE = 2 * energyOf(I, omegaBody);
    std::sort(I.data(), I.data() + 3);
    double I1 = I[0], I2 = I[1], I3 = I[2];
    if (M2 < twoE * I2) std::swap(I1, I3);
    const double lambda = std::sqrt((I3 - I2) * (M2 - twoE * I1) / (I1 * I2 * I3));
    const double k = std::sqrt((I2 - I1) * (twoE * I3 - M2) / ((I3 - I2) * (M2 - twoE * I1)));
    return 4 * std::comp_ellint_1(k) / lambda;
}

int axisOf(const Vec3& I, bool largest) {
    int k = 0;
    largest ? I.maxCoeff(&k) : I.minCoeff(&k);
    return k;
}

// The intermediate axis: neither the largest nor the smallest moment.
int intermediateAxis(const Vec3& I) { return 3 - axisOf(I, true) - axisOf(I, false); }

// Euler's equations and the quaternion kinematics, dM/dt = M x omega, dq/dt = q (0, omega) / 2
// with omega = M / I in the body frame, solved by classical Runge-Kutta (an independent reference).
void rungeKuttaStep(Quat& q, Vec3& M, const Vec3& I, double h) {
    using State = Eigen::Matrix<double, 7, 1>;
    const auto rate = [&](const State& y) {
        const Quat qy(y[0], y[1], y[2], y[3]);
        const Vec3 My = y.tail<3>(), omega = My.cwiseQuotient(I);
        const Quat dq = qy * Quat(0, omega.x(), omega.y(), omega.z());
        State r;
        r << 0.5 * dq.w(), 0.5 * dq.x(), 0.5 * dq.y(), 0.5 * dq.z(), My.cross(omega);
        return r;
    };
    State y;
    y << q.w(), q.x(), q.y(), q.z(), M;
    const State k1 = rate(y), k2 = rate(y + h / 2 * k1), k3 = rate(y + h / 2 * k2), k4 = rate(y + h * k3);
    y += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
    q = Quat(y[0], y[1], y[2], y[3]).normalized();
    M = y.tail<3>();
}

// The lab angular velocity that turns q0 into q2 over the time 2 dt, read off the orientations
// alone: the rotation q2 q0^* (lab frame) has the rotation vector 2 dt omega(t1) + O(dt^3) (the
// central difference of the orientation at the middle step).
Vec3 angularVelocityFromOrientations(const Quat& q0, const Quat& q2, double dt) {
    Quat d = q2 * q0.conjugate();
    if (d.w() < 0) d.coeffs() = -d.coeffs();  // the shorter way round
    const double sine = d.vec().norm();
    if (sine == 0) return Vec3::Zero();
    return 2 * std::atan2(sine, d.w()) / sine * d.vec() / (2 * dt);
}

}  // namespace

// Torque-free: the energy of a symplectic step oscillates within O(dt^2) without drift, and L
// stays what it was. The drift leaves the stored L alone by construction, so L is checked as the
// motion of q gives it, independently of the stored L: L_kin = A I A^T omega with omega the
// central difference of the orientations (angularVelocityFromOrientations) and A I A^T the lab
// inertia at the middle orientation. Its error is that of the difference quotient, O(dt^2), plus
// the integrator's O(dt^2) error in the motion; an orientation turned at a wrong rate or about a
// wrong axis (a first-order error or a wrong moment in a piece of the splitting) shows as O(dt)
// or O(1): measured at most 2.1e-5, bounded by 1e-4 (the isotropic piece turned 1% too fast
// gives 6.5e-3 to 1.3e-2, with the energy unchanged). |omega| = 1, dt = 0.01, 10^5 steps
// (t = 1000, some 160 turns). The textbook body (1, 2, 3) is a flat lamina (I3 = I1 + I2), the
// hardest case of this splitting: energy error 3.4e-6 at dt = 0.02, 8.5e-7 here.
TEST(RigidBodyRotation, TorqueFreeBodyConservesEnergyAndAngularMomentum) {
    const double dt = 0.01;
    double worstOfAll = 0;
    for (const Vec3& I : {textbookBody, triaxialEllipsoid}) {
        for (const Vec3& omega : startingAngularVelocities()) {
            Body body(I, omega);
            const Vec3 L0 = body.L;
            const double E0 = energyOf(I, omega);
            EXPECT_NEAR(rotationalKineticEnergy(body.q, body.L, I), E0, 1e-15);
            double worstEnergy = 0, worstMomentum = 0, worstEarlyEnergy = 0;
            Quat before = body.q;
            for (int n = 0; n < 100000; ++n) {
                const Quat middle = body.q;
                body.step(dt);
                worstEnergy = std::max(worstEnergy, std::abs(rotationalKineticEnergy(body.q, body.L, I) / E0 - 1));
                if (n > 0) {
                    const Vec3 kinematicL = labInertia(middle, I) * angularVelocityFromOrientations(before, body.q, dt);
                    worstMomentum = std::max(worstMomentum, (kinematicL - L0).norm() / L0.norm());
                }
                before = middle;
                if (n < 10000) worstEarlyEnergy = worstEnergy;
            }
            worstOfAll = std::max(worstOfAll, worstMomentum);
            std::printf("[ measured ] I = (%g, %g, %g), omega_body(0) = (%.3f, %.3f, %.3f): energy error %.2e, "
                        "L from the motion of q: error %.2e, |q| - 1 = %.1e\n",
                        I.x(), I.y(), I.z(), omega.x(), omega.y(), omega.z(), worstEnergy, worstMomentum,
                        body.q.norm() - 1);
            EXPECT_LT(worstEnergy, 1e-6);
            EXPECT_LT(worstEnergy, 1.5 * worstEarlyEnergy);  // no drift: the first tenth of the run saw most of it
            EXPECT_LT(worstMomentum, 1e-4);
            EXPECT_EQ(body.L, L0);  // the drift does not touch L (the header's promise)
            EXPECT_NEAR(body.q.norm(), 1, 1e-15);
        }
    }
}

// Rotation about the axis of largest or smallest moment is stable: started 0.01 rad off, the body
// angular momentum stays within a small cone about that axis (for ever, analytically: the
// intersection of the momentum sphere with the energy ellipsoid is a small loop there).
TEST(RigidBodyRotation, RotationAboutMajorAndMinorAxesIsStable) {
    const double dt = 0.02;
    for (const Vec3& I : {textbookBody, triaxialEllipsoid}) {
        for (bool major : {true, false}) {
            const int k = axisOf(I, major);
            Vec3 omega = Vec3::Constant(0.01 / std::sqrt(2.0));
            omega[k] = 1;
            Body body(I, omega);
            double widestCone = 0;
            for (int n = 0; n < 100000; ++n) {
                body.step(dt);
                const Vec3 M = body.bodyMomentum();
                widestCone = std::max(widestCone, std::acos(std::min(1.0, M[k] / M.norm())));
            }
            std::printf("[ measured ] I = (%g, %g, %g), %s axis: widest angle of M from the axis %.4f rad\n", I.x(),
                        I.y(), I.z(), major ? "major" : "minor", widestCone);
            EXPECT_LT(widestCone, 0.05);
        }
    }
}

// Dzhanibekov effect: started 0.01 off along both other axes, the body flips over and over: the
// body angular velocity along that axis changes sign, with the period of eulerPeriod. Measured
// 7.4e-6 and 4.2e-6 off at |omega| dt = 0.02 (the step's own error and the linear interpolation
// of the crossings within a step): checked to 1e-4 (was 1e-2).
TEST(RigidBodyRotation, IntermediateAxisFlipsWithTheEllipticPeriod) {
    const double dt = 0.02;
    for (const Vec3& I : {textbookBody, triaxialEllipsoid}) {
        const int m = intermediateAxis(I);
        Vec3 omega = Vec3::Constant(0.01);
        omega[m] = 1;
        Body body(I, omega);
        std::vector<double> downCrossings;  // times where omega_m goes from + to - (once per period)
        int signChanges = 0;
        double previous = body.bodyOmega()[m];
        for (int n = 1; n <= 100000; ++n) {
            body.step(dt);
            const double current = body.bodyOmega()[m];
            if ((previous > 0) != (current > 0)) {
                ++signChanges;
                if (previous > 0) downCrossings.push_back((n - 1 + previous / (previous - current)) * dt);
            }
            previous = current;
        }
        ASSERT_GE(downCrossings.size(), 5u);
        const double measured = (downCrossings.back() - downCrossings.front()) / double(downCrossings.size() - 1);
        const double analytic = eulerPeriod(I, omega);
        std::printf("[ measured ] I = (%g, %g, %g): %d flips, period %.5f, analytic %.5f, relative error %.2e\n", I.x(),
                    I.y(), I.z(), signChanges, measured, analytic, measured / analytic - 1);
        EXPECT_NEAR(measured / analytic, 1, 1e-4);
        EXPECT_GE(signChanges, 2 * int(downCrossings.size()) - 2);
    }
}

// Symmetric top I1 = I2 != I3. Euler's equations give omega3 constant and
// d(omega1 + i omega2)/dt = i Omega (omega1 + i omega2), Omega = (I3 - I1) / I1 * omega3: the body
// angular velocity precesses about the symmetry axis at the rate Omega. In the lab, omega =
// L / I1 + (1/I3 - 1/I1) M3 e3, so de3/dt = omega x e3 = (L / I1) x e3: the symmetry axis turns
// about the fixed L at the rate |L| / I1, at a constant angle. The step is exact for a body of
// revolution (header), so both hold to round-off at a coarse step.
TEST(RigidBodyRotation, SymmetricTopPrecessesAtTheAnalyticRate) {
    const Vec3 I = prolateSpheroid;
    const Vec3 omega0(0.3, 0.4, 2.0);
    const double Omega = (I.z() - I.x()) / I.x() * omega0.z();
    const double dt = 0.05 / omega0.norm();
    Body body(I, omega0);
    const Vec3 L = body.L;
    const Vec3 axis0 = body.q * Vec3::UnitZ();
    const int steps = 20000;  // Omega t = -580 rad, 93 body precession periods
    double bodyAngle = std::atan2(omega0.y(), omega0.x()), previousAngle = bodyAngle, worstNutation = 0;
    for (int n = 0; n < steps; ++n) {
        body.step(dt);
        const Vec3 w = body.bodyOmega();
        const double angle = std::atan2(w.y(), w.x());
        bodyAngle += std::remainder(angle - previousAngle, 2 * pi);  // unwrapped
        previousAngle = angle;
        worstNutation = std::max(worstNutation, std::abs((body.q * Vec3::UnitZ()).dot(L) - axis0.dot(L)) / L.norm());
    }
    const double t = steps * dt;
    const double bodyRateError = ((bodyAngle - std::atan2(omega0.y(), omega0.x())) / t) / Omega - 1;
    // The lab precession: e3 turned about L by |L| t / I1 from where it started.
    const Vec3 expectedAxis = Eigen::AngleAxisd(L.norm() * t / I.x(), L.normalized()) * axis0;
    const double labAxisError = (body.q * Vec3::UnitZ() - expectedAxis).norm();
    std::printf("[ measured ] symmetric top: body precession rate error %.2e over %.0f periods, lab axis error %.2e, "
                "nutation change %.2e\n",
                bodyRateError, std::abs(Omega) * t / (2 * pi), labAxisError, worstNutation);
    EXPECT_LT(std::abs(bodyRateError), 1e-10);
    EXPECT_LT(labAxisError, 1e-10);
    EXPECT_LT(worstNutation, 1e-12);
}

// Orientation and body momentum against a Runge-Kutta solution of Euler's equations with a step 64
// times smaller (its error ~1e-14): the error is O(dt^2), so it drops by ~4 when dt halves.
TEST(RigidBodyRotation, FollowsEulersEquationsWithSecondOrderError) {
    const double endTime = 20;
    for (const Vec3& I : {textbookBody, triaxialEllipsoid}) {
        const Vec3 omega0 = Vec3(0.6, -0.5, 0.62).normalized();
        std::vector<double> errors;
        for (int steps : {1000, 2000, 4000}) {
            const double dt = endTime / steps;
            Body body(I, omega0);
            Quat qReference = body.q;
            Vec3 MReference = I.cwiseProduct(omega0);
            for (int n = 0; n < steps; ++n) {
                body.step(dt);
                for (int r = 0; r < 64; ++r) rungeKuttaStep(qReference, MReference, I, dt / 64);
            }
            errors.push_back(angleBetween(body.q, qReference) + (body.bodyMomentum() - MReference).norm() / MReference.norm());
        }
        std::printf("[ measured ] I = (%g, %g, %g): error at |omega| dt = 0.02, 0.01, 0.005: %.2e %.2e %.2e (ratios %.2f %.2f)\n",
                    I.x(), I.y(), I.z(), errors[0], errors[1], errors[2], errors[0] / errors[1], errors[1] / errors[2]);
        EXPECT_LT(errors[0], 1e-2);
        EXPECT_NEAR(errors[0] / errors[1], 4, 0.4);
        EXPECT_NEAR(errors[1] / errors[2], 4, 0.4);
    }
}

// A constant torque tau along a principal axis of a body at rest: the body turns about that axis
// with theta = tau t^2 / (2 I_k). Velocity Verlet is exact for a constant acceleration, so the
// angle is right to round-off, whichever axis (the median axis of the splitting or one of the
// others).
TEST(RigidBodyRotation, ConstantTorqueAboutPrincipalAxisGivesUniformAcceleration) {
    const double dt = 1e-3, tau = 0.3;
    const int steps = 2000;
    const double t = steps * dt;
    for (const Vec3& I : {textbookBody, triaxialEllipsoid}) {
        for (int k = 0; k < 3; ++k) {
            Body body(I, Vec3::Zero());
            const Quat q0 = body.q;
            const Vec3 labAxis = q0 * Vec3::Unit(k);
            const auto torque = [&](const Quat&) -> Vec3 { return tau * labAxis; };
            for (int n = 0; n < steps; ++n) body.step(dt, torque);
            const double theta = tau * t * t / (2 * I[k]);
            const Quat expected = Quat(Eigen::AngleAxisd(theta, labAxis)) * q0;
            EXPECT_LT(angleBetween(body.q, expected), 1e-12) << "axis " << k << ", theta " << theta;
            EXPECT_LT((body.L - tau * t * labAxis).norm(), 1e-13);
            EXPECT_LT((angularVelocity(body.q, body.L, I) - tau * t / I[k] * labAxis).norm(), 1e-12);
        }
    }
}

// Integrate forward, negate L, integrate as long again: back to the start up to round-off (the
// splitting is symmetric). Also with an orientation-dependent torque (a heavy top: gravity on a
// centre of mass offset c in the body, torque (A c) x (0, 0, -1)), since the kicks are symmetric
// too. The heavy top's motion is sensitive to its initial state, so round-off grows to
// ~1e-11 - 1e-10 there (it depends on the build: -march=native fuses multiply-adds).
TEST(RigidBodyRotation, IsTimeReversible) {
    const double dt = 0.02;
    const Vec3 offset(0.2, -0.1, 0.5);
    const auto gravityTorque = [&](const Quat& q) -> Vec3 { return (q * offset).cross(Vec3(0, 0, -1)); };
    const auto noTorque = [](const Quat&) -> Vec3 { return Vec3::Zero(); };
    for (const Vec3& I : {textbookBody, triaxialEllipsoid, prolateSpheroid}) {
        for (bool heavy : {false, true}) {
            Body body(I, Vec3(0.6, -0.5, 0.62).normalized());
            const Quat q0 = body.q;
            const Vec3 L0 = body.L;
            const auto torque = heavy ? std::function<Vec3(const Quat&)>(gravityTorque) : noTorque;
            for (int n = 0; n < 2000; ++n) body.step(dt, torque);
            const double turned = angleBetween(q0, body.q);
            body.L = -body.L;
            for (int n = 0; n < 2000; ++n) body.step(dt, torque);
            const double qError = angleBetween(q0, body.q), LError = (body.L + L0).norm() / L0.norm();
            std::printf("[ measured ] reversibility, I = (%g, %g, %g)%s: after turning %.2f rad, back to %.1e rad, "
                        "L error %.1e\n",
                        I.x(), I.y(), I.z(), heavy ? ", heavy top" : "", turned, qError, LError);
            EXPECT_GT(turned, 0.1);
            EXPECT_LT(qError, 1e-9);
            EXPECT_LT(LError, 1e-9);
        }
    }
}

// A heavy top (gravity (0, 0, -1) on a centre of mass at c in the body, pivot at the origin):
// torque (A c) x (0, 0, -1), potential energy z = (A c) . e_z. T + V is conserved up to the bounded
// O(dt^2) error of a symplectic step (measured: a quarter of it at dt / 2, and no larger after 10^5
// steps than after 10^4); a wrong sign or frame in the torque kicks would make it drift.
TEST(RigidBodyRotation, HeavyTopConservesTotalEnergy) {
    const Vec3 offset(0.2, -0.1, 0.5), gravity(0, 0, -1);
    const auto torque = [&](const Quat& q) -> Vec3 { return (q * offset).cross(gravity); };
    const auto totalEnergy = [&](const Body& b) {
        return rotationalKineticEnergy(b.q, b.L, b.I) - gravity.dot(b.q * offset);
    };
    for (const Vec3& I : {textbookBody, triaxialEllipsoid}) {
        Body body(I, Vec3(0.6, -0.5, 0.62).normalized());
        const double E0 = totalEnergy(body), scale = rotationalKineticEnergy(body.q, body.L, I) + offset.norm();
        double worst = 0, worstEarly = 0;
        for (int n = 0; n < 100000; ++n) {
            body.step(0.01, torque);
            worst = std::max(worst, std::abs(totalEnergy(body) - E0) / scale);
            if (n < 10000) worstEarly = worst;
        }
        std::printf("[ measured ] heavy top, I = (%g, %g, %g), dt = 0.01: energy error %.2e (of T + m g |c|)\n", I.x(),
                    I.y(), I.z(), worst);
        EXPECT_LT(worst, 1e-4);
        EXPECT_LT(worst, 1.5 * worstEarly);  // no drift
    }
}

// I1 = I2 = I3: omega = L / I like a sphere (Simulation::integrate kicks omega += dt/2 tau / I),
// and without torque the body turns about the fixed omega at the angle |omega| t.
TEST(RigidBodyRotation, SphereLikeBodyTurnsLikeASphere) {
    const Vec3 I = Vec3::Constant(0.1);  // a sphere of mass 1, diameter 1: 2/5 m r^2
    const double dt = 1e-3;
    const Vec3 omega0(3, -1, 2);
    Body body(I, genericOrientation().conjugate() * omega0);  // lab omega = omega0
    const Quat q0 = body.q;
    Vec3 sphereOmega = omega0;
    const auto torque = [](double t) { return Vec3(std::sin(t), std::cos(2 * t), 0.3); };
    for (int n = 0; n < 1000; ++n) {
        kickAngularMomentum(body.L, torque(n * dt), dt / 2);
        sphereOmega += dt / 2 / I.x() * torque(n * dt);
        driftOrientation(body.q, body.L, I, dt);
        kickAngularMomentum(body.L, torque((n + 1) * dt), dt / 2);
        sphereOmega += dt / 2 / I.x() * torque((n + 1) * dt);
        ASSERT_LT((angularVelocity(body.q, body.L, I) - sphereOmega).norm(), 1e-12 * sphereOmega.norm()) << n;
    }
    // Torque-free: a uniform rotation about the fixed lab omega.
    body.q = q0;
    body.L = I.x() * omega0;
    for (int n = 0; n < 10000; ++n) body.step(dt);
    const Quat expected = Quat(Eigen::AngleAxisd(omega0.norm() * 10000 * dt, omega0.normalized())) * q0;
    EXPECT_LT(angleBetween(body.q, expected), 1e-11);
    EXPECT_LT((angularVelocity(body.q, body.L, I) - omega0).norm(), 1e-14);
}

// The derived quantities against their definitions for a quarter turn about z, where the body x
// axis points along lab y: the lab inertia is diag(I2, I1, I3), a lab omega along y is a body omega
// along x, and so on.
TEST(RigidBodyRotation, DerivedQuantitiesAgreeWithTheirDefinitions) {
    const Vec3 I = textbookBody;
    const Quat quarterTurn(Eigen::AngleAxisd(pi / 2, Vec3::UnitZ()));
    const Mat3 expectedInertia = Vec3(I.y(), I.x(), I.z()).asDiagonal();
    EXPECT_LT((labInertia(quarterTurn, I) - expectedInertia).norm(), 1e-15);
    const Vec3 labOmega(0.5, -2, 1.5);  // body omega (-2, -0.5, 1.5), body L (-2, -1, 4.5)
    const Vec3 L = angularMomentumFromVelocity(quarterTurn, labOmega, I);
    EXPECT_LT((L - Vec3(1, -2, 4.5)).norm(), 1e-15);
    EXPECT_LT((angularVelocity(quarterTurn, L, I) - labOmega).norm(), 1e-15);
    EXPECT_NEAR(rotationalKineticEnergy(quarterTurn, L, I), 0.5 * (1 * 4 + 2 * 0.25 + 3 * 2.25), 1e-14);
    // Any orientation: L = (A I A^T) omega and T = omega . L / 2.
    const Quat q = genericOrientation();
    EXPECT_LT((angularMomentumFromVelocity(q, labOmega, I) - labInertia(q, I) * labOmega).norm(), 1e-14);
    EXPECT_NEAR(rotationalKineticEnergy(q, labInertia(q, I) * labOmega, I), 0.5 * labOmega.dot(labInertia(q, I) * labOmega),
                1e-13);
}

TEST(RigidBodyRotation, BadOrientationOrInertiaIsAnError) {
    const Quat q = genericOrientation();
    EXPECT_NO_THROW(requireValidOrientation(q, "particle 7"));
    const Quat nearlyUnit(q.coeffs() * (1 + 0.5e-6));
    EXPECT_NO_THROW(requireValidOrientation(nearlyUnit, "particle 7"));
    const Quat stretched(q.coeffs() * (1 + 2e-6));
    test::expectError([&] { requireValidOrientation(stretched, "restart file a.restart, particle 7"); },
                      {"restart file a.restart, particle 7", "orientation", "not normalised", "|q|"});
    test::expectError([&] { requireValidOrientation(Quat(0, 0, 0, 0), "particle 7"); }, {"particle 7", "not normalised"});
    const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
    test::expectError([&] { requireValidOrientation(Quat(nan, 0, 0, 1), "particle 8"); },
                      {"particle 8", "orientation", "not finite", "nan"});
    test::expectError([&] { requireValidOrientation(Quat(1, 0, inf, 0), "particle 8"); }, {"particle 8", "not finite"});

    EXPECT_NO_THROW(requirePositiveInertia(triaxialEllipsoid, "shape 2"));
    for (const Vec3& bad : {Vec3(1, 0, 1), Vec3(1, 2, -3), Vec3(nan, 1, 1), Vec3(1, inf, 1)})
        test::expectError([&] { requirePositiveInertia(bad, "shape 2"); }, {"shape 2", "moments of inertia", "positive"});
}

// The small-angle sine and cosine of the drift (detail::sinCos) against the library's, on both
// sides of the switch to the library at 1/16 and at the angles a step turns (1e-8 to 1e-2).
TEST(RigidBodyRotation, SmallAngleSineAndCosineAreExactToRounding) {
    const double eps = std::numeric_limits<double>::epsilon();
    double worstSin = 0, worstCos = 0;
    for (int k = -4000; k <= 4000; ++k) {
        for (double x : {k * (0.07 / 4000), k * 1e-6, std::ldexp(static_cast<double>(k), -40)}) {
            double s, c;
            detail::sinCos(x, s, c);
            if (x != 0) worstSin = std::max(worstSin, std::abs(s - std::sin(x)) / std::abs(std::sin(x)));
            worstCos = std::max(worstCos, std::abs(c - std::cos(x)));
        }
    }
    EXPECT_LE(worstSin, 2 * eps);
    EXPECT_LE(worstCos, 2 * eps);
    double s, c;
    detail::sinCos(3.0, s, c);  // beyond the series: the library's
    EXPECT_EQ(s, std::sin(3.0));
    EXPECT_EQ(c, std::cos(3.0));
}

// The inlined quaternion arithmetic on plain numbers (turned, product) against Eigen's quaternion
// rotation and product, and turned against the rotation matrix, for random quaternions and vectors.
TEST(RigidBodyRotation, PlainQuaternionArithmeticAgreesWithEigen) {
    std::mt19937_64 random(20261201);
    std::normal_distribution<double> gauss;
    double worstTurn = 0, worstMatrix = 0, worstProduct = 0;
    for (int n = 0; n < 1000; ++n) {
        const Quat a = Quat(gauss(random), gauss(random), gauss(random), gauss(random)).normalized();
        const Quat b = Quat(gauss(random), gauss(random), gauss(random), gauss(random)).normalized();
        const Vec3 v(gauss(random), gauss(random), gauss(random));
        worstTurn = std::max(worstTurn, (turned(a, v) - a * v).norm() / v.norm());
        worstMatrix = std::max(worstMatrix, (turned(a, v) - a.toRotationMatrix() * v).norm() / v.norm());
        worstProduct = std::max(worstProduct, (product(a, b).coeffs() - (a * b).coeffs()).norm());
    }
    EXPECT_LT(worstTurn, 1e-15 * 8);
    EXPECT_LT(worstMatrix, 1e-15 * 8);
    EXPECT_LT(worstProduct, 1e-15 * 8);
    // A quarter turn about z takes x to y (the direction convention, not just agreement).
    const Quat quarter(std::cos(pi / 4), 0, 0, std::sin(pi / 4));
    EXPECT_LT((turned(quarter, Vec3::UnitX()) - Vec3::UnitY()).norm(), 1e-15);
    EXPECT_LT((turned(quarter.conjugate(), Vec3::UnitY()) - Vec3::UnitX()).norm(), 1e-15);
}
