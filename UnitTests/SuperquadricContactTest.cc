// Superquadric contact detection (Contacts/SuperquadricContact.h) against the sphere path and
// against the independent reference of SuperquadricReference.h. The full sweep (10^5
// configurations, a table per class) is Drivers/Validation/SuperquadricContactSweep; here a
// few hundred per class.
#include <gtest/gtest.h>

#include <cstdio>
#include <random>

#include "SuperquadricReference.h"

using namespace talus;

TEST(SuperquadricContact, SpheresGiveTheSpherePathsGeometry) {
    const Superquadric a = Superquadric::sphere(0.5), b = Superquadric::sphere(0.3);
    std::mt19937_64 random(3);
    for (int trial = 0; trial < 100; ++trial) {
        const Mat3 Ri = reference::randomRotation(random), Rj = reference::randomRotation(random);
        const Vec3 xi(0.1, -0.2, 0.3), direction = reference::randomRotation(random) * Vec3::UnitX();
        const double distance = 0.8 - 0.08 * (trial + 0.5) / 100;  // overlaps up to 10% of the smaller radius
        const Vec3 xj = xi + distance * direction;
        const SuperquadricContact c = findSuperquadricContact({&a, xi, Ri}, {&b, xj, Rj});
        ASSERT_TRUE(c.converged && c.touching);
        // Theory/ContactLaws.md eq. (1)-(3): dn = ri + rj - rij, n from j to i, contact point at
        // the middle of the overlap.
        const double overlap = 0.8 - distance;
        EXPECT_NEAR(c.overlap, overlap, 1e-12);
        EXPECT_LT((c.normal + direction).norm(), 1e-12);
        EXPECT_LT((c.contactPoint - (xi + (0.5 - overlap / 2) * direction)).norm(), 1e-12);
    }
}

TEST(SuperquadricContact, ApartWhenTheBoundingSpheresAreApart) {
    const Superquadric a = Superquadric::ellipsoid(1, 0.5, 0.5);
    const SuperquadricContact c =
        findSuperquadricContact({&a, Vec3::Zero(), Mat3::Identity()}, {&a, Vec3(2.01, 0, 0), Mat3::Identity()});
    EXPECT_FALSE(c.touching);
    EXPECT_EQ(c.iterations, 0);
}

// Fewer under AddressSanitizer, where the reference is ten times slower (CI runs both builds).
#if defined(__SANITIZE_ADDRESS__)
constexpr int trialsPerClass = 20;
#else
constexpr int trialsPerClass = 60;
#endif

TEST(SuperquadricContact, AgreesWithTheIndependentReferenceOnEveryClass) {
    std::mt19937_64 random(2026);
    for (reference::Case kind : {reference::Case::spheres, reference::Case::ellipsoids, reference::Case::blocky,
                                 reference::Case::parallelFaces, reference::Case::edgeOnFace, reference::Case::needles}) {
        int failures = 0, wrongSide = 0;
        double worst = 0;
        for (int trial = 0; trial < trialsPerClass; ++trial) {
            const reference::Configuration c = reference::randomConfiguration(kind, random);
            const SuperquadricContact found = findSuperquadricContact(c.i, c.j);
            const reference::Contact expected = reference::contact(c.i, c.j);
            if (!found.converged) {
                ++failures;
                continue;
            }
            const bool expectTouching = expected.value < 0;
            if (found.touching != expectTouching) {
                // Only at grazing contact may the two disagree (|F| at round-off).
                if (std::abs(expected.value) > 1e-12) ++wrongSide;
                continue;
            }
            const double size = std::min(c.shapeI.semiAxes().minCoeff(), c.shapeJ.semiAxes().minCoeff());
            worst = std::max(worst, std::abs(found.overlap - expected.overlap) / size);
            if (found.touching) {
                EXPECT_LT((found.normal - expected.normal).norm(), 1e-6) << name(kind);
            }
        }
        EXPECT_EQ(failures, 0) << name(kind);
        EXPECT_EQ(wrongSide, 0) << name(kind);
        EXPECT_LT(worst, 1e-6) << name(kind);
        std::printf("%s: worst overlap error %.2g of the smaller semi-axis\n", name(kind), worst);
    }
}

TEST(SuperquadricContact, WarmStartFollowsALastingContactInFewIterations) {
    std::mt19937_64 random(5);
    for (reference::Case kind : {reference::Case::ellipsoids, reference::Case::blocky}) {
        reference::Configuration c = reference::randomConfiguration(kind, random);
        c.j.centre += 0.06 * (c.i.centre - c.j.centre).normalized() * c.shapeJ.semiAxes().minCoeff();
        SuperquadricContact last = findSuperquadricContact(c.i, c.j);
        ASSERT_TRUE(last.converged && last.touching) << name(kind);
        // The particles move and turn a little per step, as in a simulation.
        const Mat3 turn = Eigen::AngleAxisd(1e-3, Vec3(1, 2, 3).normalized()).toRotationMatrix();
        for (int step = 0; step < 50; ++step) {
            c.j.centre += Vec3(1e-4, -2e-4, 1e-4);
            c.j.rotation = turn * c.j.rotation;
            const SuperquadricContact warm = findSuperquadricContact(c.i, c.j, &last.solution);
            const SuperquadricContact cold = findSuperquadricContact(c.i, c.j);
            ASSERT_TRUE(warm.converged) << name(kind);
            EXPECT_LE(warm.iterations, 4) << name(kind);
            EXPECT_NEAR(warm.overlap, cold.overlap, 1e-12);
            last = warm;
        }
    }
}

