// What a chute-flow driver measures while it runs (Theory/Chutes.md eq. (7)): bulk quantities of
// the flowing particles, the plateau of their time series (a steady flow), and depth profiles.
// These are quick diagnostics for running a study; the coarse-graining tool (Tools/CG) gives the
// proper continuum fields afterwards.
#pragma once

#include <cmath>

#include <cstddef>
#include <string>
#include <vector>

#include "Particles/ParticleStore.h"
#include "Sampling/SteadyDetector.h"

namespace talus {

class Simulation;

// Bulk state of the flowing (not fixed) particles of a chute of the given length and width.
struct ChuteSnapshot {
    double time = 0;
    double kineticEnergy = 0;   // translational and rotational, per unit base area
    double massFlux = 0;        // downslope mass flux per unit width, sum(m vx) / length / width
    double meanVelocity = 0;    // mass-weighted mean vx
    double height = 0;          // flow height: twice the mass-weighted mean z (a uniform layer on z = 0)
    double smallConcentration = 0;  // volume fraction of the particles of the small species
    // How far the sizes have separated: (zOthers - zSmall) / (height / 2), with z the
    // volume-weighted mean height of the small species and of all other particles. 0 for a mixed
    // layer, 1 for a layer of small particles under an equal volume of others, negative for
    // small on top; 0 without both kinds.
    double segregation = 0;
};
// Over the mobile particles with xMin <= x < xMax (all by default); length and width are those
// of the region measured.
ChuteSnapshot measureChute(const ParticleStore& p, double length, double width, std::size_t smallSpecies, double time,
                           double xMin = -INFINITY, double xMax = INFINITY);
// Snapshots as a list of numbers and back (for a restart file: Run::keepInRestart).
std::vector<double> snapshotNumbers(const std::vector<ChuteSnapshot>& snapshots);
std::vector<ChuteSnapshot> snapshotsFromNumbers(const std::vector<double>& numbers);
// The same over the particles of every rank of a simulation (all ranks call it together; on one
// rank it is the one above).
ChuteSnapshot measureChute(const Simulation& s, double length, double width, std::size_t smallSpecies,
                           double xMin = -INFINITY, double xMax = INFINITY);

// The plateau detector of the chutes is the general one (Sampling/SteadyDetector.h).
using PlateauDetector = SteadyDetector;

// Mean and standard error of the mean of samples, from the means of `batches` consecutive
// batches (batch means remove most of the correlation between neighbouring samples).
struct MeanAndError {
    double mean = 0, error = 0;
};
MeanAndError batchMean(const std::vector<double>& samples, std::size_t batches = 5);

// Depth profiles averaged over samples: volume fraction (of centres in each slab, a histogram,
// not a coarse-grained field), mass-weighted downslope velocity and the small species' volume
// concentration, in slabs of thickness `bin` from z = 0 up.
class DepthProfile {
public:
    DepthProfile(double bin, double top, double length, double width, std::size_t smallSpecies);
    // One sample of the owned particles. With a simulation on ranks, all ranks call it: the
    // sample's sums over ranks are added to totals that every rank holds (so they do not depend
    // on which rank owned which particle when, and a restart continues them exactly).
    void add(const ParticleStore& p, const Simulation* s = nullptr);
    // Columns z, volume fraction, vx, small concentration; one line per slab. On ranks, rank 0
    // writes.
    void write(const std::string& path, const Simulation* s = nullptr) const;
    std::size_t samples() const { return samples_; }
    // The mass and the downslope momentum (m vx) in each slab, from z = 0 up, summed over the samples.
    const std::vector<double>& slabMass() const { return mass_; }
    const std::vector<double>& slabMomentum() const { return momentum_; }
    // The totals as numbers, for a restart file (Run::keepInRestart), and back.
    std::vector<double> state() const;
    void restore(const std::vector<double>& state);

private:
    double bin_, length_, width_;
    std::size_t smallSpecies_, samples_ = 0;
    std::vector<double> volume_, smallVolume_, mass_, momentum_;
};

}  // namespace talus
