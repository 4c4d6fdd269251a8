// Frames of MercuryDPM's .data, .fstat and .ene layouts (Documentation/FileFormats/), so that
// MercuryDPM's tools and Talus's coarse graining read Talus output. Each function appends one
// frame to a buffer; with a `spill`, it hands the buffer on (OutputFiles writes it to the file)
// each time it has grown past spillBytes (64 KB), so that a frame of a large scene is never held
// whole (the .fstat text of 10^5 contacts is about 60 MB).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "Contacts/ContactReport.h"
#include "Particles/Energies.h"
#include "SimulationState.h"

namespace talus {

// Slots of the particles sorted by global id: the line order of .data.
std::vector<std::uint32_t> slotsById(const ParticleStore& particles);

// Takes the text so far and empties it.
using Spill = std::function<void(std::string& text)>;
inline constexpr std::size_t spillBytes = std::size_t{1} << 16;

void appendDataFrame(std::string& out, const SimulationState& state, const std::vector<std::uint32_t>& order,
                     const Spill& spill = {});
void appendFstatFrame(std::string& out, const SimulationState& state, const ContactRecordList& contacts,
                      const Spill& spill = {});
std::string eneHeader();
void appendEneLine(std::string& out, double time, const Energies& energies, std::size_t contacts);

}  // namespace talus
