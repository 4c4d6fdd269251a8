// Energies and centre of mass of the mobile (non-fixed) particles, as written to .ene
// (Documentation/FileFormats/ene.md). Gravitational energy is -sum m g.x (origin as reference).
#pragma once

#include "Particles/ParticleStore.h"

namespace talus {

struct Energies {
    double gravitational = 0;
    double kinetic = 0;
    double rotational = 0;
    double elastic = 0;  // filled from the contact records
    Vec3 centreOfMass = Vec3::Constant(NAN);
    double mass = 0;

    double total() const { return gravitational + kinetic + rotational + elastic; }
};

// Over the owned particles only: on ranks the ghosts after them are other ranks' particles.
inline Energies particleEnergies(const ParticleStore& p, const Vec3& gravity) {
    Energies e;
    Vec3 moment = Vec3::Zero();
    for (std::size_t i = 0; i < p.owned(); ++i) {
        if (p.fixed[i]) continue;
        e.kinetic += 0.5 * p.mass[i] * p.velocity[i].squaredNorm();
        // T = L.omega/2 for a rigid body, which for a sphere is |omega|^2 I/2.
        e.rotational += p.isShaped(i) ? 0.5 * p.angularMomentum[i].dot(p.angularVelocity[i])
                                      : 0.5 * p.angularVelocity[i].squaredNorm() / p.invInertia[i];
        e.gravitational -= p.mass[i] * gravity.dot(p.position[i]);
        moment += p.mass[i] * p.position[i];
        e.mass += p.mass[i];
    }
    if (e.mass > 0) e.centreOfMass = moment / e.mass;
    return e;
}

}  // namespace talus
