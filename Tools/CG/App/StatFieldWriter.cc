#include "App/StatFieldWriter.h"

#include <cmath>

#include "IO/InputError.h"

namespace talus::cg {

namespace {

// MercuryDPM's fields in their order with their component counts (stat.md): our sums fill
// VolumeFraction, Density, Momentum, MomentumFlux and (the whole contact stress) NormalStress.
// After them comes the boundary's force density under the name and component order of
// MercuryCG's InteractionForce (a vector X Y Z), so that readers of the 85 fields by position
// are not disturbed.
struct StatBlock {
    const char* name;
    int components;  // 1 scalar, 3 vector, 6 symmetric tensor, 9 tensor
};
constexpr StatBlock statBlocks[] = {
    {"VolumeFraction", 1}, {"Density", 1}, {"Momentum", 3}, {"DisplacementMomentum", 3}, {"Displacement", 6},
    {"MomentumFlux", 6}, {"DisplacementMomentumFlux", 6}, {"EnergyFlux", 3}, {"NormalStress", 9},
    {"TangentialStress", 9}, {"NormalTraction", 3}, {"TangentialTraction", 3}, {"Fabric", 6},
    {"CollisionalHeatFlux", 3}, {"Dissipation", 1}, {"Potential", 1}, {"LocalAngularMomentum", 3},
    {"LocalAngularMomentumFlux", 9}, {"ContactCoupleStress", 9}, {"InteractionForce", 3}};
constexpr int statColumns = 88;
constexpr int interactionForceColumn = 85;
const char* const vectorSuffix[3] = {"X", "Y", "Z"};
const char* const symmetricSuffix[6] = {"XX", "XY", "XZ", "YY", "YZ", "ZZ"};
const char* const tensorSuffix[9] = {"XX", "XY", "XZ", "YX", "YY", "YZ", "ZX", "ZY", "ZZ"};

// MercuryDPM names its polynomial functions (Lucy, Heaviside) and its Gaussian this way.
std::string mercuryFunctionName(KernelShape shape) {
    switch (shape) {
        case KernelShape::Gauss: return "Gaussian";
        case KernelShape::Heaviside: return "Heaviside";
        case KernelShape::Lucy: break;
    }
    return "Lucy";
}

}  // namespace

std::vector<std::string> StatFieldWriter::columnNames() {
    std::vector<std::string> names;
    for (const StatBlock& block : statBlocks) {
        for (int c = 0; c < block.components; ++c) {
            const char* suffix = block.components == 1   ? ""
                                 : block.components == 3 ? vectorSuffix[c]
                                 : block.components == 6 ? symmetricSuffix[c]
                                                         : tensorSuffix[c];
            names.push_back(std::string(block.name) + suffix);
        }
    }
    return names;
}

StatFieldWriter::StatFieldWriter(const FieldOutputSetup& setup) : setup_(setup), file_(std::fopen(setup.path.c_str(), "w")) {
    if (file_ == nullptr) throw InputError("-o: cannot write " + setup.path);
    std::string names;
    for (const std::string& name : columnNames()) names += name + " ";
    std::fprintf(file_, "%s\n", names.c_str());
    // MercuryDPM's second line: width, dimension, domain, counts, averaging type, function. Its
    // readers take these tokens by position, so Talus's extras (the width matrix) come last.
    const auto& b = setup.width.widths();
    double logSum = 0;
    const auto axes = setup.coordinates.kernelAxes();
    for (int k : axes) logSum += std::log(b[4 * k]);
    const double w = std::exp(logSum / double(axes.size()));
    const double cutoff = w * (setup.shape == KernelShape::Gauss ? 3.0 : 1.0);
    std::fprintf(file_, "w %.10g dim 3 domainStat %.10g %.10g %.10g %.10g %.10g %.10g n %ld %ld %ld statType %s CG_type %s cutoff %.10g%s",
                 w, setup.lo[0], setup.hi[0], setup.lo[1], setup.hi[1], setup.lo[2], setup.hi[2],
                 setup.grid ? setup.count[0] : long(setup.points.size()), setup.grid ? setup.count[1] : 1L,
                 setup.grid ? setup.count[2] : 1L, setup.coordinates.name().c_str(), mercuryFunctionName(setup.shape).c_str(),
                 cutoff, setup.timeAverage ? " doTimeAverage" : "");
    std::fprintf(file_, " widthMatrix %.10g %.10g %.10g %.10g %.10g %.10g writer talus-cg\n", b[0], b[1], b[2], b[4], b[5], b[8]);
}

StatFieldWriter::~StatFieldWriter() {
    if (file_ != nullptr) std::fclose(file_);
}

void StatFieldWriter::writeFrame(double firstTime, double time, const std::vector<double>& sums) {
    // MercuryDPM: "t" before each frame; "tmin tmax" before a time average.
    if (setup_.timeAverage) std::fprintf(file_, "%.10g %.10g\n", firstTime, time);
    else std::fprintf(file_, "%.10g\n", time);
    const FieldSums& layout = setup_.layout;
    double row[statColumns];
    for (std::size_t p = 0; p < setup_.points.size(); ++p) {
        const double* s = sums.data() + p * layout.count();
        for (double& v : row) v = 0;
        row[0] = s[FieldSums::volumeFraction];
        row[1] = s[FieldSums::density];
        for (int c = 0; c < 3; ++c) row[2 + c] = s[FieldSums::momentum + c];
        // MomentumFlux after VolumeFraction 1, Density 1, Momentum 3, DisplacementMomentum 3,
        // Displacement 6: column 14 of the 88 (0-based); same component order xx xy xz yy yz zz.
        for (int c = 0; c < 6; ++c) row[14 + c] = s[FieldSums::momentumFlux + c];
        if (layout.contactStress) {
            // NormalStress starts after DisplacementMomentumFlux 6 and EnergyFlux 3: column 29.
            for (int c = 0; c < 9; ++c) row[29 + c] = s[layout.contactStressIndex() + c];
            for (int c = 0; c < 3; ++c) row[interactionForceColumn + c] = s[layout.interactionForceIndex() + c];
        }
        const Vec3& x = setup_.points[p];
        std::fprintf(file_, "%.16g %.16g %.16g", x[0], x[1], x[2]);
        for (double v : row) std::fprintf(file_, " %.16g", v);
        std::fputc('\n', file_);
    }
}

void StatFieldWriter::close() {
    if (file_ == nullptr) return;
    const bool failed = std::ferror(file_) != 0;
    const bool closeFailed = std::fclose(file_) != 0;
    file_ = nullptr;
    if (failed || closeFailed) throw InputError("-o: writing " + setup_.path + " failed (disk full?)");
}

}  // namespace talus::cg
