// Rotation of a non-spherical rigid particle (Theory/Integration.md eq. (7)-(10): "the full
// rigid-body equations, not scalar"); Documentation/Superquadrics/RigidBodyRotation.md derives what
// is written here.
//
// State of one particle:
//   orientation q      unit quaternion, body to lab: x_lab = A(q) x_body, A = R(q);
//   angular momentum L in the LAB frame;
//   principal inertia  I = (I1, I2, I3) about the body axes (a shape's body axes are its
//                      principal axes), constant, so it lives with the shape, not the particle.
// Why L in the lab frame: contact torques are lab vectors, so the torque kick is the plain add
// L += tau dt/2 that the spheres do for their velocities (Simulation::integrate), and the
// torque-free drift leaves L untouched, so L (all three components, hence |L|) is conserved to the
// last bit by construction. Body quantities (M = A^T L, omega_body = M / I) are derived.
//
// The integrator is velocity Verlet for rotation, as Dullweber, Leimkuhler & McLachlan,
// J. Chem. Phys. 107, 5840 (1997) (DLM), split it: the torque kicks L for half a step, the
// torque-free rigid body drifts q for a whole step, the new torque kicks L for half a step:
//     kickAngularMomentum(L, torque, dt / 2);
//     driftOrientation(q, L, I, dt);
//     ... contact torques at the new orientation ...
//     kickAngularMomentum(L, torque, dt / 2);
// The drift is a symmetric splitting of the kinetic energy T = sum_i M_i^2 / (2 I_i) into pieces
// whose flows are exact rotations, so it is symplectic and time-reversible: energy errors stay
// bounded (no drift) and are O(dt^2). See driftOrientation for the splitting chosen.
#pragma once

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "Error.h"
#include "Math/Vector.h"

