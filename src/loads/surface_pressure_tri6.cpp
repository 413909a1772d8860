// Follower pressure and enclosed volume of the 6-node quadratic triangle (tri6_shape.hpp;
// theory manual (6.4)–(6.6), (5.7)): explicit instantiations for N = 6. The 6-point rule of
// degree 4 integrates them exactly (n = g1 × g2 and N_a are of degree 2).
#include "elements/tri6_shape.hpp"
#include "loads/surface_pressure_impl.hpp"

namespace tunica {

template void surface_pressure<6>(const SurfaceNodes<6>&, double, ElementVector<6>&, ElementMatrix<6>*);
template double subtract_surface_pressure<6>(const SurfaceNodes<6>&, double, ElementVector<6>&, ElementMatrix<6>*);
template double enclosed_volume<6>(const SurfaceNodes<6>&, const VolumeMeasure&, ElementVector<6>*);

}  // namespace tunica
