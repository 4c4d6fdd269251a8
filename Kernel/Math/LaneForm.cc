// The choice of the lane form (Math/LaneForm.h) and the kernel's entry points that run the
// passes of the form in use (Math/LaneKernels.h).
#include "Math/LaneForm.h"

#include "Error.h"
#include "Math/LaneKernels.h"
#include "Particles/VelocityVerlet.h"

namespace talus {

namespace {

// Whether this processor (and its operating system, which must save the wider registers) runs
// the instructions a form is compiled for: the x86-64 microarchitecture levels of its -march
// (Kernel/CMakeLists.txt), and BMI2, which the AVX-512 lanes use, for that form.
bool processorRuns(LaneForm form) {
    __builtin_cpu_init();
    switch (form) {
        case LaneForm::scalar: return true;
        case LaneForm::avx2: return __builtin_cpu_supports("x86-64-v3");
        case LaneForm::avx512: return __builtin_cpu_supports("x86-64-v4") && __builtin_cpu_supports("bmi2");
    }
    return false;
}

const LaneKernels& kernelsOf(LaneForm form) {
    switch (form) {
        case LaneForm::avx2: return lanes_avx2::kernels;
        case LaneForm::avx512: return lanes_avx512::kernels;
        case LaneForm::scalar: break;
    }
    return lanes_scalar::kernels;
}

const LaneKernels*& kernelsInUse() {
    static const LaneKernels* inUse = &kernelsOf(laneFormsOfThisProcessor().back());
    return inUse;
}

}  // namespace

const char* laneFormName(LaneForm form) {
    return form == LaneForm::avx512 ? "avx512" : form == LaneForm::avx2 ? "avx2" : "scalar";
}

LaneForm laneFormNamed(const std::string& name, const std::string& what) {
    for (LaneForm form : {LaneForm::scalar, LaneForm::avx2, LaneForm::avx512})
        if (name == laneFormName(form)) return form;
    throw Error(what + ": '" + name + "' is not a lane form (scalar, avx2 or avx512)");
}

std::vector<LaneForm> laneFormsOfThisProcessor() {
    std::vector<LaneForm> forms;
    for (LaneForm form : {LaneForm::scalar, LaneForm::avx2, LaneForm::avx512})
        if (processorRuns(form)) forms.push_back(form);
    return forms;
}

LaneForm laneForm() { return kernelsInUse()->form; }

void setLaneForm(LaneForm form) {
    if (!processorRuns(form))
        throw Error(std::string("lane form ") + laneFormName(form) + ": this processor does not run it (it runs " +
                    laneFormName(laneFormsOfThisProcessor().back()) + " and below)");
    kernelsInUse() = &kernelsOf(form);
}

const LaneKernels& laneKernels() { return *kernelsInUse(); }

// --- the entry points ---

void startForcesWithGravity(ParticleStore& p, const Vec3& gravity) { laneKernels().startForcesWithGravity(p, gravity); }
void halfKick(ParticleStore& p, std::size_t first, std::size_t last, double halfStep) {
    laneKernels().halfKick(p, first, last, halfStep);
}
void halfKickAndDrift(ParticleStore& p, std::size_t n, double halfStep, double dt) {
    laneKernels().halfKickAndDrift(p, n, halfStep, dt);
}

void Domain::wrap(Vec3* x, std::size_t n) const { laneKernels().wrap(*this, x, n); }

void turnShapedParticles(ParticleStore& p, double kick, double drift) {
    laneKernels().turnShapedParticles(p, kick, drift);
}

std::uint64_t positionSum(const ParticleStore& p, std::size_t n) { return laneKernels().driftPass->positionSum(p, n); }
void startFirstHalf(ParticleStore& p, std::vector<Vec3>& previousForce, std::vector<SweepPoint>& points) {
    laneKernels().driftPass->startFirstHalf(p, previousForce, points);
}
double largestDisplacement(const ParticleStore& p, const std::vector<Vec3>& reference, const Domain& domain) {
    return laneKernels().driftPass->largestDisplacement(p, reference, domain);
}
DriftPassResult kickDriftAndStartForces(ParticleStore& p, std::vector<Vec3>& previousForce, const Domain& domain,
                                        const std::vector<Vec3>* reference, const Vec3& gravity,
                                        const Vec3& frameVelocity, double dt, std::vector<SweepPoint>& points) {
    startFirstHalf(p, previousForce, points);
    return kickDriftAndStartForces(p, previousForce, domain, reference, gravity, frameVelocity, dt, points, 0, p.size());
}
DriftPassResult kickDriftAndStartForces(ParticleStore& p, const std::vector<Vec3>& previousForce, const Domain& domain,
                                        const std::vector<Vec3>* reference, const Vec3& gravity,
                                        const Vec3& frameVelocity, double dt, std::vector<SweepPoint>& points,
                                        std::size_t first, std::size_t last) {
    return laneKernels().driftPass->kickDriftAndStartForces(p, previousForce, domain, reference, gravity,
                                                            frameVelocity, dt, points, first, last);
}
DriftPassResult closeKickDriftAndStartForces(ParticleStore& p, std::vector<Vec3>& previousForce, const Domain& domain,
                                             const std::vector<Vec3>* reference, const Vec3& gravity,
                                             const Vec3& frameVelocity, double dt, std::vector<SweepPoint>& points,
                                             std::size_t first, std::size_t last) {
    return laneKernels().driftPass->closeKickDriftAndStartForces(p, previousForce, domain, reference, gravity,
                                                                 frameVelocity, dt, points, first, last);
}

void makeNearPairs(PairList& list, const Vec3* position, std::size_t particleCount, const double* radius, double skin,
                   const PeriodicImage& image, std::vector<SweepPoint>& grownScratch, SweptPairs& scratch) {
    laneKernels().makeNearPairs(list, position, particleCount, radius, skin, image, grownScratch, scratch);
}
SweepForm sweepForm() { return laneKernels().sweepFormInUse(); }

const ForceLoopKernelTable& forceLoopKernelsInUse() { return laneKernels().forceLoops; }

}  // namespace talus
