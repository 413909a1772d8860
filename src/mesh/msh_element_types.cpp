#include "mesh/msh_file.hpp"

namespace tunica {

MshElementType msh_element_type(int type) {
  switch (type) {
    case 1: return {1, 2, "2-node line"};
    case 2: return {2, 3, "3-node triangle"};
    case 3: return {2, 4, "4-node quadrangle"};
    case 4: return {3, 4, "4-node tetrahedron"};
    case 5: return {3, 8, "8-node hexahedron"};
    case 6: return {3, 6, "6-node prism"};
    case 7: return {3, 5, "5-node pyramid"};
    case 8: return {1, 3, "3-node second-order line"};
    case 9: return {2, 6, "6-node second-order triangle"};
    case 10: return {2, 9, "9-node second-order quadrangle"};
    case 11: return {3, 10, "10-node second-order tetrahedron"};
    case 12: return {3, 27, "27-node second-order hexahedron"};
    case 13: return {3, 18, "18-node second-order prism"};
    case 14: return {3, 14, "14-node second-order pyramid"};
    case 15: return {0, 1, "1-node point"};
    case 16: return {2, 8, "8-node second-order quadrangle"};
    case 17: return {3, 20, "20-node second-order hexahedron"};
    case 18: return {3, 15, "15-node second-order prism"};
    case 19: return {3, 13, "13-node second-order pyramid"};
    case 20: return {2, 9, "9-node third-order incomplete triangle"};
    case 21: return {2, 10, "10-node third-order triangle"};
    case 22: return {2, 12, "12-node fourth-order incomplete triangle"};
    case 23: return {2, 15, "15-node fourth-order triangle"};
    case 24: return {2, 15, "15-node fifth-order incomplete triangle"};
    case 25: return {2, 21, "21-node fifth-order triangle"};
    case 26: return {1, 4, "4-node third-order line"};
    case 27: return {1, 5, "5-node fourth-order line"};
    case 28: return {1, 6, "6-node fifth-order line"};
    case 29: return {3, 20, "20-node third-order tetrahedron"};
    case 30: return {3, 35, "35-node fourth-order tetrahedron"};
    case 31: return {3, 56, "56-node fifth-order tetrahedron"};
    case 36: return {2, 16, "16-node third-order quadrangle"};
    case 37: return {2, 25, "25-node fourth-order quadrangle"};
    case 92: return {3, 64, "64-node third-order hexahedron"};
    case 93: return {3, 125, "125-node fourth-order hexahedron"};
    default: return {};
  }
}

}  // namespace tunica
