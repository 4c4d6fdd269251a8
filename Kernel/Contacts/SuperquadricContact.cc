#include "Contacts/SuperquadricContact.h"

#include <cmath>
#include <limits>

#include <Eigen/LU>

namespace talus {

ShapeValue PlacedSuperquadric::at(const Vec3& x) const {
    if (shape->isEllipsoid()) {
        const Vec3 d = x - centre, qd = quadric * d;
        return {d.dot(qd) - 1, 2 * qd, 2 * quadric};
    }
    ShapeValue v = shape->evaluate(rotation.transpose() * (x - centre));
    v.gradient = rotation * v.gradient;
    v.hessian = rotation * v.hessian * rotation.transpose();
    return v;
}

namespace {

using Vec4 = Eigen::Matrix<double, 4, 1>;
using Mat4 = Eigen::Matrix<double, 4, 4>;

// A shape function's value and gradient: all the solve evaluates of an ellipsoid, whose Hessian
// is the constant 2 Q of its quadric.
struct ShapeSlope {
    double value;
    Vec3 gradient;
};

// How the solve evaluates the bodies: two ellipsoids (the fast path: value and gradient from the
// quadric, Hessians fixed) or any superquadrics (value, gradient and Hessian at each point).
struct TwoEllipsoids {
    using Value = ShapeSlope;
    static Value at(const PlacedSuperquadric& body, const Vec3& x) {
        const Vec3 d = x - body.centre, qd = body.quadric * d;
        return {d.dot(qd) - 1, 2 * qd};
    }
    static Mat3 hessian(const PlacedSuperquadric& body, const Value&) { return 2 * body.quadric; }
};
struct AnySuperquadrics {
    using Value = ShapeValue;
    static Value at(const PlacedSuperquadric& body, const Vec3& x) { return body.at(x); }
    static const Mat3& hessian(const PlacedSuperquadric&, const Value& v) { return v.hessian; }
};

struct NewtonResult {
    bool converged = false;
    SuperquadricContactPoint point;
    int iterations = 0;
    ShapeSlope atI{}, atJ{};  // Fi, Fj and their gradients at the point (not evaluated again)
};

// Phi of the header, its gradient rows scaled by a length so that all four components are
// dimensionless and comparable.
template <class Bodies>
struct Residual {
    Vec4 phi;
    typename Bodies::Value i, j;
};
template <class Bodies>
[[gnu::always_inline]] inline Residual<Bodies> residual(const PlacedSuperquadric& i, const PlacedSuperquadric& j,
                                                        const Vec3& x, double mu, double scale) {
    Residual<Bodies> r{Vec4::Zero(), Bodies::at(i, x), Bodies::at(j, x)};
    r.phi.template head<3>() = scale * (r.i.gradient + mu * mu * r.j.gradient);
    r.phi[3] = r.i.value - r.j.value;
    return r;
}

// The Newton step J step = -Phi with J = [[A, b], [c^T, 0]], A = scale (Hi + mu^2 Hj),
// b = 2 scale mu grad Fj, c = grad Fi - grad Fj. By the Schur complement of A (positive
// definite for two strictly convex bodies): dmu = (Phi_4 - c.A^-1 Phi_123) / (c.A^-1 b) and
// dX = -A^-1 (Phi_123 + dmu b), with the closed-form 3 x 3 inverse. Where A is nearly singular
// (the flat faces of blocky shapes) the 4 x 4 system is solved by LU instead.
template <class Bodies>
Vec4 newtonStep(const PlacedSuperquadric& i, const PlacedSuperquadric& j, const Residual<Bodies>& r, double mu,
                double scale) {
    const Mat3 A = scale * (Bodies::hessian(i, r.i) + mu * mu * Bodies::hessian(j, r.j));
    const Vec3 b = scale * 2 * mu * r.j.gradient, c = r.i.gradient - r.j.gradient;
    // A^-1 = adj(A) / det A with the cofactors computed once; the test |det A| > 1e-12 |A|^3
    // (Frobenius norm) squared, so that no square root is taken.
    Mat3 adjugate;
    adjugate.col(0) = A.col(1).cross(A.col(2));
    adjugate.col(1) = A.col(2).cross(A.col(0));
    adjugate.col(2) = A.col(0).cross(A.col(1));
    const double determinant = A.col(0).dot(adjugate.col(0)), size2 = A.squaredNorm();
    if (determinant * determinant > 1e-24 * size2 * size2 * size2) {
        const Mat3 inverse = adjugate.transpose() * (1 / determinant);  // (one division, not nine)
        const Vec3 inverseB = inverse * b, inverseR = inverse * r.phi.template head<3>();
        const double dmu = (r.phi[3] - c.dot(inverseR)) / c.dot(inverseB);
        Vec4 step;
        step.head<3>() = -(inverseR + dmu * inverseB);
        step[3] = dmu;
        if (step.allFinite()) return step;
    }
    Mat4 jacobian;
    jacobian.topLeftCorner<3, 3>() = A;
    jacobian.topRightCorner<3, 1>() = b;
    jacobian.bottomLeftCorner<1, 3>() = c.transpose();
    jacobian(3, 3) = 0;
    return Eigen::PartialPivLU<Mat4>(jacobian).solve(-r.phi);
}

// The damped Newton solve of Theory/Superquadrics.md eq. (5)-(8) from `start`.
template <class Bodies>
NewtonResult solveFor(const PlacedSuperquadric& i, const PlacedSuperquadric& j, SuperquadricContactPoint start,
                      const SuperquadricContactSettings& settings, double scale) {
    NewtonResult result;
    Vec3 x = start.point;
    double mu = start.multiplier;
    Residual<Bodies> r = residual<Bodies>(i, j, x, mu, scale);
    double residual2 = r.phi.squaredNorm();  // (squared norms throughout: no square roots)
    const double tolerance2 = settings.tolerance * settings.tolerance;
    // A warm start already at the solution, its residual a hundred times below the tolerance (a
    // contact at rest): no iteration. (A Newton step from there only stirs round-off, does not
    // lower the residual, and is halved 33 times before the loop gives up on it.)
    result.converged = newtonConverged(r.phi[3], r.phi.template head<3>().squaredNorm(), r.i.gradient.norm(),
                                       std::numeric_limits<double>::infinity(), scale, settings.tolerance);
    for (int iteration = 1; iteration <= settings.maxIterations && !result.converged; ++iteration) {
        result.iterations = iteration;
        const Vec4 step = newtonStep<Bodies>(i, j, r, mu, scale);
        if (!step.allFinite()) return result;
        // Halve the step while the residual does not decrease.
        double t = 1;
        Residual<Bodies> next = residual<Bodies>(i, j, x + step.head<3>(), mu + step[3], scale);
        double next2 = next.phi.squaredNorm();
        while (!(next2 < residual2) && t > 1e-10) {
            t *= 0.5;
            next = residual<Bodies>(i, j, x + t * step.head<3>(), mu + t * step[3], scale);
            next2 = next.phi.squaredNorm();
        }
        if (!(next2 < residual2)) {
            // No decrease along the Newton direction: at the solution to round-off, or stuck.
            result.converged = residual2 <= 100 * tolerance2;
            break;
        }
        x += t * step.head<3>();
        mu += t * step[3];
        r = next;
        residual2 = next2;
        // (SuperquadricContact.h, newtonConverged)
        if (newtonConverged(r.phi[3], r.phi.template head<3>().squaredNorm(), r.i.gradient.norm(),
                            t * t * step.head<3>().squaredNorm(), scale, settings.tolerance)) {
            result.converged = true;
            break;
        }
    }
    result.point = {x, std::abs(mu)};
    result.atI = {r.i.value, r.i.gradient};
    result.atJ = {r.j.value, r.j.gradient};
    return result;
}

NewtonResult solve(const PlacedSuperquadric& i, const PlacedSuperquadric& j, SuperquadricContactPoint start,
                   const SuperquadricContactSettings& settings, double scale) {
    if (i.shape->isEllipsoid() && j.shape->isEllipsoid()) return solveFor<TwoEllipsoids>(i, j, start, settings, scale);
    return solveFor<AnySuperquadrics>(i, j, start, settings, scale);
}

// The distance d >= 0 from a point x inside the body along the direction g (not normalised) to
// its surface: F(x + d g/|g|) = 0, given F and grad F at x and |g|. An ellipsoid's
// F(x + t g) = F + t grad F.g + t^2 g^T Q g is a quadratic in t = d/|g|: its positive root in the
// form that does not cancel (F < 0 inside); g is not normalised first, so that this square root
// and division need not wait for those of |g|. Other shapes: Newton's method kept inside a
// bracket [inside, outside] (bisection when a Newton step leaves it), since F of a blocky shape
// is very flat inside and steep outside.
double bracketedDistanceToSurface(const PlacedSuperquadric& body, const Vec3& x, const Vec3& u);
[[gnu::always_inline]] inline double distanceToSurface(const PlacedSuperquadric& body, const Vec3& x,
                                                       const ShapeSlope& atX, const Vec3& g, double gLength) {
    if (!body.shape->isEllipsoid()) return bracketedDistanceToSurface(body, x, g / gLength);
    return rootToSurface(g.dot(body.quadric * g), 0.5 * atX.gradient.dot(g), atX.value) * gLength;
}
double bracketedDistanceToSurface(const PlacedSuperquadric& body, const Vec3& x, const Vec3& u) {
    double inside = 0, outside = 2 * body.shape->boundingRadius() + (x - body.centre).norm();
    double d = 0;
    for (int k = 0; k < 200; ++k) {
        const ShapeValue v = body.at(x + d * u);
        if (v.value < 0) inside = d;
        else outside = d;
        const double slope = v.gradient.dot(u);
        double next = slope > 0 ? d - v.value / slope : 0.5 * (inside + outside);
        if (!(next > inside && next < outside)) next = 0.5 * (inside + outside);
        if (std::abs(next - d) <= 1e-15 * (1 + d) || outside - inside <= 1e-15 * outside) return next;
        d = next;
    }
    return d;
}

Superquadric morphed(const Superquadric& shape, double s) {
    const double R = shape.boundingRadius();
    auto lerp = [s](double from, double to) { return from + s * (to - from); };
    return {lerp(R, shape.a()), lerp(R, shape.b()), lerp(R, shape.c()), lerp(1, shape.e1()), lerp(1, shape.e2())};
}

// Plan B: from the bounding spheres (point `start`) to the true shapes in 4, then 8, then 16
// stages, each stage's solution starting the next; adds its iterations and stages to `contact`.
NewtonResult morphFromBoundingSpheres(const PlacedSuperquadric& i, const PlacedSuperquadric& j,
                                      const SuperquadricContactPoint& start, const SuperquadricContactSettings& settings,
                                      double scale, SuperquadricContact& contact) {
    NewtonResult found;
    for (int stages = 4; !found.converged && stages <= 16; stages *= 2) {
        SuperquadricContactPoint point = start;
        bool ok = true;
        for (int k = 1; k <= stages && ok; ++k) {
            const double s = static_cast<double>(k) / stages;
            const Superquadric shapeI = morphed(*i.shape, s), shapeJ = morphed(*j.shape, s);
            const NewtonResult stage = solve({&shapeI, i.centre, i.rotation}, {&shapeJ, j.centre, j.rotation}, point,
                                             settings, scale);
            contact.iterations += stage.iterations;
            ok = stage.converged;
            point = stage.point;
        }
        contact.morphStages = stages;
        if (ok) {
            const ShapeValue atI = i.at(point.point), atJ = j.at(point.point);
            found = {true, point, 0, {atI.value, atI.gradient}, {atJ.value, atJ.gradient}};
        }  // (the morphed shapes' Fi is not i's)
    }
    return found;
}

// findSuperquadricContact, or with newtonFirst false plan B alone.
SuperquadricContact findContact(const PlacedSuperquadric& i, const PlacedSuperquadric& j,
                                const SuperquadricContactPoint* start, const SuperquadricContactSettings& settings,
                                bool newtonFirst) {
    SuperquadricContact contact;
    const double Ri = i.shape->boundingRadius(), Rj = j.shape->boundingRadius();
    const Vec3 between = j.centre - i.centre;
    // (The distance's square root is taken only where it is used: a warm start needs none.)
    const double distance2 = between.squaredNorm();
    if (distance2 >= (Ri + Rj) * (Ri + Rj)) {  // the bounding spheres are apart: so are the bodies
        const double distance = std::sqrt(distance2);
        contact.converged = true;
        contact.solution.multiplier = 0;  // nothing solved: no warm start
        contact.gapBound = distance - (Ri + Rj);
        return contact;
    }
    if (i.shape->isSphere() && j.shape->isSphere()) {
        // Closed form: Fi = Fj on the line of centres where it divides them as ri : rj, and
        // mu^2 = rj/ri there; the overlap is the sphere path's ri + rj - rij (Theory/ContactLaws.md
        // eq. (1)-(3)).
        contact.converged = true;
        contact.touching = true;
        const double distance = std::sqrt(distance2);
        const Vec3 iToJ = between / distance;
        contact.solution = {i.centre + Ri / (Ri + Rj) * between, std::sqrt(Rj / Ri)};
        contact.normal = -iToJ;
        contact.overlap = Ri + Rj - distance;
        contact.contactPoint = i.centre + (Ri - 0.5 * contact.overlap) * iToJ;
        return contact;
    }
    const double scale = std::min(Ri, Rj);
    // The bounding spheres' contact point: the middle of their overlap on the line of centres.
    auto sphereStart = [&] {
        const double distance = std::sqrt(distance2);
        const Vec3 iToJ = distance > 0 ? Vec3(between / distance) : Vec3::UnitZ();
        return SuperquadricContactPoint{i.centre + (Ri - 0.5 * (Ri + Rj - distance)) * iToJ, 1};
    };

    NewtonResult found;
    if (newtonFirst) {
        found = solve(i, j, start ? *start : sphereStart(), settings, scale);
        contact.iterations = found.iterations;
        if (!found.converged && start) {
            found = solve(i, j, sphereStart(), settings, scale);
            contact.iterations += found.iterations;
        }
    }
    if (!found.converged) found = morphFromBoundingSpheres(i, j, sphereStart(), settings, scale, contact);
    if (!found.converged) return contact;

    contact.converged = true;
    contact.solution = found.point;
    const Vec3& x = found.point.point;
    const ShapeSlope& atI = found.atI;
    contact.touching = atI.value < 0;
    if (!contact.touching) {
        // Fi = Fj = t > 0 at Xc: f + 1 is homogeneous of degree 2/e1, so the level set F = t is the
        // body scaled by (1 + t)^(e1/2) about its centre, and the two scaled bodies touch at Xc. A
        // convex body holding the ball of its smallest semi-axis r grows by at least (scale - 1) r
        // in every direction when scaled, so the bodies are at least (si - 1) ri + (sj - 1) rj
        // apart.
        const double t = atI.value;
        auto growth = [t](const PlacedSuperquadric& body) {
            const double e1 = body.shape->e1();
            const double scale = e1 == 1 ? std::sqrt(1 + t) : std::pow(1 + t, e1 / 2);
            return (scale - 1) * body.shape->semiAxes().minCoeff();
        };
        contact.gapBound = growth(i) + growth(j);
    }
    const double gradientLength = atI.gradient.norm();
    const Vec3 outOfI = atI.gradient * (1 / gradientLength);  // (one division, not three)
    contact.normal = -outOfI;
    if (!contact.touching) return contact;
    const double di = distanceToSurface(i, x, atI, atI.gradient, gradientLength),
                 dj = distanceToSurface(j, x, found.atJ, -atI.gradient, gradientLength);
    contact.overlap = di + dj;
    contact.contactPoint = x + 0.5 * (di - dj) * outOfI;
    return contact;
}

}  // namespace

SuperquadricContact findSuperquadricContact(const PlacedSuperquadric& i, const PlacedSuperquadric& j,
                                            const SuperquadricContactPoint* start,
                                            const SuperquadricContactSettings& settings) {
    return findContact(i, j, start, settings, true);
}

SuperquadricContact findSuperquadricContactByMorphing(const PlacedSuperquadric& i, const PlacedSuperquadric& j,
                                                      const SuperquadricContactSettings& settings) {
    return findContact(i, j, nullptr, settings, false);
}

}  // namespace talus
