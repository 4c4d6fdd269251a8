// Command-line flags of a driver: the run parameters every driver has (Simulation.cc) and the
// ones a driver adds. Unknown flags, missing values and bad values are errors naming the flag.
#pragma once

#include <array>
#include <functional>
#include <string>
#include <vector>

namespace talus {

class CommandLine {
public:
    using Setter = std::function<void(const std::string& value)>;

    // A flag --name taking a value (valueName shown in --help), or a switch when valueName is empty.
    void add(const std::string& name, const std::string& valueName, const std::string& help, Setter set);

    // Applies the flags in order. Returns false if --help was given (nothing else is applied).
    bool parse(const std::vector<std::string>& args) const;

    std::string help(const std::string& program) const;

    // Parsers that name the flag in their errors.
    static double toDouble(const std::string& flag, const std::string& value);
    static int toInt(const std::string& flag, const std::string& value);
    static bool toBool(const std::string& flag, const std::string& value);
    // Three positive whole numbers joined by 'x', e.g. 2x2x1.
    static std::array<int, 3> toGrid(const std::string& flag, const std::string& value);

private:
    struct Flag {
        std::string name, valueName, help;
        Setter set;
    };
    const Flag* find(const std::string& name) const;
    std::vector<Flag> flags_;
};

}  // namespace talus
