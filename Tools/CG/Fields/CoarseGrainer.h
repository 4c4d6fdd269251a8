// Evaluates the coarse-grained sums (FieldSums.h) of one frame at any list of points
// (Theory/CoarseGraining.md "Fields": evaluation needs no grid). One code path for every point set:
// a grid is just a list of points, so identical points give bitwise identical values.
//
// Set up once with the kernel (shape, width matrix, coordinates); then per frame setFrame()
// builds the sources (particles with their periodic images, contact segments) and their cell
// lists, and evaluate() fills one row of sums per point. Cylindrical coordinates (RZ, R) are
// handed to CylindricalCoarseGrainer, which averages over the angle around the drum axis.
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

    // sums[p * layout().count() + f]: field f at points[p] (overwritten).
    void evaluate(const std::vector<Vec3>& points, std::vector<double>& sums) const;

    std::size_t particleSourceCount() const { return cylindrical_ ? cylindrical_->sourceCount() : mass_.size(); }
    std::size_t contactSourceCount() const { return contactTensor_.size(); }

private:
    template <class Profile, bool Diagonal>
    void evaluateParticles(const std::vector<Vec3>& points, std::vector<double>& sums) const;
    void evaluateContacts(const std::vector<Vec3>& points, std::vector<double>& sums) const;
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

    // Particle sources of the current frame (images included), structure of arrays.
    std::vector<Vec3> position_;
    std::vector<Vec3> velocity_;
    std::vector<double> mass_;
    std::vector<double> volume_;
    std::vector<int> species_;
    SupportBins particleBins_;

    // Contact segments: from start_ along segment_ (x_j - x_i, or c - x_i for walls), carrying
    // the tensor w f (x) b (row-major).
    std::vector<Vec3> contactStart_;
    std::vector<Vec3> contactSegment_;
    std::vector<std::array<double, 9>> contactTensor_;
    SupportBins contactBins_;
};

}  // namespace talus::cg
