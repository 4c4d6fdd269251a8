// --fixed-species (App/Options.h): the fixed particles named by species, marked in each frame,
// for runs whose particle count changes between frames (a maser-fed chute, an insertion), where
// the restart file's flags fit only frames of its own size.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "App/CoarseGrainingRun.h"
#include "App/Options.h"
#include "App/RunInputs.h"
#include "CGTestHelpers.h"
#include "IO/InputError.h"

using namespace talus::cg;
using namespace talus::cg::test;

namespace {

ProgramOptions optionsOf(std::vector<const char*> args) {
    args.insert(args.begin(), "talus-cg");
    return parseOptions(static_cast<int>(args.size()), args.data());
}

// The Density column of a talus-cg CSV, one value per data row.
std::vector<double> densities(const std::string& path) {
    std::ifstream in(path);
    std::string line;
    std::vector<std::string> names;
    std::vector<double> values;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        std::vector<std::string> cells;
        std::stringstream row(line);
        for (std::string cell; std::getline(row, cell, ',');) cells.push_back(cell);
        if (names.empty()) {
            names = cells;
            continue;
        }
        for (std::size_t k = 0; k < names.size(); ++k)
            if (names[k] == "Density") values.push_back(std::stod(cells[k]));
    }
    return values;
}

}  // namespace

TEST(FixedSpecies, MarksTheParticlesOfTheSpeciesNamed) {
    const ParticleFrame frame = makeFrame({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}}, {0.5, 0.5, 0.5, 0.5},
                                          DomainBox{{0, 0, 0}, {4, 4, 4}}, {}, {0, 2, 1, 5});
    EXPECT_EQ(fixedBySpecies(frame, {2, 5}), (std::vector<bool>{false, true, false, true}));
    EXPECT_EQ(fixedBySpecies(frame, {}), (std::vector<bool>{false, false, false, false}));
}

TEST(FixedSpecies, OptionsAreCheckedAndNamed) {
    EXPECT_EQ(optionsOf({"run", "--fixed", "exclude", "--fixed-species", "2,5"}).fixedSpecies, (std::vector<int>{2, 5}));
    EXPECT_EQ(errorOf([] { optionsOf({"run", "--fixed-species", "2"}); }),
              "--fixed-species names the fixed particles; say what to do with them: --fixed exclude or boundary");
    EXPECT_EQ(errorOf([] { optionsOf({"run", "--fixed", "exclude", "--fixed-species", "2,x"}); }),
              "--fixed-species: 'x' is not a species index (0, 1, ...)");
    EXPECT_EQ(errorOf([] { optionsOf({"run", "--fixed", "exclude", "--fixed-species", "-1"}); }),
              "--fixed-species: '-1' is not a species index (0, 1, ...)");
    EXPECT_EQ(errorOf([] { optionsOf({"run", "--fixed", "exclude", "--fixed-species", "2", "--width-scan"}); }),
              "--fixed-species: not available with --width-scan, which takes the fixed particles from the restart file "
              "(--fixed exclude without --fixed-species)");
}

// Two frames of different sizes (2 and then 3 flowing spheres of mass 1, with 2 fixed ones of
// species 2): the domain average of the density is the flowing mass over the box's volume in
// each frame, counted by hand; with the fixed ones included, 2 more.
TEST(FixedSpecies, FramesOfEverySizeLeaveTheFixedOnesOut) {
    const std::string name = ::testing::TempDir() + "fixedSpecies";
    {
        std::ofstream data(name + ".data");
        auto frame = [&](double t, int flowing) {
            data << flowing + 2 << " " << t << " 0 0 0 4 4 4\n";
            for (int k = 0; k < flowing; ++k) data << 0.5 + k << " 2 2 0 0 0 0.5 0 0 0 0 0 0 0\n";
            for (int k = 0; k < 2; ++k) data << 0.5 + 2 * k << " 2 0.5 0 0 0 0.5 0 0 0 0 0 0 2\n";
        };
        frame(0, 2);
        frame(1, 3);
    }
    std::ostringstream log;
    const std::string excluded = name + ".excluded.csv", included = name + ".included.csv";
    runCoarseGraining(optionsOf({name.c_str(), "--restart", "none", "--coordinates", "O", "--fixed", "exclude",
                                 "--fixed-species", "2", "-o", excluded.c_str()}),
                      log);
    runCoarseGraining(optionsOf({name.c_str(), "--restart", "none", "--coordinates", "O", "-o", included.c_str()}), log);
    const std::vector<double> without = densities(excluded), with = densities(included);
    ASSERT_EQ(without.size(), 2u);
    ASSERT_EQ(with.size(), 2u);
    EXPECT_NEAR(without[0], 2.0 / 64, 1e-12);
    EXPECT_NEAR(without[1], 3.0 / 64, 1e-12);
    EXPECT_NEAR(with[0], 4.0 / 64, 1e-12);
    EXPECT_NEAR(with[1], 5.0 / 64, 1e-12);
}
