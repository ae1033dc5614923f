#pragma once
/// Breeding that steers (docs/breeding.md): a person's picks, and the designs they passed over,
/// are the preferences a small model learns; each generation draws many candidate children
/// (variations of one part of the pick at adapted steps, the requested operator's own children
/// for recombination and a new initial state, recombination with earlier picks, fresh designs
/// of every generator), ranks them by the model and shows the most promising: the three
/// best-liked fresh designs, the best-liked variations of the pick (three of all of it, one of its
/// palette), then the best liked of all, the last one kept for exploration.
///
/// The model is an *ideal point* over cheap features of a design (a 16 x 16 glimpse, Operators.h:
/// its layout on an 8 x 8 grid, colour statistics, texture statistics, a colour histogram, the
/// orientations of its edges, the kinds of strokes): every round says "what you have in mind is
/// closer to the picked designs than to the ones passed over" (a half-space in feature space), so
/// a candidate is scored by how far it breaks these constraints, newer rounds weighing more, and,
/// among consistent candidates, by its closeness to the newest picks. Distances weigh the feature
/// groups by how well each orders the earlier picks as the person did (groupWeights). "Less like
/// this" marks a design as passed over twice as strongly.
///
/// Steps adapt as in a self-adaptive evolution strategy: most candidates vary one part of the
/// pick (its palette, strokes or initial state, or all), each recording in its lineage the way
/// and the step it was made with; a pick passes its step on, ways that picks came from lately
/// get more candidates, and a design picked again (no child came closer) shrinks the steps.
///
/// Everything draws from Pcg32 streams derived from the request's seed, and the features use
/// only IEEE basic operations: the same request gives the same children on every machine.

#include "marbler/Genome.h"
#include "marbler/Operators.h"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace marbler {

/// The features the model compares designs by (see above), in comparable units.
struct DesignFeatures {
    std::vector<double> values;
    /// Interpretable summaries, for the explanation: mean lightness (L*), warmth (a* + b* of
    /// the cells, halved), chroma, contrast (std of L*), fineness (share of neighbouring cells
    /// of different colour), and per tool the share of the strokes that use it.
    double lightness = 0.0, warmth = 0.0, chroma = 0.0, contrast = 0.0, fineness = 0.0;
    std::vector<double> toolShare;
};
/// The features of a design (about a millisecond; cached by content, so asking again is free).
DesignFeatures designFeatures(const Genome& genome);
/// The distance of two designs' features (0 for equal designs).
double featureDistance(const DesignFeatures& a, const DesignFeatures& b);
/// The features' groups, in the order of DesignFeatures::values.
enum class FeatureGroup { Layout, Colour, Texture, ColourHistogram, Orientation, Tools };
inline constexpr std::size_t FeatureGroups = 6;

/// One generation a person chose from: the designs picked as parents, the ones passed over and
/// the ones marked "less like this".
struct PickRound {
    std::vector<Genome> picked;
    std::vector<Genome> passed;
    std::vector<Genome> disliked;
};

/// The learned preference (see above), over up to MaxSteerRounds rounds, oldest first.
class PreferenceModel {
public:
    explicit PreferenceModel(const std::vector<PickRound>& rounds);
    /// Higher is more like the picks (0 at best; negative as constraints break).
    double score(const DesignFeatures& candidate) const;
    /// Whether a round has a pick and something to compare it with: without one, breeding is as
    /// without steering.
    bool informed() const { return mInformed; }
    /// The explanation in words: "more like your last 3 picks: finer patterns, warmer inks";
    /// empty when nothing has been learned.
    std::string explain() const;
    /// The step scales (0..1, relative to the requested strength) for palette, initial state and
    /// strokes: near 1 while picks disagree, smaller as they converge (1 without history).
    struct Steps {
        double palette = 1.0, initial = 1.0, strokes = 1.0;
    };
    Steps steps() const { return mSteps; }

    /// The weight of each feature group (FeatureGroups of them, adding up to their number):
    /// equal until the picks tell which groups the person goes by.
    const std::array<double, FeatureGroups>& groupWeights() const { return mGroupWeights; }
    /// The distance of two designs as the model sees it: featureDistance with the groups weighed.
    double distance(const DesignFeatures& a, const DesignFeatures& b) const;

private:
    void learnGroupWeights();
    double movement(std::size_t from, std::size_t to) const;
    struct Round {
        std::vector<DesignFeatures> picked, passed;
        std::vector<double> passedWeight;
        double weight = 1.0;
    };
    std::vector<Round> mRounds;
    /// The newest round with a pick (the picks a candidate should be near), -1 for none.
    int mNewest = -1;
    bool mInformed = false;
    int mInformedRounds = 0;
    Steps mSteps;
    std::array<double, FeatureGroups> mGroupWeights{1.0, 1.0, 1.0, 1.0, 1.0, 1.0};
    int mExplainedRounds = 0;
    std::vector<std::string> mWords;
};

/// The newest rounds the model reads.
inline constexpr int MaxSteerRounds = 12;
/// How many candidates a generation ranks by default.
inline constexpr int SteerCandidates = 24;

struct SteerRequest {
    BreedRequest breed;            ///< the operator, parents, seed, count... as breed() takes them
    std::vector<PickRound> rounds; ///< the person's picks, oldest first (the newest: these parents)
    int candidates = SteerCandidates;
    /// Whether fresh designs of the generators are drawn and shown beside the pick's variations
    /// (the window's Wildcard cell; `marbler breed --no-fresh` turns them off): without them
    /// every child is a variation of the picks.
    bool fresh = true;
};

/// How a steered generation varies the newest pick one way (docs/breeding.md): the palette,
/// the strokes, the initial state, or all of them.
struct SteerWay {
    std::string way;     ///< "palette", "strokes", "initial" or "all"
    double step = 0.0;   ///< the alteration strength its candidates are drawn about
    double weight = 0.0; ///< its share of the candidates (the ways add up to 1)
};

struct SteerResult {
    std::vector<Genome> children;
    /// Why these children: PreferenceModel::explain(), then how they vary the pick ("mostly
    /// the strokes; smaller steps: no child came closer last time"); empty without history.
    std::string explanation;
    PreferenceModel::Steps steps;
    double strokeStrength = 0.0; ///< the alteration strength used for the strokes
    std::vector<SteerWay> ways;  ///< how the candidates vary the pick, per way
};

/// Children ranked by the preferences (see above): `breed.count` of them, the last an exploration
/// (the best-liked candidate unlike the others). Without rounds that inform the model this is
/// breed(request.breed). Each child has the lineage breed() writes (a fresh design: operator
/// "wildcard"), plus `meta.lineage.steered`: its rank among the candidates. Throws what breed()
/// throws, and InputError for candidates outside [count, MaxChildren].
SteerResult steerBreed(const SteerRequest& request);

} // namespace marbler
