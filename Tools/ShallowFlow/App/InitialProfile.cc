#include "App/InitialProfile.h"

#include <fstream>
#include <sstream>

#include "Model/InputError.h"

namespace talus::shallow {

namespace {

std::vector<Conserved> readProfile(const std::string& path, const Grid& grid) {
    std::ifstream in(path);
    if (!in) throw InputError("--initial: cannot open '" + path + "' (empty, inflow or a csv file)");
    std::string line;
    std::size_t lineNumber = 1;
    if (!std::getline(in, line) || line.rfind("x,h,u,phi", 0) != 0) {
        throw InputError(path + " line 1: expected the header x,h,u,phi");
    }
    std::vector<Conserved> cells;
    while (std::getline(in, line)) {
        ++lineNumber;
        if (line.empty()) continue;
        const std::string where = path + " line " + std::to_string(lineNumber) + ": ";
        std::istringstream fields(line);
        double values[4];
        char comma = ',';
        for (int k = 0; k < 4; ++k) {
            if ((k > 0 && (!(fields >> comma) || comma != ',')) || !(fields >> values[k])) {
                throw InputError(where + "expected four numbers x,h,u,phi");
            }
        }
        const double h = values[1], u = values[2], phi = values[3];
        if (!(h >= 0)) throw InputError(where + "height " + str(h) + " must not be negative");
        if (!(phi >= 0 && phi <= 1)) throw InputError(where + "concentration " + str(phi) + " must be in [0, 1]");
        const std::size_t i = cells.size();
        if (i < grid.cells && std::abs(values[0] - grid.centre(i)) > 1e-6 * grid.spacing() + 1e-9 * std::abs(grid.centre(i))) {
            throw InputError(where + "x = " + str(values[0]) + " is not the centre " + str(grid.centre(i)) + " of cell " +
                             std::to_string(i));
        }
        cells.push_back(toConserved({h, u, phi}));
    }
    if (cells.size() != grid.cells) {
        throw InputError(path + ": " + std::to_string(cells.size()) + " cells, the grid has " + std::to_string(grid.cells) +
                         " (--cells)");
    }
    return cells;
}

}  // namespace

std::vector<Conserved> initialProfile(const std::string& what, const Grid& grid, const Primitive& inflow) {
    if (what == "empty") return std::vector<Conserved>(grid.cells);
    if (what == "inflow") return std::vector<Conserved>(grid.cells, toConserved(inflow));
    return readProfile(what, grid);
}

}  // namespace talus::shallow
