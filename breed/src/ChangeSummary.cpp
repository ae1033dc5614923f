#include "marbler/ChangeSummary.h"

#include "marbler/Generator.h"
#include "marbler/Params.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>
#include <string_view>
#include <vector>

namespace marbler {
namespace {

/// One change: what it concerns ("comb 2", "palette"; empty for a whole sentence), the words,
/// and its size relative to the parameter's mutation scale (which orders the summary).
struct Change {
    std::string label;
    std::string text;
    double weight = 1.0;
};

/// `value` with `decimals` decimals, trailing zeros and a negative zero dropped.
std::string fixed(double value, int decimals) {
    char text[64];
    std::snprintf(text, sizeof text, "%.*f", decimals, value);
    std::string s = text;
    if (s.find('.') != std::string::npos) {
        while (s.back() == '0')
            s.pop_back();
        if (s.back() == '.') s.pop_back();
    }
    if (s == "-0") s = "0";
    return s;
}

/// Design units: whole units from 10 up, one decimal below.
int lengthDecimals(double value) {
    return std::abs(value) >= 10.0 ? 0 : 1;
}

/// "old → new", with more decimals where the rounded values would read the same.
std::string fromTo(const std::vector<double>& from, const std::vector<double>& to, int decimals,
                   std::string_view unit = {}) {
    const auto join = [&](const std::vector<double>& values, int d) {
        std::string s;
        for (std::size_t i = 0; i < values.size(); ++i)
            s += (i ? "×" : "") + fixed(values[i], d) + std::string(unit);
        return s;
    };
    int d = decimals;
    while (d < 4 && join(from, d) == join(to, d))
        ++d;
    return join(from, d) + " → " + join(to, d);
}

/// A distance in design units, at least one significant figure.
std::string distance(double d) {
    int decimals = lengthDecimals(d);
    while (decimals < 4 && fixed(d, decimals) == "0")
        ++decimals;
    const std::string s = fixed(d, decimals);
    return s + (s == "1" ? " unit" : " units");
}

std::vector<double> components(const ParamSpec& spec, const Operation& op, int dimension) {
    std::vector<double> values(static_cast<std::size_t>(componentCount(spec, op, dimension)));
    for (std::size_t i = 0; i < values.size(); ++i)
        values[i] = getComponent(spec, op, static_cast<int>(i));
    return values;
}

/// The largest difference of the components; angles the short way round (315° → 0° is 45°).
double largestDifference(const std::vector<double>& a, const std::vector<double>& b, bool degrees = false) {
    double d = 0.0;
    for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i) {
        double di = std::abs(a[i] - b[i]);
        if (degrees) di = std::abs(std::fmod(di + 180.0, 360.0) - 180.0);
        d = std::max(d, di);
    }
    return d;
}

/// The changes of one parameter of a step that both designs have.
void describeParameter(const ParamSpec& spec, const Operation& a, const Operation& b, int dimension,
                       double side, const std::string& label, std::vector<Change>& out) {
    const std::vector<double> from = components(spec, a, dimension), to = components(spec, b, dimension);
    if (from == to) return;
    const std::string key(spec.key);
    const double scale = spec.mutationScale > 0.0 ? spec.mutationScale : 1.0;
    switch (spec.kind) {
    case ParamKind::Position: {
        double d2 = 0.0;
        for (std::size_t i = 0; i < from.size(); ++i)
            d2 += (to[i] - from[i]) * (to[i] - from[i]);
        const double d = std::sqrt(d2);
        out.push_back({label, "moved " + distance(d), d / (scale * side)});
        return;
    }
    case ParamKind::Direction: {
        double dot = 0.0, na = 0.0, nb = 0.0;
        for (std::size_t i = 0; i < from.size(); ++i) {
            dot += from[i] * to[i];
            na += from[i] * from[i];
            nb += to[i] * to[i];
        }
        const double turn = std::acos(std::clamp(dot / std::sqrt(na * nb), -1.0, 1.0));
        double degrees = turn * 180.0 / std::numbers::pi;
        int decimals = 0;
        while (decimals < 4 && fixed(degrees, decimals) == "0")
            ++decimals;
        out.push_back({label, key + " turned " + fixed(degrees, decimals) + "°", turn / scale});
        return;
    }
    case ParamKind::Angle:
    case ParamKind::Phase:
        out.push_back(
            {label, key + " " + fromTo(from, to, 0, "°"), largestDifference(from, to, true) / scale});
        return;
    case ParamKind::Length:
    case ParamKind::Shift:
    case ParamKind::Extent: {
        double largest = 0.0;
        for (double v : from)
            largest = std::max(largest, std::abs(v));
        out.push_back({label, key + " " + fromTo(from, to, lengthDecimals(largest)),
                       from.size() == to.size() ? largestDifference(from, to) / (scale * side) : 1.0});
        return;
    }
    case ParamKind::Number:
        out.push_back({label, key + " " + fromTo(from, to, std::abs(from[0]) >= 10.0 ? 0 : 2),
                       std::abs(to[0] - from[0]) / scale});
        return;
    case ParamKind::Pressure:
        out.push_back({label, key + " changed by up to " + fixed(largestDifference(from, to), 2), 1.0});
        return;
    case ParamKind::Count:
        out.push_back(
            {label, key + " " + fromTo(from, to, 0), std::abs(to[0] - from[0]) / std::max(1.0, from[0])});
        return;
    case ParamKind::Color:
        out.push_back({label, "ink " + fixed(from[0] + 1.0, 0) + " → ink " + fixed(to[0] + 1.0, 0), 1.0});
        return;
    case ParamKind::Choice:
        out.push_back({label,
                       key + " " + std::string(spec.choices[static_cast<std::size_t>(from[0])]) + " → " +
                           std::string(spec.choices[static_cast<std::size_t>(to[0])]),
                       1.0});
        return;
    case ParamKind::Teeth:
    case ParamKind::Path: // a stylus's path: its numbers' count, else how far they moved
        if (from.size() != to.size())
            out.push_back(
                {label, key + " " + std::to_string(from.size()) + " → " + std::to_string(to.size()), 1.0});
        else {
            const double d = largestDifference(from, to);
            out.push_back({label, key + " moved up to " + distance(d), d / (scale * side)});
        }
        return;
    }
}

/// The parameter changes of a step both designs have (the same tool).
void describeStep(const Operation& a, const Operation& b, int dimension, double side,
                  const std::string& label, std::vector<Change>& out) {
    for (const ParamSpec& spec : toolSpec(a.tool).params(dimension))
        describeParameter(spec, a, b, dimension, side, label, out);
}

/// "comb 2": each step's tool and its number among that tool's steps of the list.
std::vector<std::string> stepLabels(const std::vector<Operation>& steps) {
    std::array<int, ToolCount> seen{};
    std::vector<std::string> labels;
    labels.reserve(steps.size());
    for (const Operation& op : steps)
        labels.push_back(std::string(toolSpec(op.tool).name) + " " +
                         std::to_string(++seen[static_cast<std::size_t>(op.tool)]));
    return labels;
}

std::string withArticle(std::string_view name) {
    const bool vowel = !name.empty() && std::string_view("aeiou").find(name[0]) != std::string_view::npos;
    return (vowel ? "an " : "a ") + std::string(name);
}

/// "combs", "stretches", "vortices": the registry spells each out (no rule covers English).
std::string plural(Tool tool) {
    return std::string(toolSpec(tool).plural);
}

/// The pairs of steps matched by the longest common run of their tools; nothing when
/// the lists are too long to align cheaply.
std::optional<std::vector<std::pair<std::size_t, std::size_t>>> alignSteps(const std::vector<Operation>& a,
                                                                           const std::vector<Operation>& b) {
    const std::size_t n = a.size(), m = b.size();
    if (n == m && std::equal(a.begin(), a.end(), b.begin(),
                             [](const Operation& x, const Operation& y) { return x.tool == y.tool; })) {
        std::vector<std::pair<std::size_t, std::size_t>> pairs;
        for (std::size_t i = 0; i < n; ++i)
            pairs.emplace_back(i, i);
        return pairs;
    }
    if ((n + 1) * (m + 1) > 4'000'000) return std::nullopt;
    // score[i][j]: the best matching of a[i..] with b[j..], an unchanged step counting more
    // than a changed one of the same tool, so a removed comb among combs is the one gone.
    const auto worth = [&](std::size_t i, std::size_t j) {
        return a[i].tool != b[j].tool ? 0 : a[i] == b[j] ? 3 : 2;
    };
    std::vector<int> score((n + 1) * (m + 1), 0);
    const auto at = [&](std::size_t i, std::size_t j) -> int& { return score[i * (m + 1) + j]; };
    for (std::size_t i = n; i-- > 0;)
        for (std::size_t j = m; j-- > 0;) {
            at(i, j) = std::max(at(i + 1, j), at(i, j + 1));
            if (int w = worth(i, j)) at(i, j) = std::max(at(i, j), at(i + 1, j + 1) + w);
        }
    std::vector<std::pair<std::size_t, std::size_t>> pairs;
    for (std::size_t i = 0, j = 0; i < n && j < m;) {
        const int w = worth(i, j);
        if (w && at(i, j) == at(i + 1, j + 1) + w)
            pairs.emplace_back(i++, j++);
        else if (at(i, j) == at(i + 1, j))
            ++i;
        else
            ++j;
    }
    return pairs;
}

/// The parents a child may have taken strokes from besides its home parent, numbered from 1.
struct Donor {
    const Genome* genome;
    std::size_t number;
};

/// The stroke changes: matched strokes parameter by parameter, the strokes removed, and the
/// strokes added (counted by tool, and by the parent that holds them when one does).
void describeStrokes(const std::vector<Operation>& a, const std::vector<Operation>& b, int dimension,
                     double side, const std::vector<Donor>& donors, std::vector<Change>& out) {
    if (a == b) return;
    for (const Donor& d : donors)
        if (!b.empty() && d.genome->operations == b) {
            out.push_back({"", "the strokes of parent " + std::to_string(d.number), 50.0});
            return;
        }
    const auto pairs = alignSteps(a, b);
    if (!pairs) {
        out.push_back({"", "strokes: " + std::to_string(a.size()) + " → " + std::to_string(b.size()), 10.0});
        return;
    }
    const std::vector<std::string> oldLabels = stepLabels(a), newLabels = stepLabels(b);
    std::vector<bool> keptOld(a.size(), false), keptNew(b.size(), false);
    for (auto [i, j] : *pairs) {
        keptOld[i] = keptNew[j] = true;
        describeStep(a[i], b[j], dimension, side, newLabels[j], out);
    }
    // Added and removed strokes reshape the design more than any nudge.
    for (std::size_t i = 0; i < a.size(); ++i)
        if (!keptOld[i]) out.push_back({"", "removed " + oldLabels[i], 5.0});
    // (tool, donor number or 0) -> how many were added, in the order first added.
    std::vector<std::pair<std::pair<Tool, std::size_t>, int>> added;
    for (std::size_t j = 0; j < b.size(); ++j) {
        if (keptNew[j]) continue;
        std::size_t from = 0;
        for (const Donor& d : donors)
            if (std::find(d.genome->operations.begin(), d.genome->operations.end(), b[j]) !=
                d.genome->operations.end()) {
                from = d.number;
                break;
            }
        const std::pair key{b[j].tool, from};
        auto it = std::find_if(added.begin(), added.end(), [&](const auto& e) { return e.first == key; });
        if (it == added.end())
            added.push_back({key, 1});
        else
            ++it->second;
    }
    for (const auto& [key, count] : added) {
        const std::string_view name = toolSpec(key.first).name;
        std::string text =
            "added " + (count == 1 ? withArticle(name) : std::to_string(count) + " " + plural(key.first));
        if (key.second) text += " from parent " + std::to_string(key.second);
        out.push_back({"", text, 5.0 * count});
    }
}

/// "14 drops", "12 drops and 2 sprays".
std::string countSteps(const std::vector<Operation>& steps) {
    std::array<int, ToolCount> count{};
    for (const Operation& op : steps)
        ++count[static_cast<std::size_t>(op.tool)];
    std::string text;
    for (const ToolSpec& tool : allTools()) {
        const int c = count[static_cast<std::size_t>(tool.tool)];
        if (c == 0) continue;
        if (!text.empty()) text += " and ";
        text += std::to_string(c) + " " + (c == 1 ? std::string(tool.name) : plural(tool.tool));
    }
    return text.empty() ? "empty" : text;
}

/// The initial state: a few changed inks step by step, more as one change.
void describeInitial(const Genome& parent, const Genome& child, double side, std::vector<Change>& out) {
    const auto& a = parent.initial;
    const auto& b = child.initial;
    if (a == b) return;
    if (a.size() != b.size() ||
        !std::equal(a.begin(), a.end(), b.begin(),
                    [](const Operation& x, const Operation& y) { return x.tool == y.tool; })) {
        const std::string from = countSteps(a), to = countSteps(b);
        out.push_back({"", from == to ? "new initial state" : "initial state: " + from + " → " + to, 20.0});
        return;
    }
    std::size_t changed = 0;
    for (std::size_t i = 0; i < a.size(); ++i)
        changed += a[i] == b[i] ? 0 : 1;
    if (changed > 3) {
        out.push_back({"",
                       changed == a.size() ? "new initial state"
                                           : "initial state: " + std::to_string(changed) + " of " +
                                                 std::to_string(a.size()) + " inks changed",
                       changed == a.size()
                           ? 20.0
                           : 2.0 * static_cast<double>(changed) / static_cast<double>(a.size())});
        return;
    }
    const std::vector<std::string> labels = stepLabels(b);
    for (std::size_t i = 0; i < a.size(); ++i)
        describeStep(a[i], b[i], child.dimension, side, labels[i], out);
}

/// The hue words a shift is named after, by the hue it moves towards.
struct HueWord {
    double hue;
    const char* word;
};
constexpr std::array<HueWord, 8> HueWords{{{0.0, "redder"},
                                           {30.0, "more orange"},
                                           {60.0, "yellower"},
                                           {120.0, "greener"},
                                           {180.0, "more turquoise"},
                                           {240.0, "bluer"},
                                           {285.0, "more violet"},
                                           {330.0, "pinker"}}};

/// The first hue word met going from `from` by `delta` degrees (its sign the way round).
const char* hueWord(double from, double delta) {
    const char* best = HueWords[0].word;
    double nearest = 1e9;
    for (const HueWord& w : HueWords) {
        // How far along the shift's way round the word's hue lies, beyond the starting hue.
        double ahead = delta > 0.0 ? w.hue - from : from - w.hue;
        ahead = std::fmod(ahead + 720.0, 360.0);
        if (ahead <= 0.0) ahead += 360.0;
        if (ahead < nearest) nearest = ahead, best = w.word;
    }
    return best;
}

/// What became of a colour: "Cobalt → Saffron" when its colour word changes, else its largest
/// shifts ("redder and lighter"); the weight is the shift in units of a gentle nudge.
std::pair<std::string, double> describeColor(Color a, Color b) {
    const std::string wordA = colorWord(a), wordB = colorWord(b);
    const Hsl x = hslOf(a), y = hslOf(b);
    double hue = std::fmod(y.h - x.h + 540.0, 360.0) - 180.0;
    // A grey has no hue to speak of.
    if (std::min(x.s, y.s) < 0.08 || std::min(x.l, y.l) < 0.04 || std::max(x.l, y.l) > 0.96) hue = 0.0;
    const double weight =
        std::max({std::abs(hue) / 15.0, std::abs(y.l - x.l) / 0.05, std::abs(y.s - x.s) / 0.08});
    if (wordA != wordB) return {": " + wordA + " → " + wordB, weight + 1.0};
    std::vector<std::pair<double, std::string>> shifts;
    if (std::abs(hue) >= 3.0) shifts.emplace_back(std::abs(hue) / 15.0, hueWord(x.h, hue));
    if (std::abs(y.l - x.l) >= 0.02)
        shifts.emplace_back(std::abs(y.l - x.l) / 0.05, y.l > x.l ? "lighter" : "darker");
    if (std::abs(y.s - x.s) >= 0.04)
        shifts.emplace_back(std::abs(y.s - x.s) / 0.08, y.s > x.s ? "more vivid" : "duller");
    std::stable_sort(shifts.begin(), shifts.end(),
                     [](const auto& p, const auto& q) { return p.first > q.first; });
    if (shifts.empty()) return {" nudged", weight};
    std::string text = " " + shifts[0].second;
    if (shifts.size() > 1) text += " and " + shifts[1].second;
    return {text, weight};
}

void describePalette(const Genome& parent, const Genome& child, std::vector<Change>& out) {
    const auto& a = parent.palette;
    const auto& b = child.palette;
    if (a.size() != b.size())
        out.push_back(
            {"palette", std::to_string(a.size()) + " inks → " + std::to_string(b.size()) + " inks", 5.0});
    for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i) {
        if (a[i] == b[i]) continue;
        auto [text, weight] = describeColor(a[i], b[i]);
        out.push_back({"palette", "ink " + std::to_string(i + 1) + text, weight});
    }
    if (parent.background != child.background) {
        auto [text, weight] = describeColor(parent.background, child.background);
        out.push_back({"", "background" + text, weight});
    }
}

} // namespace

