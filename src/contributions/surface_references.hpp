#pragma once
// Reference data of the 3-D membrane elements of a part (membrane3d.hpp):
// material frames from the part's frame rule, shape derivatives, weights.
#include <vector>

#include "elements/membrane3d.hpp"
#include "model/model.hpp"

namespace tunica {

/// The direction rule of a part's frame for element e of a block (frame rules: model.hpp).
DirectionRule direction_rule(const Model& model, const FrameRule& frame, const ElementBlock& block, int e);

/// Reference data of every element of a 3-D block of N-node elements. Throws
/// BadElement whose message names the element (0-based within the part, in
/// block order) and says what is wrong.
template <int N>
std::vector<MembraneReference<N>> block_references(const Model& model, const Part& part, const ElementBlock& block,
                                                   int first_element);

}  // namespace tunica
