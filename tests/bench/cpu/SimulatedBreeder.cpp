// The simulated breeder (issue 26, docs/breeding.md): a target design; each generation the
// simulated person picks the child closest to it by a perceptual distance on small CPU renders,
// and breeds from it as the window does (Alter at 40 %, every third generation Recombine the two
// closest, the wildcard cell on, the picks kept in their cells), for 20 generations. Compared
// with random search: as many designs drawn from the same generators (the families and the free
// generator), keeping the closest.
//
//   bench_simulated_breeder [--runs R] [--generations G] [--side S] [--modes classic,steered]
//                           [--distance pixel|stats|both|ssim|all] [--targets N] [--only K] [--first-run N]
//                           [--candidates N] [--dislike N] [--trace 1]
//
// `--dislike N`: the person also marks the N designs farthest from the target "less like this"
// each generation, as the window lets one (steered mode only; 0, the default, picks alone).
//
// Prints one line per run and a summary per mode and distance: wins against random search with
// the same budget, medians of the best distance after the first nine, 5, 10 and 20 generations,
// and of random search with the same budget and with 169 designs.

#include "marbler/CpuRenderer.h"
#include "marbler/Families.h"
#include "marbler/Generator.h"
#include "marbler/GenomeIO.h"
#include "marbler/Operators.h"
#include "marbler/Random.h"
#include "marbler/Steer.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace {

using namespace marbler;

int gSide = 48;
bool gTrace = false;               // --trace 1: a line per generation, what was picked and how it was made
int gCandidates = SteerCandidates; // --candidates N: how many candidates steering ranks
int gDislike = 0;                  // --dislike N: the N farthest marked "less like this"

struct Look {
    std::vector<double> raw;     // L*a*b* per pixel
    std::vector<double> lab;     // blurred L*a*b* per pixel
    std::vector<double> colours; // histogram: 4 x 4 x 4 bins of L*a*b*
    std::vector<double> texture; // histogram: 8 orientations x 2 magnitudes of the L* gradient
};

