#pragma once
/// A generation made quickly for long-session tests and the soak benchmark: 1 to 3 variants of a
/// few random designs put into the grid beside a parent kept, each named anew so no two are the
/// same (what opening or bringing back designs makes; as large as a bred generation, made in a
/// fraction of the time).

#include "marbler/Generator.h"
#include "workbench/PopulationModel.h"

#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace marbler::test {

inline void placeVariants(ui::PopulationModel& model, std::mt19937_64& rng) {
    static std::vector<Genome> pool;
    if (pool.empty())
        for (std::uint64_t seed = 1; seed <= 6; ++seed)
            pool.push_back(randomGenome(seed, 2));
    std::vector<Genome> designs;
    for (int n = 1 + int(rng() % 3); n > 0; --n) {
        Genome g = pool[rng() % pool.size()];
        g.meta.name = "variant " + std::to_string(rng() % 1000000);
        g.meta.id.reset();
        designs.push_back(std::move(g));
    }
    model.placeDesigns(designs, QStringLiteral("Opened variants"),
                       ui::PopulationModel::Placement::KeepParents);
}

} // namespace marbler::test
