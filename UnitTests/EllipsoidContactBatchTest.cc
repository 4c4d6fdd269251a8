// The batched lasting ellipsoid contacts (Contacts/EllipsoidContactBatch.h) against the scalar
// exact stage (Contacts/SuperquadricContact.h) from the same warm starts: a lane the batch
// finishes must give the scalar answer (point, multiplier, and touching, normal, overlap, contact
// point, or apart, the gap bound), and every lane the scalar solve would take further (more than
// one iteration) must be left to it. A sphere partner enters the batch as the force loop gives it, a plain sphere:
// the quadric diag((1/r)^2) and the bounding radius r (Contacts/ShapedContactForces.h, batchBody).
#include <cstring>
#include <random>

#include "LaneFormTest.h"
#include "Contacts/EllipsoidContactBatch.h"
#include "SuperquadricReference.h"

using namespace talus;
using namespace talus::TALUS_LANES;

namespace {

// A full batch of `kind`'s pairs as the force loop would give them after one step from their last
// solution (with `cases` the configurations and `scalar` the scalar solve from the same warm
// starts).
void fillBatch(reference::Case kind, std::mt19937_64& random, EllipsoidContactBatch& batch,
               std::vector<reference::Configuration>& cases, std::vector<SuperquadricContact>& scalar) {
    std::uniform_real_distribution<double> uniform(-1, 1);
    cases.reserve(EllipsoidContactBatch::size);
    while (!batch.full()) {
        cases.push_back(reference::randomConfiguration(kind, random));
        reference::Configuration& c = cases.back();
        const SuperquadricContact last = findSuperquadricContact(c.i, c.j);
        ASSERT_TRUE(last.converged);
        if (last.solution.multiplier == 0) {  // (bounding spheres apart: nothing to warm-start)
            cases.pop_back();
            continue;
        }
        // One step of a simulation: j moves by up to 1e-7 and turns by up to 1e-6 (a
        // settled packing: Newton's first step lands within the tolerance), or by up to
        // 1e-4 and 1e-3 (a fast flow: the scalar solve needs a second iteration), or, a
        // third of the lanes, not at all, with the warm start of a contact at rest (solved
        // again from its own solution: its residual is at round-off, and the solve takes no
        // step).
        const int motion = batch.count % 3;
        SuperquadricContactPoint start = last.solution;
        if (motion == 2) {
            start = findSuperquadricContact(c.i, c.j, &last.solution).solution;
        } else {
            const double move = motion == 1 ? 1e-4 : 1e-7;
            const Vec3 axis = Vec3(uniform(random), uniform(random), uniform(random)).normalized();
            const Mat3 turn = Eigen::AngleAxisd(10 * move * uniform(random), axis).toRotationMatrix();
            c.j = PlacedSuperquadric(&c.shapeJ, c.j.centre + move * Vec3(uniform(random), uniform(random), uniform(random)),
                                     turn * c.j.rotation);
        }
        // (Bounding spheres apart: the force loop leaves the pair to the scalar path, which
        // needs no solve for it.)
        const double reach = c.shapeI.boundingRadius() + c.shapeJ.boundingRadius();
        if ((c.j.centre - c.i.centre).squaredNorm() >= reach * reach) {
            cases.pop_back();
            continue;
        }
        if (kind == reference::Case::sphereOnEllipsoid) {
            const double r = c.shapeI.a();
            const Mat3 sphere = EllipsoidContactBatch::sphereQuadric(r);
            batch.add(0, 0, 1, {c.i.centre, sphere, r, r},
                      {c.j.centre, c.j.quadric, c.shapeJ.boundingRadius(), c.shapeJ.semiAxes().minCoeff()}, start);
        } else {
            batch.add(0, 0, 1, c.i, c.j.centre, c.j, start);
        }
        scalar.push_back(findSuperquadricContact(c.i, c.j, &start));
    }
}

}  // namespace

