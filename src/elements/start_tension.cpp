// Explicit instantiations of the normal-tension stiffness (start_tension.hpp; theory manual (7.7))
// for the 3-node triangle and the 4-node quadrilateral; the definition is in start_tension_impl.hpp.
#include "elements/start_tension_impl.hpp"

namespace tunica {

template void normal_tension_stiffness<3>(const MembraneReference<3>&, double, ElementMatrix<3>&);
template void normal_tension_stiffness<4>(const MembraneReference<4>&, double, ElementMatrix<4>&);

}  // namespace tunica
