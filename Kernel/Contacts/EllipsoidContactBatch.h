// Lasting contacts of two ellipsoids (a sphere counts as one: Q = I / r^2), gathered in batches
// and taken one Newton iteration forward lane by lane, in loops of plain numbers that the
// compiler vectorises: the warm-started exact stage of Theory/Superquadrics.md for the common
// case, as ContactBatch (ContactBatch.h) does the sphere contacts. A contact costs one long chain
// of dependent arithmetic (residual, Newton step, residual, normal, the two distances); one at a
// time, the core cannot overlap it with the next contact's
// (Documentation/Superquadrics/Superquadrics.md), lanes side by side it can.
//
// The arithmetic is that of the scalar solve (SuperquadricContact.cc, TwoEllipsoids): the first
// iteration of solveFor from the warm start, its full step, and its convergence test (or, a
// warm start already at the solution, none); then the normal and the overlap from the values and
// gradients at the solution, or, the bodies apart, the lower bound of their gap. A lane that the
// scalar solve would take further (the full step does not lower the residual, the test fails
// after one iteration, or anything is not finite) is marked, and the force loop gives that pair
// to the scalar path, which starts again from the same warm start: every lane's answer is the
// scalar solve's, to rounding. With the linear law the contact's step follows in lanes too
// (forceLanes). (Pairs whose bounding spheres are apart do not come here: the force loop leaves
// them to the scalar path, which needs no solve for them.)
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "Contacts/SuperquadricContact.h"
#include "Math/Vector.h"
#include "Species/ContactKinematics.h"
#include "Species/LinearSpringDashpot.h"
#include "Math/LaneNamespace.h"

namespace talus::TALUS_LANES {

struct EllipsoidContactBatch {
    static constexpr int size = 16;
    int count = 0;
    std::uint32_t k[size], i[size], j[size];
    // In: centres (j's periodic image), quadrics Q (symmetric: xx, yy, zz, xy, xz, yz), the warm
    // start (point, multiplier), the length that scales the residual (the smaller bounding
    // radius) and each body's smallest semi-axis (for the gap bound of bodies apart).
    double cix[size], ciy[size], ciz[size], cjx[size], cjy[size], cjz[size];
    double qi0[size], qi1[size], qi2[size], qi3[size], qi4[size], qi5[size];
    double qj0[size], qj1[size], qj2[size], qj3[size], qj4[size], qj5[size];
    double x0[size], y0[size], z0[size], mu0[size], scale[size], smallestI[size], smallestJ[size];
    // Out: done (1: the answer below is the scalar solve's; 0: give the pair to the scalar path),
    // the contact point (Newton's) and multiplier, whether the bodies are apart; touching, the
    // unit normal from j to i, the overlap and the middle of the overlap; apart, the lower bound of
    // their gap (SuperquadricContact::gapBound).
    double done[size], px[size], py[size], pz[size], mu[size], apart[size], gapBound[size];
    double nx[size], ny[size], nz[size], overlap[size], mx[size], my[size], mz[size];

    // The contact's step, for the linear law (forceLanes): in, the motion of both bodies, the
    // spring and whether the pair touched at the last step, the law; out, the force on i, the
    // torques on i and j, the normal force and the advanced spring.
    double vix[size], viy[size], viz[size], wix[size], wiy[size], wiz[size];
    double vjx[size], vjy[size], vjz[size], wjx[size], wjy[size], wjz[size];
    double sx[size], sy[size], sz[size], touched[size], kn[size], gn[size], kt[size], gt[size], friction[size];
    double fx[size], fy[size], fz[size], tix[size], tiy[size], tiz[size], tjx[size], tjy[size], tjz[size], fn[size];

    bool full() const { return count == size; }

    // The lanes past `count` made copies of lane 0, so that compute and forceLanes run all
    // `size` lanes: a loop over a count the compiler cannot know ends in a scalar remainder,
    // whose arithmetic (its contractions into fused multiply-adds) may round differently from
    // the vector body's. A pair's answer would then depend on its place in the batch, and the
    // two copies of a pair across ranks (each rank solves it for its own particle) could part,
    // which a restart (it gives both ranks the same copy) would not repeat.
    template <std::size_t n>
    void fillLanes(double* const (&inputs)[n]) {
        if (count == 0 || count == size) return;
        for (double* lanes : inputs) std::fill(lanes + count, lanes + size, lanes[0]);
    }
    LinearSpringDashpot law(int l) const { return {kn[l], gn[l], kt[l], gt[l], friction[l]}; }

