// The cost of the child filter (Operators.h): one glimpse of a design, and breeding a
// generation of 8 children with it, for a random design of each dimension and a family's; and a
// generation as the window makes it, plain or steered (Steer.h), from the same pick and picks.

#include "marbler/Families.h"
#include "marbler/Generator.h"
#include "marbler/Operators.h"
#include "marbler/Random.h"
#include "marbler/Steer.h"

#include <benchmark/benchmark.h>

namespace {

using namespace marbler;

Genome design(int which) {
    switch (which) {
    case 0:
        return randomGenome(7, 2);
    case 1:
        return randomGenome(7, 3);
    default:
        return familyGenome(*findFamily("nonpareil"), 7);
    }
}

const char* label(int which) {
    return which == 0 ? "random 2D" : which == 1 ? "random 3D" : "nonpareil";
}

void BM_Glimpse(benchmark::State& state) {
    const Genome g = design(static_cast<int>(state.range(0)));
    for (auto _ : state)
        benchmark::DoNotOptimize(glimpseOf(g));
    state.SetLabel(label(static_cast<int>(state.range(0))));
}
BENCHMARK(BM_Glimpse)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);

/// Eight children of alteration at 0.5 (argument 1: 0) or of reinit (1), with the filter.
void BM_BreedEight(benchmark::State& state) {
    const Genome g = design(static_cast<int>(state.range(0)));
    BreedRequest request;
    request.op = state.range(1) == 0 ? GeneticOperator::Alter : GeneticOperator::Reinit;
    request.parents = {g};
    request.count = 8;
    int redraws = 0;
    std::uint64_t seed = 0;
    for (auto _ : state) {
        request.seed = ++seed;
        for (const Genome& child : breed(request))
            redraws += child.meta.toJson()["lineage"].value("redraws", 0);
    }
    state.SetLabel(std::string(label(static_cast<int>(state.range(0)))) +
                   (state.range(1) == 0 ? ", alter" : ", reinit"));
    state.counters["redraws/child"] = benchmark::Counter(redraws / 8.0, benchmark::Counter::kAvgIterations);
}
BENCHMARK(BM_BreedEight)->ArgsProduct({{0, 1, 2}, {0, 1}})->Unit(benchmark::kMillisecond);

/// The families a generation is timed from: baths of drops and combs, and strokes of a stylus.
constexpr const char* GenerationFamilies[] = {"zebra", "spanish-wave", "nonpareil", "stone", "hearts"};

/// A generation of 8 from a family's design after six rounds of picks (each the fourth of eight
/// alterations at 0.4 of the one before, the others passed over): plain breeding (argument 1: 0)
/// or steered (1). Each iteration has a seed of its own, so the candidates' looks are new; the
/// rounds' are cached after the first, as in a session.
void BM_Generation(benchmark::State& state) {
    const char* name = GenerationFamilies[state.range(0)];
    std::vector<PickRound> rounds;
    Genome pick = familyGenome(*findFamily(name), 90001);
    for (int r = 0; r < 6; ++r) {
        PickRound round;
        round.picked.push_back(pick);
        for (int k = 0; k < 8; ++k) {
            Pcg32 rng(std::uint64_t(100 + 10 * r + k));
            round.passed.push_back(alterGenome(pick, 0.4, rng));
        }
        rounds.push_back(round);
        pick = round.passed[3];
    }
    SteerRequest request;
    request.rounds = rounds;
    request.breed.parents = {rounds.back().picked.front()};
    request.breed.count = 8;
    request.breed.strength = 0.4;
    std::uint64_t seed = 0;
    for (auto _ : state) {
        request.breed.seed = ++seed;
        if (state.range(1) == 0)
            benchmark::DoNotOptimize(breed(request.breed));
        else
            benchmark::DoNotOptimize(steerBreed(request));
    }
    state.SetLabel(std::string(name) + (state.range(1) == 0 ? ", plain" : ", steered"));
}
BENCHMARK(BM_Generation)->ArgsProduct({{0, 1, 2, 3, 4}, {0, 1}})->Unit(benchmark::kMillisecond)->MinTime(2.0);

} // namespace

BENCHMARK_MAIN();
