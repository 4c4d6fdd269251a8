#include "IO/OutputFiles.h"

#include <filesystem>

#include "Contacts/ContactReport.h"
#include "Error.h"
#include "IO/DurableFile.h"
#include "IO/MercuryFormats.h"
#include "IO/RestartFile.h"
#include "IO/VtuWriter.h"

namespace talus {

namespace fs = std::filesystem;

OutputFiles::OutputFiles(const SimulationState& state, bool restarted) {
    const RunSettings& c = state.settings;
    // A fresh run's files replace those of an earlier run of the same name; its restart file,
    // which describes them, goes first, so that a run killed before it wrote its own leaves none.
    if (!restarted) {
        std::error_code ignored;
        fs::remove(c.name + ".restart", ignored);
    }
    if (c.writeData) open(data_, c.name + ".data", restarted, state.output.dataBytes);
    if (c.writeFstat) open(fstat_, c.name + ".fstat", restarted, state.output.fstatBytes);
    if (c.writeEne) open(ene_, c.name + ".ene", restarted, state.output.eneBytes);
    // The index lists the frames of the restart point (a killed run may have listed later ones).
    if (restarted && c.writeVtu) writePvd(c.name + ".pvd", c.name, state.output.frameTimes);
    if (restarted && c.writeVtu && meshesMove(state)) writePvd(c.name + "_mesh.pvd", c.name + "_mesh", state.output.frameTimes);
    // Meshes at rest: one file, written when the run starts (ParaView opens it beside the .pvd).
    if (c.writeVtu && !state.meshes.empty() && !meshesMove(state)) writeMeshVtu(c.name + "_mesh.vtu", state.meshes);
}

// Moving meshes get a file a frame (NAME_mesh_K.vtu, indexed by NAME_mesh.pvd), beside the particles'.
bool OutputFiles::meshesMove(const SimulationState& state) {
    for (const auto& m : state.meshes)
        if (m->moves()) return true;
    return false;
}

OutputFiles::~OutputFiles() {
    for (File* f : {&data_, &fstat_, &ene_})
        if (f->handle) std::fclose(f->handle);
}

void OutputFiles::open(File& file, const std::string& path, bool restarted, std::uint64_t bytes) {
    file.path = path;
    if (restarted) {
        cutBackToRestartPoint(path, bytes);  // drop frames written after the restart point
        file.handle = std::fopen(path.c_str(), "ab");
    } else {
        file.handle = std::fopen(path.c_str(), "wb");
    }
    if (!file.handle) throwWriteError(path);
}

void OutputFiles::write(File& file, std::string& text) {
    if (std::fwrite(text.data(), 1, text.size(), file.handle) != text.size())
        throwWriteError(file.path);
    text.clear();
}

std::uint64_t OutputFiles::append(File& file, std::string& text) {
    write(file, text);
    if (std::fflush(file.handle) != 0) throwWriteError(file.path);
    return static_cast<std::uint64_t>(std::ftell(file.handle));
}

void OutputFiles::writeFrame(SimulationState& state, const ContactRecordList& records, std::size_t contacts,
                             double elasticEnergy) {
    const RunSettings& c = state.settings;
    const std::vector<std::uint32_t> order = slotsById(state.particles);
    // The frames are written 64 KB at a time (MercuryFormats.h); the restart file records
    // the size after the whole frame (a restart cuts the file back to it).
    const auto spillTo = [this](File& file) { return [this, &file](std::string& text) { write(file, text); }; };
    if (data_.handle) {
        buffer_.clear();
        appendDataFrame(buffer_, state, order, spillTo(data_));
        state.output.dataBytes = append(data_, buffer_);
    }
    if (fstat_.handle) {
        buffer_.clear();
        appendFstatFrame(buffer_, state, records, spillTo(fstat_));
        state.output.fstatBytes = append(fstat_, buffer_);
    }
    if (ene_.handle) {
        buffer_.clear();
        if (state.output.savedFrames == 0) buffer_ = eneHeader();
        Energies e = particleEnergies(state.particles, state.gravity);
        e.elastic = elasticEnergy;
        appendEneLine(buffer_, state.time, e, contacts);
        state.output.eneBytes = append(ene_, buffer_);
    }
    if (c.writeVtu) {
        writeVtu(c.name + "_" + std::to_string(state.output.frameTimes.size()) + ".vtu", state.particles, order,
                 state.shapes);
        if (meshesMove(state))
            writeMeshVtu(c.name + "_mesh_" + std::to_string(state.output.frameTimes.size()) + ".vtu", state.meshes);
        state.output.frameTimes.push_back(state.time);
        writePvd(c.name + ".pvd", c.name, state.output.frameTimes);
        if (meshesMove(state)) writePvd(c.name + "_mesh.pvd", c.name + "_mesh", state.output.frameTimes);
    }
    ++state.output.savedFrames;
}

void OutputFiles::writeRestart(const SimulationState& state) {
    if (!state.settings.writeRestart) return;
    // The restart file records the sizes of these files: they reach the disk first.
    for (File* f : {&data_, &fstat_, &ene_})
        if (f->handle) flushToDisk(f->handle, f->path);
    writeRestartFile(state.settings.name + ".restart", state);
}

}  // namespace talus
