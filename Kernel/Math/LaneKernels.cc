// The table of one lane form (Math/LaneKernels.h): compiled once per form, with its
// instruction set, into its namespace (Kernel/CMakeLists.txt, talusLaneSources).
#include "Math/LaneKernels.h"

#include "Contacts/ContactForceLoop.h"
#include "Contacts/PairSweepLanes.h"
#include "Math/LaneNamespace.h"
#include "Particles/RotationBatchLanes.h"
#include "Particles/VelocityVerletLanes.h"

namespace talus::TALUS_LANES {

namespace {

template <class Law>
std::unique_ptr<ContactForceLoopOfForm<Law>> makeLoop(const ContactForceLoopArguments<Law>& arguments) {
    return std::make_unique<ContactForceLoopInLanes<Law>>(arguments);
}

// The force loop of every law of the list, compiled in this form.
template <class... Laws>
constexpr ForceLoopKernelTable forceLoopsOf(LawList<Laws...>) {
    return {ForceLoopKernels<Laws>{makeLoop<Laws>, addContactForces<Laws>}...};
}

}  // namespace

const LaneKernels kernels{compiledLaneForm,
                          startForcesWithGravity,
                          halfKick,
                          halfKickAndDrift,
                          wrapPositions,
                          turnShapedParticles,
                          &driftPassKernels,
                          makeNearPairs,
                          [] { return sweepForm(); },
                          forceLoopsOf(ContactLawList{})};

}  // namespace talus::TALUS_LANES
