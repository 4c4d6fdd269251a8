// Fuzz target: a driver's command line. The input is the argument list, one argument per line
// (or per NUL byte); a Simulation with a driver's own flags besides the common ones parses it,
// with each flag's real setter and checks. The run itself is not made: parsing ends where the
// driver would set up its scene.
#include <cmath>
#include <iostream>
#include <sstream>

#include "Error.h"
#include "FuzzEntries.h"
#include "Simulation.h"

namespace talus::fuzz {

namespace {

struct Parsed {};  // thrown where the scene would be set up: the flags were all taken

class FlagsOnly : public Simulation {
public:
    double angle = 24;
    int layers = 3;
    std::string data = "start.data";

    FlagsOnly() {
        run().addFlag("angle", "inclination in degrees", angle);
        run().addFlag("layers", "number of layers", layers);
        run().addTextFlag("data", "file to start from", data);
    }

protected:
    void setupInitialConditions() override { throw Parsed{}; }
};

}  // namespace

bool commandLine(const std::uint8_t* data, std::size_t size) {
    std::vector<std::string> args(1);
    for (std::size_t k = 0; k < size; ++k) {
        const char c = static_cast<char>(data[k]);
        if (c == '\n' || c == '\0') args.emplace_back();
        else args.back().push_back(c);
    }
    if (args.back().empty()) args.pop_back();
    for (const std::string& a : args)
        if (a.rfind("--restart", 0) == 0) return false;  // (a restart file is the restart target's input, not a flag's)
    FlagsOnly driver;
    // (--help prints the flag list: not to the fuzzer's terminal)
    struct Silence {
        std::streambuf* out = std::cout.rdbuf(nullptr);
        ~Silence() { std::cout.rdbuf(out); }
    } silence;
    try {
        driver.solveOrThrow(args);
        return true;  // (--help)
    } catch (const Parsed&) {
        promise(std::isfinite(driver.angle), "a flag value not finite");
        promise(driver.settings().timeStep >= 0 && std::isfinite(driver.settings().endTime), "a bad time step or end time");
        return true;
    } catch (const Error&) {
        return false;
    }
}

}  // namespace talus::fuzz
