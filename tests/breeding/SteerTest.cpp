// Breeding that steers (Steer.h): the preference model, adaptive steps, reproducibility and the
// explanation in words.

#include "marbler/Steer.h"
#include "marbler/Error.h"
#include "marbler/Families.h"
#include "marbler/Generator.h"
#include "marbler/GenomeIO.h"
#include "marbler/Operators.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>

using namespace marbler;

namespace {

Genome family(const char* name, std::uint64_t seed) {
    return familyGenome(*findFamily(name), seed);
}

/// A round where a zebra was picked and designs of other families passed over.
PickRound zebraRound(std::uint64_t seed) {
    PickRound round;
    round.picked.push_back(family("zebra", seed));
    for (const char* other : {"stone", "chevron", "shawl", "spanish-wave", "first-paper", "french-curl"})
        round.passed.push_back(family(other, seed + 17));
    return round;
}

/// Rounds whose picks are `step`-strength alterations of each other (0: the same design kept),
/// each passed over beside strong alterations of it.
std::vector<PickRound> roundsAlong(const Genome& start, double step, std::uint64_t seed) {
    std::vector<PickRound> rounds;
    Genome pick = start;
    for (int r = 0; r < 4; ++r) {
        PickRound round;
        round.picked.push_back(pick);
        for (int k = 0; k < 8; ++k) {
            Pcg32 rng(seed + std::uint64_t(r * 10 + k));
            round.passed.push_back(alterGenome(pick, 0.9, rng));
        }
        rounds.push_back(round);
        Pcg32 rng(seed + 999 + std::uint64_t(r));
        if (step > 0.0) pick = alterGenome(pick, step, rng);
    }
    return rounds;
}

SteerRequest requestAfterZebras(std::uint64_t seed) {
    SteerRequest request;
    request.rounds = {zebraRound(1), zebraRound(2), zebraRound(3)};
    request.breed.op = GeneticOperator::Alter;
    request.breed.parents = {request.rounds.back().picked.front()};
    request.breed.seed = seed;
    request.breed.count = 8;
    request.breed.strength = 0.5;
    return request;
}

} // namespace

namespace {
std::pair<std::string, double> wayOf(const Genome& child);
}

TEST(Steer, TheModelRanksADesignLikeThePicksAboveOneUnlikeThem) {
    const PreferenceModel model({zebraRound(1), zebraRound(2), zebraRound(3)});
    ASSERT_TRUE(model.informed());
    // Designs neither picked nor passed over: another zebra, and families passed over.
    const double like = model.score(designFeatures(family("zebra", 4242)));
    for (const char* other : {"stone", "chevron", "shawl", "spanish-wave"})
        EXPECT_GT(like, model.score(designFeatures(family(other, 4242)))) << other;
}

TEST(Steer, LessLikeThisPushesAwayFromTheMarkedDesign) {
    // The same rounds, once with a chevron passed over and once marked "less like this": the
    // mark makes a chevron-like candidate score lower.
    std::vector<PickRound> plain = {zebraRound(1), zebraRound(2)};
    std::vector<PickRound> marked = plain;
    const Genome chevron = marked.back().passed[1];
    ASSERT_EQ(chevron.meta.family, std::optional<std::string>("chevron"));
    marked.back().passed.erase(marked.back().passed.begin() + 1);
    marked.back().disliked.push_back(chevron);
    Pcg32 rng(777);
    const DesignFeatures candidate = designFeatures(alterGenome(chevron, 0.1, rng));
    EXPECT_LT(PreferenceModel(marked).score(candidate), PreferenceModel(plain).score(candidate));
}

TEST(Steer, StepsShrinkAsPicksConverge) {
    const Genome start = family("first-paper", 31);
    const PreferenceModel wandering(roundsAlong(start, 0.9, 5));
    const PreferenceModel settling(roundsAlong(start, 0.0, 5));
    EXPECT_LT(settling.steps().strokes, wandering.steps().strokes);
    EXPECT_LT(settling.steps().strokes, 1.0);
    // Picks that jump between families: the largest steps.
    const PreferenceModel jumping({zebraRound(1), zebraRound(2), zebraRound(3)});
    EXPECT_GE(jumping.steps().initial, settling.steps().initial);
    // And the children: alteration at a smaller strength than asked once picks agree.
    SteerRequest request;
    request.rounds = roundsAlong(start, 0.0, 5);
    request.breed.parents = {request.rounds.back().picked.front()};
    request.breed.seed = 3;
    request.breed.strength = 0.5;
    EXPECT_LT(steerBreed(request).strokeStrength, 0.5);
}