    void setMotion(int l, const Vec3& vi, const Vec3& wi, const Vec3& vj, const Vec3& wj, const Vec3& spring,
                   bool touchedBefore, const LinearSpringDashpot& pairLaw) {
        vix[l] = vi.x(), viy[l] = vi.y(), viz[l] = vi.z(), wix[l] = wi.x(), wiy[l] = wi.y(), wiz[l] = wi.z();
        vjx[l] = vj.x(), vjy[l] = vj.y(), vjz[l] = vj.z(), wjx[l] = wj.x(), wjy[l] = wj.y(), wjz[l] = wj.z();
        sx[l] = spring.x(), sy[l] = spring.y(), sz[l] = spring.z(), touched[l] = touchedBefore ? 1.0 : 0.0;
        kn[l] = pairLaw.normalStiffness, gn[l] = pairLaw.normalDamping, kt[l] = pairLaw.tangentialStiffness;
        gt[l] = pairLaw.tangentialDamping, friction[l] = pairLaw.friction;
    }

    // The superquadric path's contact step (ContactForces.h, shapedContact) for every lane, after
    // compute: the velocity of the contact point (branch vectors b from the centres to it), the
    // spring of a lasting contact turned into the new tangent plane (a new contact's is zero),
    // the law's plain step, the torques b x F.
    [[gnu::noinline]] void forceLanes(double dt) {
        fillLanes({vix, viy, viz, wix, wiy, wiz, vjx, vjy, vjz, wjx, wjy, wjz, sx, sy, sz, touched, kn, gn, kt, gt,
                   friction});
        for (int l = 0; l < size; ++l) {
            LinearSpringDashpot::Lane c{};
            c.nx = nx[l], c.ny = ny[l], c.nz = nz[l], c.overlap = overlap[l];
            const double bix = mx[l] - cix[l], biy = my[l] - ciy[l], biz = mz[l] - ciz[l];
            const double bjx = mx[l] - cjx[l], bjy = my[l] - cjy[l], bjz = mz[l] - cjz[l];
            c.vx = vix[l] + (wiy[l] * biz - wiz[l] * biy) - vjx[l] - (wjy[l] * bjz - wjz[l] * bjy);
            c.vy = viy[l] + (wiz[l] * bix - wix[l] * biz) - vjy[l] - (wjz[l] * bjx - wjx[l] * bjz);
            c.vz = viz[l] + (wix[l] * biy - wiy[l] * bix) - vjz[l] - (wjx[l] * bjy - wjy[l] * bjx);
            c.normalVelocity = c.vx * c.nx + c.vy * c.ny + c.vz * c.nz;
            c.tx = c.vx - c.normalVelocity * c.nx, c.ty = c.vy - c.normalVelocity * c.ny;
            c.tz = c.vz - c.normalVelocity * c.nz;
            const bool lasting = touched[l] != 0;
            c.sx = lasting ? sx[l] : 0.0, c.sy = lasting ? sy[l] : 0.0, c.sz = lasting ? sz[l] : 0.0;
            turnSpringIntoTangentPlane(c.sx, c.sy, c.sz, c.nx, c.ny, c.nz);
            law(l).plainContact(c, dt);
            const double Fx = c.normalForce * c.nx + c.fx, Fy = c.normalForce * c.ny + c.fy,
                         Fz = c.normalForce * c.nz + c.fz;
            fx[l] = Fx, fy[l] = Fy, fz[l] = Fz, fn[l] = c.normalForce;
            sx[l] = c.sx, sy[l] = c.sy, sz[l] = c.sz;
            tix[l] = biy * Fz - biz * Fy, tiy[l] = biz * Fx - bix * Fz, tiz[l] = bix * Fy - biy * Fx;
            tjx[l] = -(bjy * Fz - bjz * Fy), tjy[l] = -(bjz * Fx - bjx * Fz), tjz[l] = -(bjx * Fy - bjy * Fx);
        }
    }