TALUS_LANE_TEST(EllipsoidContactBatch, AgreesWithTheScalarSolveFromTheSameWarmStart) {
    std::mt19937_64 random(20261201);
    const double tolerance = SuperquadricContactSettings{}.tolerance;
    for (reference::Case kind : {reference::Case::ellipsoids, reference::Case::needles, reference::Case::sphereOnEllipsoid}) {
        int lanes = 0, done = 0, oneIteration = 0, atRest = 0, apart = 0, apartDone = 0;
        double worstPoint = 0, worstNormal = 0, worstOverlap = 0, worstMiddle = 0, worstGap = 0;
        for (int round = 0; round < 25; ++round) {
            EllipsoidContactBatch batch;
            std::vector<reference::Configuration> cases;
            std::vector<SuperquadricContact> scalar;
            fillBatch(kind, random, batch, cases, scalar);
            batch.compute(tolerance);
            for (int l = 0; l < batch.count; ++l) {
                const SuperquadricContact& s = scalar[l];
                ASSERT_TRUE(s.converged);
                ++lanes;
                const bool inOne = s.iterations <= 1;
                oneIteration += inOne;
                atRest += s.touching && s.iterations == 0;
                apart += !s.touching;
                if (batch.done[l] == 0) continue;
                ++done;
                // A finished lane is a pair the scalar solve finished in one iteration or none, and
                // says touching or apart as the scalar solve does.
                EXPECT_TRUE(inOne) << name(kind) << " lane " << l << ": scalar iterations " << s.iterations;
                const double size = std::min(cases[l].shapeI.semiAxes().minCoeff(), cases[l].shapeJ.semiAxes().minCoeff());
                worstPoint = std::max(worstPoint, (Vec3(batch.px[l], batch.py[l], batch.pz[l]) - s.solution.point).norm() / size);
                worstPoint = std::max(worstPoint, std::abs(batch.mu[l] - s.solution.multiplier));
                ASSERT_EQ(batch.apart[l] != 0, !s.touching) << name(kind) << " lane " << l;
                if (!s.touching) {
                    ++apartDone;
                    ASSERT_GT(s.gapBound, 0) << name(kind) << " lane " << l;
                    worstGap = std::max(worstGap, std::abs(batch.gapBound[l] - s.gapBound) / size);
                    continue;
                }
                worstNormal = std::max(worstNormal, (Vec3(batch.nx[l], batch.ny[l], batch.nz[l]) - s.normal).norm());
                worstOverlap = std::max(worstOverlap, std::abs(batch.overlap[l] - s.overlap) / size);
                worstMiddle = std::max(worstMiddle, (Vec3(batch.mx[l], batch.my[l], batch.mz[l]) - s.contactPoint).norm() / size);
            }
        }
        // The same arithmetic up to rounding (the scalar path through Eigen, the lanes on plain
        // numbers).
        EXPECT_LT(worstPoint, 1e-13) << name(kind);
        EXPECT_LT(worstNormal, 1e-13) << name(kind);
        EXPECT_LT(worstOverlap, 1e-13) << name(kind);
        EXPECT_LT(worstMiddle, 1e-13) << name(kind);
        EXPECT_LT(worstGap, 1e-13) << name(kind);
        // Every pair the scalar solve finished in one iteration or none was finished by the lanes
        // too (up to a rounding at the convergence threshold), none other: those at rest, most of
        // the small steps and none of the large ones; among them pairs apart (a tenth of the
        // configurations), with their gap bounds.
        EXPECT_GE(done, oneIteration - lanes / 100) << name(kind);
        EXPECT_GT(done, lanes / 4) << name(kind);
        EXPECT_LT(done, lanes * 3 / 4) << name(kind);
        EXPECT_GT(apartDone, 0) << name(kind);
        EXPECT_GT(atRest, lanes / 4) << name(kind);
        std::printf("%s: %d lanes, %d finished by the batch (%d of them apart), %d finished by the scalar solve in one iteration or none (%d at rest), %d apart; "
                    "worst differences: point %.1e, normal %.1e, overlap %.1e, contact point %.1e, gap bound %.1e\n",
                    name(kind), lanes, done, apartDone, oneIteration, atRest, apart, worstPoint, worstNormal, worstOverlap, worstMiddle,
                    worstGap);
    }
}