TEST(Steer, TheSameRequestGivesTheSameChildrenAndAnotherSeedOthers) {
    const auto ids = [](const SteerRequest& request) {
        std::vector<std::string> out;
        for (const Genome& child : steerBreed(request).children)
            out.push_back(serializeGenome(child));
        return out;
    };
    const std::vector<std::string> a = ids(requestAfterZebras(11));
    EXPECT_EQ(a, ids(requestAfterZebras(11)));
    EXPECT_NE(a, ids(requestAfterZebras(12)));
}

TEST(Steer, ChildrenAreValidDistinctRankedAndExplained) {
    const SteerResult result = steerBreed(requestAfterZebras(11));
    ASSERT_EQ(result.children.size(), 8u);
    std::set<std::string> seen;
    for (const Genome& child : result.children) {
        EXPECT_NO_THROW(validateGenome(child, "child"));
        EXPECT_TRUE(seen.insert(genomeId(child)).second) << "no two children alike";
        const auto lineage = child.meta.toJson()["lineage"];
        EXPECT_TRUE(lineage.contains("steered")) << lineage.dump();
        EXPECT_EQ(lineage.value("generation", 0), 1 + lineageGeneration(result.children.front()) - 1);
    }
    EXPECT_EQ(result.explanation.rfind("more like your last 3 picks", 0), 0u) << result.explanation;
    // Zebras against other families: their stroke kinds or looks are named.
    EXPECT_NE(result.explanation.find(": "), std::string::npos) << result.explanation;
}

TEST(Steer, WithoutHistoryItBreedsAsBefore) {
    SteerRequest request = requestAfterZebras(5);
    request.rounds.clear(); // nothing picked yet
    std::vector<std::string> steered, plain;
    for (const Genome& g : steerBreed(request).children)
        steered.push_back(serializeGenome(g));
    for (const Genome& g : breed(request.breed))
        plain.push_back(serializeGenome(g));
    EXPECT_EQ(steered, plain);
    EXPECT_TRUE(steerBreed(request).explanation.empty());
}

TEST(Steer, TheFirstPickAlreadySteers) {
    // One round: the pick from the first nine against the eight passed over. The first bred
    // generation learns from it (a generation sooner than before).
    SteerRequest request = requestAfterZebras(5);
    request.rounds.resize(1);
    const SteerResult result = steerBreed(request);
    EXPECT_EQ(result.explanation.rfind("more like your last pick", 0), 0u) << result.explanation;
    for (const Genome& child : result.children)
        EXPECT_TRUE(child.meta.toJson()["lineage"].contains("steered"));
}

TEST(Steer, TheModelWeighsTheFeaturesThePicksGoBy) {
    // Every round a zebra in inks of its own is picked over designs of other families: by the kinds
    // of strokes every earlier pick is nearer the newest than what it was passed over for, so that
    // group weighs most; a group that orders them no better than chance weighs little.
    std::vector<PickRound> rounds;
    for (int r = 0; r < 5; ++r) {
        PickRound round;
        Genome pick = family("zebra", 100 + std::uint64_t(r));
        Pcg32 rng(300 + std::uint64_t(r));
        pick = alterPart(pick, DesignPart::Palette, 1.0, rng);
        round.picked.push_back(pick);
        for (const char* other : {"stone", "chevron", "shawl", "spanish-wave", "first-paper", "french-curl"})
            round.passed.push_back(family(other, 200 + std::uint64_t(r)));
        rounds.push_back(round);
    }
    const PreferenceModel model(rounds);
    const auto& w = model.groupWeights();
    EXPECT_EQ(*std::max_element(w.begin(), w.end()), w[std::size_t(FeatureGroup::Tools)]);
    EXPECT_GT(w[std::size_t(FeatureGroup::Tools)], 1.0);
    EXPECT_LT(*std::min_element(w.begin(), w.end()), 0.5);
    double sum = 0.0;
    for (double v : w)
        sum += v;
    EXPECT_NEAR(sum, double(FeatureGroups), 1e-9);
    // Without such a history every group weighs the same.
    const PreferenceModel once({rounds.front()});
    for (double v : once.groupWeights())
        EXPECT_EQ(v, 1.0);
}

