// The 6-node quadratic triangle membrane (tri6_shape.hpp; theory manual §5.1, (5.5)–(5.7), §7.2):
// explicit instantiations of the element kernels for N = 6. Its follower pressure and enclosed
// volume are instantiated in loads/surface_pressure_tri6.cpp.
#include "elements/membrane3d_impl.hpp"
#include "elements/start_tension_impl.hpp"
#include "elements/tri6_shape.hpp"

namespace tunica {

template MembraneReference<6> membrane_reference<6>(const SurfaceNodes<6>&, double, const DirectionRule&);
template void membrane3d<6>(const MembraneReference<6>&, const SurfaceNodes<6>&, const MembraneMaterial&,
                            ElementVector<6>&, ElementMatrix<6>*, std::array<MembranePoint, 6>*);
template void normal_tension_stiffness<6>(const MembraneReference<6>&, double, ElementMatrix<6>&);

}  // namespace tunica
