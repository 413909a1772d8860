#include "solver/failure_hints.hpp"
#include "solver/contact_chatter.hpp"

#include "model/boundary_motion_check.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "assembly/pressure_load_checks.hpp"
#include "elements/membrane_compression.hpp"
#include "materials/membrane_material.hpp"
#include "model/boundary_motion_check.hpp"
#include "model/meridian_curvature.hpp"
#include "model/rigid_motion_check.hpp"
#include "model/surface_curvature.hpp"

namespace tunica {

namespace {

/// The bodies that nothing holds against rigid motion in step `step` (0-based; a body counts once
/// one of its parts has entered), as the deck's warnings name them; empty if none.
std::string free_body_hint(const Model& model, int step, bool singular = true) {
  std::string out;
  for (const UnheldBody& b : unheld_rigid_motions(model)) {
    bool active = false;
    for (int p : b.parts) active = active || model.part_active(p, step);
    if (active) out += (out.empty() ? "" : "; ") + b.message;
  }
  if (out.empty()) return out;
  return singular ? "the tangent is singular because a body is free to move rigidly (as `tunica check` warns): " + out + "."
                  : "a body is free to move rigidly (as `tunica check` warns), so the tangent is singular or nearly so "
                    "and Newton's corrections wander along the free motion whatever the iteration limit: " +
                        out + ".";
}

/// A singular tangent of a model held against rigid motion, at a state Newton reached: no
/// stiffness left against the load. Names the loads the step raises, what the failed increment
/// tried and the step's target, the remedies, and the bodies held only by contact.
std::string held_singular_hint(const Model& model, const Step& step, const StepTrace& converged,
                               const LoadState& attempted) {
  const auto kpa = [&](double p) { return model.units.from_internal(p, "kPa", Dimension::pressure); };
  const auto mmhg = [&](double p) { return model.units.from_internal(p, "mmHg", Dimension::pressure); };
  std::string tried, control;
  for (std::size_t l = 0; l < model.loads.size() && l < attempted.pressure.size(); ++l) {
    const auto target = step.targets.find(model.loads[l].name);
    if (target == step.targets.end()) continue;
    tried += fmt::format(" Load '{}' tried {:.4g} kPa = {:.4g} mmHg (the step's target: {:.4g} kPa = {:.4g} mmHg).",
                         model.loads[l].name, kpa(attempted.pressure[l]), mmhg(attempted.pressure[l]),
                         kpa(target->second), mmhg(target->second));
    if (control.empty())
      control = fmt::format(", and to pass a pressure maximum control the volume (`volume_control: {{load: {}, volume: "
                            "<enclosed volume>}}`, user guide §3.1)",
                            model.loads[l].name);
  }
  if (converged.count() == 1) tried += " No increment of this step converged, down to the smallest allowed.";
  // Bodies that only contact holds: once out of contact nothing holds them.
  std::string contact;
  const std::vector<UnheldBody> free = unheld_rigid_motions(model);
  for (const UnheldBody& b : unheld_rigid_motions(model, false)) {
    bool listed = false;
    for (const UnheldBody& f : free) listed = listed || f.parts == b.parts;
    if (!listed) contact += " Held by contact only: " + b.message + ", once it is out of contact.";
  }
  return fmt::format(
      "the model is held against rigid-body motion (`tunica check` finds no body free to move), so a singular "
      "tangent at a state Newton reached means that no stiffness is left against the load: likely a load beyond "
      "what the structure carries, with no equilibrium state at it (a limit point).{} Check the value and unit of "
      "the load against the pressure the structure can carry; to follow the structure up to its limit take smaller "
      "increments (`increments`){}.{}",
      tried, control, contact);
}

/// A load at least this many times the pressure scale of its part's wall is named as the likely cause.
constexpr double kLoadScaleFactor = 100;

/// A load the step raises far beyond the pressure scale 2 μ₀ H |H_m| of its part's wall (μ₀H/R for a
/// tube, 2μ₀H/R for a sphere; μ₀ the material's shear modulus at rest, H the thickness, |H_m| the
/// median of the elements' mean curvature): a value or a unit mistyped. "" if none.
std::string load_scale_hint(const Model& model, const Step& step) {
  for (const PressureLoad& load : model.loads) {
    const auto target = step.targets.find(load.name);
    if (target == step.targets.end() || load.part < 0 || load.part >= static_cast<int>(model.parts.size())) continue;
    const Part& part = model.parts[static_cast<std::size_t>(load.part)];
    if (!part.material || !(part.thickness > 0)) continue;
    const MembraneResponse rest = membrane_response(*part.material, Eigen::Vector3d(1, 1, 0));
    const double mu0 = (rest.D(0, 0) + rest.D(1, 1)) / 8;
    if (!(mu0 > 0) || !std::isfinite(mu0)) continue;
    std::vector<double> curvature;
    const auto blocks = model.dofs_per_node() == 3 ? element_mean_curvature(model, part)
                                                   : meridian_mean_curvature(model, part);
    for (const auto& block : blocks)
      for (double h : block)
        if (std::isfinite(h)) curvature.push_back(std::abs(h));
    if (curvature.empty()) continue;
    std::nth_element(curvature.begin(), curvature.begin() + curvature.size() / 2, curvature.end());
    const double hm = curvature[curvature.size() / 2];
    const double scale = 2 * mu0 * part.thickness * hm, p = std::abs(target->second);
    if (!(hm > 0) || !(p > kLoadScaleFactor * scale)) continue;
    const auto kpa = [&](double x) { return model.units.from_internal(x, "kPa", Dimension::pressure); };
    const std::string len = model.units.display_unit(Dimension::length);
    return fmt::format(
        "load '{}' is raised to {:.4g} kPa ({:.4g} mmHg), {:.3g} times the pressure scale of part '{}', 2μ₀H|H_m| = "
        "{:.4g} kPa (μ₀ = {:.4g} kPa, its material's shear modulus at rest; H = {:.4g} {}, its thickness; |H_m| = "
        "{:.4g}/{}, the median mean curvature of its elements, 1/R on a sphere and 1/(2R) on a tube, so that the "
        "scale is 2μ₀H/R and μ₀H/R): a wall of this material carries such a pressure only at an extreme stretch, if "
        "at all. Check the value and its unit (1 kPa = 7.5 mmHg, 1 MPa "
        "= 1000 kPa); more iterations or smaller increments will not carry it.",
        load.name, kpa(p), model.units.from_internal(p, "mmHg", Dimension::pressure), p / scale, part.name, kpa(scale),
        kpa(mu0), model.units.from_internal(part.thickness, len, Dimension::length), len,
        1 / model.units.from_internal(1 / hm, len, Dimension::length), len);
  }
  return "";
}

/// A boundary value at least this many times the model's size is named as the likely cause.
constexpr double kDisplacementScaleFactor = 3;

/// A displacement the step prescribes beyond kDisplacementScaleFactor times the diagonal of the
/// model's bounding box (a stretch of 1 + that at least, where tissue and balloons reach 2–3):
/// a value or a unit mistyped; else one that moves nodes past the model's far side or across the
/// axis (model/boundary_motion_check.hpp). "" if none.
/// The 0-based index of `step` in model.steps, or -1 for a step that is not one of them (as a
/// unit test's own step is not).
int index_in_model(const Model& model, const Step& step) {
  for (std::size_t i = 0; i < model.steps.size(); ++i)
    if (&model.steps[i] == &step) return static_cast<int>(i);
  return -1;
}

std::string displacement_scale_hint(const Model& model, const Step& step) {
  if (model.X.empty()) return "";
  Eigen::Vector3d lo = model.X.front(), hi = lo;
  for (const Eigen::Vector3d& x : model.X) lo = lo.cwiseMin(x), hi = hi.cwiseMax(x);
  const bool axisymmetric = model.dofs_per_node() != 3;
  if (axisymmetric) lo(0) = std::min(lo(0), 0.0);  // the meridian turns about the axis
  const double size = (hi - lo).norm();
  if (!(size > 0)) return "";
  const std::string len = model.units.display_unit(Dimension::length);
  const auto in_len = [&](double x) { return model.units.from_internal(x, len, Dimension::length); };
  for (const Boundary& b : model.boundaries) {
    const auto target = step.targets.find(b.name);
    if (target == step.targets.end()) continue;
    const bool translation =
        std::any_of(b.dofs.begin(), b.dofs.end(), [&](int d) { return d < (axisymmetric ? 2 : 3); });
    const double d = std::abs(target->second);
    if (!translation || !(d > kDisplacementScaleFactor * size)) continue;
    return fmt::format(
        "boundary '{}' is moved by {:.4g} {}, {:.3g} times the size of the whole model (the diagonal of its bounding "
        "box, {:.4g} {}): a stretch of at least {:.3g} somewhere, where arteries and balloons reach 2 to 3. Check the value "
        "and its unit (the deck's length unit is {}); more iterations or smaller increments will not carry it.",
        b.name, in_len(d), len, d / size, in_len(size), len, 1 + d / size, len);
  }
  // A value that moves nodes past the model's far side or across the axis.
  const int index = index_in_model(model, step);
  return index >= 0 ? boundary_motion_hint(model, index) : "";
}

}  // namespace

std::string failure_hints(const Model& model, const Step& step, const NewtonResult& last, const StepTrace& converged,
                          const LoadState& attempted, const std::vector<double>& reference_volume) {
  std::string hints;
  const auto add = [&](const std::string& h) { hints += " Hint: " + h; };
  // An inverse step that stops: the imaged mesh may be no deformed state of the discrete
  // membrane (theory manual §13, user guide §3.5), whatever Newton's residual did.
  if (step.inverse)
    return " Hint: an inverse step finds a reference only for an imaged mesh that the discrete membrane can carry "
           "(close to a deformed state of it: the deformed mesh of a forward run, a uniform tube). A mesh laid on an "
           "ideal or segmented surface asks for tensions set by its discrete curvature, which node positions off by "
           "O(h²) change by O(1): it stalls, earlier the finer it is. Use a coarser or smoothed imaged mesh, or "
           "`method: fixed_point`, which finds the reference whose forward solution comes nearest the imaged mesh, or "
           "check the pressure against what the imaged shape carries (user guide §3.5).";
  // The residual test held and the energy test stalled: the iterate is in equilibrium to the
  // residual tolerance, and |Δu·R| sits at the round-off floor this model reaches (7.2).
  if (last.energy_stall > 0) {
    const double floor = std::pow(10.0, std::ceil(std::log10(last.energy_stall)) + 1);
    return fmt::format(
        " Hint: the residual criterion held and the energy criterion stalled at {:.3g}, the round-off floor of "
        "|Δu·R| for this model (stiff penalty contact and parts of very different stiffness raise it; theory manual "
        "(7.2)); more iterations do not lower it. `energy_tolerance: {:g}` in `solver` (now {:g}) accepts such an "
        "iterate, whose equilibrium the residual criterion already checks.",
        last.energy_stall, floor, step.solver.energy_tolerance);
  }
  // A load the step raises that was written without a unit (the reader warned): a bare `150` is
  // 150 N/mm² in mm and N, a million mmHg, beyond what any membrane carries; this comes first.
  for (const auto& [load, written] : step.unitless_loads) {
    const auto target = step.targets.find(load);
    if (target == step.targets.end()) continue;
    const auto kpa = model.units.from_internal(target->second, "kPa", Dimension::pressure);
    const auto mmhg = model.units.from_internal(target->second, "mmHg", Dimension::pressure);
    return fmt::format(
        " Hint: load '{}' is set to `{}` without a unit ({}), which is read in the deck's pressure unit, {}: {:.4g} kPa "
        "= {:.4g} mmHg. If mmHg or kPa was meant, write it (`{} mmHg`); raising `max_iterations` or cutting the "
        "increments finer will not carry such a load.",
        load, written.second, written.first, model.units.display_unit(Dimension::pressure), kpa, mmhg, written.second);
  }
  // A volume target below the stress-free volume: along the path p = dW/dV (theory manual (7.13))
  // with W least at the reference, so the pressure turns negative and the membrane is compressed.
  if (const int l = step.volume_control.load; l >= 0 && l < static_cast<int>(reference_volume.size()) &&
                                              reference_volume[l] > 0 &&
                                              step.volume_control.target < reference_volume[l] * (1 - 1e-9)) {
    const std::string unit = model.units.display_unit(Dimension::volume);
    const auto vol = [&](double v) { return model.units.from_internal(v, unit, Dimension::volume); };
    return fmt::format(
        " Hint: the step's `volume_control.volume`, {:.6g} {}, is below the stress-free volume of load '{}', {:.6g} {} "
        "(its enclosed volume at the reference state): deflating a membrane below its rest volume needs a negative "
        "pressure and compresses it, and a compressed membrane wrinkles or buckles, which Tunica does not model "
        "(user guide §5, compression), so Newton finds no path. To inflate, give a volume above {:.6g} {}.",
        vol(step.volume_control.target), unit, model.loads[l].name, vol(reference_volume[l]), unit,
        vol(reference_volume[l]), unit);
  }
  // A step that stretches a 3-D membrane with no pressure on it, before or during: a closed wall then
  // carries no hoop tension and nothing resists ovalizing (neutral stability, user guide §3.1); Newton
  // wanders along those modes, the more the finer the mesh. A little pressure keeps the wall round.
  const bool slack = model.dofs_per_node() == 3 && !model.loads.empty() && step.volume_control.load < 0 &&
                     converged.count() > 0 &&
                     std::all_of(attempted.pressure.begin(), attempted.pressure.end(), [](double p) { return p == 0; }) &&
                     std::all_of(converged.last(0).pressure.begin(), converged.last(0).pressure.end(),
                                 [](double p) { return p == 0; });
  bool linear_triangles = false;  // a part meshed with 3-node triangles: 6-node ones are a way out
  for (const Part& part : model.parts)
    for (const ElementBlock& b : part.blocks) linear_triangles = linear_triangles || b.kind == ElementKind::tri3;
  // A step that shortens the wall: compression, which a membrane does not carry (it wrinkles).
  const std::string shortening =
      slack && index_in_model(model, step) >= 0 ? shortening_motions(model, index_in_model(model, step)) : std::string();
  if (slack && !shortening.empty())
    add(fmt::format(
        "step '{}' shortens the wall with no pressure on it ({}): a membrane carries no compression, it wrinkles or "
        "buckles (user guide §5, compression), and Newton finds no path through such a state. Apply a pressure "
        "together with the shortening (e.g. `{}: 10 mmHg` in this step's `set`), whose tension takes up the "
        "compression as long as it exceeds it (the run notes any compression left, `compressed_fraction`), or "
        "shorten it less; no iteration limit or increment size gets the step past without it.",
        step.name, shortening, model.loads.front().name));
  else if (slack)
    add(fmt::format(
        "step '{}' moves the membrane with no pressure on it: a closed or curved 3-D membrane without pressure carries "
        "no tension across the stretch and has no stiffness against ovalizing (neutral stability, user guide §3.1), so "
        "Newton wanders along those modes, the more the finer the mesh. Apply a little pressure together with the "
        "stretch (e.g. `{}: 10 mmHg` in this step's `set`), which keeps the wall round; the step after it raises the "
        "pressure to its value. {}",
        step.name, model.loads.front().name,
        linear_triangles
            ? "On an unstructured mesh of 3-node triangles the faceted wall is not round without pressure and its hoop "
              "stress scatters about zero: no iteration limit or increment size gets such a step past, only the "
              "pressure (or 6-node triangles, `Mesh.ElementOrder = 2`)."
            : "On a mesh whose wall is not round without pressure (a bulge, a segmented vessel) no iteration limit or "
              "increment size gets such a step past, only the pressure."));
  // Still converging: the relative residual small, and the absolute one falling and small against
  // the forces that cancel in it. A relative residual is no evidence alone: measured against an
  // R₀ blown up by a wild first correction it is tiny while ‖R‖ is not.
  const bool still_converging = last.energy_stall == 0 && last.failure.rfind("no convergence in", 0) == 0 &&
                                last.last_relative_residual < 1e-3 &&
                                last.residual_falling && last.last_residual <= 1e-3 * last.last_force_scale;
  const std::string more_iterations =
      fmt::format("Newton was still converging when it reached the iteration limit (relative residual {:.1e}): "
                  "raise `max_iterations` in `solver` (now {}).",
                  last.last_relative_residual, step.solver.max_iterations);
  // One hint for one failure: a pressure at a maximum of p(V) (or an asymptote) has no state near
  // the last one to converge to however many iterations are allowed, so that hint replaces raising
  // the limit;
  // a curve that flattened but still rises leaves the slow convergence as the evidence.
  std::string limit, rising;
  // A pressure the step raises, under pressure control, whose p–V curve flattens: theory manual §7.1.
  const auto kpa = [&](double p) { return model.units.from_internal(p, "kPa", Dimension::pressure); };
  const auto mmhg = [&](double p) { return model.units.from_internal(p, "mmHg", Dimension::pressure); };
  if (step.volume_control.load < 0 && converged.count() >= 3) {
    for (std::size_t l = 0; l < model.loads.size(); ++l) {
      const auto target = step.targets.find(model.loads[l].name);
      const LoadState& a = converged.first(0);
      if (target == step.targets.end() || std::abs(target->second) <= std::abs(a.pressure[l])) continue;
      const auto slope = [&](const LoadState& x, const LoadState& y) {
        const double dV = y.volume[l] - x.volume[l];
        return dV != 0 ? (y.pressure[l] - x.pressure[l]) / dV : 0.0;
      };
      const LoadState& end = converged.last(0);
      const double first = slope(converged.first(0), converged.first(1));
      const double now = slope(converged.last(1), end);
      if (first == 0 || now / first >= 0.2) continue;
      // Where the curve's trend puts its maximum (7.9): dp/dV linear in V through the slopes of
      // the last two increments, p* = p + ∫ dp/dV dV up to its zero. None in sight (±∞) while
      // dp/dV does not fall; reached when dp/dV has changed sign or its zero lies behind.
      const double sense = target->second > a.pressure[l] ? 1.0 : -1.0;  // the pressure rises or falls
      double peak = sense * std::numeric_limits<double>::infinity();
      if (now / first <= 0) {
        peak = end.pressure[l];
      } else if (converged.count() >= 4) {
        const double before = slope(converged.last(2), converged.last(1));
        const double v_now = 0.5 * (converged.last(1).volume[l] + end.volume[l]);
        const double v_before = 0.5 * (converged.last(2).volume[l] + converged.last(1).volume[l]);
        const double bend = v_now != v_before ? (now - before) / (v_now - v_before) : 0.0;  // d²p/dV²
        if (bend * now < 0 && std::abs(now - before) > 1e-9 * std::abs(before)) {  // falling beyond round-off
          const double v_peak = v_now - now / bend;
          const double ahead = v_peak - end.volume[l];  // the volume still to go, along the way V moves
          const double moving = end.volume[l] - converged.last(1).volume[l];
          peak = ahead * moving <= 0 ? end.pressure[l]
                                     : end.pressure[l] + 0.5 * (now + bend * (end.volume[l] - v_now)) * ahead;
        }
      }
      const double tried = attempted.pressure.size() > l ? attempted.pressure[l] : end.pressure[l];
      const bool beyond = sense * tried >= sense * peak;
      if (beyond) {
        // dp/dV changed sign: a maximum passed; still positive: a maximum or an asymptote ahead.
        // What lies beyond a maximum depends on the material: one that stiffens at large stretch
        // carries the pressure again far along the curve (a snap-through), a neo-Hookean one does
        // not (its pressure falls beyond the maximum or approaches an asymptote).
        const int part = model.loads[l].part;
        const MembraneMaterial* material =
            part >= 0 && part < static_cast<int>(model.parts.size()) ? model.parts[part].material : nullptr;
        const auto target_kpa = kpa(target->second);
        std::string beyond_max;
        // A slave of a contact pair can snap through onto its surface, which then carries the rest.
        std::string touching;
        for (const ContactPair& pair : model.contacts)
          if (!pair.is_reverse_pass() && pair.part == part && touching.empty())
            touching = fmt::format("contact pair '{}'", pair.name);
        if (!touching.empty())
          beyond_max = fmt::format(
              "Beyond the maximum part '{}' may snap through onto the surface of {}, which then carries the rest: "
              "the {:.4g} kPa the failed increment tried and the step's target, {:.4g} kPa, may be carried there, "
              "which pressure control cannot reach from here",
              model.parts[part].name, touching, kpa(tried), target_kpa);
        else if (material && material->type() == "neo_hookean")
          beyond_max = fmt::format(
              "Its material (neo_hookean) does not stiffen: beyond the maximum the pressure falls (a balloon) or "
              "approaches an asymptote (a tube at fixed length), so likely no state carries the {:.4g} kPa the failed "
              "increment tried. Lower the load below about {:.4g} kPa",
              kpa(tried), kpa(end.pressure[l]));
        else
          beyond_max = fmt::format(
              "Beyond a maximum the structure may snap through to a larger volume where the pressure rises again, "
              "if its material stiffens at large stretch ({}Mooney–Rivlin, Ogden, Fung and HGO can): the {:.4g} kPa "
              "the failed increment tried and the step's target, {:.4g} kPa, may then be carried far along the "
              "curve, which pressure control cannot reach from here. Lower the load below about {:.4g} kPa only if "
              "the target is meant to lie below the maximum",
              material ? fmt::format("part '{}' is {}; ", model.parts[part].name, material->type()) : "", kpa(tried),
              target_kpa, kpa(end.pressure[l]));
        limit += fmt::format(
            " Hint: the pressure–volume curve of load '{}' has flattened over this step (dp/dV down to {:.0f} % of its "
            "value at the step's start, at {:.4g} kPa = {:.4g} mmHg): the pressure is likely at {}: pressure control "
            "cannot pass it{}. {}. To follow the curve through a maximum, "
            "control the enclosed volume instead: a step with `volume_control: {{load: {}, volume: <enclosed "
            "volume>}}` passes a maximum and approaches an asymptote from below (user guide §3.1, volume control).",
            model.loads[l].name, 100 * now / first, kpa(end.pressure[l]), mmhg(end.pressure[l]),
            now / first <= 0
                ? "a maximum of the curve near the last converged state (a limit point, already passed: dp/dV has "
                  "turned negative)"
                : "a maximum of the curve near the last converged state (a limit point), or at an asymptote that it "
                  "approaches",
            still_converging ? " (raising `max_iterations` would not help)" : "", beyond_max, model.loads[l].name);
      } else {
        const std::string trend =
            std::isfinite(peak) ? fmt::format("its trend puts a maximum near {:.4g} kPa, above the {:.4g} kPa the failed "
                                              "increment tried", kpa(peak), kpa(tried))
                                : "its trend shows no maximum";
        // Where to look: the last ParaView frame shows the state the run stopped at, if frames are written.
        const std::string look =
            model.output.vtk ? "look at newton.csv (active_changes) and the last frame where the residual sits, e.g. at "
                               "contact"
                             : "look at newton.csv (active_changes) and history.csv for where the residual sits, e.g. "
                               "at contact (no ParaView frames were written, `output.vtk` is false: set it to true to "
                               "see the last converged state)";
        rising += fmt::format(
            " Hint: the pressure–volume curve of load '{}' has flattened over this step (dp/dV down to {:.0f} % of "
            "its value at the step's start, at {:.4g} kPa = {:.4g} mmHg) but the pressure still rises: {}. The "
            "failure is likely not a limit point of the pressure but a local one, which `volume_control` need not "
            "pass: {} (user guide §6).",
            model.loads[l].name, 100 * now / first, kpa(end.pressure[l]), mmhg(end.pressure[l]), trend, look);
      }
    }
  }
  if (last.singular) {
    // Free to move rigidly: the cause whatever the curve says. Held: a load with no equilibrium,
    // unless the curve says the pressure still rises there.
    if (const std::string free = free_body_hint(model, attempted.step); !free.empty()) return " Hint: " + free;
    if (std::string h = displacement_scale_hint(model, step); !h.empty()) return " Hint: " + h;
    if (!limit.empty()) return limit;
    if (!rising.empty()) return rising;
    add(held_singular_hint(model, step, converged, attempted));
    return hints;
  }
  if (!limit.empty()) return limit;
  // No limit point on the way, and a load far beyond what the wall carries: a value or unit mistyped.
  // A body free to move rigidly fails this way too when the tangent is regular only by round-off.
  if (const std::string free = free_body_hint(model, attempted.step, false); !free.empty()) return " Hint: " + free;
  if (std::string h = load_scale_hint(model, step); !h.empty()) return " Hint: " + h;
  if (std::string h = displacement_scale_hint(model, step); !h.empty()) return " Hint: " + h;
  if (still_converging && !slack) add(more_iterations);
  else hints += rising;
  // No other evidence, and no increment converged from the stress-free reference (the first step):
  // an unstressed membrane resists motion out of its surface only through its curvature.
  // A load the step raises that pushes its surface inward from the start (the run warned): the
  // likely cause, before any advice on the stress-free start.
  if (hints.empty() && !model.steps.empty() && &step == &model.steps.front() && converged.count() == 1) {
    const LoadState& start = converged.first(0);
    for (std::size_t l = 0; l < model.loads.size() && l < start.volume.size(); ++l) {
      const PressureLoad& load = model.loads[l];
      if (!(start.volume[l] < 0) || !step.targets.count(load.name) || load.part < 0 ||
          load.part >= static_cast<int>(model.parts.size()))
        continue;
      add(fmt::format("load '{}' pushes its surface (part '{}') inward: its enclosed volume at the reference state is "
                      "negative, because {}, as the warning at the start said. A pressure inside a vessel or balloon "
                      "pushes outward: {}.",
                      load.name, model.parts[load.part].name, inward_load_cause(load), inward_load_fix(model, load)));
      return hints;
    }
  }
  if (hints.empty() && !model.steps.empty() && &step == &model.steps.front() && converged.count() == 1)
    add(step.solver.stiffen_stress_free_start
            ? "no increment converged from the stress-free reference state, where an unstressed membrane resists "
              "motion out of its surface only through its curvature. Apply a little pressure together with a "
              "stretch in the first step (e.g. 10 mmHg in its `set`), or a small pressure step before a "
              "volume-controlled one; take more `increments` in this step; and look at newton.csv: if the "
              "residual was still falling at the last iteration, raise `max_iterations` in `solver`."
            : "no increment converged from the stress-free reference state with the plain first correction the "
              "step asks for (`stress_free_start: exact` in its `solver`): leave it out, and the default "
              "`stiffened` start resists the uneven normal motion an unstressed membrane does not (theory manual "
              "§7.2).");
  return hints;
}

std::string compression_hint(const System& system, const Eigen::VectorXd& u, const Step& step, int step_index,
                             const StepTrace& converged) {
  const Model& m = system.model();
  const auto kpa = [&](double p) { return m.units.from_internal(p, "kPa", Dimension::pressure); };
  const auto mmhg = [&](double p) { return m.units.from_internal(p, "mmHg", Dimension::pressure); };
  const std::string len = m.units.display_unit(Dimension::length);
  const auto mm = [&](double x) { return m.units.from_internal(x, len, Dimension::length); };
  std::string parts;
  for (std::size_t p = 0; p < m.parts.size(); ++p) {
    const Part& part = m.parts[p];
    if (part.is_solid() || part.is_shell() || !m.part_active(static_cast<int>(p), step_index)) continue;
    const std::vector<MembranePoint> points = system.points(u, static_cast<int>(p), step_index);
    const double f = compressed_fraction(points);
    if (f < kCompressedShareForHint) continue;
    const CompressionSize size = compression_size(points);
    const MembranePoint* worst = nullptr;
    for (const MembranePoint& q : points)
      if (!worst || q.sigma_principal(1) < worst->sigma_principal(1)) worst = &q;
    parts += fmt::format(
        "{}part '{}' is in compression over {:.3g} % of its area, its smaller principal stress down to {:.4g} kPa "
        "({}), most at the point ({:.4g}, {:.4g}, {:.4g}) {} of the reference",
        parts.empty() ? "" : "; ", part.name, 100 * f, kpa(size.compression),
        size.tension > 0 ? fmt::format("{:.3g} % of the largest tension, {:.4g} kPa",
                                       -100 * size.compression / size.tension, kpa(size.tension))
                         : std::string("no point is in tension"),
        mm(worst->X(0)), mm(worst->X(1)), mm(worst->X(2)), len);
  }
  if (parts.empty()) return "";
  // Under volume control: did the pressure pass a maximum over the step (dp/dV < 0 at its end)?
  std::string path;
  if (const int l = step.volume_control.load; l >= 0 && converged.count() >= 3) {
    const std::string vunit = m.units.display_unit(Dimension::volume);
    const auto vol = [&](double v) { return m.units.from_internal(v, vunit, Dimension::volume); };
    const LoadState& end = converged.last(0);
    const LoadState* peak = &end;  // the highest of the kept states (StepTrace)
    for (const LoadState& k : converged.kept())
      if (k.pressure[l] > peak->pressure[l]) peak = &k;
    if (peak != &end)
      path = fmt::format(
          " The pressure of load '{}' has passed a maximum: it fell from {:.4g} kPa = {:.4g} mmHg at {:.6g} {} to "
          "{:.4g} kPa = {:.4g} mmHg at the last converged volume, {:.6g} {}: beyond a maximum an inflated wall "
          "tends to bulge locally, one region growing as another shrinks at the same volume (a bifurcation, which "
          "volume control does not remove).",
          m.loads[l].name, kpa(peak->pressure[l]), mmhg(peak->pressure[l]), vol(peak->volume[l]), vunit,
          kpa(end.pressure[l]), mmhg(end.pressure[l]), vol(end.volume[l]), vunit);
    else
      path = fmt::format(" The last converged state: {:.6g} {} at {:.4g} kPa = {:.4g} mmHg.", vol(end.volume[l]),
                         vunit, kpa(end.pressure[l]), mmhg(end.pressure[l]));
  }
  return fmt::format(
      " Hint: at the last converged state {}. A real membrane cannot carry compression, it wrinkles; Tunica does not "
      "model wrinkling (user guide §5, compression), and its membrane, which carries the compression instead, has "
      "next to no stiffness against the out-of-plane modes of a compressed region: the tangent is near singular "
      "there (a bifurcation), and Newton finds no path from that state.{} Smaller increments (`increments`, "
      "`max_cutbacks`) reach closer to it but not past it: take the results up to the last converged increment, or "
      "end the step short of it (a smaller target), and look at the ParaView field `compressed` and the history "
      "quantity `compressed_fraction` for where the wall is compressed (often next to a clamped end, or where the "
      "wall's curvature changes sign).",
      parts, path);
}

std::string eversion_hint(const Model& model, int load, const Step& step, int step_index, const StepTrace& converged) {
  const std::string& name = model.loads[load].name;
  // A boundary value that moves nodes past the model's far side or across the axis turns the
  // surface inside out whatever the increments: that value, first.
  if (const std::string motion = boundary_motion_hint(model, step_index); !motion.empty())
    return " Hint: " + motion;
  // A step that leaves every pressure where it was: its boundary motion everted the surface.
  const auto target = step.targets.find(name);
  const bool pressure_moves =
      step.volume_control.load >= 0 ||
      (target != step.targets.end() &&
       (converged.count() == 0 ||
        std::abs(std::abs(target->second) - std::abs(converged.first(0).pressure[static_cast<std::size_t>(load)])) >
            1e-12 * std::abs(target->second)));
  if (!pressure_moves) {
    std::string moved;
    for (const Boundary& b : model.boundaries)
      if (const auto t = step.targets.find(b.name); t != step.targets.end())
        moved += fmt::format("{}'{}'", moved.empty() ? "" : ", ", b.name);
    return fmt::format(
        " Hint: step '{}' changes no pressure, so its boundary motion ({}) turned the surface of load '{}' inside out "
        "(its enclosed volume of the other sign), which no real membrane reaches: check each value, its sign and its "
        "unit (a boundary value is the displacement from the reference, user guide §3.1), and that the motion "
        "compresses the wall no more than it can take: a membrane carries no compression, it wrinkles (user guide "
        "§5, compression).",
        step.name, moved.empty() ? std::string("none set in this step") : moved, name);
  }
  return fmt::format(
      " Hint: Newton found equilibrium only with the surface of load '{}' turned inside out (its enclosed volume of "
      "the other sign), which no real membrane reaches: the increment starts too far from the state it should end "
      "at, most likely at or near a maximum of the pressure (a limit point), beyond which the pressure's next "
      "equilibrium lies far along the curve. Take smaller increments (a larger `increments` in the step, or "
      "`max_cutbacks` in `solver`), or control the enclosed volume instead, which keeps its sign and follows the "
      "curve through a maximum: a step with `volume_control: {{load: {}, volume: <enclosed volume>}}` (user guide "
      "§3.1, volume control).",
      name, name);
}

std::string contact_resolution_hints(const System& system, const Eigen::VectorXd& u, int step) {
  std::string hints;
  const Model& m = system.model();
  for (std::size_t c = 0; c < m.contacts.size(); ++c) {
    const ContactPair& pair = m.contacts[c];
    if (!pair.deformable() || pair.reverse >= 0 || pair.is_reverse_pass()) continue;  // two-pass: both sides push
    const std::vector<ContactNodeState> states = system.contact_states(u, static_cast<int>(c), step);
    double span = 0;
    int gaps = 0, active = 0;
    for (std::size_t k = 0; k < states.size(); ++k) {
      if (!states[k].point.active || states[k].master_segment < 0) continue;
      ++active;
      if (k + 1 < states.size() && states[k + 1].point.active && states[k + 1].master_segment >= 0) {
        span += std::abs((states[k + 1].master_segment + states[k + 1].point.xi) -
                         (states[k].master_segment + states[k].point.xi));
        ++gaps;
      }
    }
    if (gaps < 2 || span / gaps < kCoarseSlaveSpacing) continue;
    hints += fmt::format(
        " Hint: in contact pair '{}' the {} active slave nodes lie on average {:.1f} master segments apart (the "
        "slave is the coarser mesh where they touch): each slave node pushes the master at one point, and the "
        "master's nodes between them are held by nothing but its own stiffness, which can leave Newton without a "
        "basin at any increment size. Refine the slave's mesh, or give the pair `passes: 2`, so that the "
        "nodes of '{}' push back on the slave too (two-pass contact, theory manual §9.1).",
        pair.name, active, span / gaps, pair.master_name);
  }
  return hints;
}

}  // namespace tunica