TEST(Steer, TheChildrenVaryAllOfThePickMostAndItsPaletteToo) {
    // The model's ranking is a guess: the children show the best liked of more than one way, so
    // the person's pick says which way to go; varying all of the pick, the way that brings a
    // person closest per child shown, three times.
    for (std::uint64_t seed : {11, 12, 13}) {
        const SteerResult result = steerBreed(requestAfterZebras(seed));
        std::map<std::string, int> ways;
        for (const Genome& child : result.children)
            if (!wayOf(child).first.empty()) ++ways[wayOf(child).first];
        EXPECT_GE(ways["all"], 3) << "seed " << seed;
        EXPECT_GE(ways["palette"], 1) << "seed " << seed;
    }
    // With more children asked for, the strokes and the initial state alone are shown too.
    SteerRequest many = requestAfterZebras(11);
    many.breed.count = 16;
    many.candidates = 40;
    std::set<std::string> ways;
    for (const Genome& child : steerBreed(many).children)
        if (!wayOf(child).first.empty()) ways.insert(wayOf(child).first);
    EXPECT_EQ(ways.size(), 4u) << "ways among 16 children: " << ways.size();
}

TEST(Steer, ABadCandidateCountIsRefused) {
    SteerRequest request = requestAfterZebras(5);
    request.candidates = 3;
    EXPECT_THROW(steerBreed(request), InputError);
}

namespace {

/// The way and step a steered child records, or ("", 0).
std::pair<std::string, double> wayOf(const Genome& child) {
    if (!child.meta.lineage) return {"", 0.0};
    const auto& other = child.meta.lineage->other;
    if (!other.contains("way") || !other.contains("step")) return {"", 0.0};
    return {other["way"].get<std::string>(), other["step"].get<double>()};
}

const SteerWay& way(const SteerResult& result, const std::string& name) {
    for (const SteerWay& w : result.ways)
        if (w.way == name) return w;
    throw std::runtime_error("no way " + name);
}

} // namespace

TEST(Steer, APickPassesItsStepOnAndAPickKeptAgainShrinksThenWidensIt) {
    SteerRequest request = requestAfterZebras(11);
    const SteerResult first = steerBreed(request);
    ASSERT_EQ(first.ways.size(), 4u);
    // Children that vary one way record it; pick one of them.
    const Genome* pick = nullptr;
    for (const Genome& child : first.children)
        if (!wayOf(child).first.empty()) pick = &child;
    ASSERT_NE(pick, nullptr);
    const auto [name, step] = wayOf(*pick);
    EXPECT_GT(step, 0.0);
    EXPECT_LE(step, 1.0);

    PickRound round;
    round.picked = {*pick};
    for (const Genome& child : first.children)
        if (&child != pick) round.passed.push_back(child);
    request.rounds.push_back(round);
    request.breed.parents = {*pick};
    const SteerResult second = steerBreed(request);
    EXPECT_DOUBLE_EQ(way(second, name).step, std::clamp(step, 0.02, 1.0)) << name;
    for (const SteerWay& w : second.ways) {
        if (w.way == name) continue;
        EXPECT_GT(way(second, name).weight, w.weight) << "picks came " << name;
    }
    EXPECT_NE(second.explanation.find("as your last picks came"), std::string::npos) << second.explanation;

    // The same design picked again: no child came closer, smaller steps.
    std::vector<double> steps;
    for (int again = 1; again <= 4; ++again) {
        request.rounds.push_back(round);
        const SteerResult kept = steerBreed(request);
        steps.push_back(way(kept, name).step);
        EXPECT_NE(kept.explanation.find("smaller steps"), std::string::npos) << kept.explanation;
    }
    EXPECT_LT(steps[0], way(second, name).step);
    EXPECT_LT(steps[1], steps[0]);
    // Stuck longer: a plateau, where only larger steps change anything.
    EXPECT_GT(steps[2], steps[1]);
    EXPECT_GT(steps[3], steps[2]);
}

