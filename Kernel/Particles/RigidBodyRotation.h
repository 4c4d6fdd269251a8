// Rotation of a non-spherical rigid particle (SPEC.md 4: "the full rigid-body equations, not
// scalar"); Documentation/Superquadrics/RigidBodyRotation.md derives what is written here.
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

// Lab inertia tensor A I A^T (SPEC.md 4).
inline Mat3 labInertia(const Quat& orientation, const Vec3& principalInertia) {
    const Mat3 A = orientation.toRotationMatrix();
    return A * principalInertia.asDiagonal() * A.transpose();
}

// v turned by the unit quaternion q (q v q*): v + 2w (u x v) + 2 u x (u x v) with u the vector
// part. Written on plain numbers and always inlined: it runs per particle and step, and as
// Eigen's quaternion product GCC called it out of line.
[[gnu::always_inline]] inline Vec3 turned(const Quat& q, const Vec3& v) {
    const double w = q.w(), ux = q.x(), uy = q.y(), uz = q.z();
    const double tx = 2 * (uy * v.z() - uz * v.y()), ty = 2 * (uz * v.x() - ux * v.z()), tz = 2 * (ux * v.y() - uy * v.x());
    return {v.x() + w * tx + (uy * tz - uz * ty), v.y() + w * ty + (uz * tx - ux * tz), v.z() + w * tz + (ux * ty - uy * tx)};
}

// The quaternion product a b, on plain numbers and always inlined (Eigen's is called out of line
// in the per-particle loop).
[[gnu::always_inline]] inline Quat product(const Quat& a, const Quat& b) {
    return Quat(a.w() * b.w() - a.x() * b.x() - a.y() * b.y() - a.z() * b.z(),
                a.w() * b.x() + a.x() * b.w() + a.y() * b.z() - a.z() * b.y(),
                a.w() * b.y() - a.x() * b.z() + a.y() * b.w() + a.z() * b.x(),
                a.w() * b.z() + a.x() * b.y() - a.y() * b.x() + a.z() * b.w());
}

