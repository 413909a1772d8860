#pragma once
// Reading an axisymmetric part's generated meridian (`mesh:` of an `axisymmetric_membrane` or
// `axisymmetric_shell` part): one generator map (`type: line` or `type: arc`, mesh/meridian.hpp)
// or a list of them joined end to start into one meridian, e.g. a capsule of an arc, a line and
// an arc. Each piece is read and checked as a mesh of its own (io/meridian_checks.hpp); the node
// where two pieces meet is one node of the part, so the membrane runs through it.
#include <vector>

#include "io/deck_node.hpp"
#include "model/model.hpp"

namespace tunica {

/// The end of one piece and the start of the next are taken as one point when they lie within
/// this fraction of the shorter of the two elements that meet there.
constexpr double kMeridianJoinFraction = 1e-2;

/// Reads the part's `mesh` into the model: its nodes in meridian order (part.nodes), one axisym2
/// block and the node sets `<part>.start`, `.end`, `.all`. Returns the positions in part.nodes
/// where a piece after the first begins (the joints; empty for a single generator).
std::vector<int> read_meridian_part(const DeckNode& node, Part& part, Model& m);

}  // namespace tunica
