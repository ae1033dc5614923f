#pragma once
/// What changed from a parent to a child, in plain words and the registry's terms, for the
/// workbench's tooltips and lineage: "comb 2: spacing 18 → 23; palette: ink 3 redder".
///
/// Steps are named by their tool and their number among that tool's steps of the list they
/// are in ("comb 2" is the second comb of `operations`, "drop 3" the third drop of `initial`),
/// counted in the child, or in the parent for a removed step. Inks are numbered from 1 ("ink 1"
/// is palette index 0). Strokes are matched by the longest common run of tools, so an added or
/// removed stroke does not make every later one look changed.
///
/// Values are rounded by kind: lengths and shifts to whole units (one decimal below 10),
/// angles and phases in whole degrees, positions as the distance moved, colours as the colour
/// word (colorWord) when it changes, else the largest shifts of hue, lightness and saturation
/// ("redder", "lighter", "duller"). The changes are ordered by their size relative to the
/// parameter's mutation scale, the largest first, and at most ChangeSummaryLimit are spelled
/// out ("and 5 more"). Equal designs (meta aside) give "no visible change".

#include "marbler/Genome.h"

#include <cstddef>
#include <string>
#include <vector>

namespace marbler {

/// The most changes describeChange spells out; the rest are counted.
inline constexpr int ChangeSummaryLimit = 4;

/// What differs from `parent` to `child`, in one line.
std::string describeChange(const Genome& parent, const Genome& child);
/// What differs from a child's home parent `parents[home]`, naming the other parent a part
/// came from where the child holds it unchanged: "the strokes of parent 2" (swap), "added a
/// wave from parent 3" (recombine). Parents are numbered from 1, in the order given.
std::string describeChange(const std::vector<Genome>& parents, std::size_t home, const Genome& child);

} // namespace marbler