// Lab angular velocity omega = A I^-1 A^T L, for contact kinematics (v + omega x branch).
inline Vec3 angularVelocity(const Quat& orientation, const Vec3& angularMomentum, const Vec3& principalInertia) {
    const Vec3 bodyMomentum = turned(orientation.conjugate(), angularMomentum);  // M = A^T L
    return turned(orientation, bodyMomentum.cwiseQuotient(principalInertia).eval());
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

// sin x and cos x. A step turns a particle by a small angle (|omega| dt ~ 1e-3), where the
// Taylor series to x^9 and x^10 is exact to rounding (the next terms are below 1e-22 relative
// for |x| <= 1/16) and several times cheaper than the library's sin and cos.
[[gnu::always_inline]] inline void sinCos(double x, double& s, double& c) {
    if (!(std::abs(x) <= 0.0625)) {
        s = std::sin(x), c = std::cos(x);
        return;
    }
    const double x2 = x * x;
    s = x * (1 + x2 * (-1.0 / 6 + x2 * (1.0 / 120 + x2 * (-1.0 / 5040 + x2 * (1.0 / 362880)))));
    c = 1 + x2 * (-0.5 + x2 * (1.0 / 24 + x2 * (-1.0 / 720 + x2 * (1.0 / 40320 + x2 * (-1.0 / 3628800)))));
}

// The exact flow of T_k = c M_k^2 / 2 (k a body axis) for a time t: the body turns about its own
// axis k at the constant rate c M_k, so q <- q (cos(phi/2), sin(phi/2) e_k) with phi = c M_k t,
// and the body components of the lab-fixed L turn the other way, M <- R_k(-phi) M, as in DLM.
[[gnu::always_inline]] inline void rotateAboutBodyAxis(Quat& q, Vec3& bodyMomentum, int k, double rate, double t) {
    double s, c;
    sinCos(0.5 * rate * bodyMomentum[k] * t, s, c);
    Quat turn(c, 0, 0, 0);
    turn.vec()[k] = s;
    q = product(q, turn);
    const int i = (k + 1) % 3, j = (k + 2) % 3;  // (k, i, j) cyclic
    const double cosAngle = c * c - s * s, sinAngle = 2 * s * c;
    const double Mi = bodyMomentum[i], Mj = bodyMomentum[j];
    bodyMomentum[i] = cosAngle * Mi + sinAngle * Mj;
    bodyMomentum[j] = -sinAngle * Mi + cosAngle * Mj;
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
//   - four trigonometric pairs per step instead of five (two for a body of revolution: with the
//     inner rate zero, the two outer half-steps about the same axis are one whole step);
//   - for 25 random triaxial ellipsoids (semi-axes 0.5-2, random omega, |omega| dt ~ 0.02, 2e4
//     steps) the energy error was 60 times smaller than DLM's x y z y x (geometric mean 1.9e-7 vs
//     1.2e-5) and 18 times smaller than DLM with its best axis order for each body (3.3e-6). Only
//     flat bodies (I3 = I1 + I2, e.g. I = (1, 2, 3)) favour DLM's order (3.4e-6 vs 4.3e-7).
// The inner (full-step) rotation is the one with the smaller residual rate: the Strang error term
// of the middle piece carries twice the weight of the outer one.
//
// q is renormalised at the end: each step multiplies q by unit quaternions, but rounding moves |q|
// away from 1 by ~1e-16 per step, unbounded over a run (a random walk at best, a drift if the
// rounding is biased). toRotationMatrix assumes |q| = 1, so a drifted q would scale every body
// vector it turns (contact points, normals, lab inertia), and a restart reader refuses it
// (requireValidOrientation). One square root per step keeps |q| = 1 to round-off for ever.
inline void driftOrientation(Quat& orientation, const Vec3& angularMomentum, const Vec3& principalInertia, double dt) {
    const Vec3& I = principalInertia;
    int smallest = 0, largest = 0;
    I.minCoeff(&smallest);
    I.maxCoeff(&largest);
    const int median = smallest == largest ? 0 : 3 - smallest - largest;  // all equal: any axis
    const double medianRate = 1 / I[median];

    // Isotropic part: about the lab L, i.e. a left (lab-frame) multiplication.
    const double momentum = angularMomentum.norm();
    if (momentum > 0) {
        double s, c;
        detail::sinCos(0.5 * momentum * medianRate * dt, s, c);
        const Vec3 axis = (s / momentum) * angularMomentum;
        orientation = product(Quat(c, axis.x(), axis.y(), axis.z()), orientation);
    }

    int outer = (median + 1) % 3, inner = (median + 2) % 3;
    double outerRate = 1 / I[outer] - medianRate, innerRate = 1 / I[inner] - medianRate;
    if (std::abs(innerRate) > std::abs(outerRate)) {
        std::swap(outer, inner);
        std::swap(outerRate, innerRate);
    }
    // A residual rate is exactly zero for a body of revolution (both for a sphere-like body): its
    // rotation is skipped, and the two outer half-steps, then about the same axis with nothing
    // between them, are one whole step.
    if (outerRate != 0) {
        Vec3 bodyMomentum = turned(orientation.conjugate(), angularMomentum);
        if (innerRate == 0) {
            detail::rotateAboutBodyAxis(orientation, bodyMomentum, outer, outerRate, dt);
        } else {
            detail::rotateAboutBodyAxis(orientation, bodyMomentum, outer, outerRate, 0.5 * dt);
            detail::rotateAboutBodyAxis(orientation, bodyMomentum, inner, innerRate, dt);
            detail::rotateAboutBodyAxis(orientation, bodyMomentum, outer, outerRate, 0.5 * dt);
        }
    }
    orientation.coeffs() *= 1 / orientation.norm();  // (one division, not four)
}

}  // namespace talus
