#pragma once
// A converged state whose contact penetration is far beyond what the penalty should leave. The
// penalty lets a slave node sink by about p_c/ε (theory manual (9.4)), which the user guide (§3.2,
// choosing ε) asks to keep small against the element length; a penetration of a good part of an
// element means a penalty far too small for the contact pressure, or a slave pressed the wrong way
// through the surface. The run says so once per pair (output/run_writer.cpp); it does not stop.
#include <string>

#include "assembly/system.hpp"

namespace tunica {

/// A penetration ⟨−g_N⟩ beyond this fraction of the slave node's reference element length is far
/// beyond the penalty's scale (a good ε leaves 10⁻³ … 10⁻⁴ of it).
constexpr double kFarPenetration = 0.1;

/// Empty, or the warning for contact pair `c` (not a reverse pass) at u in step `step` (0-based)
/// when some slave node has penetrated beyond kFarPenetration of its element length: at the pair's
/// place in the deck, naming `when` (the increment), the node, the penetration and the element
/// length in the deck's length unit, the contact pressure, and the fixes (a penalty that would
/// leave 10⁻³ of the element length, or the surface's side / the master's orientation).
std::string far_penetration_warning(const System& system, const Eigen::VectorXd& u, int step, int c,
                                    const std::string& when);

}  // namespace tunica
