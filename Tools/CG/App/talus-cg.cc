// talus-cg: coarse-grains .data/.fstat files into continuum fields
// (Theory/CoarseGraining.md eq. (5)-(10), Documentation/CoarseGraining.md). Usage: talus-cg NAME
// [options]; talus-cg --help.
#include <iostream>

#include "App/CoarseGrainingRun.h"
#include "App/Options.h"
#include "IO/InputError.h"

int main(int argc, char** argv) {
    try {
        const talus::cg::ProgramOptions options = talus::cg::parseOptions(argc, argv);
        if (options.help) {
            std::cout << talus::cg::usage();
            return 0;
        }
        talus::cg::runCoarseGraining(options, std::cerr);
        return 0;
    } catch (const talus::cg::InputError& error) {
        std::cerr << "talus-cg: " << error.what() << "\n";
        return 1;
    } catch (const std::exception& error) {
        std::cerr << "talus-cg: error: " << error.what() << "\n";
        return 2;
    }
}
