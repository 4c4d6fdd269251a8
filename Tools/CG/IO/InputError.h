// The one error type of the coarse-graining tool: a problem with an input file or a parameter.
// Messages name the file and line (Documentation/Reliability.md: every reader rejects malformed input with
// a message naming the file, line and problem), or the offending program option.
#pragma once

#include <stdexcept>
#include <string>

namespace talus::cg {

class InputError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Shortest decimal form of a number for messages ("0.5", "1e-09").
std::string str(double value);

}  // namespace talus::cg
