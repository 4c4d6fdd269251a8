// Evaluates the coarse-grained sums (FieldSums.h) of one frame at any list of points
// (Theory/CoarseGraining.md "Fields": evaluation needs no grid). One code path for every point set:
// a grid is just a list of points, so identical points give bitwise identical values.
//
// Set up once with the kernel (shape, width matrix, coordinates); then per frame setFrame()
// builds the sources (particles with their periodic images, contact segments) and their cell
// lists (none for a profile along one axis, Fields/AlongOneAxis.cc), and evaluate() fills one row
// of sums per point. Cylindrical coordinates (RZ, R) are
// handed to CylindricalCoarseGrainer, which averages over the angle around the drum axis.
//
// Boundaries (Weinhart, Thornton, Luding and Bokhove 2012, "From discrete particles to continuum
// fields near a boundary", Granular Matter 14; Documentation/CoarseGraining.md "Boundaries"): a
// contact of a flowing particle i with a wall, or with a fixed particle under --fixed boundary
// (CoarseGrainingSetup::excludedAreBoundary), at contact point c with force f on i contributes
//   contact stress     f (x) (r_i - c) int_0^1 W(r - r_i + s (r_i - c)) ds   (branch r_i to c only)
//   InteractionForce   f W(r - c)
// Since the divergence of the first is f [W(r - c) - W(r - r_i)], the two together carry the
// force f to the particle's centre, where the momentum balance of the flow needs it:
//   d(rho V)/dt + div(rho V V) = -div(sigma) + rho g + InteractionForce
// (sigma = kinetic + contact stress, compressive positive as everywhere in talus-cg).
//
// The domain average (coordinates O, MercuryCG's `O`): no kernel. Each field is the sum over the
// particles (every one in the frame that is not left out, wherever its centre) and contacts of
// the frame divided by the volume V of the domain box of the .data header:
//   rho = sum_i m_i / V,  p = sum_i m_i v_i / V,  K = sum_i m_i v_i v_i / V,
//   sigma_c = sum_c w_c f_c (x) b_c / V (whole branches; for a boundary contact b = r_i - c),
//   InteractionForce = sum over boundary contacts of w_c f_c / V.
// It is the limit of every kernel field averaged over a periodic box (Theory/CoarseGraining.md
// eq. (5)-(10) integrated over the box, int_box W = 1); in a box that is not periodic the mean of
// a kernel field is smaller by the parts of the kernels that reach out of the box.
#pragma once

#include <array>
#include <memory>
#include <vector>

#include "Fields/CoarseGrainingSetup.h"
#include "Fields/Coordinates.h"
#include "Fields/CylindricalCoarseGrainer.h"
#include "Fields/FieldSums.h"
#include "Fields/SupportBins.h"
#include "IO/FstatFileReader.h"
#include "IO/ParticleFrame.h"
#include "Kernels/KernelProfile.h"
#include "Kernels/WidthMatrix.h"

namespace talus::cg {

struct PointsAlongAxis;

class CoarseGrainer {
public:
    explicit CoarseGrainer(CoarseGrainingSetup setup);

    const FieldSums& layout() const { return layout_; }
    const CoarseGrainingSetup& setup() const { return setup_; }
    const KernelProfile& profile() const { return profile_; }

    // Builds the sources of a frame. `contacts` may be null (no contact stress). `dataPath`
    // and `fstatPath` name the files in error messages. Throws InputError for inconsistent
    // input (unknown species, contact indices beyond the frame, contact points that do not
    // match the particle positions).
    void setFrame(const ParticleFrame& frame, const ContactFrame* contacts,
                  const std::string& dataPath = ".data", const std::string& fstatPath = ".fstat");

    // The particles left out (CoarseGrainingSetup::excluded, one flag per line) from the next
    // frame on: for a caller whose frames change in length (a run coarse-graining its own
    // particles, InRun/InRunFields.h, whose fixed particles and ghosts change from sample to sample).
    void setExcluded(std::vector<bool> excluded);

    // From the next frame on, sources whose support reaches none of `points` are left out of the
    // frames (they would add nothing to these points, so their sums are bitwise those without);
    // evaluate() then takes points within the bounding box of these only (InputError otherwise).
    // For an object whose points cover part of the domain: one point at the base of a flow skips
    // the flow above it. Not for cylindrical coordinates or the domain average (no effect).
    void restrictTo(const std::vector<Vec3>& points);

