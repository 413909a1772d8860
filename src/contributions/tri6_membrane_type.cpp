// The 6-node quadratic triangle membrane (elements/tri6_shape.hpp, theory manual (5.7)): the
// generic surface membrane kernel (contributions/surface_membrane_kernel.hpp) on the 6-node
// shape, written to ParaView as VTK_QUADRATIC_TRIANGLE (same node order as Gmsh's type 9).
#include "contributions/surface_membrane_kernel.hpp"
#include "elements/tri6_shape.hpp"

namespace tunica {

namespace {

const bool registered = [] {
  register_element_type(surface_membrane_type<6>(ElementKind::tri6, "6-node triangle membrane", 22));  // VTK_QUADRATIC_TRIANGLE
  return true;
}();

}  // namespace

}  // namespace tunica