std::string describeChange(const Genome& parent, const Genome& child) {
    return describeChange({parent}, 0, child);
}

std::string describeChange(const std::vector<Genome>& parents, std::size_t home, const Genome& child) {
    const Genome& parent = parents.at(home);
    std::vector<Donor> donors;
    for (std::size_t k = 0; k < parents.size(); ++k)
        if (k != home && parents[k].dimension == child.dimension) donors.push_back({&parents[k], k + 1});
    std::vector<Change> changes;
    const double side =
        std::max({child.size.x, child.size.y, child.dimension == 3 ? child.size.z : 0.0, 1.0});
    if (parent.dimension != child.dimension) {
        changes.push_back({"", "now " + std::to_string(child.dimension) + "D", 100.0});
    } else {
        if (parent.size != child.size) {
            const auto extent = [](const Genome& g) {
                std::vector<double> v{g.size.x, g.size.y};
                if (g.dimension == 3) v.push_back(g.size.z);
                return v;
            };
            changes.push_back({"", "size " + fromTo(extent(parent), extent(child), 0), 10.0});
        }
        describeInitial(parent, child, side, changes);
        describeStrokes(parent.operations, child.operations, child.dimension, side, donors, changes);
    }
    if (parent.source != child.source)
        changes.push_back({"",
                           child.source ? (parent.source ? "new source image" : "added a source image")
                                        : "removed the source image",
                           20.0});
    describePalette(parent, child, changes);
    if (parent.bleed != child.bleed)
        changes.push_back({"", "bleed " + fromTo({parent.bleed}, {child.bleed}, 1),
                           std::abs(child.bleed - parent.bleed) / 2.0 + 0.5});
    if (changes.empty()) return "no visible change";

    // The largest first; equal weights keep the design's order.
    std::stable_sort(changes.begin(), changes.end(),
                     [](const Change& p, const Change& q) { return p.weight > q.weight; });
    const std::size_t shown = std::min(changes.size(), static_cast<std::size_t>(ChangeSummaryLimit));
    // The shown changes of one step read together ("comb 2: spacing 18 → 23, alpha 40 → 45"),
    // where its largest change stands.
    std::vector<std::string> parts;
    std::vector<std::string> partLabels;
    for (std::size_t k = 0; k < shown; ++k) {
        const Change& c = changes[k];
        if (!c.label.empty()) {
            auto it = std::find(partLabels.begin(), partLabels.end(), c.label);
            if (it != partLabels.end()) {
                parts[static_cast<std::size_t>(it - partLabels.begin())] += ", " + c.text;
                continue;
            }
        }
        parts.push_back(c.label.empty() ? c.text : c.label + ": " + c.text);
        partLabels.push_back(c.label);
    }
    std::string text;
    for (const std::string& part : parts)
        text += (text.empty() ? "" : "; ") + part;
    if (changes.size() > shown) text += "; and " + std::to_string(changes.size() - shown) + " more";
    return text;
}

} // namespace marbler
