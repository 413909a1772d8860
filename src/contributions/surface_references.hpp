#pragma once
// Reference data of the 3-D membrane elements of a part (membrane3d.hpp):
// material frames from the part's frame rule, shape derivatives, weights.
#include <fmt/format.h>

#include <string>
#include <vector>

#include "contributions/element_type.hpp"
#include "elements/membrane3d.hpp"
#include "elements/membrane3d_inverse.hpp"
#include "model/model.hpp"

namespace tunica {

/// The direction rule of a part's frame for element e of a block (frame rules: model.hpp).
DirectionRule direction_rule(const Model& model, const FrameRule& frame, const ElementBlock& block, int e);

/// The same rule as a function of the element's reference nodes, for the inverse element
/// (elements/membrane3d_inverse.hpp): the edge rule follows the element's first edge as X moves.
FrameDirection frame_direction(const Model& model, const FrameRule& frame, const ElementBlock& block, int e);

/// The index of the block's first Gauss point among the part's, in System::points order (blocks of
/// a part may differ in their points per element: triangles and quadrilaterals of one surface).
inline std::size_t first_point_of(const Part& part, const ElementBlock& block) {
  std::size_t k = 0;
  for (const ElementBlock& b : part.blocks) {
    if (&b == &block) break;
    k += static_cast<std::size_t>(b.size()) * static_cast<std::size_t>(element_type(b.kind).points_per_element(part));
  }
  return k;
}

/// Reference data of every element of a 3-D block of N-node elements. Throws
/// BadElement whose message names the element (as in the mesh file, else 0-based within
/// the part, in block order) and says what is wrong.
template <int N>
std::vector<MembraneReference<N>> block_references(const Model& model, const Part& part, const ElementBlock& block,
                                                   int first_element) {
  std::vector<MembraneReference<N>> out;
  out.reserve(block.size());
  SurfaceNodes<N> X;
  const std::size_t first_point =
      part.point_thickness.empty() && part.point_prestretch.empty() ? 0 : first_point_of(part, block);
  for (int e = 0; e < block.size(); ++e) {
    const int* n = block.element(e);
    for (int a = 0; a < N; ++a) X.col(a) = model.X[n[a]];
    try {
      out.push_back(membrane_reference<N>(X, part.thickness, direction_rule(model, part.frame, block, e)));
      // A reference an inverse step computed from an imaged thickness: H per Gauss point (13.14).
      if (!part.point_thickness.empty()) {
        MembraneReference<N>& ref = out.back();
        for (int q = 0; q < MembraneReference<N>::Q; ++q) {
          const double H = part.point_thickness.at(first_point + static_cast<std::size_t>(e) * MembraneReference<N>::Q + q);
          ref.weight[q] *= H / ref.thickness[q];
          ref.thickness[q] = H;
        }
      }
      // A prestretch P from a prestress step (13.20): the stress-free coordinates s̃ with s = P s̃, so
      // ∂N/∂s̃ = ∂N/∂s P and the stress-free volume w_q dA H̃ / det P, dA the mesh's area element.
      if (!part.point_prestretch.empty()) {
        MembraneReference<N>& ref = out.back();
        for (int q = 0; q < MembraneReference<N>::Q; ++q) {
          prestretch_reference<N>(
              ref, q, part.point_prestretch.at(first_point + static_cast<std::size_t>(e) * MembraneReference<N>::Q + q));
        }
      }
    } catch (const BadElement& err) {
      // Named as in the mesh file where the elements come from one, else by 0-based index.
      const bool from_file = static_cast<int>(block.tags.size()) == block.size();
      std::string nodes;
      for (int a = 0; a < N; ++a) {
        const long tag = n[a] < static_cast<int>(model.node_tags.size()) ? model.node_tags[n[a]] : 0;
        nodes += fmt::format("{}{}", a ? ", " : "", from_file && tag > 0 ? tag : n[a]);
      }
      if (from_file)
        throw BadElement(fmt::format("{}: element {} ({}, nodes {}): {}", block.file, block.tags[e],
                                     std::string("a ") + SurfaceShapeTraits<N>::kName, nodes, err.what()));
      throw BadElement(fmt::format("element {} ({}, nodes {}): {}", first_element + e, SurfaceShapeTraits<N>::kName,
                                   nodes, err.what()));
    }
  }
  return out;
}

}  // namespace tunica
