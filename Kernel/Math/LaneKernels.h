// The passes of one lane form (Math/LaneForm.h), as one table per form: each form's sources
// (Kernel/CMakeLists.txt, talusLaneSources) are compiled with its instruction set into a
// namespace of its own (lanes_scalar, lanes_avx2, lanes_avx512: Math/LaneNamespace.h) and fill
// its table; the kernel's entry points (VelocityVerlet.h, DriftPass.h, Domain::wrap,
// turnShapedParticles, ContactForces.h, makeNearPairs) call the table of the form in use
// (Math/LaneForm.cc). Internal to the kernel.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "Contacts/ContactForces.h"
#include "Contacts/PairSweep.h"
#include "Math/LaneForm.h"
#include "Particles/DriftPass.h"
#include "Particles/RotationBatch.h"

namespace talus {

// The drift pass of one form (Particles/DriftPass.h), defined by its own compilation of
// Particles/DriftPass.cc.
struct DriftPassKernels {
    std::uint64_t (*positionSum)(const ParticleStore& p, std::size_t n);
    void (*startFirstHalf)(ParticleStore& p, std::vector<Vec3>& previousForce, std::vector<SweepPoint>& points);
    double (*largestDisplacement)(const ParticleStore& p, const std::vector<Vec3>& reference, const Domain& domain);
    DriftPassResult (*kickDriftAndStartForces)(ParticleStore& p, const std::vector<Vec3>& previousForce,
                                               const Domain& domain, const std::vector<Vec3>* reference,
                                               const Vec3& gravity, const Vec3& frameVelocity, double dt,
                                               std::vector<SweepPoint>& points, std::size_t first, std::size_t last);
    DriftPassResult (*closeKickDriftAndStartForces)(ParticleStore& p, std::vector<Vec3>& previousForce,
                                                    const Domain& domain, const std::vector<Vec3>* reference,
                                                    const Vec3& gravity, const Vec3& frameVelocity, double dt,
                                                    std::vector<SweepPoint>& points, std::size_t first,
                                                    std::size_t last);
};

struct LaneKernels {
    LaneForm form;
    // Particles/VelocityVerlet.h
    void (*startForcesWithGravity)(ParticleStore& p, const Vec3& gravity);
    void (*halfKick)(ParticleStore& p, std::size_t first, std::size_t last, double halfStep);
    void (*halfKickAndDrift)(ParticleStore& p, std::size_t n, double halfStep, double dt);
    // Boundaries/Domain.h
    void (*wrap)(const Domain& domain, Vec3* x, std::size_t n);
    // Particles/RotationBatch.h
    void (*turnShapedParticles)(ParticleStore& p, double kick, double drift);
    // Particles/DriftPass.h (Particles/DriftPass.cc)
    const DriftPassKernels* driftPass;
    // Contacts/PairSweep.h
    void (*makeNearPairs)(PairList& list, const Vec3* position, std::size_t particleCount, const double* radius,
                          double skin, const PeriodicImage& image, std::vector<SweepPoint>& grownScratch,
                          SweptPairs& scratch);
    SweepForm (*sweepFormInUse)();
    // Contacts/ContactForces.h, one entry per contact law of Species/ContactLaws.h
    ForceLoopKernelTable forceLoops;
};

// The table of the form in use (laneForm()).
const LaneKernels& laneKernels();

// Each form's tables, defined in its own compilations of Math/LaneKernels.cc and
// Particles/DriftPass.cc.
namespace lanes_scalar {
extern const LaneKernels kernels;
extern const DriftPassKernels driftPassKernels;
}  // namespace lanes_scalar
namespace lanes_avx2 {
extern const LaneKernels kernels;
extern const DriftPassKernels driftPassKernels;
}  // namespace lanes_avx2
namespace lanes_avx512 {
extern const LaneKernels kernels;
extern const DriftPassKernels driftPassKernels;
}  // namespace lanes_avx512

}  // namespace talus
