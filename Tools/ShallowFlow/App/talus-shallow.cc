// talus-shallow: solves the depth-averaged bidisperse chute-flow model
// (Documentation/ShallowFlow.md, Theory/DepthAveraged.md). talus-shallow --help lists the flags.
// Exit status 1 on bad input (InputError), 2 on any other failure.
#include <iostream>

#include "App/Options.h"
#include "App/ShallowRun.h"
#include "Model/InputError.h"

int main(int argc, char** argv) {
    try {
        const talus::shallow::ProgramOptions options = talus::shallow::parseOptions(argc, argv);
        if (options.help) {
            std::cout << talus::shallow::usage();
            return 0;
        }
        talus::shallow::runShallowFlow(options, std::cerr);
        return 0;
    } catch (const talus::shallow::InputError& error) {
        std::cerr << "talus-shallow: error: " << error.what() << "\n";
        return 1;
    } catch (const std::exception& error) {
        std::cerr << "talus-shallow: failed: " << error.what() << "\n";
        return 2;
    }
}
