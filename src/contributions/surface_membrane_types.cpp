// The 3-node triangle and 4-node quadrilateral membranes (contributions/surface_membrane_kernel.hpp).
#include "contributions/surface_membrane_kernel.hpp"

namespace tunica {

namespace {

const bool registered = [] {
  register_element_type(surface_membrane_type<3>(ElementKind::tri3, "triangle membrane (3 nodes)", 5));  // VTK_TRIANGLE
  register_element_type(surface_membrane_type<4>(ElementKind::quad4, "quadrilateral membrane (4 nodes)", 9));  // VTK_QUAD
  return true;
}();

}  // namespace

}  // namespace tunica
