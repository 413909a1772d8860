// Explicit instantiations of the inverse 3-D membrane elements (membrane3d_inverse.hpp; theory
// manual §13) for the 3-node triangle, the 4-node quadrilateral and the 6-node triangle.
#include "elements/membrane3d_inverse_impl.hpp"
#include "elements/tri6_shape.hpp"

namespace tunica {

template void membrane3d_inverse<3>(const SurfaceNodes<3>&, const SurfaceNodes<3>&, double, const FrameDirection&,
                                    const MembraneMaterial&, ElementVector<3>&, ElementMatrix<3>*,
                                    const std::array<double, SurfaceShapeTraits<3>::kPoints>*,
                                    std::array<MembranePoint, SurfaceShapeTraits<3>::kPoints>*);
template void membrane3d_inverse<4>(const SurfaceNodes<4>&, const SurfaceNodes<4>&, double, const FrameDirection&,
                                    const MembraneMaterial&, ElementVector<4>&, ElementMatrix<4>*,
                                    const std::array<double, SurfaceShapeTraits<4>::kPoints>*,
                                    std::array<MembranePoint, SurfaceShapeTraits<4>::kPoints>*);
template void membrane3d_inverse<6>(const SurfaceNodes<6>&, const SurfaceNodes<6>&, double, const FrameDirection&,
                                    const MembraneMaterial&, ElementVector<6>&, ElementMatrix<6>*,
                                    const std::array<double, SurfaceShapeTraits<6>::kPoints>*,
                                    std::array<MembranePoint, SurfaceShapeTraits<6>::kPoints>*);

}  // namespace tunica
