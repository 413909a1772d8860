#pragma once
// A meridian that crosses or runs back over itself (two elements that are not neighbours meet, or
// two neighbours fold back onto each other): no surface of revolution, though every element may be
// valid on its own. A meridian whose last node lies on its first (a closed ring) is one too: its
// ends are not joined there.
#include <optional>

#include "mesh/meridian.hpp"

namespace tunica {

/// Two elements of a meridian that meet where they should not: element e joins nodes e and e + 1.
struct MeridianCrossing {
  int first = -1, second = -1;  ///< first < second
  Eigen::Vector2d at = Eigen::Vector2d::Zero();  ///< a point they share
};

/// The first crossing of `m` (by the later element, then the nearest earlier one), or none. Neighbours
/// meet only at their shared node, unless they fold back (one runs back along the other).
/// Expected time O(n) for a meridian of evenly sized elements (a grid of cells of the longest
/// element's size).
std::optional<MeridianCrossing> meridian_crossing(const Meridian& m);

}  // namespace tunica
