#pragma once
// What an inverse step (Step::inverse; theory manual §13) needs of the model, checked when the
// deck is read: it is the deck's first step and its only inverse one (the steps after it are
// forward steps on the zero-pressure reference it computes, solver/analysis.hpp), no volume control, every part an element with an inverse
// element (the membranes: tri3, quad4, tri6, axisymmetric), no part entering later, no contact
// pairs, and a linear solver that takes unsymmetric tangents.
#include "io/deck_node.hpp"
#include "model/model.hpp"

namespace tunica {

/// InputError at the step's `type` (or the key concerned) naming what an inverse step cannot do.
/// `step` is the step being read, `node` its deck node; m.steps holds the steps before it.
void check_inverse_step(const DeckNode& node, const Model& m, const Step& step);

}  // namespace tunica
