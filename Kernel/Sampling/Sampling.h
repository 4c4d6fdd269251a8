// The driver helpers of Kernel/Sampling in one include: whole-scene sums and extrema
// (ParticleSums.h), the sampling clock, running sums, the steady-state detector, timed events,
// messages and files written once, particles added once (Documentation/UserGuide/Sampling.md).
#pragma once

#include "IO/SeriesFile.h"
#include "Sampling/AddedOnce.h"
#include "Sampling/Messages.h"
#include "Sampling/ParticleSums.h"
#include "Sampling/RunningSums.h"
#include "Sampling/SamplingClock.h"
#include "Sampling/SteadyDetector.h"
#include "Sampling/TimedEvents.h"
