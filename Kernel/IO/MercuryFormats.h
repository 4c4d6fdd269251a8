// Frames of MercuryDPM's .data, .fstat and .ene layouts (Documentation/FileFormats/), so that
// MercuryDPM's tools and Talus's coarse graining read Talus output. Each function appends one
// whole frame to a buffer, which OutputFiles writes in one piece.
#pragma once

#include <string>
#include <vector>

#include "Contacts/ContactReport.h"
#include "Particles/Energies.h"
#include "SimulationState.h"

namespace talus {

// Slots of the particles sorted by global id: the line order of .data.
std::vector<std::uint32_t> slotsById(const ParticleStore& particles);

void appendDataFrame(std::string& out, const SimulationState& state, const std::vector<std::uint32_t>& order);
void appendFstatFrame(std::string& out, const SimulationState& state, const std::vector<ContactRecord>& contacts);
std::string eneHeader();
void appendEneLine(std::string& out, double time, const Energies& energies, std::size_t contacts);

}  // namespace talus