namespace talus {

// How far |q| may be from 1 before a quaternion is refused as an orientation (restart files
// hold 17 digits, so a correct file is ~1e-16 off; anything beyond this is a broken file or state).
inline constexpr double orientationNormTolerance = 1e-6;

// Throws Error naming `what` unless q is finite and | |q| - 1 | <= orientationNormTolerance.
inline void requireValidOrientation(const Quat& q, const std::string& what) {
    if (std::isfinite(q.w()) && isFinite(q.vec()) && std::abs(q.norm() - 1) <= orientationNormTolerance) return;
    const std::string components =
        "(w, x, y, z) = (" + str(q.w()) + ", " + str(q.x()) + ", " + str(q.y()) + ", " + str(q.z()) + ")";
    require(std::isfinite(q.w()) && isFinite(q.vec()), what + ": orientation quaternion " + components + " is not finite");
    const double normError = std::abs(q.norm() - 1);
    require(normError <= orientationNormTolerance, what + ": orientation quaternion " + components +
                                                       " is not normalised: | |q| - 1 | = " + str(normError) +
                                                       " > " + str(orientationNormTolerance));
}

// Throws Error naming `what` unless all three principal moments of inertia are positive and finite.
inline void requirePositiveInertia(const Vec3& principalInertia, const std::string& what) {
    const Vec3& I = principalInertia;
    require(isFinite(I) && I.minCoeff() > 0, what + ": principal moments of inertia must be positive and finite, got (" +
                                                 str(I.x()) + ", " + str(I.y()) + ", " + str(I.z()) + ")");
}

// Half (or any part) of a velocity-Verlet kick: dL/dt = torque, exact for a constant torque.
inline void kickAngularMomentum(Vec3& angularMomentum, const Vec3& torque, double duration) {
    angularMomentum += duration * torque;
}

// Lab inertia tensor A I A^T (Theory/Superquadrics.md eq. (4)).
inline Mat3 labInertia(const Quat& orientation, const Vec3& principalInertia) {
    const Mat3 A = orientation.toRotationMatrix();
    return A * principalInertia.asDiagonal() * A.transpose();
}

namespace detail {

// The quaternion product (aw, a) (bw, b) into (aw, a).
[[gnu::always_inline]] inline void multiply(double& aw, double& ax, double& ay, double& az, double bw, double bx,
                                            double by, double bz) {
    const double w = aw * bw - ax * bx - ay * by - az * bz, x = aw * bx + ax * bw + ay * bz - az * by,
                 y = aw * by - ax * bz + ay * bw + az * bx, z = aw * bz + ax * by - ay * bx + az * bw;
    aw = w, ax = x, ay = y, az = z;
}
// v turned by the unit quaternion (w, u): v + 2w (u x v) + 2 u x (u x v).
[[gnu::always_inline]] inline void turn(double w, double ux, double uy, double uz, double& vx, double& vy, double& vz) {
    const double tx = 2 * (uy * vz - uz * vy), ty = 2 * (uz * vx - ux * vz), tz = 2 * (ux * vy - uy * vx);
    const double x = vx + w * tx + (uy * tz - uz * ty), y = vy + w * ty + (uz * tx - ux * tz),
                 z = vz + w * tz + (ux * ty - uy * tx);
    vx = x, vy = y, vz = z;
}
// The lab angular velocity omega = A I^-1 A^T L of the orientation q = (w, u), from the lab L and
// 1/I, into L's place.
[[gnu::always_inline]] inline void labSpin(double w, double ux, double uy, double uz, double& Lx, double& Ly,
                                           double& Lz, const double (&inverseInertia)[3]) {
    turn(w, -ux, -uy, -uz, Lx, Ly, Lz);  // M = A^T L
    Lx *= inverseInertia[0], Ly *= inverseInertia[1], Lz *= inverseInertia[2];
    turn(w, ux, uy, uz, Lx, Ly, Lz);
}

}  // namespace detail

// v turned by the unit quaternion q (q v q*), and the quaternion product a b, on plain numbers
// and always inlined: they run per particle and step, and as Eigen's GCC called them out of line.
[[gnu::always_inline]] inline Vec3 turned(const Quat& q, const Vec3& v) {
    double x = v.x(), y = v.y(), z = v.z();
    detail::turn(q.w(), q.x(), q.y(), q.z(), x, y, z);
    return {x, y, z};
}
[[gnu::always_inline]] inline Quat product(const Quat& a, const Quat& b) {
    double w = a.w(), x = a.x(), y = a.y(), z = a.z();
    detail::multiply(w, x, y, z, b.w(), b.x(), b.y(), b.z());
    return Quat(w, x, y, z);
}

// Lab angular velocity omega = A I^-1 A^T L, for contact kinematics (v + omega x branch).
inline Vec3 angularVelocity(const Quat& orientation, const Vec3& angularMomentum, const Vec3& principalInertia) {
    double x = angularMomentum.x(), y = angularMomentum.y(), z = angularMomentum.z();
    const double inverseInertia[3] = {1 / principalInertia.x(), 1 / principalInertia.y(), 1 / principalInertia.z()};
    detail::labSpin(orientation.w(), orientation.x(), orientation.y(), orientation.z(), x, y, z, inverseInertia);
    return {x, y, z};
}

// The lab angular momentum L = A I A^T omega of a body turning at lab angular velocity omega
// (to set initial conditions given as angular velocities).
inline Vec3 angularMomentumFromVelocity(const Quat& orientation, const Vec3& labAngularVelocity,
                                        const Vec3& principalInertia) {
    const Vec3 bodyVelocity = orientation.conjugate() * labAngularVelocity;
    return orientation * principalInertia.cwiseProduct(bodyVelocity).eval();
}

// Rotational kinetic energy T = L . omega / 2 = sum_i M_i^2 / (2 I_i).
inline double rotationalKineticEnergy(const Quat& orientation, const Vec3& angularMomentum, const Vec3& principalInertia) {
    const Vec3 bodyMomentum = orientation.conjugate() * angularMomentum;
    return 0.5 * bodyMomentum.dot(bodyMomentum.cwiseQuotient(principalInertia));
}

namespace detail {

// sin x and cos x for a small angle, |x| <= 1/16 (a step turns a particle by |omega| dt ~ 1e-3):
// the Taylor series to x^9 and x^10 is exact to rounding there (the next terms are below 1e-22
// relative) and several times cheaper than the library's sin and cos. Branch-free, for lanes.
[[gnu::always_inline]] inline void smallSinCos(double x, double& s, double& c) {
    const double x2 = x * x;
    s = x * (1 + x2 * (-1.0 / 6 + x2 * (1.0 / 120 + x2 * (-1.0 / 5040 + x2 * (1.0 / 362880)))));
    c = 1 + x2 * (-0.5 + x2 * (1.0 / 24 + x2 * (-1.0 / 720 + x2 * (1.0 / 40320 + x2 * (-1.0 / 3628800)))));
}
constexpr double smallAngle = 0.0625;
// Any angle: the series where it is exact, else the library's.
[[gnu::always_inline]] inline void sinCos(double x, double& s, double& c) {
    if (!(std::abs(x) <= smallAngle)) {
        s = std::sin(x), c = std::cos(x);
        return;
    }
    smallSinCos(x, s, c);
}

}  // namespace detail

// The body axes of the drift's splitting (driftOrientation, below), chosen once per inertia: the
// median axis m and its rate 1/Im; the outer and inner axes as unit vectors with their residual
// rates 1/Ik - 1/Im, the inner one the smaller in magnitude; and 1/I for the angular velocity.
struct RotationAxes {
    double medianRate;
    double outer[3], outerRate, inner[3], innerRate;
    double inverseInertia[3];
};
inline RotationAxes rotationAxesOf(const Vec3& principalInertia) {
    const Vec3& I = principalInertia;
    int smallest = 0, largest = 0;
    I.minCoeff(&smallest);
    I.maxCoeff(&largest);
    const int median = smallest == largest ? 0 : 3 - smallest - largest;  // all equal: any axis
    RotationAxes a{};
    for (int k = 0; k < 3; ++k) a.inverseInertia[k] = 1 / I[k];  // three divisions serve all the rates
    a.medianRate = a.inverseInertia[median];
    int outer = (median + 1) % 3, inner = (median + 2) % 3;
    a.outerRate = a.inverseInertia[outer] - a.medianRate, a.innerRate = a.inverseInertia[inner] - a.medianRate;
    if (std::abs(a.innerRate) > std::abs(a.outerRate)) {
        std::swap(outer, inner);
        std::swap(a.outerRate, a.innerRate);
    }
    a.outer[outer] = 1, a.inner[inner] = 1;
    return a;
}

// One particle's rotation on plain numbers, branch-free: written once for the scalar calls
// (driftOrientation, angularVelocity) and for lanes of particles that the compiler vectorises
// (Particles/RotationBatch.h).
struct RotationLane {
    double qw, qx, qy, qz;  // orientation
    double Lx, Ly, Lz;      // lab angular momentum
    RotationAxes axes;
    double wx, wy, wz;      // out: lab angular velocity (turnedSpin)
    double largestAngle;    // out: the largest half angle of the drift's pieces (detail::smallAngle)
};

namespace detail {

// The exact flow of T_k = rate M_k^2 / 2 (e the body axis k) for a time t: the body turns about
// its own axis at the constant rate `rate M_k`, q <- q (cos(phi/2), sin(phi/2) e) with
// phi = rate M_k t, and the body components of the lab-fixed L turn the other way, M <- R_e(-phi)
// M, as in DLM: M - 2 sin^2(phi/2) (M - e M_k) - 2 sin(phi/2) cos(phi/2) (e x M), which leaves M_k
// exactly as it was. A zero rate or time is the identity, exactly (sin 0 = 0, cos 0 = 1).
template <class SinCos>
[[gnu::always_inline]] inline void rotateAboutBodyAxis(RotationLane& r, double& Mx, double& My, double& Mz,
                                                       const double (&e)[3], double rate, double t, SinCos sinCos) {
    const double along = e[0] * Mx + e[1] * My + e[2] * Mz;
    const double half = 0.5 * rate * along * t;
    double s, c;
    sinCos(half, s, c);
    r.largestAngle = std::max(r.largestAngle, std::abs(half));
    multiply(r.qw, r.qx, r.qy, r.qz, c, s * e[0], s * e[1], s * e[2]);
    const double fold = 2 * s * s, twist = 2 * s * c;
    const double px = Mx - e[0] * along, py = My - e[1] * along, pz = Mz - e[2] * along;
    const double cx = e[1] * Mz - e[2] * My, cy = e[2] * Mx - e[0] * Mz, cz = e[0] * My - e[1] * Mx;  // e x M
    Mx -= fold * px + twist * cx, My -= fold * py + twist * cy, Mz -= fold * pz + twist * cz;
}

}  // namespace detail

// The torque-free rigid body for a time dt: q changes, L (lab) is a constant of this motion and
// is not touched.
//
// Splitting. DLM split T = M1^2/(2 I1) + M2^2/(2 I2) + M3^2/(2 I3) and compose the exact body-axis
// rotations x dt/2, y dt/2, z dt, y dt/2, x dt/2. We first take out an isotropic part, with the
// median moment Im (the intermediate axis m):
//     T = |M|^2 / (2 Im) + sum_{k != m} (1/I_k - 1/Im) M_k^2 / 2.
// |M|^2 is a Casimir of the body-frame Lie-Poisson bracket, so the isotropic flow (a rotation of
// the whole body about the lab-fixed L by the angle |L| dt / Im) commutes exactly with the other
// two flows and needs no symmetric placement; the two remaining body-axis rotations are composed
// symmetrically (Strang): outer dt/2, inner dt, outer dt/2. The idea of splitting off a symmetric
// or isotropic part is that of Touma & Wisdom, Astron. J. 107, 1189 (1994) and Fasso,
// J. Comput. Phys. 189, 527 (2003). Why it beats the plain DLM sequence for DEM:
//   - only the two residual rates (1/I_k - 1/Im) cause splitting error; the leading O(dt^2) error
//     term is proportional to their product, which the median makes the smallest of the three
//     choices of reference (a rule of thumb: the other factors of that term depend on M too);
//   - a body of revolution (I1 = I2 or I2 = I3: spheroids, most superquadrics in practice) has one
//     residual rate zero, the remaining pieces commute, and the step is exact: the precession is
//     right to round-off at any dt; a sphere-like body (I1 = I2 = I3) turns exactly about L;
//   - for 25 random triaxial ellipsoids (semi-axes 0.5-2, random omega, |omega| dt ~ 0.02, 2e4
//     steps) the energy error was 60 times smaller than DLM's x y z y x (geometric mean 1.9e-7 vs
//     1.2e-5) and 18 times smaller than DLM with its best axis order for each body (3.3e-6). Only
//     flat bodies (I3 = I1 + I2, e.g. I = (1, 2, 3)) favour DLM's order (3.4e-6 vs 4.3e-7).
// The inner (full-step) rotation is the one with the smaller residual rate: the Strang error term
// of the middle piece carries twice the weight of the outer one. With the inner rate zero (a
// body of revolution) the two outer half-steps, about the same axis with nothing between them,
// are taken as one whole step.
//
// q is renormalised at the end: each step multiplies q by unit quaternions, but rounding moves |q|
// away from 1 by ~1e-16 per step, unbounded over a run (a random walk at best, a drift if the
// rounding is biased). toRotationMatrix assumes |q| = 1, so a drifted q would scale every body
// vector it turns (contact points, normals, lab inertia), and a restart reader refuses it
// (requireValidOrientation). One square root per step keeps |q| = 1 to round-off for ever.
template <class SinCos>
[[gnu::always_inline]] inline void driftOrientation(RotationLane& r, double dt, SinCos sinCos) {
    const RotationAxes& a = r.axes;
    // Isotropic part: about the lab L, i.e. a left (lab-frame) multiplication.
    const double momentum = std::sqrt(r.Lx * r.Lx + r.Ly * r.Ly + r.Lz * r.Lz);
    const double half = 0.5 * momentum * a.medianRate * dt;
    double s, c;
    sinCos(half, s, c);
    r.largestAngle = std::abs(half);
    const double k = s / std::max(momentum, 1e-300);  // (no momentum: s = 0, the identity)
    double w = c, x = k * r.Lx, y = k * r.Ly, z = k * r.Lz;
    detail::multiply(w, x, y, z, r.qw, r.qx, r.qy, r.qz);
    r.qw = w, r.qx = x, r.qy = y, r.qz = z;
    // The body components M = A^T L, turned by the body-axis rotations.
    double Mx = r.Lx, My = r.Ly, Mz = r.Lz;
    detail::turn(r.qw, -r.qx, -r.qy, -r.qz, Mx, My, Mz);
    const bool revolution = a.innerRate == 0;
    const double first = revolution ? dt : 0.5 * dt, last = revolution ? 0.0 : 0.5 * dt;
    detail::rotateAboutBodyAxis(r, Mx, My, Mz, a.outer, a.outerRate, first, sinCos);
    detail::rotateAboutBodyAxis(r, Mx, My, Mz, a.inner, a.innerRate, dt, sinCos);
    detail::rotateAboutBodyAxis(r, Mx, My, Mz, a.outer, a.outerRate, last, sinCos);
    const double inverseNorm = 1 / std::sqrt(r.qw * r.qw + r.qx * r.qx + r.qy * r.qy + r.qz * r.qz);
    r.qw *= inverseNorm, r.qx *= inverseNorm, r.qy *= inverseNorm, r.qz *= inverseNorm;
}
inline void driftOrientation(Quat& orientation, const Vec3& angularMomentum, const Vec3& principalInertia, double dt) {
    RotationLane r{orientation.w(), orientation.x(), orientation.y(), orientation.z(),
                   angularMomentum.x(), angularMomentum.y(), angularMomentum.z(), rotationAxesOf(principalInertia),
                   0, 0, 0, 0};
    driftOrientation(r, dt, [](double x, double& sine, double& cosine) { detail::sinCos(x, sine, cosine); });
    orientation = Quat(r.qw, r.qx, r.qy, r.qz);
}

// The lab angular velocity omega = A I^-1 A^T L of the lane, into (wx, wy, wz).
[[gnu::always_inline]] inline void turnedSpin(RotationLane& r) {
    double x = r.Lx, y = r.Ly, z = r.Lz;
    detail::labSpin(r.qw, r.qx, r.qy, r.qz, x, y, z, r.axes.inverseInertia);
    r.wx = x, r.wy = y, r.wz = z;
}

}  // namespace talus