TEST(Steer, FreshDesignsLikeThePicksAreAThirdOfTheChildren) {
    // A pick among several strangers says where to look: three of the eight children are the
    // best liked of many fresh designs, and say so.
    const SteerResult result = steerBreed(requestAfterZebras(11));
    int fresh = 0;
    for (const Genome& child : result.children)
        if (child.meta.lineage && child.meta.lineage->op == std::optional<std::string>("wildcard")) {
            ++fresh;
            EXPECT_NE(child.meta.lineage->change.value_or("").find("fresh design"), std::string::npos);
        }
    EXPECT_GE(fresh, 3);
}

TEST(Steer, WithTheWildcardOffEveryChildVariesThePick) {
    // The window's Wildcard cell off: no fresh design among the children, each one bred from the
    // pick (its lineage names it).
    SteerRequest request = requestAfterZebras(11);
    request.fresh = false;
    const SteerResult result = steerBreed(request);
    ASSERT_EQ(result.children.size(), 8u);
    const std::string pick = genomeId(request.breed.parents.front());
    for (const Genome& child : result.children) {
        ASSERT_TRUE(child.meta.lineage);
        EXPECT_NE(child.meta.lineage->op, std::optional<std::string>("wildcard"));
        EXPECT_EQ(child.meta.lineage->parents, std::optional(std::vector<std::string>{pick}));
    }
}

TEST(Steer, OnAPlateauHalfOfManyChildrenAreFresh) {
    // The same zebra kept three rounds running: no variation came closer, so however many
    // children are asked for, half of them (not three) are the best liked of the fresh designs.
    SteerRequest request = requestAfterZebras(11);
    request.rounds = {zebraRound(1), zebraRound(2), zebraRound(2), zebraRound(2)};
    request.breed.parents = {request.rounds.back().picked.front()};
    request.breed.count = 20;
    request.candidates = 40;
    const auto freshIn = [](const SteerResult& result) {
        int fresh = 0;
        for (const Genome& child : result.children)
            fresh += child.meta.lineage && child.meta.lineage->op == std::optional<std::string>("wildcard");
        return fresh;
    };
    EXPECT_EQ(freshIn(steerBreed(request)), 9);
    // Not on a plateau: three, as in a generation of eight.
    request.rounds = {zebraRound(1), zebraRound(2), zebraRound(3)};
    request.breed.parents = {request.rounds.back().picked.front()};
    EXPECT_EQ(freshIn(steerBreed(request)), 3);
}

TEST(Steer, WithinOneFamilyFreshDesignsAreOfIt) {
    // Every design of the rounds a zebra (a population of one family chosen in the tool bar):
    // the fresh designs among the children are zebras too.
    SteerRequest request;
    request.rounds = roundsAlong(family("zebra", 31), 0.5, 5);
    for (const PickRound& round : request.rounds)
        for (const Genome& g : round.passed)
            ASSERT_EQ(g.meta.family, std::optional<std::string>("zebra"));
    request.breed.parents = {request.rounds.back().picked.front()};
    request.breed.seed = 9;
    request.breed.strength = 0.5;
    int fresh = 0;
    for (const Genome& child : steerBreed(request).children) {
        EXPECT_EQ(child.meta.family, std::optional<std::string>("zebra"));
        fresh += child.meta.lineage && child.meta.lineage->op == std::optional<std::string>("wildcard");
    }
    EXPECT_GE(fresh, 1);
}

TEST(Steer, ARoundWithoutAPickIsReadWithoutIt) {
    // A rounds file may hold a round with designs passed over and none picked (marbler breed
    // --picks): the model learns from the others.
    PickRound empty;
    empty.passed.push_back(family("stone", 5));
    const PreferenceModel model({zebraRound(1), zebraRound(2), empty});
    EXPECT_TRUE(model.informed());
    EXPECT_GT(model.score(designFeatures(family("zebra", 4242))),
              model.score(designFeatures(family("stone", 4242))));
    SteerRequest request = requestAfterZebras(3);
    request.rounds.push_back(empty);
    EXPECT_EQ(steerBreed(request).children.size(), 8u);
}
