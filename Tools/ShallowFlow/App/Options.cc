#include "App/Options.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <sstream>

#include "Model/InputError.h"

namespace talus::shallow {

namespace {

double parseNumber(const std::string& text, const std::string& option) {
    std::size_t used = 0;
    double value = 0;
    try {
        value = std::stod(text, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (used == 0 || used != text.size()) throw InputError(option + ": '" + text + "' is not a number");
    if (!std::isfinite(value)) throw InputError(option + ": '" + text + "' is not a finite number");
    return value;
}

std::vector<double> parseNumbers(const std::string& text, const std::string& option) {
    std::vector<double> values;
    std::istringstream in(text);
    std::string item;
    while (std::getline(in, item, ',')) values.push_back(parseNumber(item, option));
    if (values.empty()) throw InputError(option + ": expected a comma-separated list of numbers");
    return values;
}

// "d1,d2,A,beta" of --small or --large (the diameter is set separately).
FrictionParameters parseFrictionParameters(const std::string& text, const std::string& option) {
    const std::vector<double> values = parseNumbers(text, option);
    if (values.size() != 4) throw InputError(option + ": expected four numbers d1,d2,A,beta, got '" + text + "'");
    return {values[0], values[1], values[2], values[3], 1.0};
}

void requireNonNegative(double value, const std::string& what) {
    if (!(value >= 0)) throw InputError(what + ": " + str(value) + " must not be negative");
}

}  // namespace

std::string usage() {
    return R"(usage: talus-shallow [options]
Solves the depth-averaged bidisperse chute-flow model (Documentation/ShallowFlow.md) on x in
[0, length]: h, h u and h phi with the basal friction of Weinhart et al. per constituent mixed by
phi, and the segregation flux. Units: large-particle diameters and sqrt(dL/g).
Geometry and time:
  --length L              domain length (2000)
  --cells N               number of cells (2000)
  --end-time T            simulated time (500)
  --output-times t1,t2..  times of the profiles written (the end time)
  --output PREFIX         writes PREFIX.profiles.csv and PREFIX.fronts.csv (shallow)
Model (defaults: table 3.1 of Denissen 2019):
  --angle DEG             chute inclination (24)
  --basal-slip AS         basal slip a_s of the velocity profile, alpha = 1 + (1 - a_s)^2 / 3 (0.17)
  --small D1,D2,A,BETA    friction law of the small particles (17.92,36.53,0.71,0.148)
  --large D1,D2,A,BETA    friction law of the large particles (18.60,30.06,3.07,0.146)
  --small-diameter D      small diameter in large diameters (0.7937 = 2^(-1/3))
  --frictionless          no basal friction
Boundaries and initial state:
  --left KIND, --right KIND   inflow, transmissive, wall or periodic (inflow, transmissive)
  --inflow-height H       (15)
  --inflow-concentration PHI  (0.5)
  --inflow-velocity U     (the steady speed, where friction balances gravity)
  --initial WHAT          empty, inflow (the inflow state everywhere) or a csv file with the
                          columns x,h,u,phi, one line per cell (empty)
Numerics:
  --cfl C                 Courant number in (0, 1]; h >= 0 is guaranteed up to 0.5 (0.45)
  --limiter NAME          first-order, minmod or van-leer (van-leer)
  --dry-height H          below it velocities are desingularised; it bounds the speed of
                          the thin layer ahead of a front, hence the time step (0.01)
Diagnostics:
  --front-height H        the height that marks the front (0.5)
  --shock-concentration PHI  the phi that marks the small-particle shock (0.25)
  --progress-interval T   simulated time between progress lines (a tenth of the run)
  --help                  this text
)";
}

ProgramOptions parseOptions(int argc, const char* const* argv) {
    ProgramOptions o;
    double smallDiameter = o.model.small.diameter;
    using Setter = std::function<void(const std::string&, const std::string&)>;
    const auto number = [](double& target) {
        return Setter([&target](const std::string& v, const std::string& f) { target = parseNumber(v, f); });
    };
    const std::map<std::string, Setter> valued{
        {"--length", number(o.grid.length)},
        {"--cells", Setter([&](const std::string& v, const std::string& f) {
             const double n = parseNumber(v, f);
             if (!(n >= 2 && n <= 1e9 && n == static_cast<double>(static_cast<long long>(n)))) {
                 throw InputError(f + ": " + v + " must be a whole number of at least 2");
             }
             o.grid.cells = static_cast<std::size_t>(n);
         })},
        {"--end-time", number(o.endTime)},
        {"--output-times", Setter([&](const std::string& v, const std::string& f) { o.outputTimes = parseNumbers(v, f); })},
        {"--output", Setter([&](const std::string& v, const std::string&) { o.output = v; })},
        {"--angle", number(o.model.angleDegrees)},
        {"--basal-slip", number(o.model.basalSlip)},
        {"--small", Setter([&](const std::string& v, const std::string& f) { o.model.small = parseFrictionParameters(v, f); })},
        {"--large", Setter([&](const std::string& v, const std::string& f) { o.model.large = parseFrictionParameters(v, f); })},
        {"--small-diameter", number(smallDiameter)},
        {"--left", Setter([&](const std::string& v, const std::string& f) { o.left = parseBoundaryKind(v, f); })},
        {"--right", Setter([&](const std::string& v, const std::string& f) { o.right = parseBoundaryKind(v, f); })},
        {"--inflow-height", number(o.inflowHeight)},
        {"--inflow-concentration", number(o.inflowConcentration)},
        {"--inflow-velocity", Setter([&](const std::string& v, const std::string& f) { o.inflowVelocity = parseNumber(v, f); })},
        {"--initial", Setter([&](const std::string& v, const std::string&) { o.initial = v; })},
        {"--cfl", number(o.numerics.cfl)},
        {"--limiter", Setter([&](const std::string& v, const std::string&) { o.numerics.limiter = parseLimiter(v); })},
        {"--dry-height", number(o.numerics.dryHeight)},
        {"--front-height", number(o.frontHeight)},
        {"--shock-concentration", number(o.shockConcentration)},
        {"--progress-interval", number(o.progressInterval)},
    };
    for (int i = 1; i < argc; ++i) {
        const std::string flag = argv[i];
        if (flag == "--help" || flag == "-h") {
            o.help = true;
        } else if (flag == "--frictionless") {
            o.model.frictionless = true;
        } else if (const auto setter = valued.find(flag); setter != valued.end()) {
            // No value may start with "--" (negative numbers start with one dash): "--cells --cfl 1"
            // lacks the number of cells rather than having "--cfl" as it.
            if (i + 1 >= argc || std::string(argv[i + 1]).rfind("--", 0) == 0) throw InputError(flag + ": missing value");
            setter->second(argv[++i], flag);
        } else {
            throw InputError(flag + ": unknown option (talus-shallow --help lists them)");
        }
    }
    if (o.help) return o;
    o.model.small.diameter = smallDiameter;
    o.model.large.diameter = 1.0;
    o.model.validate();
    if (!(o.numerics.cfl > 0 && o.numerics.cfl <= 1)) {
        throw InputError("--cfl: " + str(o.numerics.cfl) + " must be in (0, 1]");
    }
    requireNonNegative(o.inflowHeight, "--inflow-height");
    if (!(o.inflowConcentration >= 0 && o.inflowConcentration <= 1)) {
        throw InputError("--inflow-concentration: " + str(o.inflowConcentration) + " must be in [0, 1]");
    }
    requireNonNegative(o.endTime, "--end-time");
    if (!(o.grid.length > 0)) throw InputError("--length: " + str(o.grid.length) + " must be positive");
    if (!(o.numerics.dryHeight > 0)) throw InputError("--dry-height: " + str(o.numerics.dryHeight) + " must be positive");
    if (!(o.frontHeight > 0)) throw InputError("--front-height: " + str(o.frontHeight) + " must be positive");
    requireNonNegative(o.progressInterval, "--progress-interval");
    if (o.outputTimes.empty()) o.outputTimes.push_back(o.endTime);
    for (double t : o.outputTimes) {
        if (!(t >= 0 && t <= o.endTime)) {
            throw InputError("--output-times: " + str(t) + " must be in [0, end time " + str(o.endTime) + "]");
        }
    }
    std::sort(o.outputTimes.begin(), o.outputTimes.end());
    return o;
}

}  // namespace talus::shallow
