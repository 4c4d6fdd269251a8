#include "IO/CommandLine.h"

#include <sstream>

#include "Error.h"
#include "IO/InputNumbers.h"

namespace talus {

void CommandLine::add(const std::string& name, const std::string& valueName, const std::string& help, Setter set) {
    require(find(name) == nullptr, "flag --" + name + " is defined twice");
    flags_.push_back({name, valueName, help, std::move(set)});
}

const CommandLine::Flag* CommandLine::find(const std::string& name) const {
    for (const Flag& f : flags_)
        if (f.name == name) return &f;
    return nullptr;
}

bool CommandLine::parse(const std::vector<std::string>& args) const {
    for (const std::string& a : args)
        if (a == "--help" || a == "-h") return false;
    for (std::size_t k = 0; k < args.size(); ++k) {
        const std::string& arg = args[k];
        if (arg.rfind("--", 0) != 0)
            throw Error("unexpected argument '" + arg + "': flags start with -- (see --help)");
        std::string name = arg.substr(2), value;
        bool inlineValue = false;
        if (auto eq = name.find('='); eq != std::string::npos) {
            value = name.substr(eq + 1);
            name = name.substr(0, eq);
            inlineValue = true;
        }
        const Flag* flag = find(name);
        if (!flag) throw Error("unknown flag '--" + name + "' (see --help)");
        if (flag->valueName.empty()) {
            if (inlineValue) throw Error("flag --" + name + " takes no value");
            flag->set("");
            continue;
        }
        if (!inlineValue) {
            if (k + 1 >= args.size()) throw Error("flag --" + name + " needs a value (" + flag->valueName + ")");
            value = args[++k];
        }
        flag->set(value);
    }
    return true;
}

std::string CommandLine::help(const std::string& program) const {
    std::ostringstream out;
    out << "usage: " << program << " [flags]\n\nflags:\n";
    for (const Flag& f : flags_) {
        std::string left = "  --" + f.name + (f.valueName.empty() ? "" : " " + f.valueName);
        out << left << std::string(left.size() < 30 ? 30 - left.size() : 1, ' ') << f.help << "\n";
    }
    out << "  --help                      this list\n";
    return out.str();
}

double CommandLine::toDouble(const std::string& flag, const std::string& value) {
    double x = 0;
    if (!toFiniteReal(value, x)) throw Error("flag --" + flag + ": '" + value + "' is not a finite number");
    return x;
}

int CommandLine::toInt(const std::string& flag, const std::string& value) {
    std::int64_t x = 0;
    if (!toInteger(value, x) || x < -2147483647 || x > 2147483647)
        throw Error("flag --" + flag + ": '" + value + "' is not an integer");
    return static_cast<int>(x);
}

std::array<int, 3> CommandLine::toGrid(const std::string& flag, const std::string& value) {
    std::array<int, 3> grid{0, 0, 0};
    std::size_t from = 0;
    for (int a = 0; a < 3; ++a) {
        const std::size_t to = a < 2 ? value.find('x', from) : value.size();
        const std::string part = to == std::string::npos ? "" : value.substr(from, to - from);
        const bool digits = !part.empty() && part.size() < 9 && part.find_first_not_of("0123456789") == std::string::npos;
        if (to == std::string::npos || !digits || (grid[a] = std::stoi(part)) < 1)
            throw Error("flag --" + flag + ": '" + value + "' is not three positive whole numbers joined by x (e.g. 2x2x1)");
        from = to + 1;
    }
    return grid;
}

bool CommandLine::toBool(const std::string& flag, const std::string& value) {
    if (value == "on" || value == "1" || value == "true" || value == "yes") return true;
    if (value == "off" || value == "0" || value == "false" || value == "no") return false;
    throw Error("flag --" + flag + ": '" + value + "' is not on or off");
}

}  // namespace talus
