#include "InRun/InRunFrame.h"

#include <cstdint>

#include "Simulation.h"
#include "SimulationState.h"

namespace talus::cg {

namespace {
talus::cg::Vec3 array(const talus::Vec3& v) { return {v.x(), v.y(), v.z()}; }

// Fills `frame` (and `contacts` from `records`, when given) from the state after a step; `fixed`
// gets one flag per line.
void fillInRunFrame(const SimulationState& state, const ContactRecordList* records, ParticleFrame& frame,
                    ContactFrame& contacts, std::vector<bool>& fixed) {
    const ParticleStore& p = state.particles;
    frame.clear();
    frame.time = state.time;
    frame.box.lo = array(state.domain.lo);
    frame.box.hi = array(state.domain.hi);
    frame.ghosts = p.ghostCount;
    const std::size_t n = p.size();
    // (Sized, then written by index: a sample copies every particle and contact.)
    frame.position.resize(n);
    frame.velocity.resize(n);
    frame.radius.assign(p.radius.begin(), p.radius.begin() + static_cast<std::ptrdiff_t>(n));
    frame.species.resize(n);
    frame.mass.assign(p.mass.begin(), p.mass.begin() + static_cast<std::ptrdiff_t>(n));
    fixed.assign(n, false);
    for (std::size_t i = 0; i < n; ++i) {
        frame.position[i] = array(p.position[i]);
        frame.velocity[i] = array(p.velocity[i]);
        frame.species[i] = static_cast<int>(p.species[i]);
        fixed[i] = p.fixed[i] != 0;
    }
    contacts.time = state.time;
    contacts.eachContactOnce = true;  // (the kernel records a pair once: Contacts/ContactReport.h)
    contacts.fromTheRun = true;
    if (!records) {
        contacts.contacts.clear();
        return;
    }
    contacts.contacts.resize(records->size());
    ContactLine* c = contacts.contacts.data();
    for (const ContactRecord& r : *records) {
        c->i = static_cast<long>(r.i);
        c->j = static_cast<long>(r.j);
        c->point = array(r.contactPoint);
        // (the .fstat reader's normal of a wall contact points into the wall)
        c->normal = array(c->isWall() ? talus::Vec3(-r.normal) : r.normal);
        c->overlap = r.overlap;
        c->force = array(r.normalForce * r.normal + r.tangentialForce);  // on i (fstat.md)
        c->line = 0;
        ++c;
    }
}

// The frame last filled on this thread, and the run and step it belongs to.
struct SharedFrame {
    InRunFrame frame;
    const Simulation* simulation = nullptr;  // none: nothing kept
    std::uint64_t step = 0;
};
thread_local SharedFrame shared;

}  // namespace

const InRunFrame& sharedInRunFrame(const Simulation& simulation, const ContactRecordList* records) {
    const bool kept = shared.simulation == &simulation && shared.step == simulation.step() &&
                      (shared.frame.withContacts || records == nullptr);
    if (!kept) {
        InRunFrame& f = shared.frame;
        fillInRunFrame(simulation.state(), records, f.particles, f.contacts, f.fixed);
        f.withContacts = records != nullptr;
        shared.simulation = &simulation;
        shared.step = simulation.step();
    }
    return shared.frame;
}

void forgetSharedInRunFrame() { shared.simulation = nullptr; }

}  // namespace talus::cg
