// The one error type of the shallow-flow tool: a bad parameter or input file. Its message names the
// parameter (the program option) or the file and line; talus-shallow exits with status 1 on it.
#pragma once

#include <stdexcept>
#include <string>

namespace talus::shallow {

class InputError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Shortest decimal form of a number for messages ("0.5", "1e-09").
std::string str(double value);

}  // namespace talus::shallow
