#pragma once
// The restart fingerprint of a deck: everything the converged states of a run depend on, so
// that `tunica run --restart` can refuse a deck that changed it (naming the key) instead of
// continuing one model's history with another. It holds every key of `units`, `materials`,
// `parts`, `node_sets`, `boundary`, `loads`, `rigid_surfaces`, `contact`, the steps' keys but
// their `name` and `solver`, and `output.history` and `output.vtk_fields` (the columns and
// arrays the run's files already hold), each with its value as written; and a digest of each
// part's mesh (node positions, elements) and each node set's nodes, so that a mesh file edited
// under the same name is caught. Left out, free to change on a restart: `title`, `solver`,
// each step's `solver` and `name`, and the rest of `output` (how often frames and checkpoints
// are written). A value respelt (`30 kPa` as `0.03 MPa`) or a default written out counts as a
// change: the check compares what is written. `places` receives the line and column of every
// key it holds, and of the maps and lists holding them (Model::fingerprint_places).
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "io/deck_node.hpp"
#include "model/model.hpp"

namespace tunica {

std::vector<FingerprintEntry> deck_fingerprint(const DeckNode& deck, const Model& m,
                                               std::map<std::string, std::pair<int, int>>* places = nullptr);

}  // namespace tunica