    // sums[p * layout().count() + f]: field f at points[p] (overwritten).
    void evaluate(const std::vector<Vec3>& points, std::vector<double>& sums) const;

    std::size_t particleSourceCount() const { return cylindrical_ ? cylindrical_->sourceCount() : mass_.size(); }
    std::size_t contactSourceCount() const { return contactForce_.size(); }
    std::size_t boundaryContactCount() const { return boundaryForce_.size(); }

private:
    template <class Profile, bool Diagonal>
    void evaluateParticles(const std::vector<Vec3>& points, std::vector<double>& sums) const;
    void evaluateContacts(const std::vector<Vec3>& points, std::vector<double>& sums) const;
    void evaluateBoundaryForces(const std::vector<Vec3>& points, std::vector<double>& sums) const;
    // A profile along one axis (X, Y or Z with a diagonal width; Fields/AlongOneAxis.cc): every
    // source adds itself to the points its support covers, with no cell lists.
    bool alongOneAxis() const;
    void evaluateAlongOneAxis(const std::vector<Vec3>& points, std::vector<double>& sums) const;
    template <class Profile>
    void scatterParticlesAlongAxis(const std::vector<Vec3>& points, const PointsAlongAxis& byAxis,
                                   std::vector<double>& sums) const;
    template <class Profile>
    void scatterContactsAlongAxis(const std::vector<Vec3>& points, const PointsAlongAxis& byAxis,
                                  std::vector<double>& sums) const;
    // The tensor f (x) b of contact source c (row-major), and row[0..8] += weight * that tensor.
    void contactTensor(std::size_t c, double (&tensor)[9]) const;
    void addContactTensor(std::size_t c, double weight, double* row) const;
    // Coordinates O: the sums over every source of the frame divided by the box volume.
    void evaluateDomainAverage(double* row) const;
    // Adds the contact lines of a frame: pair segments, boundary segments and boundary forces.
    void addContacts(const ParticleFrame& frame, const ContactFrame& contacts, const std::string& dataPath,
                     const std::string& fstatPath, const Vec3& cellSize);
    // Whether a support box [lo, hi] meets the region of restrictTo (widened by round-off).
    bool meetsRegion(const Vec3& lo, const Vec3& hi) const {
        for (int k = 0; k < 3; ++k) {
            if (hi[k] < regionLo_[k] || lo[k] > regionHi_[k]) return false;
        }
        return true;
    }
    // Shifts (one per periodic image, the original included) of a support box along the
    // periodic kernel axes that bring it into the domain box.
    void imageShifts(const Vec3& lo, const Vec3& hi, const DomainBox& box, std::vector<Vec3>& shifts) const;

    CoarseGrainingSetup setup_;
    KernelProfile profile_;
    std::unique_ptr<CylindricalCoarseGrainer> cylindrical_;  // set for RZ and R only
    FieldSums layout_;
    Vec3 halfExtent_{};  // support half-extent per lab axis (zero on averaged axes)
    std::array<long, 3> imagesEachSide_{};  // of the current frame per lab axis (0: no images)
    double scale_ = 1;   // c_d det(A) / (lengths of the averaged directions) of the current frame
    // The region of restrictTo along each lab axis (everything unless restricted), and the
    // points' own bounding box, which evaluate() checks its points against.
    Vec3 regionLo_, regionHi_, pointsLo_, pointsHi_;

    // Particle sources of the current frame (images included), structure of arrays.
    std::vector<Vec3> position_;
    std::vector<Vec3> velocity_;
    std::vector<double> mass_;
    std::vector<double> volume_;
    std::vector<int> species_;
    SupportBins particleBins_;

    // Contact segments: from start_ along segment_ = -b (x_j - x_i, or c - x_i for boundary
    // contacts), carrying the force f, whose tensor f (x) b is formed when summed (a third of
    // the memory of the tensor: frames of 10^5 particles have 6 10^5 contact lines).
    std::vector<Vec3> contactStart_;
    std::vector<Vec3> contactSegment_;
    std::vector<Vec3> contactForce_;
    SupportBins contactBins_;

    // Boundary contacts (images included): the contact point and the force on the flowing particle.
    std::vector<Vec3> boundaryPoint_;
    std::vector<Vec3> boundaryForce_;
    SupportBins boundaryBins_;

    // Scratch: the support boxes of the sources while their bins are built.
    std::vector<Vec3> boxLo_, boxHi_;
};

}  // namespace talus::cg
