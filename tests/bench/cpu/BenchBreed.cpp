// The cost of the child filter (Operators.h): one glimpse of a design, and breeding a
// generation of 8 children with it, for a random design of each dimension and a family's.

#include "marbler/Families.h"
#include "marbler/Generator.h"
#include "marbler/Operators.h"

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

} // namespace

BENCHMARK_MAIN();
