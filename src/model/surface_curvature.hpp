#pragma once
// Mean curvature of a faceted surface, element by element, from the normals of
// neighbouring elements (used for the Laplace tension estimate of the first Newton
// correction from a stress-free state, theory manual §7.2).
//
// The total mean curvature of a polyhedral surface is ∫ H dA = ½ Σ_edges |e| θ_e, θ_e the
// angle between the normals of the two facets sharing edge e (exact for any polyhedron; H =
// (κ₁ + κ₂)/2). Giving each facet half of each of its edges' share,
//     H_e = (Σ_shared |e| θ_e / 4) / A_e × P_e / P_shared,
// A_e the facet's area, P_e its perimeter and P_shared the length of its edges shared with
// another facet of the part: the last factor makes up for the edges on the part's boundary
// (free edges, symmetry planes), which have no neighbour. The facet's normal n_e is
// (x₁ − x₀) × (x₂ − x₀) for a triangle, (x₂ − x₀) × (x₃ − x₁) for a quadrilateral (node order
// gives the side), and θ_e is signed: positive where the surface bends away from the side its
// normals point to, (n_f − n_e)·(c_f − c_e) > 0 with c the centroids (a sphere with outward
// normals: H_e = 1/R to O(h²) on quadrilaterals and on triangles alike). 0 for a facet with no
// shared edge. A higher-order element's facet is that of its corner nodes (corner_nodes, model.hpp).
#include <vector>

#include "model/model.hpp"

namespace tunica {

/// H_e of every element of every 3-D block (tri3, quad4) of the part, per block in block order
/// (empty vectors for other blocks); elements of different 3-D blocks of the part are neighbours
/// when they share an edge.
std::vector<std::vector<double>> element_mean_curvature(const Model& model, const Part& part);

}  // namespace tunica
