// The form of the sweep a lane form's force loop uses (Contacts/PairSweep.h): the scalar loop,
// four pairs at a time without gathers (lanes; AVX2), or eight at a time with gathers (gathers;
// AVX-512, for the whole list: a near list or a wave's selection goes in four-pair lanes then).
// Undecided until chooseSweepForm (Contacts/PairSweepLanes.h) has timed those the lane form has;
// a run may fix it (StepperTuning::sweepForm, --sweep scalar|lanes|gathers: for measurements; a
// form the lane form lacks is the scalar loop). All forms pick the same pairs, so only the speed
// depends on it.
#pragma once

#include <string>

namespace talus {

enum class SweepForm { undecided, scalar, lanes, gathers };

inline const char* sweepFormName(SweepForm form) {
    return form == SweepForm::gathers ? "gathers" : form == SweepForm::lanes ? "lanes"
                                          : form == SweepForm::scalar ? "scalar" : "undecided";
}

// The form the runs of this process ask for (undecided: the fastest, chosen by timing), set at
// the start of each run from its tuning (Integration/Integrator.h) and read by every lane form.
inline SweepForm& requestedSweepForm() {
    static SweepForm form = SweepForm::undecided;
    return form;
}

}  // namespace talus
