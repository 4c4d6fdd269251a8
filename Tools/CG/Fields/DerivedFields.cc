#include "Fields/DerivedFields.h"

#include <algorithm>

namespace talus::cg {

namespace {
const char* const vectorSuffix[3] = {"X", "Y", "Z"};
const char* const symmetricSuffix[6] = {"XX", "XY", "XZ", "YY", "YZ", "ZZ"};
const char* const tensorSuffix[9] = {"XX", "XY", "XZ", "YX", "YY", "YZ", "ZX", "ZY", "ZZ"};
// Cylindrical components (Fields/CylindricalCoarseGrainer.h): radial, azimuthal, axial.
const char* const cylindricalVectorSuffix[3] = {"R", "Theta", "Axial"};
const char* const cylindricalSymmetricSuffix[6] = {"RR", "RTheta", "RAxial", "ThetaTheta", "ThetaAxial", "AxialAxial"};
const char* const cylindricalTensorSuffix[9] = {"RR",     "RTheta", "RAxial",     "ThetaR",    "ThetaTheta",
                                                "ThetaAxial", "AxialR", "AxialTheta", "AxialAxial"};
constexpr int symmetricRow[6] = {0, 0, 0, 1, 1, 2};
constexpr int symmetricCol[6] = {0, 1, 2, 1, 2, 2};
}  // namespace

std::vector<OutputColumn> derivedColumns(const FieldSums& layout) {
    std::vector<OutputColumn> columns;
    columns.push_back({"Density", "M/L^3"});
    columns.push_back({"VolumeFraction", "1"});
    const char* const* vector = layout.cylindrical ? cylindricalVectorSuffix : vectorSuffix;
    const char* const* symmetric = layout.cylindrical ? cylindricalSymmetricSuffix : symmetricSuffix;
    for (int c = 0; c < 3; ++c) columns.push_back({std::string("Momentum") + vector[c], "M/(L^2 T)"});
    for (int c = 0; c < 3; ++c) columns.push_back({std::string("Velocity") + vector[c], "L/T"});
    for (int c = 0; c < 6; ++c) columns.push_back({std::string("KineticStress") + symmetric[c], "M/(L T^2)"});
    if (layout.contactStress) {
        const char* const* tensor = layout.cylindrical ? cylindricalTensorSuffix : tensorSuffix;
        for (int c = 0; c < 9; ++c) columns.push_back({std::string("ContactStress") + tensor[c], "M/(L T^2)"});
        for (int c = 0; c < 9; ++c) columns.push_back({std::string("Stress") + tensor[c], "M/(L T^2)"});
        for (int c = 0; c < 3; ++c) columns.push_back({std::string("InteractionForce") + vector[c], "M/(L^2 T^2)"});
    }
    for (int s = 0; s < layout.species; ++s) columns.push_back({"Density_s" + std::to_string(s), "M/L^3"});
    for (int s = 0; s < layout.species; ++s) columns.push_back({"Concentration_s" + std::to_string(s), "1"});
    if (layout.cylindrical) columns.push_back({"AngularVelocity", "1/T"});
    return columns;
}

std::vector<FieldArray> fieldArrays(const FieldSums& layout) {
    const std::vector<OutputColumn> columns = derivedColumns(layout);
    const char* const* vector = layout.cylindrical ? cylindricalVectorSuffix : vectorSuffix;
    const char* const* symmetric = layout.cylindrical ? cylindricalSymmetricSuffix : symmetricSuffix;
    const char* const* tensor = layout.cylindrical ? cylindricalTensorSuffix : tensorSuffix;
    auto startsGroup = [&](std::size_t at, const std::string& prefix, const char* firstSuffix) {
        return columns[at].name == prefix + firstSuffix;
    };
    std::vector<FieldArray> arrays;
    for (std::size_t at = 0; at < columns.size();) {
        FieldArray array;
        const int first = static_cast<int>(at);
        bool grouped = false;
        for (const char* prefix : {"Momentum", "Velocity", "InteractionForce"}) {
            if (!grouped && startsGroup(at, prefix, vector[0])) {
                array.name = prefix;
                for (int c = 0; c < 3; ++c) {
                    array.columns.push_back(first + c);
                    array.componentNames.push_back(vector[c]);
                }
                at += 3;
                grouped = true;
            }
        }
        if (!grouped && startsGroup(at, "KineticStress", symmetric[0])) {
            // Component (r, q) of the symmetric tensor is CSV column symmetricIndex(min, max).
            array.name = "KineticStress";
            for (int r = 0; r < 3; ++r) {
                for (int q = 0; q < 3; ++q) {
                    for (int c = 0; c < 6; ++c) {
                        if (symmetricRow[c] == std::min(r, q) && symmetricCol[c] == std::max(r, q)) array.columns.push_back(first + c);
                    }
                    array.componentNames.push_back(tensor[3 * r + q]);
                }
            }
            at += 6;
            grouped = true;
        }
        for (const char* prefix : {"ContactStress", "Stress"}) {
            if (!grouped && startsGroup(at, prefix, tensor[0])) {
                array.name = prefix;
                for (int c = 0; c < 9; ++c) {
                    array.columns.push_back(first + c);
                    array.componentNames.push_back(tensor[c]);
                }
                at += 9;
                grouped = true;
            }
        }
        if (!grouped) {
            array.name = columns[at].name;
            array.columns.push_back(first);
            ++at;
        }
        arrays.push_back(std::move(array));
    }
    return arrays;
}

void appendDerivedFields(const FieldSums& layout, const double* sums, std::vector<double>& values) {
    const double rho = sums[FieldSums::density];
    const double* p = sums + FieldSums::momentum;
    const double* k = sums + FieldSums::momentumFlux;
    values.push_back(rho);
    values.push_back(sums[FieldSums::volumeFraction]);
    for (int c = 0; c < 3; ++c) values.push_back(p[c]);
    for (int c = 0; c < 3; ++c) values.push_back(rho > 0 ? p[c] / rho : 0.0);
    double kinetic[9] = {};
    for (int c = 0; c < 6; ++c) {
        const int r = symmetricRow[c], q = symmetricCol[c];
        const double value = rho > 0 ? k[c] - p[r] * p[q] / rho : 0.0;
        kinetic[3 * r + q] = kinetic[3 * q + r] = value;
        values.push_back(value);
    }
    if (layout.contactStress) {
        const double* contact = sums + layout.contactStressIndex();
        for (int c = 0; c < 9; ++c) values.push_back(contact[c]);
        for (int c = 0; c < 9; ++c) values.push_back(kinetic[c] + contact[c]);
        for (int c = 0; c < 3; ++c) values.push_back(sums[layout.interactionForceIndex() + c]);
    }
    for (int s = 0; s < layout.species; ++s) values.push_back(sums[layout.speciesDensityIndex(s)]);
    for (int s = 0; s < layout.species; ++s) {
        // A partial sum can exceed the full one by rounding (different summation order):
        // clamp into [0, 1].
        const double phi = rho > 0 ? sums[layout.speciesDensityIndex(s)] / rho : 0.0;
        values.push_back(std::clamp(phi, 0.0, 1.0));
    }
    if (layout.cylindrical) {
        // Angular momentum over moment of inertia about the axis: exactly omega for solid-body
        // rotation (Fields/CylindricalCoarseGrainer.h).
        const double inertia = sums[layout.angularMomentumIndex() + 1];
        values.push_back(inertia > 0 ? sums[layout.angularMomentumIndex()] / inertia : 0.0);
    }
}

}  // namespace talus::cg
