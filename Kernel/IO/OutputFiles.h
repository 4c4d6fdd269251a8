// The output files of a run: name.data, name.fstat, name.ene (MercuryDPM layouts), one VTU
// file per frame with a name.pvd index for ParaView (and the mesh walls: name_mesh.vtu once, or a
// frame of them beside each particles' frame, indexed by name_mesh.pvd, when a mesh moves), and
// name.restart.
//
// Every frame is written whole and flushed, and the byte size of each file after the frame is
// kept in the run state. Before the restart file is written, .data, .fstat and .ene are synced
// to the disk; the restart file, each .vtu frame and the .pvd are written to FILE.tmp, synced
// and renamed (IO/DurableFile.h). So whenever a run stops (killed at any moment, or the machine
// down), NAME.restart is whole and the appended files hold at least the bytes it records. A
// restarted run cuts each appended file back to those sizes (dropping frames written after the
// restart point, whole or half) and rewrites the .pvd with the restart point's frames, so it
// writes exactly the files of an uninterrupted run. Every failed write (a full disk, a missing
// folder) stops the run with a talus::Error naming the file and the reason.
#pragma once

#include <cstdio>
#include <string>
#include <vector>

#include "Contacts/ContactReport.h"
#include "SimulationState.h"

namespace talus {

class OutputFiles {
public:
    // Creates the files anew (restarted = false) or continues them from state.output.
    OutputFiles(const SimulationState& state, bool restarted);
    ~OutputFiles();
    OutputFiles(const OutputFiles&) = delete;
    OutputFiles& operator=(const OutputFiles&) = delete;

    // Appends the frame of the current state. records: each contact of the last force loop (read
    // only for .fstat, and empty without it); contacts: their number, for .ene.
    void writeFrame(SimulationState& state, const ContactRecordList& records, std::size_t contacts,
                    double elasticEnergy);
    void writeRestart(const SimulationState& state);

private:
    struct File {
        std::FILE* handle = nullptr;
        std::string path;
    };
    void open(File& file, const std::string& path, bool restarted, std::uint64_t bytes);
    void write(File& file, std::string& text);            // writes text and empties it
    std::uint64_t append(File& file, std::string& text);  // the same, flushed; returns the file's size
    static bool meshesMove(const SimulationState& state);

    File data_, fstat_, ene_;
    std::string buffer_;
};

}  // namespace talus
