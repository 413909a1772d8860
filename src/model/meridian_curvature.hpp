#pragma once
// Mean curvature of an axisymmetric membrane's meridian, element by element (the Laplace tension
// estimate of the first Newton correction from a stress-free state, theory manual §7.2, (7.8)).
//
// A straight segment from node a to node b, tangent t = (X_b − X_a)/L in the (r, z) plane, has
// the unit normal n = (t_z, −t_r) (outward for a meridian running counterclockwise, south to
// north on the right of the axis) and the two principal curvatures of the surface of revolution
//     κ_θ = n_r / R_mid                     (the parallel circle; R_mid the segment's mid radius),
//     κ_s = (κ_a + κ_b)/2,  κ_node = θ / ((L_in + L_out)/2)
// with θ the signed turning angle of the meridian at a node shared by two segments (positive
// counterclockwise), so that H_e = (κ_s + κ_θ)/2 is 1/R on a sphere of radius R, whichever way
// its meridian runs up to the sign, and ½/R on a tube. A node with one segment (an end, a pole)
// takes the other node's κ; segments that meet head to head or tail to tail are not chained.
#include <vector>

#include "model/model.hpp"

namespace tunica {

/// H_e of every element of the part's axisym2 blocks, per block in block order (empty vectors for
/// other blocks); segments of different axisym2 blocks of the part are chained through shared nodes.
std::vector<std::vector<double>> meridian_mean_curvature(const Model& model, const Part& part);

}  // namespace tunica
