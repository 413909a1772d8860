#pragma once
// A 3-D part without `frame` takes direction 1 along each element's first edge (FrameRule::edge),
// which an isotropic material allows. Its stresses and stretches along directions 1 and 2
// (lambda_1, S_2, sigma_1, ...) then mean something only if the first edges run one way over the
// part (a generated tube of quadrilaterals: around it); on a Gmsh mesh or a tube of triangles
// they turn from element to element, and a history mean of lambda_1 mixes the hoop and axial
// stretches with no sign of it.
#include "model/model.hpp"

namespace tunica {

/// Neighbouring elements whose directions 1 differ by more than this are counted as turned.
constexpr double kEdgeFrameTurnDeg = 15;

/// For a 3-D part with FrameRule::edge, the fraction of the element pairs that share an edge whose
/// directions 1 (first edges) differ by more than kEdgeFrameTurnDeg, the neighbour's taken into
/// the element's tangent plane and either sense (±d give the same stretch); 0 for other parts.
double edge_frame_turned_fraction(const Model& m, int part);

}  // namespace tunica
