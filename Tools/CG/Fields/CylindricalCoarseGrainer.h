// Coarse-grained fields in cylindrical coordinates about a drum axis (Theory/RotatingDrum.md
// rotating drums, Theory/CoarseGraining.md eq. (5)-(10) fields; derivation in
// Documentation/CoarseGraining.md "Cylindrical coordinates").
//
// The fields are the Cartesian fields of Theory/CoarseGraining.md eq. (5)-(10) (densities per unit
// volume) averaged over the angle theta around the axis: rho(r, s) = (1/2 pi) int rho(r, theta, s)
// dtheta, so that int rho 2 pi r dr ds is the mass. For a kernel W(x) = c_d/(wp^2 wa) f(u^2) that
// is isotropic across the axis (width wp) with width wa along it, the average of one particle's
// kernel over the circle of radius r is c_d/(wp^2 wa) C0(r, ri, s - si) (Kernels/AngularMoments.h):
// the exact measure, not a 2-D kernel in an (r, s) plane.
//
// Vectors and tensors are averaged in the local basis (e_r, e_theta, e_s) of the point, e_theta =
// e_s x e_r (right-handed about the positive axis direction). With phi = theta - theta_i,
// e_r(theta) = cos(phi) e_r(theta_i) + sin(phi) e_theta(theta_i), so a particle with radial,
// azimuthal and axial velocity (u_r, u_t, u_s) contributes (the sin(n phi) parts vanish because
// the kernel is even in phi):
//   momentum        p_r = m u_r C1,  p_t = m u_t C1,  p_s = m u_s C0
//   momentum flux   K_rr = m (u_r^2 (C0 + C2) + u_t^2 (C0 - C2)) / 2,  K_rt = m u_r u_t C2,
//                   K_tt = m (u_r^2 (C0 - C2) + u_t^2 (C0 + C2)) / 2,  K_rs = m u_r u_s C1,
//                   K_ts = m u_t u_s C1,  K_ss = m u_s^2 C0
// and mass, volume and species densities m C0, V C0. Velocity and kinetic stress then follow
// from these sums as in Cartesian coordinates (DerivedFields.h). Two more scalar sums, the
// angular momentum m r_i u_t C0 and the moment of inertia m r_i^2 C0 about the axis, give the
// angular velocity L / I, exactly omega for solid-body rotation (V_theta = p_t / rho is omega times
// the kernel-weighted mean radius, omega r only where the density is uniform).
//
// `RZ` uses the 3-D kernel; `R` the 2-D kernel of the cross-section, divided by the box length
// along the axis (as `XZ` divides by the y length). Periodicity along the axis adds images for
// RZ; periodic directions across the axis are refused.
//
// Contact stress (Theory/CoarseGraining.md eq. (10)) in the components (r, theta, s): the Cartesian
// contact stress averaged over the angle in the local basis. Each branch's line integral is taken
// by composite Gauss-Legendre quadrature (5 points per panel, panels at most maxPanelInWidths of
// the widths long); each node carries the branch's tensor T = f (x) b turned into the local
// basis of the node, T'_ab = e_a . T e_b, and, as the momentum flux above, contributes
//   rr: T'rr (C0 + C2)/2 + T'tt (C0 - C2)/2     tt: T'rr (C0 - C2)/2 + T'tt (C0 + C2)/2
//   rt: T'rt (C0 + C2)/2 - T'tr (C0 - C2)/2     tr: T'tr (C0 + C2)/2 - T'rt (C0 - C2)/2
//   rs, ts, sr, st: T'ab C1                      ss: T'ss C0
// (the friction's antisymmetric part kept). The boundary's force (walls: the drum's cylinder;
// fixed particles with --fixed boundary) is spread from the contact point: f'_r C1, f'_t C1, f'_s C0.
#pragma once

#include <array>
#include <functional>
#include <string>
#include <vector>

#include "Fields/CoarseGrainingSetup.h"
#include "Fields/FieldSums.h"
#include "Fields/SupportBins.h"
#include "IO/FstatFileReader.h"
#include "IO/ParticleFrame.h"
#include "Kernels/AngularMoments.h"
#include "Kernels/KernelProfile.h"

namespace talus::cg {

class CylindricalCoarseGrainer {
public:
    // Throws InputError naming the flag for a missing axis, a width matrix that is not isotropic
    // across the axis, or periodic directions across the axis.
    explicit CylindricalCoarseGrainer(const CoarseGrainingSetup& setup);

    const FieldSums& layout() const { return layout_; }
    double crossWidth() const { return crossWidth_; }
    double axialWidth() const { return axialWidth_; }

    // Builds the particle sources of a frame (radius, axial coordinate, velocity components) and,
    // with the contact stress, the quadrature nodes of the contact branches (contacts may be null).
    void setFrame(const ParticleFrame& frame, const ContactFrame* contacts, const std::string& dataPath,
                  const std::string& fstatPath);
    void setExcluded(std::vector<bool> excluded) { setup_.excluded = std::move(excluded); }
    // sums[p * layout().count() + f] at points (r, -, s) (overwritten); throws for r < 0.
    void evaluate(const std::vector<Vec3>& points, std::vector<double>& sums) const;

    std::size_t sourceCount() const { return mass_.size(); }
    std::size_t contactNodeCount() const { return contactTensor_.size(); }

    // The longest quadrature panel along a branch, in widths (a branch 1 width long gets 4 panels
    // of 5 nodes).
    static constexpr double maxPanelInWidths = 0.25;

private:
    // A position's distance from the axis, coordinate along it and local basis (e_r, e_theta, e_s)
    // in lab components.
    struct LocalFrame {
        double radius = 0, axial = 0;
        std::array<Vec3, 3> basis{};
    };
    LocalFrame localFrame(const Vec3& x) const;
    void setContacts(const ParticleFrame& frame, const ContactFrame& contacts, double reachAcross, double reachAlong,
                     const std::function<void(double, const std::function<void(double)>&)>& images,
                     const std::string& dataPath, const std::string& fstatPath);
    // The angular moments at (r, s) of a source at (ri, si); zero outside the support.
    AngularMoments momentsAt(double r, double s, double ri, double si) const;

    CoarseGrainingSetup setup_;
    KernelProfile profile_;
    FieldSums layout_;
    int axis_ = 2;
    double crossWidth_ = 1, axialWidth_ = 1;
    double scale_ = 1;  // 1/(wp^2 wa) for RZ, 1/(wp^2 L) for R

    // Sources of the current frame (axial images included).
    std::vector<double> radius_, axial_, mass_, volume_;
    std::vector<Vec3> velocity_;  // (u_r, u_theta, u_s)
    std::vector<int> species_;
    SupportBins bins_;
    // Contact branch quadrature nodes (tensors in local components, times the node weight) and
    // boundary contact points (forces in local components), axial images included.
    std::vector<double> contactRadius_, contactAxial_;
    std::vector<std::array<double, 9>> contactTensor_;
    SupportBins contactBins_;
    std::vector<double> boundaryRadius_, boundaryAxial_;
    std::vector<Vec3> boundaryForce_;
    SupportBins boundaryBins_;
};

}  // namespace talus::cg