double toLinear(double c) {
    c /= 255.0;
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

std::array<double, 3> labOfRgb(const std::uint8_t* p) {
    const double r = toLinear(p[0]), g = toLinear(p[1]), b = toLinear(p[2]);
    const double x = (0.4124 * r + 0.3576 * g + 0.1805 * b) / 0.95047;
    const double y = 0.2126 * r + 0.7152 * g + 0.0722 * b;
    const double z = (0.0193 * r + 0.1192 * g + 0.9505 * b) / 1.08883;
    const auto f = [](double t) { return t > 0.008856 ? std::cbrt(t) : 7.787 * t + 16.0 / 116.0; };
    return {116.0 * f(y) - 16.0, 500.0 * (f(x) - f(y)), 200.0 * (f(y) - f(z))};
}

Look lookOf(const Genome& genome) {
    RenderSettings settings;
    settings.width = gSide;
    settings.height = gSide;
    settings.threads = 1;
    const Image image = CpuRenderer(genome).render(settings);
    const int n = gSide * gSide;
    std::vector<double> lab(std::size_t(3 * n));
    for (int k = 0; k < n; ++k) {
        const auto v = labOfRgb(image.rgb.data() + 3 * k);
        for (int c = 0; c < 3; ++c)
            lab[std::size_t(3 * k + c)] = v[std::size_t(c)];
    }
    Look look;
    look.raw = lab;
    look.lab.assign(lab.size(), 0.0);
    look.colours.assign(64, 0.0);
    look.texture.assign(16, 0.0);
    for (int j = 0; j < gSide; ++j)
        for (int i = 0; i < gSide; ++i) {
            // A 3 x 3 blur: a one-pixel shift of a comb's line is not a different design.
            int count = 0;
            for (int dj = -1; dj <= 1; ++dj)
                for (int di = -1; di <= 1; ++di) {
                    const int x = i + di, y = j + dj;
                    if (x < 0 || y < 0 || x >= gSide || y >= gSide) continue;
                    ++count;
                    for (int c = 0; c < 3; ++c)
                        look.lab[std::size_t(3 * (j * gSide + i) + c)] +=
                            lab[std::size_t(3 * (y * gSide + x) + c)];
                }
            for (int c = 0; c < 3; ++c)
                look.lab[std::size_t(3 * (j * gSide + i) + c)] /= count;
            const double* p = &lab[std::size_t(3 * (j * gSide + i))];
            const int bl = std::clamp(int(p[0] / 25.0), 0, 3),
                      ba = std::clamp(int((p[1] + 100.0) / 50.0), 0, 3),
                      bb = std::clamp(int((p[2] + 100.0) / 50.0), 0, 3);
            look.colours[std::size_t(bl * 16 + ba * 4 + bb)] += 1.0 / n;
            if (i + 1 < gSide && j + 1 < gSide) {
                const double gx = lab[std::size_t(3 * (j * gSide + i + 1))] - p[0];
                const double gy = lab[std::size_t(3 * ((j + 1) * gSide + i))] - p[0];
                const double m = std::hypot(gx, gy);
                if (m < 2.0) continue;
                const double angle = std::atan2(gy, gx); // orientation, folded to [0, pi)
                const int o = std::clamp(int((angle < 0 ? angle + M_PI : angle) / M_PI * 8.0), 0, 7);
                look.texture[std::size_t(o * 2 + (m > 20.0 ? 1 : 0))] += 1.0;
            }
        }
    // Texture as shares of the pixels (how much edge, and which way).
    for (double& t : look.texture)
        t /= n;
    return look;
}

/// Pixel distance: the mean CIE76 ΔE of the blurred renders, over 100.
double pixelDistance(const Look& a, const Look& b) {
    double sum = 0.0;
    const std::size_t n = a.lab.size() / 3;
    for (std::size_t k = 0; k < n; ++k)
        sum += std::sqrt(std::pow(a.lab[3 * k] - b.lab[3 * k], 2) +
                         std::pow(a.lab[3 * k + 1] - b.lab[3 * k + 1], 2) +
                         std::pow(a.lab[3 * k + 2] - b.lab[3 * k + 2], 2));
    return sum / double(n) / 100.0;
}

/// Statistics distance, blind to where things are: half the L1 distance of the colour
/// histograms plus the L1 distance of the gradient histograms.
double statsDistance(const Look& a, const Look& b) {
    double colours = 0.0, texture = 0.0;
    for (std::size_t k = 0; k < a.colours.size(); ++k)
        colours += std::abs(a.colours[k] - b.colours[k]);
    for (std::size_t k = 0; k < a.texture.size(); ++k)
        texture += std::abs(a.texture[k] - b.texture[k]);
    return 0.5 * (0.5 * colours + texture);
}

/// Structure distance (SSIM, Wang et al. 2004): compares, window by window, the local means,
/// contrasts and correlations of the unblurred renders, so where the structure lies counts. One
/// minus the mean structural similarity over 7 x 7 windows (every other pixel), L* weighing half
/// and a* and b* a quarter each, halved into 0..1. Never used while choosing the steering: it
/// stands in for a distance the steering was not tuned to.
double ssimDistance(const Look& a, const Look& b) {
    constexpr int Window = 7;
    constexpr std::array<double, 3> Range{100.0, 200.0, 200.0}, Weight{0.5, 0.25, 0.25};
    double total = 0.0;
    int windows = 0;
    for (int y = 0; y + Window <= gSide; y += 2)
        for (int x = 0; x + Window <= gSide; x += 2) {
            ++windows;
            for (int c = 0; c < 3; ++c) {
                double ma = 0.0, mb = 0.0, va = 0.0, vb = 0.0, cov = 0.0;
                const auto at = [&](const Look& l, int i, int j) {
                    return l.raw[std::size_t(3 * ((y + j) * gSide + x + i) + c)];
                };
                for (int j = 0; j < Window; ++j)
                    for (int i = 0; i < Window; ++i) {
                        ma += at(a, i, j);
                        mb += at(b, i, j);
                    }
                ma /= Window * Window;
                mb /= Window * Window;
                for (int j = 0; j < Window; ++j)
                    for (int i = 0; i < Window; ++i) {
                        const double da = at(a, i, j) - ma, db = at(b, i, j) - mb;
                        va += da * da;
                        vb += db * db;
                        cov += da * db;
                    }
                va /= Window * Window - 1;
                vb /= Window * Window - 1;
                cov /= Window * Window - 1;
                const double c1 = std::pow(0.01 * Range[std::size_t(c)], 2),
                             c2 = std::pow(0.03 * Range[std::size_t(c)], 2);
                total += Weight[std::size_t(c)] * (2.0 * ma * mb + c1) * (2.0 * cov + c2) /
                         ((ma * ma + mb * mb + c1) * (va + vb + c2));
            }
        }
    return 0.5 * (1.0 - total / windows);
}

/// A design from the window's mix of generators: a flat family or the free generator.
Genome generated(std::uint64_t seed) {
    std::vector<const Family*> sources;
    for (const Family& f : allFamilies())
        if (f.dimension == 2) sources.push_back(&f);
    sources.push_back(nullptr);
    Pcg32 rng(seed, 0x72616e646f6dULL);
    const Family* source = sources[rng.below(std::uint32_t(sources.size()))];
    const std::uint64_t s = rng.nextUint();
    return source ? familyGenome(*source, s) : randomGenome(s, 2);
}

struct Target {
    std::string name;
    Genome genome;
};

enum class Metric { Pixel, Stats, Ssim };

/// Renders by content, shared by every distance and mode of a run.
std::map<std::string, Look>& lookCache() {
    static std::map<std::string, Look> cache;
    return cache;
}

struct Evaluator {
    Metric metric;
    Look target;
    double operator()(const Genome& g) {
        const std::string id = genomeId(g);
        auto it = lookCache().find(id);
        if (it == lookCache().end()) it = lookCache().emplace(id, lookOf(g)).first;
        return metric == Metric::Pixel   ? pixelDistance(it->second, target)
               : metric == Metric::Stats ? statsDistance(it->second, target)
                                         : ssimDistance(it->second, target);
    }
};

struct RunResult {
    std::vector<double> bestAfter; // best distance after generation g (index 0: the first nine)
    std::vector<int> shown;        // designs shown up to generation g
    double millisPerGeneration = 0.0;
};

RunResult breedRun(Evaluator& distance, std::uint64_t seed, int generations, bool steered) {
    RunResult result;
    std::array<Genome, 9> grid;
    // The first nine as the window draws a new population: nine generators of the eighteen.
    const std::vector<Genome> first = newPopulation(seed, 2, nullptr, 9);
    std::copy(first.begin(), first.end(), grid.begin());
    int shown = 9;
    double best = 1e9;
    for (const Genome& g : grid)
        best = std::min(best, distance(g));
    result.bestAfter.push_back(best);
    result.shown.push_back(shown);
    std::vector<PickRound> rounds;
    double millis = 0.0;
    for (int gen = 1; gen <= generations; ++gen) {
        std::array<int, 9> order{};
        for (int i = 0; i < 9; ++i)
            order[std::size_t(i)] = i;
        std::array<double, 9> d{};
        for (int i = 0; i < 9; ++i)
            d[std::size_t(i)] = distance(grid[std::size_t(i)]);
        std::stable_sort(order.begin(), order.end(),
                         [&](int a, int b) { return d[std::size_t(a)] < d[std::size_t(b)]; });
        if (gTrace) {
            const Genome& pick = grid[std::size_t(order[0])];
            std::string how = "first nine";
            if (pick.meta.lineage) {
                const MetaLineage& l = *pick.meta.lineage;
                how = l.op.value_or("?");
                if (l.other.contains("way")) how += "/" + l.other["way"].get<std::string>();
                if (l.other.contains("step")) how += " " + std::to_string(l.other["step"].get<double>());
                if (l.other.contains("steered"))
                    how += " rank " + std::to_string(l.other["steered"].get<int>());
            }
            std::printf("  g%-2d best %.3f picked %.3f (%s); shown:", gen - 1, best, d[std::size_t(order[0])],
                        how.c_str());
            for (int i = 0; i < 9; ++i)
                std::printf(" %.3f", d[std::size_t(order[std::size_t(i)])]);
            std::printf("\n");
        }
        const bool recombine = gen % 3 == 0;
        const int parentCount = recombine ? 2 : 1;
        std::vector<bool> selected(9, false);
        BreedRequest request;
        request.op = recombine ? GeneticOperator::Recombine : GeneticOperator::Alter;
        request.strength = 0.4;
        request.seed = mixSeed(seed, 1001 + std::uint64_t(gen));
        for (int k = 0; k < parentCount; ++k) {
            selected[std::size_t(order[std::size_t(k)])] = true;
            request.parents.push_back(grid[std::size_t(order[std::size_t(k)])]);
        }
        request.count = 9 - parentCount;
        request.generation = gen + 1;
        PickRound round;
        round.picked = request.parents;
        for (int k = 0; k < 9; ++k) {
            const int i = order[std::size_t(k)];
            if (selected[std::size_t(i)]) continue;
            (k >= 9 - gDislike ? round.disliked : round.passed).push_back(grid[std::size_t(i)]);
        }
        rounds.push_back(round);
        const auto start = std::chrono::steady_clock::now();
        std::vector<Genome> children;
        if (steered) {
            SteerRequest steer;
            steer.breed = request;
            steer.rounds = rounds;
            steer.candidates = gCandidates;
            children = steerBreed(steer).children;
        } else {
            children = breed(request);
        }
        children.back() = wildcardChild(request, children.back()); // as the window's wildcard cell
        millis += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        std::size_t c = 0;
        for (int i = 0; i < 9; ++i)
            if (!selected[std::size_t(i)]) {
                grid[std::size_t(i)] = children[c++];
                best = std::min(best, distance(grid[std::size_t(i)]));
                ++shown;
            }
        result.bestAfter.push_back(best);
        result.shown.push_back(shown);
    }
    result.millisPerGeneration = millis / generations;
    return result;
}

std::vector<double> randomRun(Evaluator& distance, std::uint64_t seed, int count) {
    std::vector<double> bestAfter; // after k+1 designs
    double best = 1e9;
    for (int k = 0; k < count; ++k) {
        best = std::min(best, distance(generated(mixSeed(seed ^ 0x5241ULL, std::uint64_t(k) + 1))));
        bestAfter.push_back(best);
    }
    return bestAfter;
}

double medianOf(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n == 0 ? 0.0 : n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

std::vector<Target> targets(int count) {
    std::vector<Target> list;
    list.push_back({"nonpareil family (seed 90001)", familyGenome(*findFamily("nonpareil"), 90001)});
    list.push_back({"spanish-wave family (seed 90002)", familyGenome(*findFamily("spanish-wave"), 90002)});
    const std::string data = MARBLER_TEST_DATA;
    list.push_back(
        {"marbled-paper (hand-tuned paper)", loadGenome(data + "/examples/marbled-paper.marble.json")});
    list.push_back({"ebru-hearts (hand-made)", loadGenome(data + "/examples/ebru-hearts.marble.json")});
    list.push_back(
        {"flame-comb-vortex (hand-made)", loadGenome(data + "/examples/flame-comb-vortex.marble.json")});
    // Marbled-paper images made outside Marbler (tests/data/targets/make-images.py), as `source`.
    list.push_back(
        {"turbulent-marble (an image)", loadGenome(data + "/targets/turbulent-marble.marble.json")});
    list.push_back({"stone-battal (an image)", loadGenome(data + "/targets/stone-battal.marble.json")});
    list.resize(std::min<std::size_t>(list.size(), std::size_t(count)));
    return list;
}

} // namespace

int main(int argc, char** argv) {
    int runs = 3, generations = 20, targetCount = 7, only = -1, firstRun = 1;
    std::string modes = "classic,steered", metrics = "both";
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string key = argv[i], value = argv[i + 1];
        if (key == "--runs")
            runs = std::stoi(value);
        else if (key == "--generations")
            generations = std::stoi(value);
        else if (key == "--side")
            gSide = std::stoi(value);
        else if (key == "--modes")
            modes = value;
        else if (key == "--distance")
            metrics = value;
        else if (key == "--targets")
            targetCount = std::stoi(value);
        else if (key == "--only")
            only = std::stoi(value);
        else if (key == "--first-run")
            firstRun = std::max(1, std::stoi(value));
        else if (key == "--candidates")
            gCandidates = std::stoi(value);
        else if (key == "--dislike")
            gDislike = std::clamp(std::stoi(value), 0, 6);
        else if (key == "--trace")
            gTrace = value == "1";
        else {
            std::fprintf(stderr, "unknown option %s\n", key.c_str());
            return 2;
        }
    }
    std::vector<std::pair<Metric, const char*>> metricList;
    const bool pair = metrics == "both" || metrics == "all";
    if (metrics == "pixel" || pair) metricList.push_back({Metric::Pixel, "pixel"});
    if (metrics == "stats" || pair) metricList.push_back({Metric::Stats, "stats"});
    if (metrics == "ssim" || metrics == "all") metricList.push_back({Metric::Ssim, "ssim"});
    std::vector<std::string> modeList;
    for (const char* m : {"classic", "steered"})
        if (modes.find(m) != std::string::npos) modeList.push_back(m);

    const std::vector<Target> list = targets(targetCount);
    struct Summary {
        int wins = 0, total = 0, reached = 0;
        std::vector<double> first, at5, at10, atEnd, random, random169, ms, reachGens;
    };
    std::map<std::string, Summary> summaries;
    for (std::size_t t = 0; t < list.size(); ++t) {
        if (only >= 0 && int(t) != only) continue;
        for (int r = firstRun - 1; r < firstRun - 1 + runs; ++r) {
            lookCache().clear();
            const Look target = lookOf(list[t].genome);
            const std::uint64_t seed = 7919ULL * (t + 1) + 104729ULL * std::uint64_t(r + 1);
            for (const auto& [metric, metricName] : metricList) {
                for (const std::string& mode : modeList) {
                    Summary& s = summaries[std::string(metricName) + " " + mode];
                    Evaluator distance{metric, target};
                    const RunResult run = breedRun(distance, seed, generations, mode == "steered");
                    const std::vector<double> rnd =
                        randomRun(distance, seed, std::max(169, run.shown.back()));
                    const double same = rnd[std::size_t(run.shown.back() - 1)];
                    const double r169 = rnd[168];
                    int reach = -1;
                    for (std::size_t g = 0; g < run.bestAfter.size(); ++g)
                        if (run.bestAfter[g] <= r169) {
                            reach = int(g);
                            break;
                        }
                    ++s.total;
                    s.wins += run.bestAfter.back() < same;
                    if (reach >= 0) {
                        ++s.reached;
                        s.reachGens.push_back(reach);
                    }
                    s.first.push_back(run.bestAfter[0]);
                    s.at5.push_back(run.bestAfter[std::size_t(std::min(5, generations))]);
                    s.at10.push_back(run.bestAfter[std::size_t(std::min(10, generations))]);
                    s.atEnd.push_back(run.bestAfter.back());
                    s.random.push_back(same);
                    s.random169.push_back(r169);
                    s.ms.push_back(run.millisPerGeneration);
                    std::printf(
                        "%-6s %-8s %-34s run %d: first nine %.3f, g5 %.3f, g10 %.3f, g%d %.3f (%d designs); "
                        "random same budget %.3f, 169 %.3f; reaches random-169 at g%d; %.0f ms/generation\n",
                        metricName, mode.c_str(), list[t].name.c_str(), r + 1, run.bestAfter[0], s.at5.back(),
                        s.at10.back(), generations, run.bestAfter.back(), run.shown.back(), same, r169, reach,
                        run.millisPerGeneration);
                    std::fflush(stdout);
                }
            }
        }
    }
    for (const auto& [name, s] : summaries)
        std::printf(
            "SUMMARY %s: breeding beat random search in %d of %d runs; medians: first nine %.3f, g5 %.3f, "
            "g10 %.3f, g%d %.3f, random same budget %.3f, random 169 %.3f; reached random-169 in %d runs "
            "(median generation %.0f); %.0f ms/generation (median)\n",
            name.c_str(), s.wins, s.total, medianOf(s.first), medianOf(s.at5), medianOf(s.at10), generations,
            medianOf(s.atEnd), medianOf(s.random), medianOf(s.random169), s.reached, medianOf(s.reachGens),
            medianOf(s.ms));
    return 0;
}
