// A way of advancing a run's state in time (Documentation/Architecture.md, "Steppers"): by one
// velocity Verlet step (Documentation/Theory/Integration.md), or by a wave of steps. Each says
// why it declines a scene; the Integrator (Integration/Integrator.h) takes, at every advance,
// the first in its order that accepts it.
#pragma once

#include <cstdint>
#include <string_view>

#include "Integration/StepHost.h"

namespace talus {

class Stepper {
public:
    virtual ~Stepper() = default;
    virtual std::string_view name() const = 0;
    // Why it declines the scene as it is now (empty: it accepts it). No allocation: asked at
    // every advance.
    virtual std::string_view whyNot(const StepHost& host) const = 0;
    // The steps the next advance takes, where the scene is accepted: 1, or a wave's; 0 where it
    // does not fit now (stepsLeft: in the run; saveEvery: steps between output). May prepare for
    // it (a wave builds the list anew where it has no room left).
    virtual std::uint64_t stepsNext(StepHost& /*host*/, std::uint64_t /*stepsLeft*/, std::uint64_t /*saveEvery*/) {
        return 1;
    }
    // Advances by the steps stepsNext gave; recordContacts: the contacts of its last step.
    virtual void advance(StepHost& host, bool recordContacts) = 0;
};

}  // namespace talus