    // A plain sphere's quadric I / r^2, formed as the frame of Superquadric::sphere(r) forms it
    // (diag((1/r)^2): SuperquadricContact.h, PlacedSuperquadric), so that a lane's answer is the
    // scalar path's to the bit of its inputs.
    static Mat3 sphereQuadric(double radius) {
        const double inverse = 1 / radius;
        Mat3 q = Mat3::Zero();
        q.diagonal().setConstant(inverse * inverse);
        return q;
    }
    // A body as the batch sees it: its centre, its quadric Q, its bounding radius and its
    // smallest semi-axis.
    struct Body {
        const Vec3& centre;
        const Mat3& quadric;
        double boundingRadius, smallestSemiAxis;
    };
    // An ellipsoid's placed frame (at bodyI's own centre; j's image at centreJ).
    void add(std::size_t pair, std::uint32_t a, std::uint32_t b, const PlacedSuperquadric& bodyI, const Vec3& centreJ,
             const PlacedSuperquadric& bodyJ, const SuperquadricContactPoint& start) {
        add(pair, a, b, {bodyI.centre, bodyI.quadric, bodyI.shape->boundingRadius(), bodyI.shape->semiAxes().minCoeff()},
            {centreJ, bodyJ.quadric, bodyJ.shape->boundingRadius(), bodyJ.shape->semiAxes().minCoeff()}, start);
    }
    void add(std::size_t pair, std::uint32_t a, std::uint32_t b, const Body& bodyI, const Body& bodyJ,
             const SuperquadricContactPoint& start) {
        const int l = count++;
        k[l] = static_cast<std::uint32_t>(pair), i[l] = a, j[l] = b;
        cix[l] = bodyI.centre.x(), ciy[l] = bodyI.centre.y(), ciz[l] = bodyI.centre.z();
        cjx[l] = bodyJ.centre.x(), cjy[l] = bodyJ.centre.y(), cjz[l] = bodyJ.centre.z();
        const Mat3 &A = bodyI.quadric, &B = bodyJ.quadric;
        qi0[l] = A(0, 0), qi1[l] = A(1, 1), qi2[l] = A(2, 2), qi3[l] = A(0, 1), qi4[l] = A(0, 2), qi5[l] = A(1, 2);
        qj0[l] = B(0, 0), qj1[l] = B(1, 1), qj2[l] = B(2, 2), qj3[l] = B(0, 1), qj4[l] = B(0, 2), qj5[l] = B(1, 2);
        x0[l] = start.point.x(), y0[l] = start.point.y(), z0[l] = start.point.z(), mu0[l] = start.multiplier;
        scale[l] = std::min(bodyI.boundingRadius, bodyJ.boundingRadius);
        smallestI[l] = bodyI.smallestSemiAxis, smallestJ[l] = bodyJ.smallestSemiAxis;
    }

    // F = d.Q d - 1 and grad F = 2 Q d at x (TwoEllipsoids::at), Q symmetric (xx yy zz xy xz yz).
    struct Slope {
        double value, gx, gy, gz;
    };
    struct Symmetric {
        double xx, yy, zz, xy, xz, yz;
    };
    [[gnu::always_inline]] static Slope at(const Symmetric& q, double dx, double dy, double dz) {
        const double qx = q.xx * dx + q.xy * dy + q.xz * dz, qy = q.xy * dx + q.yy * dy + q.yz * dz,
                     qz = q.xz * dx + q.yz * dy + q.zz * dz;
        return {dx * qx + dy * qy + dz * qz - 1, 2 * qx, 2 * qy, 2 * qz};
    }
    // The distance from the point where F and grad F are f to the surface along g (|g| = length):
    // the root of F + t grad F.g + t^2 g.Q g = 0 (distanceToSurface, ellipsoids), times |g|.
    [[gnu::always_inline]] static double distance(const Symmetric& q, const Slope& f, double gx, double gy, double gz,
                                                  double length) {
        const double qx = q.xx * gx + q.xy * gy + q.xz * gz, qy = q.xy * gx + q.yy * gy + q.yz * gz,
                     qz = q.xz * gx + q.yz * gy + q.zz * gz;
        return rootToSurface(gx * qx + gy * qy + gz * qz, 0.5 * (f.gx * gx + f.gy * gy + f.gz * gz), f.value) * length;
    }

