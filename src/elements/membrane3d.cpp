// Explicit instantiations of the 3-D membrane elements (membrane3d.hpp; theory manual §5.1)
// for the 3-node triangle and the 4-node quadrilateral; the definitions are in membrane3d_impl.hpp.
#include "elements/membrane3d_impl.hpp"

namespace tunica {

template MembraneReference<3> membrane_reference<3>(const SurfaceNodes<3>&, double, const DirectionRule&);
template MembraneReference<4> membrane_reference<4>(const SurfaceNodes<4>&, double, const DirectionRule&);
template void membrane3d<3>(const MembraneReference<3>&, const SurfaceNodes<3>&, const MembraneMaterial&,
                            ElementVector<3>&, ElementMatrix<3>*, std::array<MembranePoint, 1>*);
template void membrane3d<4>(const MembraneReference<4>&, const SurfaceNodes<4>&, const MembraneMaterial&,
                            ElementVector<4>&, ElementMatrix<4>*, std::array<MembranePoint, 4>*);

}  // namespace tunica