namespace tunica {

namespace {

/// The largest in-plane tension σ₁h of a membrane part at u (force per length), or −1 for a part
/// without membrane points (a solid).
double largest_tension(const System& system, const Eigen::VectorXd& u, int part, int step) {
  const std::vector<MembranePoint> points = system.points(u, part, step);
  if (points.empty()) return -1;
  double t = 0;
  for (const MembranePoint& q : points) t = std::max(t, q.sigma_principal(0) * q.thickness);
  return t;
}

}  // namespace

std::string contact_convergence_hint(const System& system, const Eigen::VectorXd& u, const Step& step, int step_index,
                                     const NewtonResult& last) {
  const Model& m = system.model();
  const std::vector<int> pairs = contact_pairs_in_play(m, step_index);
  if (pairs.empty()) return "";
  std::string names;
  for (std::size_t k = 0; k < pairs.size(); ++k)
    names += fmt::format("{}'{}'", k == 0 ? "" : k + 1 == pairs.size() ? " and " : ", ", m.contacts[pairs[k]].name);
  // Contact near at the last converged state: some slave node within its chain's mean element
  // length of its surface. A failed attempt that found nodes in contact from far away diverged
  // first; its contact is a symptom.
  bool near = false;
  for (int c : pairs) near = near || contact_near(system, u, c, step_index);
  if (!near) return "";
  const bool contact_in_play = last.active_contacts > 0 || last.active_set_changes > 0;
  std::string slack;
  for (int c : pairs) {
    const ContactPair& pair = m.contacts[c];
    if (!pair.deformable()) continue;
    const int master = part_of_chain(m, pair.master);
    if (master < 0 || pair.part < 0) continue;
    const double tm = largest_tension(system, u, master, step_index);
    const double ts = largest_tension(system, u, pair.part, step_index);
    if (tm < 0 || !(ts > 0) || tm > kSlackMasterTension * ts) continue;
    const std::string fu = m.units.display_unit(Dimension::force), lu = m.units.display_unit(Dimension::length);
    const std::string unit = fu + "/" + lu;
    const auto tension = [&](double v) {
      return m.units.from_internal(v, fu, Dimension::force) / m.units.from_internal(1.0, lu, Dimension::length);
    };
    slack += fmt::format(
        " The master of pair '{}', part '{}', carries almost no tension at the last converged state (its largest "
        "tension {:.3g} {} against {:.3g} {} in the slave '{}'): a membrane without tension has no stiffness against "
        "its nodes moving across its surface, and the slave nodes' penalty forces push them in and out at every "
        "iteration. Give '{}' the tension it has in the body before this step (an artery's axial prestretch, as the "
        "`prestretch` step of examples/balloon-angioplasty.yaml).",
        pair.name, m.parts[master].name, tension(tm), unit, tension(ts), unit, m.parts[pair.part].name,
        m.parts[master].name);
  }
  // Volume control takes the bordered correction (7.5) whole: no line search (7.4) halves one that
  // drives slave nodes deep into the surface, whose penalty forces (9.3) then overflow the residual.
  if (step.volume_control.load >= 0 && contact_in_play &&
      (last.failure == "the residual is not finite" || last.failure == "diverging"))
    return fmt::format(
        " Hint: under volume control each correction is taken whole (no line search halves it, theory manual (7.5)), "
        "and with contact pair(s) {} active ({} slave node(s) at the last iterate, the active set changed at {} of its "
        "{} iterations) a correction drove slave nodes deep into their surface, where the penalty forces grew without "
        "bound.{} A smaller `penalty` makes the contact softer, at the price of a deeper "
        "penetration (p_c/ε, user guide §3.2, choosing ε); more `increments` in this step push the contact less far "
        "in each volume step.",
        names, last.active_contacts, last.active_set_changes, last.iterations, slack);
  // Chattering, or contact on a master without tension (whose nodes a full correction moves in
  // and out of contact even when the line search keeps the active set).
  if (last.active_set_changes < kContactChatterIterations && (slack.empty() || last.active_contacts == 0)) return "";
  bool deformable = false;
  for (int c : pairs) deformable = deformable || m.contacts[c].deformable();
  // A slave inflated under pressure control: a compliant balloon past its own pressure maximum
  // spreads along the surface it presses on at about the same pressure, a path on which the
  // pressure does not rise and which pressure control cannot follow (theory manual (7.9)).
  std::string inflated;
  if (step.volume_control.load < 0)
    for (int c : pairs)
      for (const PressureLoad& l : m.loads)
        if (inflated.empty() && l.part >= 0 && l.part == m.contacts[c].part && step.targets.count(l.name))
          inflated = fmt::format(
              " The slave '{}' is inflated by '{}' under pressure control: a compliant balloon past its own pressure "
              "maximum (where it is free it would bulge without bound) spreads along the surface it presses on at "
              "about the same pressure, which pressure control cannot follow; `volume_control: {{load: {}, volume: "
              "<the volume to reach>}}` on this step follows it (user guide §3.1, volume control).",
              m.parts[l.part].name, l.name, l.name);
  // A pair without smoothing: the C¹ blend (9.2) of about 10⁻³ of its slave's element length.
  std::string smoothing;
  for (int c : pairs) {
    const ContactPair& pair = m.contacts[c];
    if (pair.law.smoothing > 0 || pair.area_chain.size() < 2) continue;
    const std::string lu = m.units.display_unit(Dimension::length);
    smoothing = fmt::format(
        "`smoothing: {:.2g} {}` on pair '{}' (10⁻³ of its slave's mean element length) makes the contact pressure C¹ "
        "across the touch, so that nodes at the edge of the contact zone, where the pressure is about zero, stop "
        "entering and leaving (theory manual (9.2)). ",
        m.units.from_internal(auto_smoothing_width(m, c), lu, Dimension::length), lu, pair.name);
    break;
  }
  return fmt::format(
      " Hint: the failed attempt had slave nodes in contact ({} at its last iterate, pair(s) {}), and the contact "
      "active set changed at {} of its {} iterations: Newton did not settle which slave nodes touch, and cutting "
      "the increment back did not help.{}{} {}{}A smaller `penalty` makes the contact softer, at the price of a "
      "deeper penetration (p_c/ε, user guide §3.2, choosing ε).",
      last.active_contacts, names, last.active_set_changes, last.iterations, inflated, slack, smoothing,
      deformable ? "A finer slave mesh spreads the contact over more nodes (theory manual §9.1). " : "");
}

}  // namespace tunica