// Plan B, the fallback when Newton's method fails (morphing from the bounding spheres to the
// true shapes, SuperquadricContact.h), run alone on every class of configurations but two spheres
// (which take the closed form), blocky (e down to 0.1), flat faces, edges and needles included:
// it must find the same contact as
// the independent reference (the dual route of SuperquadricReference.h), that is the same
// overlap, normal and contact point (the middle of the overlap along the normal,
// Xc + (di - dj)/2 outOfI with di, dj the reference's bisected distances to the surfaces).
TEST(SuperquadricContact, PlanBAloneAgreesWithTheIndependentReference) {
    std::mt19937_64 random(41);
    for (reference::Case kind : {reference::Case::ellipsoids, reference::Case::blocky, reference::Case::parallelFaces,
                                 reference::Case::edgeOnFace, reference::Case::needles}) {
        int failures = 0, wrongSide = 0;
        double worstOverlap = 0, worstNormal = 0, worstPoint = 0;
        for (int trial = 0; trial < trialsPerClass / 3; ++trial) {
            const reference::Configuration c = reference::randomConfiguration(kind, random);
            const SuperquadricContact found = findSuperquadricContactByMorphing(c.i, c.j);
            const reference::Contact expected = reference::contact(c.i, c.j);
            if (!found.converged) {
                ++failures;
                continue;
            }
            EXPECT_GT(found.morphStages, 0) << name(kind);
            if (found.touching != (expected.value < 0)) {
                if (std::abs(expected.value) > 1e-12) ++wrongSide;  // (grazing: |F| at round-off)
                continue;
            }
            if (!found.touching) continue;
            const double size = std::min(c.shapeI.semiAxes().minCoeff(), c.shapeJ.semiAxes().minCoeff());
            const Vec3 outOfI = -expected.normal;
            const double di = reference::surfaceDistance(c.i, expected.point, outOfI),
                         dj = reference::surfaceDistance(c.j, expected.point, -outOfI);
            const Vec3 expectedPoint = expected.point + 0.5 * (di - dj) * outOfI;
            worstOverlap = std::max(worstOverlap, std::abs(found.overlap - expected.overlap) / size);
            worstNormal = std::max(worstNormal, (found.normal - expected.normal).norm());
            worstPoint = std::max(worstPoint, (found.contactPoint - expectedPoint).norm() / size);
        }
        std::printf("plan B, %s: worst overlap error %.2g, normal %.2g, contact point %.2g\n", name(kind), worstOverlap,
                    worstNormal, worstPoint);
        EXPECT_EQ(failures, 0) << name(kind);
        EXPECT_EQ(wrongSide, 0) << name(kind);
        EXPECT_LT(worstOverlap, 1e-6) << name(kind);
        EXPECT_LT(worstNormal, 1e-6) << name(kind);
        EXPECT_LT(worstPoint, 1e-6) << name(kind);
    }
}

// The tolerance (SuperquadricContactSettings, --shape-tolerance; Theory/Superquadrics.md
// "Convergence"): a lasting contact followed step by step, warm-started at each tolerance T,
// against the same contact solved to 1e-14. The convergence test promises an error of order
// T x scale in the contact point, so the overlap and the normal may differ by about that and no
// more (a margin of 10); and the looser T, the fewer iterations.
TEST(SuperquadricContact, ToleranceBoundsTheErrorOfAWarmStartedContact) {
    const SuperquadricContactSettings reference{.tolerance = 1e-14};
    std::mt19937_64 random(11);
    for (reference::Case kind : {reference::Case::ellipsoids, reference::Case::blocky}) {
        double iterationsBefore = 1e9;
        for (double tolerance : {1e-10, 1e-8, 1e-6}) {
            std::mt19937_64 same(17);
            reference::Configuration c = reference::randomConfiguration(kind, same);
            c.j.centre += 0.06 * (c.i.centre - c.j.centre).normalized() * c.shapeJ.semiAxes().minCoeff();
            const double scale = std::min(c.shapeI.boundingRadius(), c.shapeJ.boundingRadius());
            SuperquadricContact last = findSuperquadricContact(c.i, c.j, nullptr, reference);
            ASSERT_TRUE(last.converged && last.touching) << name(kind);
            const Mat3 turn = Eigen::AngleAxisd(2e-3, Vec3(1, 2, 3).normalized()).toRotationMatrix();
            double worstOverlap = 0, worstNormal = 0, iterations = 0;
            for (int step = 0; step < 100; ++step) {
                c.j.centre += Vec3(2e-4, -3e-4, 1e-4);  // (about 1e-3 of a radius a step, as in a flow)
                c.j.rotation = turn * c.j.rotation;
                const SuperquadricContact loose = findSuperquadricContact(c.i, c.j, &last.solution, {.tolerance = tolerance});
                const SuperquadricContact tight = findSuperquadricContact(c.i, c.j, &last.solution, reference);
                ASSERT_TRUE(loose.converged && tight.converged && tight.touching) << name(kind);
                worstOverlap = std::max(worstOverlap, std::abs(loose.overlap - tight.overlap) / scale);
                worstNormal = std::max(worstNormal, (loose.normal - tight.normal).norm());
                iterations += loose.iterations;
                last = loose;
            }
            EXPECT_LE(worstOverlap, 10 * tolerance) << name(kind) << " T = " << tolerance;
            EXPECT_LE(worstNormal, 10 * tolerance) << name(kind) << " T = " << tolerance;
            EXPECT_LE(iterations, iterationsBefore) << name(kind) << " T = " << tolerance;
            iterationsBefore = iterations;
            std::printf("%s T = %g: overlap error %.2g scale, normal error %.2g, %.2f iterations a step\n",
                        name(kind), tolerance, worstOverlap, worstNormal, iterations / 100);
        }
    }
}