// A pair's answer must not depend on where in a batch it sits, nor on how full the batch is: the
// same pair across two ranks sits in different batches, and a restart gives both ranks the copy
// of one (the lanes past the count are filled, so that no lane is left to the loop's scalar
// remainder). Every lane of a full batch against the same lane as the last of a partial batch,
// to the bit, through compute and forceLanes.
TALUS_LANE_TEST(EllipsoidContactBatch, ALaneAnswersTheSameInAnyPlaceOfAnyBatch) {
    std::mt19937_64 random(20261207);
    std::uniform_real_distribution<double> uniform(-1, 1);
    const double tolerance = SuperquadricContactSettings{}.tolerance, dt = 1e-4;
    const LinearSpringDashpot law{2e5, 40, 2e5 * 2 / 7, 10, 0.5};
    auto vector = [&](double size) { return Vec3(size * uniform(random), size * uniform(random), size * uniform(random)); };
    int compared = 0;
    for (reference::Case kind : {reference::Case::ellipsoids, reference::Case::needles, reference::Case::sphereOnEllipsoid}) {
        for (int round = 0; round < 4; ++round) {
            EllipsoidContactBatch full;
            std::vector<reference::Configuration> cases;
            std::vector<SuperquadricContact> scalar;
            fillBatch(kind, random, full, cases, scalar);
            for (int l = 0; l < full.count; ++l)
                full.setMotion(l, vector(0.1), vector(1), vector(0.1), vector(1), vector(1e-4), l % 2 == 0, law);
            const EllipsoidContactBatch given = full;
            full.compute(tolerance);
            full.forceLanes(dt);
            for (int l = 0; l + 1 < EllipsoidContactBatch::size; ++l) {
                EllipsoidContactBatch partial = given;
                partial.count = l + 1;
                partial.compute(tolerance);
                partial.forceLanes(dt);
                for (double(EllipsoidContactBatch::*out)[EllipsoidContactBatch::size] :
                     {&EllipsoidContactBatch::done, &EllipsoidContactBatch::px, &EllipsoidContactBatch::py,
                      &EllipsoidContactBatch::pz, &EllipsoidContactBatch::mu, &EllipsoidContactBatch::apart,
                      &EllipsoidContactBatch::gapBound, &EllipsoidContactBatch::nx, &EllipsoidContactBatch::ny,
                      &EllipsoidContactBatch::nz, &EllipsoidContactBatch::overlap, &EllipsoidContactBatch::mx,
                      &EllipsoidContactBatch::my, &EllipsoidContactBatch::mz, &EllipsoidContactBatch::fx,
                      &EllipsoidContactBatch::fy, &EllipsoidContactBatch::fz, &EllipsoidContactBatch::tix,
                      &EllipsoidContactBatch::tiy, &EllipsoidContactBatch::tiz, &EllipsoidContactBatch::tjx,
                      &EllipsoidContactBatch::tjy, &EllipsoidContactBatch::tjz, &EllipsoidContactBatch::fn,
                      &EllipsoidContactBatch::sx, &EllipsoidContactBatch::sy, &EllipsoidContactBatch::sz}) {
                    // (As bits: the distances of bodies apart may be NaN.)
                    ASSERT_EQ(std::memcmp(&(full.*out)[l], &(partial.*out)[l], sizeof(double)), 0)
                        << name(kind) << " lane " << l << " of " << l + 1 << ": " << (full.*out)[l] << " against "
                        << (partial.*out)[l] << " in the full batch";
                    ++compared;
                }
            }
        }
    }
    EXPECT_GT(compared, 1000);
}
