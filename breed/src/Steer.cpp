#include "marbler/Steer.h"

#include "marbler/ChangeSummary.h"
#include "marbler/Error.h"
#include "marbler/Families.h"
#include "marbler/Generator.h"
#include "marbler/Params.h"
#include "marbler/Random.h"
#include "marbler/Workers.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <map>
#include <mutex>
#include <numeric>
#include <set>
#include <span>
#include <type_traits>

namespace marbler {

// Named, not anonymous: the unity build puts this file beside the other breed sources.
namespace steerdetail {

constexpr int LayoutSide = 8; // the glimpse's layout, averaged over 2 x 2 cells
constexpr int LookSide = 16;  // a quarter of the child filter's glimpse: candidates are many
constexpr std::uint64_t CandidateStream = 0x7374656572000000ULL;
/// The fresh designs' budget of look work (lookWork): as many looks of the parents', and at least
/// this much.
constexpr double FreshParentLooks = 64.0;
constexpr double FreshFloorWork = 8000.0;
/// Fresh designs drawn a generation (more while picks stall), and how many of the best liked are
/// shown: a person's pick among several strangers tells where to look more than among near
/// neighbours, and the best liked of many are likelier close than one drawn at random.
constexpr int FreshDesigns = 32;
constexpr int FreshShown = 3;
/// How much closeness to the newest pick counts among candidates that break no round.
constexpr double NearestWeight = 0.05;

/// Weights of the feature groups: the layout has 192 values, the statistics a few, so each
/// group adds about as much to a distance between two unlike designs.
constexpr double LayoutWeight = 1.0 / 100.0;
constexpr double ColourWeight = 4.0 / 100.0;
constexpr double TextureWeight = 6.0;
constexpr double ToolWeight = 1.5;
constexpr double HistogramWeight = 2.0;   // the colour histogram's shares
constexpr double OrientationWeight = 7.0; // the edge orientations' shares, at two scales
constexpr int ColourBins = 4 * 7;         // four lightnesses by six hues and grey
constexpr int OrientationBins = 9;        // eight orientations and "no edge", per scale

double sq(double x) {
    return x * x;
}

DesignFeatures computeFeatures(const Genome& genome, const Glimpse& look) {
    constexpr int Side = LookSide;
    constexpr int Block = Side / LayoutSide;
    DesignFeatures f;
    f.values.reserve(3 * LayoutSide * LayoutSide + 20 + ColourBins + 2 * OrientationBins + ToolCount);
    const auto lab = [&](int i, int j, int c) { return look.lab[std::size_t(3 * (j * Side + i) + c)]; };
    // Layout: where light, dark and each hue lie.
    for (int bj = 0; bj < LayoutSide; ++bj)
        for (int bi = 0; bi < LayoutSide; ++bi)
            for (int c = 0; c < 3; ++c) {
                double sum = 0.0;
                for (int j = 0; j < Block; ++j)
                    for (int i = 0; i < Block; ++i)
                        sum += lab(bi * Block + i, bj * Block + j, c);
                f.values.push_back(sum / (Block * Block) * LayoutWeight);
            }
    // Colour statistics.
    constexpr double Cells = Side * Side;
    std::array<double, 3> mean{}, var{};
    double chroma = 0.0, warmth = 0.0;
    for (int j = 0; j < Side; ++j)
        for (int i = 0; i < Side; ++i) {
            for (int c = 0; c < 3; ++c)
                mean[std::size_t(c)] += lab(i, j, c) / Cells;
            chroma += std::sqrt(sq(lab(i, j, 1)) + sq(lab(i, j, 2))) / Cells;
            warmth += 0.5 * (lab(i, j, 1) + lab(i, j, 2)) / Cells;
        }
    for (int j = 0; j < Side; ++j)
        for (int i = 0; i < Side; ++i)
            for (int c = 0; c < 3; ++c)
                var[std::size_t(c)] += sq(lab(i, j, c) - mean[std::size_t(c)]) / Cells;
    for (int c = 0; c < 3; ++c) {
        f.values.push_back(mean[std::size_t(c)] * ColourWeight);
        f.values.push_back(std::sqrt(var[std::size_t(c)]) * ColourWeight);
    }
    f.values.push_back(chroma * ColourWeight);
    // Texture: how often neighbours differ, at one and at four cells, across and down, and how
    // much one ink dominates.
    std::array<double, 4> edges{};
    const auto differs = [&](int i0, int j0, int i1, int j1) {
        return lab(i0, j0, 0) != lab(i1, j1, 0) || lab(i0, j0, 1) != lab(i1, j1, 1) ||
               lab(i0, j0, 2) != lab(i1, j1, 2);
    };
    for (int j = 0; j < Side; ++j)
        for (int i = 0; i < Side; ++i) {
            if (i + 1 < Side && differs(i, j, i + 1, j)) edges[0] += 1.0;
            if (j + 1 < Side && differs(i, j, i, j + 1)) edges[1] += 1.0;
            if (i + 3 < Side && differs(i, j, i + 3, j)) edges[2] += 1.0;
            if (j + 3 < Side && differs(i, j, i, j + 3)) edges[3] += 1.0;
        }
    edges[0] /= Side * (Side - 1);
    edges[1] /= Side * (Side - 1);
    edges[2] /= Side * (Side - 3);
    edges[3] /= Side * (Side - 3);
    for (double e : edges)
        f.values.push_back(e * TextureWeight);
    // Which way the ink edges run (a comb's lines across or down, a swirl's every way): the
    // share of cells whose lightness changes mostly across, down, or along either diagonal,
    // told with comparisons only (tan 67.5 degrees = 2.414).
    std::array<double, 4> ways{};
    for (int j = 0; j + 1 < Side; ++j)
        for (int i = 0; i + 1 < Side; ++i) {
            const double gx = lab(i + 1, j, 0) - lab(i, j, 0), gy = lab(i, j + 1, 0) - lab(i, j, 0);
            const double ax = std::abs(gx), ay = std::abs(gy);
            if (ax + ay < 2.0) continue;
            const int way = ax > 2.414 * ay ? 0 : ay > 2.414 * ax ? 1 : gx * gy > 0.0 ? 2 : 3;
            ways[std::size_t(way)] += 1.0 / ((Side - 1) * (Side - 1));
        }
    for (double w : ways)
        f.values.push_back(w * TextureWeight);
    f.values.push_back(look.dominantShare * TextureWeight);
    // The colour histogram: the share of cells of each lightness (quarters of L*) and hue (six
    // sectors of 60 degrees, or grey below a chroma of 10), told with comparisons only
    // (tan 60 degrees = 1.73205).
    std::array<double, ColourBins> colours{};
    for (int j = 0; j < Side; ++j)
        for (int i = 0; i < Side; ++i) {
            const double l = lab(i, j, 0), a = lab(i, j, 1), b = lab(i, j, 2);
            const int light = l < 25.0 ? 0 : l < 50.0 ? 1 : l < 75.0 ? 2 : 3;
            int hue = 6;
            if (a * a + b * b >= 100.0) {
                const double ab = std::abs(b), aa = std::abs(a);
                const bool steep = ab >= 1.73205 * aa;
                hue = b >= 0.0 ? (steep ? 1 : a > 0.0 ? 0 : 2) : (steep ? 4 : a < 0.0 ? 3 : 5);
            }
            colours[std::size_t(light * 7 + hue)] += 1.0 / Cells;
        }
    for (double c : colours)
        f.values.push_back(c * HistogramWeight);
    // The orientations of lightness edges at one and two cells: eight sectors of 22.5 degrees
    // (tan 22.5 = 0.41421, tan 67.5 = 2.41421), and the share of cells with an edge.
    for (int step : {1, 2}) {
        std::array<double, OrientationBins> bins{};
        const double share = 1.0 / ((Side - step) * (Side - step));
        for (int j = 0; j + step < Side; ++j)
            for (int i = 0; i + step < Side; ++i) {
                double gx = lab(i + step, j, 0) - lab(i, j, 0), gy = lab(i, j + step, 0) - lab(i, j, 0);
                if (std::abs(gx) + std::abs(gy) < 2.0) continue;
                if (gy < 0.0 || (gy == 0.0 && gx < 0.0)) {
                    gx = -gx;
                    gy = -gy;
                }
                const double ax = std::abs(gx);
                const int near = gy < 0.41421 * ax ? 0 : gy < ax ? 1 : gy < 2.41421 * ax ? 2 : 3;
                bins[std::size_t(gx >= 0.0 ? near : 7 - near)] += share;
                bins[8] += share;
            }
        for (double b : bins)
            f.values.push_back(b * OrientationWeight);
    }
    // The kinds of strokes.
    f.toolShare.assign(ToolCount, 0.0);
    for (const Operation& op : genome.operations)
        f.toolShare[std::size_t(op.tool)] += 1.0 / double(genome.operations.size());
    for (double share : f.toolShare)
        f.values.push_back(share * ToolWeight);

    f.lightness = mean[0];
    f.warmth = warmth;
    f.chroma = chroma;
    f.contrast = std::sqrt(var[0]);
    f.fineness = 0.5 * (edges[0] + edges[1]);
    return f;
}

/// A cheap key of a design's content, for the feature cache and for telling designs apart:
/// genomeId writes the design as JSON (about a millisecond for a bath of hundreds of drops, and
/// a generation asks for a few hundred). A 64-bit hash of the bytes of every field of the design
/// (genomeId's: all but meta and the fields not saved), FNV-1a mixed a word at a time: equal
/// designs have equal keys; unequal ones share one with a chance of about 2^-64.
class ContentKey {
public:
    std::uint64_t value = 0xcbf29ce484222325ULL;
    /// Eight bytes at a time (a bath of hundreds of drops is tens of kilobytes), the rest one by one.
    void bytes(const void* data, std::size_t size) {
        const auto* p = static_cast<const unsigned char*>(data);
        for (; size >= 8; p += 8, size -= 8) {
            std::uint64_t word;
            std::memcpy(&word, p, 8);
            value = (value ^ word) * 0x9e3779b97f4a7c15ULL;
            value ^= value >> 29;
        }
        for (; size > 0; ++p, --size)
            value = (value ^ *p) * 0x100000001b3ULL;
    }
    template <typename T> void add(const T& x) {
        static_assert(std::is_trivially_copyable_v<T>);
        bytes(&x, sizeof x);
    }
    template <typename T> void add(const std::vector<T>& list) {
        add(list.size());
        for (const T& x : list)
            add(x);
    }
    void add(const Operation& op) {
        // A field added to Operation must be added here (the size tells, where it is known).
#if defined(__GLIBCXX__) && defined(__x86_64__)
        static_assert(sizeof(Operation) == 360, "add the new field of Operation to ContentKey");
#endif
        add(op.tool), add(op.center), add(op.axis), add(op.direction), add(op.normal), add(op.angle);
        add(op.radius), add(op.alpha), add(op.lambda), add(op.spacing), add(op.amplitude);
        add(op.wavelength), add(op.phase), add(op.shape), add(op.color), add(op.core), add(op.teeth);
        add(op.shift), add(op.power), add(op.field), add(op.extent), add(op.speed), add(op.time);
        add(op.steps), add(op.path), add(op.pressure), add(op.reach), add(op.tines);
    }
};

std::uint64_t contentKey(const Genome& genome) {
#if defined(__GLIBCXX__) && defined(__x86_64__)
    static_assert(sizeof(Genome) == 960, "add the new field of Genome to contentKey");
#endif
    ContentKey key;
    key.add(genome.dimension), key.add(genome.size), key.add(genome.background), key.add(genome.palette);
    key.add(genome.initial), key.add(genome.operations), key.add(genome.bleed), key.add(genome.wrap);
    key.add(genome.lattice), key.add(genome.source.has_value());
    if (genome.source) key.bytes(genome.source->image.data(), genome.source->image.size());
    return key.value;
}

/// Features (and the look they come from) by content: a generation's history is asked for
/// again and again.
struct Seen {
    DesignFeatures features;
    Glimpse look;
};

class FeatureCache {
public:
    Seen get(const Genome& genome) { return get(genome, contentKey(genome)); }
    /// The same, for a design whose contentKey is known.
    Seen get(const Genome& genome, std::uint64_t id) {
        {
            std::lock_guard<std::mutex> lock(mMutex);
            if (auto it = mMap.find(id); it != mMap.end()) return it->second;
        }
        Seen seen;
        seen.look = glimpseOf(genome, LookSide);
        seen.features = computeFeatures(genome, seen.look);
        std::lock_guard<std::mutex> lock(mMutex);
        if (mMap.size() >= 4096) mMap.clear();
        mMap.emplace(id, seen);
        return seen;
    }

private:
    std::mutex mMutex;
    std::map<std::uint64_t, Seen> mMap;
};

FeatureCache& featureCache() {
    static FeatureCache cache;
    return cache;
}

double median(std::vector<double> values) {
    if (values.empty()) return 0.0;
    std::sort(values.begin(), values.end());
    const std::size_t n = values.size();
    return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

/// The distance of two feature vectors over one range of their values.
double partDistance(const DesignFeatures& a, const DesignFeatures& b, std::size_t from, std::size_t to) {
    double sum = 0.0;
    to = std::min({to, a.values.size(), b.values.size()});
    for (std::size_t k = from; k < to; ++k)
        sum += sq(a.values[k] - b.values[k]);
    return std::sqrt(sum);
}

constexpr std::size_t LayoutEnd = 3 * LayoutSide * LayoutSide;
constexpr std::size_t ColourEnd = LayoutEnd + 7;
constexpr std::size_t TextureEnd = ColourEnd + 9;
constexpr std::size_t HistogramEnd = TextureEnd + ColourBins;
constexpr std::size_t OrientationEnd = HistogramEnd + 2 * OrientationBins;
constexpr std::size_t FeaturesEnd = OrientationEnd + ToolCount; // the stroke kinds' shares last

/// The squared distances of two designs' features per group (FeatureGroup).
std::array<double, FeatureGroups> groupSquares(const DesignFeatures& a, const DesignFeatures& b) {
    constexpr std::array<std::size_t, FeatureGroups + 1> bounds{
        0, LayoutEnd, ColourEnd, TextureEnd, HistogramEnd, OrientationEnd, FeaturesEnd};
    std::array<double, FeatureGroups> out{};
    for (std::size_t g = 0; g < FeatureGroups; ++g)
        out[g] = sq(partDistance(a, b, bounds[g], bounds[g + 1]));
    return out;
}

/// A fresh design of a family, or of the free generator (null), that knows its seed.
Genome freshDesign(const Family* source, std::uint64_t seed, int dimension) {
    Genome g = source ? familyGenome(*source, seed) : randomGenome(seed, dimension);
    if (!g.meta.seed) g.meta.seed = seed;
    return g;
}

/// About how much work one sample of a design's look takes, in drops applied: a stylus step
/// counts for each tine, over the share of its steps within reach of a point, as much as twenty
/// drops (the velocities its solve evaluates; measured on the families' designs); a flow's steps
/// as much.
double lookWork(const Genome& genome) {
    constexpr double StepWork = 20.0;
    double work = 0.0;
    for (const Operation& op : genome.operations) {
        if (op.tool == Tool::Stylus) {
            double length = 0.0;
            for (std::size_t i = 1; i < op.path.size(); ++i)
                length += glm::length(op.path[i] - op.path[i - 1]);
            const double reach = std::min(1.0, 2.0 * op.reach / std::max(length + 2.0 * op.reach, 1e-9));
            work += StepWork * op.steps * std::max(op.tines, 1) * reach;
        } else if (op.tool == Tool::Flow) {
            work += StepWork * op.steps;
        } else {
            work += 1.0;
        }
    }
    return work + double(genome.initial.size());
}

/// The ways a steered candidate varies its parent: one part of it (DesignPart), or all.
enum class Way { Palette, Strokes, Initial, All, Count };
constexpr std::array<const char*, std::size_t(Way::Count)> WayNames{"palette", "strokes", "initial", "all"};

/// What the picks say about how to vary the newest pick: per way, the step the newest pick
/// made that way was bred with (a steered child records its way and step; the requested
/// strength before any), and how often picks came from that way lately. The first two rounds in
/// a row in which the same design was picked again (no child came closer) shrink the steps by
/// 0.6 each; later ones, a plateau, widen them by 1.6 each: steps follow the person's picks, as
/// in a self-adaptive evolution strategy.
struct Plan {
    std::array<double, std::size_t(Way::Count)> step{};
    std::array<double, std::size_t(Way::Count)> weight{};
    int stale = 0; ///< rounds in a row that picked the same design again
};

Plan planFrom(const SteerRequest& request) {
    Plan plan;
    plan.step.fill(request.breed.strength);
    plan.weight.fill(1.0);
    const std::vector<PickRound>& rounds = request.rounds;
    std::array<bool, std::size_t(Way::Count)> seen{};
    double age = 1.0;
    std::set<std::uint64_t> credited;
    for (std::size_t r = rounds.size(); r-- > 0 && age > 0.1; age *= 0.7) {
        if (rounds[r].picked.empty()) continue;
        const Genome& pick = rounds[r].picked.front();
        if (!pick.meta.lineage || !credited.insert(contentKey(pick)).second) continue;
        const auto& other = pick.meta.lineage->other;
        const auto way = other.find("way");
        const auto step = other.find("step");
        if (way == other.end() || !way->is_string() || step == other.end() || !step->is_number()) continue;
        for (std::size_t w = 0; w < WayNames.size(); ++w)
            if (way->get<std::string>() == WayNames[w]) {
                plan.weight[w] += 2.0 * age;
                if (!seen[w]) plan.step[w] = step->get<double>();
                seen[w] = true;
            }
    }
    for (std::size_t r = rounds.size(); r-- > 1;) {
        if (rounds[r].picked.empty() || rounds[r - 1].picked.empty() ||
            contentKey(rounds[r].picked.front()) != contentKey(rounds[r - 1].picked.front()))
            break;
        ++plan.stale;
    }
    // Two rounds without a closer child: smaller steps. Longer than that the pick sits on a
    // plateau, where small steps change nothing the person sees: larger ones again.
    double shrink = std::pow(0.6, std::min(plan.stale, 2));
    if (plan.stale > 2) shrink *= std::pow(1.6, plan.stale - 2);
    for (double& step : plan.step)
        step = std::clamp(step * shrink, 0.02, 1.0);
    return plan;
}

/// The English words for one summary difference, or empty when it is too small to tell.
struct Word {
    double weight;
    std::string text;
};

} // namespace steerdetail

using namespace steerdetail;

DesignFeatures designFeatures(const Genome& genome) {
    return featureCache().get(genome).features;
}

double featureDistance(const DesignFeatures& a, const DesignFeatures& b) {
    return partDistance(a, b, 0, a.values.size());
}

double PreferenceModel::distance(const DesignFeatures& a, const DesignFeatures& b) const {
    const std::array<double, FeatureGroups> squares = groupSquares(a, b);
    double sum = 0.0;
    for (std::size_t g = 0; g < FeatureGroups; ++g)
        sum += mGroupWeights[g] * squares[g];
    return std::sqrt(sum);
}

PreferenceModel::PreferenceModel(const std::vector<PickRound>& rounds) {
    const std::size_t first =
        rounds.size() > std::size_t(MaxSteerRounds) ? rounds.size() - MaxSteerRounds : 0;
    const std::span<const PickRound> recent(rounds.data() + first, rounds.size() - first);
    // The features of every design of the rounds, on every core (most are cached from the
    // generation before, but a bath of hundreds of drops takes a while to tell by content).
    std::vector<const Genome*> designs;
    for (const PickRound& in : recent)
        for (const auto* list : {&in.picked, &in.passed, &in.disliked})
            for (const Genome& g : *list)
                designs.push_back(&g);
    std::vector<DesignFeatures> features(designs.size());
    forEachOnCores(designs.size(), [&](std::size_t i) { features[i] = designFeatures(*designs[i]); });
    std::size_t next = designs.size();
    double weight = 1.0;
    for (std::size_t r = recent.size(); r-- > 0;) {
        const PickRound& in = recent[r];
        next -= in.picked.size() + in.passed.size() + in.disliked.size();
        auto from = features.begin() + std::ptrdiff_t(next);
        Round round;
        round.weight = weight;
        weight *= 0.85; // newer rounds say more of what one has in mind now
        for (std::size_t k = 0; k < in.picked.size(); ++k)
            round.picked.push_back(std::move(*from++));
        for (std::size_t k = 0; k < in.passed.size(); ++k) {
            round.passed.push_back(std::move(*from++));
            round.passedWeight.push_back(1.0);
        }
        for (std::size_t k = 0; k < in.disliked.size(); ++k) {
            round.passed.push_back(std::move(*from++));
            round.passedWeight.push_back(2.0);
        }
        if (!round.picked.empty() && !round.passed.empty()) ++mInformedRounds;
        mRounds.insert(mRounds.begin(), std::move(round));
    }
    for (int r = int(mRounds.size()); r-- > 0 && mNewest < 0;)
        if (!mRounds[std::size_t(r)].picked.empty()) mNewest = r;
    mInformed = mInformedRounds >= 1;
    if (!mInformed) return;
    learnGroupWeights();

    mSteps.palette = movement(LayoutEnd, ColourEnd);
    mSteps.initial = movement(0, LayoutEnd);
    mSteps.strokes = movement(ColourEnd, FeaturesEnd);

    // The words: the newest rounds' picks against what they passed over.
    DesignFeatures pickMean, passMean;
    int picks = 0, passes = 0;
    pickMean.toolShare.assign(ToolCount, 0.0);
    passMean.toolShare.assign(ToolCount, 0.0);
    const auto add = [](DesignFeatures& sum, const DesignFeatures& f) {
        sum.lightness += f.lightness;
        sum.warmth += f.warmth;
        sum.chroma += f.chroma;
        sum.contrast += f.contrast;
        sum.fineness += f.fineness;
        for (std::size_t t = 0; t < sum.toolShare.size() && t < f.toolShare.size(); ++t)
            sum.toolShare[t] += f.toolShare[t];
    };
    for (std::size_t r = mRounds.size() > 3 ? mRounds.size() - 3 : 0; r < mRounds.size(); ++r) {
        if (mRounds[r].picked.empty() || mRounds[r].passed.empty()) continue;
        ++mExplainedRounds;
        for (const DesignFeatures& f : mRounds[r].picked) {
            add(pickMean, f);
            ++picks;
        }
        for (const DesignFeatures& f : mRounds[r].passed) {
            add(passMean, f);
            ++passes;
        }
    }
    const double p = 1.0 / std::max(picks, 1), q = 1.0 / std::max(passes, 1);
    std::vector<Word> words;
    const auto say = [&](double difference, double scale, const char* more, const char* less) {
        const double z = difference / scale;
        if (z > 1.0) words.push_back({z, more});
        if (z < -1.0) words.push_back({-z, less});
    };
    say(pickMean.fineness * p - passMean.fineness * q, 0.04, "finer patterns", "broader patterns");
    say(pickMean.warmth * p - passMean.warmth * q, 5.0, "warmer inks", "cooler inks");
    say(pickMean.lightness * p - passMean.lightness * q, 6.0, "lighter", "darker");
    say(pickMean.chroma * p - passMean.chroma * q, 6.0, "more vivid colours", "softer colours");
    say(pickMean.contrast * p - passMean.contrast * q, 5.0, "more contrast", "less contrast");
    for (int t = 0; t < ToolCount; ++t) {
        const double d = pickMean.toolShare[std::size_t(t)] * p - passMean.toolShare[std::size_t(t)] * q;
        const std::string plural(toolSpec(Tool(t)).plural);
        say(d, 0.15, ("more " + plural).c_str(), ("fewer " + plural).c_str());
    }
    std::stable_sort(words.begin(), words.end(),
                     [](const Word& a, const Word& b) { return a.weight > b.weight; });
    for (std::size_t k = 0; k < words.size() && k < 3; ++k)
        mWords.push_back(words[k].text);
}

double PreferenceModel::score(const DesignFeatures& c) const {
    // Each round: the target is closer to the picks than to what was passed over, so a
    // candidate closer to a passed-over design than to the round's nearest pick breaks it.
    double broken = 0.0, total = 0.0;
    for (const Round& round : mRounds) {
        if (round.picked.empty() || round.passed.empty()) continue;
        double toPick = 1e300;
        for (const DesignFeatures& p : round.picked)
            toPick = std::min(toPick, distance(c, p));
        double sum = 0.0, weights = 0.0;
        for (std::size_t k = 0; k < round.passed.size(); ++k) {
            sum += round.passedWeight[k] * std::max(0.0, toPick - distance(c, round.passed[k]));
            weights += round.passedWeight[k];
        }
        broken += round.weight * sum / weights;
        total += round.weight;
    }
    if (total == 0.0) return 0.0;
    // Among candidates that break nothing, the one nearest the newest picks.
    double nearest = 0.0;
    if (mNewest >= 0) {
        nearest = 1e300;
        for (const DesignFeatures& p : mRounds[std::size_t(mNewest)].picked)
            nearest = std::min(nearest, distance(c, p));
    }
    return -(broken / total) - NearestWeight * nearest;
}

/// How far the newest picks moved, against the spread of their rounds, over one feature range:
/// near 1 (or more) while picks jump about, small as they settle.
double PreferenceModel::movement(std::size_t from, std::size_t to) const {
    std::vector<double> ratios;
    const std::size_t n = mRounds.size();
    for (std::size_t r = n > 3 ? n - 3 : 1; r < n; ++r) {
        const Round& now = mRounds[r];
        const Round& before = mRounds[r - 1];
        if (now.picked.empty() || before.picked.empty()) continue;
        const DesignFeatures& a = now.picked.front();
        const DesignFeatures& b = before.picked.front();
        std::vector<double> spread;
        for (std::size_t k = 0; k < now.passed.size(); ++k)
            if (now.passedWeight[k] == 1.0)
                spread.push_back(partDistance(a, now.passed[k], from, to)); // not the disliked
        const double typical = median(spread);
        if (typical <= 0.0) continue;
        ratios.push_back(partDistance(a, b, from, to) / typical);
    }
    if (ratios.empty()) return 1.0;
    const double mean = std::accumulate(ratios.begin(), ratios.end(), 0.0) / double(ratios.size());
    return std::clamp(0.3 + 0.9 * mean, 0.15, 1.5);
}

void PreferenceModel::learnGroupWeights() {
    // The newest pick is the closest yet to what the person has in mind: a group of features by
    // which earlier picks lie nearer to it than what they were passed over for is a group the
    // person goes by. Each group is weighed by how often it orders such pairs as the picks did.
    if (mNewest < 0) return;
    const DesignFeatures& newest = mRounds[std::size_t(mNewest)].picked.front();
    std::array<double, FeatureGroups> agree{};
    double pairs = 0.0;
    for (std::size_t r = 0; r < std::size_t(mNewest); ++r) {
        std::vector<std::array<double, FeatureGroups>> toPassed;
        for (const DesignFeatures& passed : mRounds[r].passed)
            toPassed.push_back(groupSquares(passed, newest));
        for (const DesignFeatures& pick : mRounds[r].picked) {
            const std::array<double, FeatureGroups> toPick = groupSquares(pick, newest);
            if (std::all_of(toPick.begin(), toPick.end(), [](double d) { return d == 0.0; })) continue;
            for (const std::array<double, FeatureGroups>& passed : toPassed) {
                for (std::size_t g = 0; g < FeatureGroups; ++g)
                    agree[g] += toPick[g] < passed[g] ? 1.0 : toPick[g] == passed[g] ? 0.5 : 0.0;
                pairs += 1.0;
            }
        }
    }
    if (pairs < 8.0) return;
    double total = 0.0;
    for (std::size_t g = 0; g < FeatureGroups; ++g) {
        // Chance is a half; a group that orders no better than chance keeps a little weight.
        mGroupWeights[g] = sq(std::max(0.05, 2.0 * agree[g] / pairs - 1.0));
        total += mGroupWeights[g];
    }
    for (double& w : mGroupWeights)
        w *= double(FeatureGroups) / total;
}

std::string PreferenceModel::explain() const {
    if (!mInformed) return {};
    std::string text = mExplainedRounds == 1
                           ? "more like your last pick"
                           : "more like your last " + std::to_string(mExplainedRounds) + " picks";
    if (mWords.empty()) return text + ": close to what you picked";
    text += ": ";
    for (std::size_t k = 0; k < mWords.size(); ++k)
        text += (k ? ", " : "") + mWords[k];
    return text;
}

SteerResult steerBreed(const SteerRequest& request) {
    const BreedRequest& base = request.breed;
    PreferenceModel model(request.rounds);
    SteerResult result;
    // Swap has two results; without what to learn from there is nothing to rank by.
    if (!model.informed() || base.op == GeneticOperator::Swap) {
        result.children = breed(base);
        return result;
    }
    if (request.candidates < base.count || request.candidates > MaxChildren)
        throw InputError("candidates must be between the count (" + std::to_string(base.count) + ") and " +
                         std::to_string(MaxChildren) + " (got " + std::to_string(request.candidates) + ")");
    // breed() checks the request (parents, count, strength, dimensions) and makes the
    // requested operator's own candidates; alteration's are the variations below, drawn by
    // part and at the adapted steps.
    checkBreedRequest(base);
    BreedRequest own = base;
    own.childNumbers.clear();
    if (base.op == GeneticOperator::Alter) own.count = 0;
    std::vector<Genome> pool = own.count > 0 ? breed(own) : std::vector<Genome>{};
    std::vector<std::size_t> home(pool.size(), 0);
    for (std::size_t i = 0; i < pool.size(); ++i)
        if (base.op == GeneticOperator::Recombine) home[i] = i % base.parents.size();

    result.steps = model.steps();

    // The aids: alteration at the adaptive steps, recombination with the newest earlier picks,
    // fresh designs of the generators.
    std::vector<Genome> mates = base.parents;
    for (std::size_t r = request.rounds.size(); r-- > 0 && mates.size() < base.parents.size() + 2;)
        for (const Genome& g : request.rounds[r].picked)
            if (g.dimension == base.parents.front().dimension &&
                std::none_of(mates.begin(), mates.end(),
                             [&](const Genome& m) { return contentKey(m) == contentKey(g); }))
                mates.push_back(g);
    const Family* family = parentsFamily(base.parents);
    const int dimension = base.parents.front().dimension;
    // A person working within one family (every design of the rounds is of the parents' family,
    // as a population of one family chosen in the tool bar makes): fresh designs of it only.
    bool oneFamily = family != nullptr;
    for (const PickRound& round : request.rounds)
        for (const auto* designs : {&round.picked, &round.passed, &round.disliked})
            for (const Genome& g : *designs)
                oneFamily =
                    oneFamily && g.meta.family == std::optional<std::string>(std::string(family->name));
    std::vector<std::string> kinds(pool.size(), std::string(operatorName(base.op)));
    std::vector<double> childSteps(pool.size(), 0.0);
    std::vector<int> childWays(pool.size(), -1);
    const Plan plan = planFrom(request);
    result.strokeStrength = plan.step[std::size_t(Way::Strokes)];
    const int aids = request.candidates - int(pool.size());
    for (int k = 0; k < aids; ++k) {
        Pcg32 rng = childRng(base.seed, k, 0x61696473ULL, CandidateStream);
        const std::size_t p = std::size_t(k) % base.parents.size();
        // Every seventh a recombination with earlier picks or a fresh design; the others vary
        // the parent one way, drawn by how often picks came that way lately, at a step drawn
        // about that way's adapted one.
        Genome g;
        std::string name = "alter";
        int way = -1;
        double own = 0.0;
        if (k % 7 == 6 && (request.fresh || mates.size() > 1)) {
            if (mates.size() > 1 && (!request.fresh || rng.chance(0.5))) {
                g = recombineGenomes(mates, p, rng);
                name = "recombine";
            } else {
                const std::uint64_t seed = rng.nextUint();
                // The parents' family (as the wildcard) or the free generator: some families take
                // a second for one look (a rake's many tines), too slow to draw many of them.
                const Family* source = family && (rng.chance(0.5) || oneFamily) ? family : nullptr;
                g = freshDesign(source, seed, dimension);
                name = "wildcard";
            }
        } else {
            // The first of each way once, then by weight.
            if (k < int(Way::Count)) {
                way = k;
            } else {
                double total = 0.0;
                for (double w : plan.weight)
                    total += w;
                double x = rng.uniform(0.0, total);
                way = 0;
                while (way + 1 < int(Way::Count) && x >= plan.weight[std::size_t(way)])
                    x -= plan.weight[std::size_t(way++)];
            }
            own = std::clamp(plan.step[std::size_t(way)] * std::exp((0.5 + 0.15 * plan.stale) * rng.normal()),
                             0.01, 1.0);
            switch (Way(way)) {
            case Way::Palette:
                g = alterPart(base.parents[p], DesignPart::Palette, own, rng);
                break;
            case Way::Strokes:
                g = alterPart(base.parents[p], DesignPart::Strokes, own, rng);
                break;
            case Way::Initial:
                g = alterPart(base.parents[p], DesignPart::Initial, own, rng);
                break;
            case Way::All:
            case Way::Count:
                g = alterPart(alterGenome(base.parents[p], own, rng), DesignPart::Palette, own, rng);
                break;
            }
        }
        keepWrapValid(g);
        pool.push_back(std::move(g));
        home.push_back(p);
        kinds.push_back(name);
        childSteps.push_back(own);
        childWays.push_back(way);
    }
    // Fresh designs of every generator (the flat or solid families and the free generator), the
    // best liked of them shown beside the pick's variations: picks steer the search beyond the
    // pick's own family; more of them the longer no child comes closer.
    std::vector<const Family*> generators;
    for (const Family& f : allFamilies())
        if (f.dimension == dimension && (!oneFamily || f.name == family->name)) generators.push_back(&f);
    if (!oneFamily) generators.push_back(nullptr);
    const std::size_t firstFresh = pool.size();
    const int fresh = request.fresh ? FreshDesigns + 6 * std::min(plan.stale, 3) : 0;
    // The fresh designs' looks share a budget of work: as much as FreshParentLooks looks of the
    // parents', and at least FreshFloorWork (a dozen small designs). One that does not fit is
    // drawn again (twice at most), then left out: a generation must not wait on strangers' looks.
    double parentWork = 0.0;
    for (const Genome& parent : base.parents)
        parentWork = std::max(parentWork, lookWork(parent));
    double budget = std::max(FreshFloorWork, FreshParentLooks * parentWork);
    for (int k = 0; k < fresh; ++k) {
        Pcg32 rng = childRng(base.seed, k, 0x6672657368ULL, CandidateStream);
        Genome g;
        bool found = false;
        for (int attempt = 0; attempt < 3 && !found; ++attempt) {
            const Family* source = generators[rng.below(std::uint32_t(generators.size()))];
            const std::uint64_t seed = rng.nextUint();
            g = freshDesign(source, seed, dimension);
            const double work = lookWork(g);
            found = work <= budget;
            if (found) budget -= work;
        }
        if (!found) continue;
        // Every other one in the pick's inks: a new pattern with the colours picks have tuned.
        const Genome& pick = base.parents.front();
        if (k % 2 == 1 && !pick.palette.empty() && !locksOf(pick).palette) {
            for (std::size_t i = 0; i < g.palette.size(); ++i)
                g.palette[i] = pick.palette[i % pick.palette.size()];
            g.background = pick.background;
        }
        pool.push_back(std::move(g));
        home.push_back(0);
        kinds.push_back("wildcard");
        childSteps.push_back(0.0);
        childWays.push_back(-1);
    }

    // Rank, then choose with diversity: no near-duplicate of a parent or of a child chosen before,
    // no dull design; the last child explores (the best-liked of the most unlike half).
    std::vector<Glimpse> looks;
    double parentShare = 0.0;
    std::set<std::uint64_t> taken;
    for (const Genome& parent : base.parents) {
        looks.push_back(featureCache().get(parent).look);
        parentShare = std::max(parentShare, looks.back().dominantShare);
        taken.insert(contentKey(parent));
    }
    std::vector<double> scores(pool.size());
    std::vector<Glimpse> poolLooks(pool.size());
    std::vector<std::uint64_t> ids(pool.size());
    {
        // The looks on every core: each candidate's alone, so the order does not matter.
        std::vector<Seen> seen(pool.size());
        forEachOnCores(pool.size(), [&](std::size_t i) {
            ids[i] = contentKey(pool[i]);
            seen[i] = featureCache().get(pool[i], ids[i]);
        });
        for (std::size_t i = 0; i < pool.size(); ++i) {
            scores[i] = model.score(seen[i].features);
            poolLooks[i] = std::move(seen[i].look);
        }
    }
    std::vector<std::size_t> order(pool.size());
    std::iota(order.begin(), order.end(), std::size_t(0));
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return scores[a] > scores[b]; });
    std::vector<std::size_t> chosen;
    const auto acceptable = [&](std::size_t i, double apart) {
        if (taken.count(ids[i])) return false;
        if (poolLooks[i].dominantShare > DullShare && poolLooks[i].dominantShare > parentShare) return false;
        for (const Glimpse& look : looks)
            if (meanDeltaE(look, poolLooks[i]) < apart) return false;
        return true;
    };
    const auto choose = [&](std::size_t i) {
        chosen.push_back(i);
        looks.push_back(poolLooks[i]);
        taken.insert(ids[i]);
    };
    const int exploit = base.count > 2 ? base.count - 1 : base.count;
    // First the best-liked fresh designs: three (a third of a generation of eight), fewer when the
    // children are few; on a plateau (the pick kept twice) half the children, however many.
    const int freshShown = !request.fresh    ? 0
                           : plan.stale >= 2 ? exploit / 2
                                             : std::min(FreshShown, exploit / 2);
    for (std::size_t i : order) {
        if (int(chosen.size()) >= freshShown) break;
        if (i >= firstFresh && acceptable(i, NearDuplicateDeltaE)) choose(i);
    }
    // Then the best-liked variations of the pick: three that vary all of it and one its palette,
    // then the best liked of the other candidates of the pick (the operator's own children,
    // recombinations). The model's ranking is a guess, and the person's pick among different
    // moves tells more than among near neighbours. Of the ways, a child varying all of it brings
    // the person closest per child shown, one varying the palette about half as close, and one
    // varying the strokes or the initial state alone a fifth (docs/performance.md), so all of it
    // is shown most. The other ways are still drawn and shown when more children are asked for.
    constexpr std::array<int, 5> Strata{int(Way::All), int(Way::Palette), int(Way::All), int(Way::All),
                                        int(Way::Count)};
    for (int stratum : Strata)
        for (std::size_t i : order) {
            if (int(chosen.size()) >= exploit) break;
            const bool fits = stratum < int(Way::Count)
                                  ? childWays[i] == stratum
                                  : i < firstFresh && childWays[i] < 0 && kinds[i] != "wildcard";
            if (fits && acceptable(i, 4.0 * NearDuplicateDeltaE)) {
                choose(i);
                break;
            }
        }
    // Then the best liked of all.
    for (double apart : {4.0 * NearDuplicateDeltaE, NearDuplicateDeltaE, -1.0})
        for (std::size_t i : order) {
            if (int(chosen.size()) >= exploit) break;
            if (std::find(chosen.begin(), chosen.end(), i) == chosen.end() && acceptable(i, apart)) choose(i);
        }
    if (int(chosen.size()) < base.count) {
        // Exploration: among the candidates not chosen, the half farthest from the chosen ones,
        // and of those the best liked.
        std::vector<std::pair<double, std::size_t>> far;
        for (std::size_t i : order) {
            if (std::find(chosen.begin(), chosen.end(), i) != chosen.end() || taken.count(ids[i])) continue;
            double nearest = 1e300;
            for (std::size_t c : chosen)
                nearest = std::min(nearest, meanDeltaE(poolLooks[c], poolLooks[i]));
            far.push_back({nearest, i});
        }
        std::stable_sort(far.begin(), far.end(),
                         [](const auto& a, const auto& b) { return a.first > b.first; });
        far.resize(std::max<std::size_t>(1, far.size() / 2));
        std::size_t best = far.front().second;
        for (const auto& [d, i] : far)
            if (scores[i] > scores[best]) best = i;
        chosen.push_back(best);
    }