    // One Newton iteration from the warm start and the geometry, for every lane.
    [[gnu::noinline]] void compute(double tolerance) {
        fillLanes({cix, ciy, ciz, cjx, cjy, cjz, qi0, qi1, qi2, qi3, qi4, qi5, qj0, qj1, qj2, qj3, qj4, qj5, x0, y0,
                   z0, mu0, scale, smallestI, smallestJ});
        constexpr double infinity = std::numeric_limits<double>::infinity();
        for (int l = 0; l < size; ++l) {
            const Symmetric Qi{qi0[l], qi1[l], qi2[l], qi3[l], qi4[l], qi5[l]};
            const Symmetric Qj{qj0[l], qj1[l], qj2[l], qj3[l], qj4[l], qj5[l]};
            const double s = scale[l], m = mu0[l];
            const Slope i0 = at(Qi, x0[l] - cix[l], y0[l] - ciy[l], z0[l] - ciz[l]);
            const Slope j0 = at(Qj, x0[l] - cjx[l], y0[l] - cjy[l], z0[l] - cjz[l]);
            // Phi = [scale (grad Fi + mu^2 grad Fj); Fi - Fj] (SuperquadricContact.cc, residual).
            const double r0x = s * (i0.gx + m * m * j0.gx), r0y = s * (i0.gy + m * m * j0.gy), r0z = s * (i0.gz + m * m * j0.gz);
            const double r0w = i0.value - j0.value;
            const double gradient0 = r0x * r0x + r0y * r0y + r0z * r0z, residual2 = gradient0 + r0w * r0w;
            // A warm start already at the solution: solveFor takes no step (a contact at rest).
            const double length0 = std::sqrt(i0.gx * i0.gx + i0.gy * i0.gy + i0.gz * i0.gz);
            const bool atStart = newtonConverged(r0w, gradient0, length0, infinity, s, tolerance);
            // The Newton step by the Schur complement of A = scale (2 Qi + mu^2 2 Qj) (newtonStep).
            const double axx = s * (2 * Qi.xx + m * m * (2 * Qj.xx)), ayy = s * (2 * Qi.yy + m * m * (2 * Qj.yy)),
                         azz = s * (2 * Qi.zz + m * m * (2 * Qj.zz)), axy = s * (2 * Qi.xy + m * m * (2 * Qj.xy)),
                         axz = s * (2 * Qi.xz + m * m * (2 * Qj.xz)), ayz = s * (2 * Qi.yz + m * m * (2 * Qj.yz));
            // adj(A) of the symmetric A, and det A.
            const double cxx = ayy * azz - ayz * ayz, cyy = axx * azz - axz * axz, czz = axx * ayy - axy * axy;
            const double cxy = axz * ayz - axy * azz, cxz = axy * ayz - axz * ayy, cyz = axy * axz - axx * ayz;
            const double determinant = axx * cxx + axy * cxy + axz * cxz;
            const double size2 = axx * axx + ayy * ayy + azz * azz + 2 * (axy * axy + axz * axz + ayz * ayz);
            const bool regular = determinant * determinant > 1e-24 * size2 * size2 * size2;
            const double inverseDeterminant = 1 / determinant;
            const double bx = s * 2 * m * j0.gx, by = s * 2 * m * j0.gy, bz = s * 2 * m * j0.gz;
            const double ccx = i0.gx - j0.gx, ccy = i0.gy - j0.gy, ccz = i0.gz - j0.gz;
            const double ibx = (cxx * bx + cxy * by + cxz * bz) * inverseDeterminant,
                         iby = (cxy * bx + cyy * by + cyz * bz) * inverseDeterminant,
                         ibz = (cxz * bx + cyz * by + czz * bz) * inverseDeterminant;
            const double irx = (cxx * r0x + cxy * r0y + cxz * r0z) * inverseDeterminant,
                         iry = (cxy * r0x + cyy * r0y + cyz * r0z) * inverseDeterminant,
                         irz = (cxz * r0x + cyz * r0y + czz * r0z) * inverseDeterminant;
            const double dmu = (r0w - (ccx * irx + ccy * iry + ccz * irz)) / (ccx * ibx + ccy * iby + ccz * ibz);
            const double sx = -(irx + dmu * ibx), sy = -(iry + dmu * iby), sz = -(irz + dmu * ibz);
            // The full step, and the residual there.
            const double x1 = x0[l] + sx, y1 = y0[l] + sy, z1 = z0[l] + sz, m1 = m + dmu;
            const Slope i1 = at(Qi, x1 - cix[l], y1 - ciy[l], z1 - ciz[l]);
            const Slope j1 = at(Qj, x1 - cjx[l], y1 - cjy[l], z1 - cjz[l]);
            const double r1x = s * (i1.gx + m1 * m1 * j1.gx), r1y = s * (i1.gy + m1 * m1 * j1.gy),
                         r1z = s * (i1.gz + m1 * m1 * j1.gz), r1w = i1.value - j1.value;
            const double gradient2 = r1x * r1x + r1y * r1y + r1z * r1z, next2 = gradient2 + r1w * r1w;
            // The convergence test of solveFor after its first iteration.
            const double length1 = std::sqrt(i1.gx * i1.gx + i1.gy * i1.gy + i1.gz * i1.gz);
            const bool converged = newtonConverged(r1w, gradient2, length1, sx * sx + sy * sy + sz * sz, s, tolerance);
            // The solution: the warm start, or the point after the step.
            const double x = atStart ? x0[l] : x1, y = atStart ? y0[l] : y1, z = atStart ? z0[l] : z1,
                         mSolved = atStart ? m : m1;
            const Slope I{atStart ? i0.value : i1.value, atStart ? i0.gx : i1.gx, atStart ? i0.gy : i1.gy,
                          atStart ? i0.gz : i1.gz};
            const Slope J{atStart ? j0.value : j1.value, atStart ? j0.gx : j1.gx, atStart ? j0.gy : j1.gy,
                          atStart ? j0.gz : j1.gz};
            const double gradientLength = atStart ? length0 : length1;
            // Touching (Fi < 0): the normal, and the distances to both surfaces along the gradient
            // of Fi. Apart (Fi = Fj = t >= 0): each body scaled by sqrt(1 + t) about its centre
            // touches the other's, so the gap is at least the growth of their smallest semi-axes
            // (findContact, SuperquadricContact.cc).
            const bool touching = I.value < 0;
            const double grown = std::sqrt(1 + I.value) - 1;
            const double gap = grown * smallestI[l] + grown * smallestJ[l];
            const double inverseLength = 1 / gradientLength;
            const double ux = I.gx * inverseLength, uy = I.gy * inverseLength, uz = I.gz * inverseLength;
            const double di = distance(Qi, I, I.gx, I.gy, I.gz, gradientLength),
                         dj = distance(Qj, J, -I.gx, -I.gy, -I.gz, gradientLength);
            const double half = 0.5 * (di - dj);
            px[l] = x, py[l] = y, pz[l] = z, mu[l] = std::abs(mSolved);
            nx[l] = -ux, ny[l] = -uy, nz[l] = -uz;
            overlap[l] = di + dj;
            mx[l] = x + half * ux, my[l] = y + half * uy, mz[l] = z + half * uz;
            apart[l] = touching ? 0.0 : 1.0, gapBound[l] = gap;
            // (false for an infinity or NaN; isfinite would not vectorise. The distances of bodies
            // apart are not used, and may be NaN.)
            const double sum = ux + uy + uz + mSolved + gap, distances = di + dj + half;
            const bool finite = (sum - sum == 0) & (!touching | (distances - distances == 0));
            const bool solved = atStart | (regular & (next2 < residual2) & converged);
            done[l] = (solved & finite) ? 1.0 : 0.0;
        }
    }
};

}  // namespace talus::TALUS_LANES
