#pragma once
// Notes on a converged increment whose state is far from the one before it or from any a membrane
// reaches, though Newton converged to it: said once, so that such a state is not taken for a
// result without a word.
//  - Under pressure control, an increment across a maximum of the pressure lands on a far branch
//    of the pressure–volume curve (a snap-through: a stiffening material carries the pressure
//    again at a much larger volume), skipping the states between (theory manual §7.1); near an
//    asymptote (a neo-Hookean tube at fixed length) the volume grows as steeply without a jump:
//    the note names both.
//  - A stretch far beyond what arteries and balloons reach, or a wall crushed to a fraction of
//    its area: loads or boundary values (or their units) off.
#include <string>
#include <vector>

#include "assembly/system.hpp"
#include "elements/membrane_point.hpp"
#include "model/model.hpp"
#include "solver/step_trace.hpp"

namespace tunica {

/// An increment's compliance ΔV/Δp at least this many times the increment's before it, with
/// the volume growing at least kVolumeJumpRatio-fold in it, is a jump onto a far branch.
constexpr double kComplianceJump = 5;
constexpr double kVolumeJumpRatio = 1.5;

/// Empty, or the note for load `load` whose last converged increment of step `step` (0-based;
/// `trace`: the step's converged states, the last one just converged; at least 3 of them) jumped:
/// under pressure control, V_k / V_{k−1} ≥ kVolumeJumpRatio and ΔV_k/Δp_k ≥ kComplianceJump ×
/// ΔV_{k−1}/Δp_{k−1} (both Δp of one sign). `when`: "at step 1 'blow', increment 8".
std::string volume_jump_note(const Model& m, int load, int step, const StepTrace& trace, const std::string& when);

/// A principal in-plane stretch beyond this, or a thickness stretch beyond it (the area shrunk to
/// less than its inverse), is no state of an artery (2 to 3) or a balloon (rarely 6).
constexpr double kExtremeStretch = 8;

/// Empty, or the note for membrane part `part` at `points` (its Gauss points at the converged
/// state) whose largest in-plane stretch (λ1, λ2 along the material directions) or thickness
/// stretch λ3 exceeds kExtremeStretch: the stretch, where it is, and the likely causes.
std::string extreme_stretch_note(const Model& m, int part, const std::vector<MembranePoint>& points,
                                 const std::string& when);

}  // namespace tunica