    // The lineage breed() writes, with the number each child goes to and its rank.
    int generation = 0;
    std::vector<std::string> parentIds;
    for (const Genome& parent : base.parents) {
        generation = std::max(generation, lineageGeneration(parent));
        parentIds.push_back(genomeId(parent));
    }
    generation = base.generation.value_or(generation + 1);
    for (std::size_t k = 0; k < chosen.size() && int(k) < base.count; ++k) {
        const std::size_t i = chosen[k];
        Genome child = pool[i];
        const int number = base.childNumbers.empty() ? int(k) + 1 : base.childNumbers[k];
        MetaLineage lineage;
        lineage.seed = base.seed;
        lineage.child = int(k) + 1;
        lineage.generation = generation;
        lineage.op = kinds[i];
        const int rank = int(std::find(order.begin(), order.end(), i) - order.begin()) + 1;
        lineage.other["steered"] = rank;
        if (kinds[i] == "wildcard") {
            lineage.change = "everything: a fresh design, one of the best liked of many";
            child.meta.lineage = lineage;
            if (child.meta.name)
                child.meta.name = *child.meta.name + " (g" + std::to_string(generation) + " #" +
                                  std::to_string(number) + ")";
        } else {
            lineage.parents = parentIds;
            if (childWays[i] >= 0) {
                lineage.strength = childSteps[i];
                lineage.other["step"] = childSteps[i];
                lineage.other["way"] = WayNames[std::size_t(childWays[i])];
            }
            const std::size_t h = std::min(home[i], base.parents.size() - 1);
            lineage.change =
                i < std::size_t(own.count) && pool[i].meta.lineage && pool[i].meta.lineage->change
                    ? *pool[i].meta.lineage->change
                    : describeChange(base.parents, h, child);
            if (i < std::size_t(own.count) && pool[i].meta.lineage) {
                lineage.strength = pool[i].meta.lineage->strength;
                lineage.variation = pool[i].meta.lineage->variation;
                lineage.redraws = pool[i].meta.lineage->redraws;
            }
            child.meta = childMeta(base.parents[h], generation, number, lineage);
        }
        child.meta.id = genomeId(child);
        result.children.push_back(std::move(child));
    }
    // Why: what the picks say, and how the children vary the newest pick.
    double total = 0.0;
    for (double w : plan.weight)
        total += w;
    std::size_t most = 0;
    for (std::size_t w = 0; w < WayNames.size(); ++w) {
        result.ways.push_back({WayNames[w], plan.step[w], plan.weight[w] / total});
        if (plan.weight[w] > plan.weight[most]) most = w;
    }
    result.explanation = model.explain();
    if (plan.weight[most] > 1.0)
        result.explanation +=
            most == std::size_t(Way::All)
                ? "; varying everything, as your last picks came"
                : std::string("; varying mostly the ") + WayNames[most] + ", as your last picks came";
    if (plan.stale > 0) result.explanation += "; smaller steps: no child came closer last time";
    return result;
}

} // namespace marbler
