#include "Run/Run.h"

#include <cmath>
#include <unordered_map>

#include "Error.h"
#include "IO/CommandLine.h"
#include "SimulationState.h"

namespace talus {

Run::Run() : commandLine_(std::make_unique<CommandLine>()) {}

Run::~Run() = default;

void Run::addFlag(const std::string& name, const std::string& help, double& value) {
    commandLine_->add(name, "X", help + " (default " + str(value) + ")",
                      [&value, name](const std::string& v) { value = CommandLine::toDouble(name, v); });
    keepInRestart("flag." + name, value);
}
void Run::addFlag(const std::string& name, const std::string& help, int& value) {
    commandLine_->add(name, "N", help + " (default " + std::to_string(value) + ")",
                      [&value, name](const std::string& v) { value = CommandLine::toInt(name, v); });
    keepInRestart("flag." + name, value);
}
void Run::addTextFlag(const std::string& name, const std::string& help, std::string& value) {
    commandLine_->add(name, "TEXT", help + " (default " + value + ")", [&value](const std::string& v) { value = v; });
}

void Run::keepInRestart(const std::string& name, double& value) { addKept({name, &value, nullptr, {}, {}}); }
void Run::keepInRestart(const std::string& name, int& value) { addKept({name, nullptr, &value, {}, {}}); }
void Run::keepInRestart(const std::string& name, std::function<std::vector<double>()> save,
                        std::function<void(const std::vector<double>&)> restore) {
    require(save && restore, "keepInRestart: '" + name + "' needs both a save and a restore function");
    addKept({name, nullptr, nullptr, std::move(save), std::move(restore)});
}

void Run::addKept(KeptValue value) {
    require(!value.name.empty() && value.name.find_first_of(" \t\n") == std::string::npos,
            "keepInRestart: the name must be one word, got '" + value.name + "'");
    for (const KeptValue& k : kept_)
        require(k.name != value.name, "keepInRestart: the name '" + value.name + "' is taken");
    kept_.push_back(std::move(value));
}

void Run::saveKeptValues(SimulationState& state) const {
    state.keptValues.clear();
    for (const KeptValue& k : kept_) {
        if (!k.saveList) {
            state.keptValues.emplace_back(k.name, k.real ? *k.real : *k.integer);
            continue;
        }
        const std::vector<double> values = k.saveList();
        state.keptValues.emplace_back(k.name + ".size", static_cast<double>(values.size()));
        for (std::size_t i = 0; i < values.size(); ++i) state.keptValues.emplace_back(k.name + "." + std::to_string(i), values[i]);
    }
}

void Run::restoreKeptValues(const SimulationState& state) const {
    const std::unordered_map<std::string, double> values(state.keptValues.begin(), state.keptValues.end());
    auto saved = [&](const std::string& name) {
        const auto it = values.find(name);
        require(it != values.end(), restartFile_ + ": no value '" + name + "' (a restart file of another driver?)");
        return it->second;
    };
    for (const KeptValue& k : kept_) {
        if (k.real)
            *k.real = saved(k.name);
        else if (k.integer)
            *k.integer = static_cast<int>(saved(k.name));
        else {
            const double size = saved(k.name + ".size");
            require(size >= 0 && size == std::floor(size) && size <= static_cast<double>(state.keptValues.size()),
                    restartFile_ + ": '" + k.name + ".size' is not a list length");
            std::vector<double> list(static_cast<std::size_t>(size));
            for (std::size_t i = 0; i < list.size(); ++i) list[i] = saved(k.name + "." + std::to_string(i));
            k.restoreList(list);
        }
    }
}

}  // namespace talus
