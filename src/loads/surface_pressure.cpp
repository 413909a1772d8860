// Explicit instantiations of the follower pressure and enclosed volume (surface_pressure.hpp;
// theory manual (6.4)–(6.6)) for the 3-node triangle and the 4-node quadrilateral; the
// definitions are in surface_pressure_impl.hpp.
#include "loads/surface_pressure_impl.hpp"

namespace tunica {

template void surface_pressure<3>(const SurfaceNodes<3>&, double, ElementVector<3>&, ElementMatrix<3>*);
template double subtract_surface_pressure<3>(const SurfaceNodes<3>&, double, ElementVector<3>&, ElementMatrix<3>*);
template void surface_pressure<4>(const SurfaceNodes<4>&, double, ElementVector<4>&, ElementMatrix<4>*);
template double subtract_surface_pressure<4>(const SurfaceNodes<4>&, double, ElementVector<4>&, ElementMatrix<4>*);
template double enclosed_volume<3>(const SurfaceNodes<3>&, const VolumeMeasure&, ElementVector<3>*);
template double enclosed_volume<4>(const SurfaceNodes<4>&, const VolumeMeasure&, ElementVector<4>*);

}  // namespace tunica
