#pragma once
// What a failed increment's message suggests (the likely fix), from the Newton result and the
// step's converged increments so far.
#include <string>
#include <vector>

#include "assembly/system.hpp"
#include "solver/contact_chatter.hpp"
#include "solver/newton.hpp"
#include "solver/step_trace.hpp"

namespace tunica {

/// Empty, or one hint (a sentence or more naming the deck key that would help), chosen from the
/// evidence so that a failure gets one coherent explanation:
///  - a singular tangent (NewtonResult::singular) of a model with a body that nothing holds
///    against rigid motion in this step (model/rigid_motion_check.hpp): that body and its hold;
///  - the step raises a pressure without volume control and the pressure–volume curve of that
///    load flattened over the step's converged increments (dp/dV of the last below a fifth of
///    the first's, or negative): if the pressure the failed increment tried lies at or beyond
///    the maximum that the curve's trend predicts (theory manual (7.9); the maximum passed when
///    dp/dV has changed sign), a maximum near the last converged state (a limit point) or an
///    asymptote, which pressure control cannot pass: `volume_control` follows the curve through
///    it; beyond it a material that stiffens (all but neo-Hookean) may snap through to a larger
///    volume where the pressure rises again, so the load is to be lowered below the maximum only
///    if the target is meant to lie below it (a neo-Hookean membrane has no such state: lower the
///    load) — whatever Newton's residual did, since no state near the last one exists to converge
///    to (raising `max_iterations` would not help, and is said so when Newton was still converging);
///  - else a singular tangent of a held model: no stiffness left against the load, likely a load
///    beyond what the structure carries (the loads tried and their targets; smaller increments,
///    `volume_control`; bodies held by contact alone), unless the curve says the pressure still
///    rises there (next);
///  - else Newton was still converging at `max_iterations` (last relative residual below 1e-3,
///    and the absolute residual ‖R‖ falling over the last two iterations and below 1e-3 of the
///    forces that cancel in it): raise `max_iterations`;
///  - else a curve that flattened short of its predicted maximum: the pressure still rises there,
///    and the failure is likely a local one, which volume control need not pass;
///  - else, when no increment of the first step converged (from the stress-free reference): a
///    little pressure with a stretch, a pressure step before volume control, more increments or
///    iterations; or, where the step asks for the plain start, the default stiffened one.
/// Before all but the unit hint: a step under volume control whose target lies below the load's
/// stress-free volume `reference_volume[load]` (deflating the membrane below its rest volume
/// compresses it): the key, the target and that volume.
/// `converged`: the step's start and its converged increments' states (also those before a
/// restart); `attempted`: the loads of the failed increment; `reference_volume`: per load, its
/// enclosed volume at the stress-free reference state (empty: not known).
std::string failure_hints(const Model& model, const Step& step, const NewtonResult& last, const StepTrace& converged,
                          const LoadState& attempted, const std::vector<double>& reference_volume = {});

/// A membrane part counts as compressed for compression_hint where this share of its reference
/// area or more is (elements/membrane_compression.hpp).
constexpr double kCompressedShareForHint = 1e-3;

/// Empty, or a hint for a failure with no other evidence whose last converged state `u` (of step
/// `step_index`, 0-based) has a membrane part in compression over kCompressedShareForHint of its
/// area or more: where (the most compressed point), how strong against the largest tension, and
/// that a compressed membrane, which the model lets carry compression without wrinkling, is near
/// a bifurcation whose neighbouring states Newton cannot follow (theory manual (7.13)). Under volume
/// control, also whether the pressure passed a maximum over the step's converged increments
/// (dp/dV turned negative: a localizing bulge) and the state reached (the last converged volume
/// and pressure), which more increments do not pass.
std::string compression_hint(const System& system, const Eigen::VectorXd& u, const Step& step, int step_index,
                             const StepTrace& converged);

/// The hint of an increment whose every attempt, down to the smallest allowed, converged to a
/// state that load `load`'s surface reaches only by passing through itself (the enclosed volume
/// changed sign, solver/analysis.hpp): a boundary value of step `step_index` (0-based) that moves
/// nodes past the model's far side or across the axis (model/boundary_motion_check.hpp); else, for
/// a step that changes no pressure (`converged`: its start and converged increments), its boundary
/// motion; else smaller increments, or volume control, which keeps the volume's sign.
std::string eversion_hint(const Model& model, int load, const Step& step, int step_index, const StepTrace& converged);

/// The slave nodes of a deformable contact pair that are active at u, next to each other on the
/// slave chain, lie this many master segments apart on average (or more): the slave is the
/// coarser mesh in contact.
constexpr double kCoarseSlaveSpacing = 1.5;

/// Empty, or a hint per deformable contact pair of step `step` (0-based) whose neighbouring
/// active slave nodes lie on average at least kCoarseSlaveSpacing master segments apart at u (the
/// distance along the master as segment index + ξ of their feet; pairs with fewer than 3 active
/// nodes in a row are skipped): node-to-surface contact then loads the master at points only, and
/// the master's nodes between them are held by nothing but the master's own stiffness (theory
/// manual §9.1, one pass). It names the remedies: a finer slave mesh, or the reverse pass.
std::string contact_resolution_hints(const System& system, const Eigen::VectorXd& u, int step);

/// A membrane master whose largest tension is below this fraction of its slave's carries almost no
/// tension (a stress-free artery before its prestretch).
constexpr double kSlackMasterTension = 1e-3;

/// Empty, or one hint for an attempt that failed with contact in play (`last`: the failed attempt,
/// `u`: the last converged state, `step` 0-based):
///  - the residual became non-finite in a volume-controlled step with active contact nodes: the
///    bordered correction (theory manual (7.5)) is taken whole, with no line search (7.4) to halve a
///    correction that drives slave nodes deep into the surface; more `increments`, a smaller
///    `penalty`, or pressure control up to the contact;
///  - else the active set changed at kContactChatterIterations or more of its iterations
///    (NewtonResult::active_set_changes): names each deformable pair of the step, and where its master
///    membrane carries almost no tension at u (largest σ₁h below kSlackMasterTension of the
///    slave's), that it has no stiffness against the motion of its nodes across its surface, which
///    the penalty forces (theory manual (9.3), (9.5)) push in and out: give it its tension first (an
///    artery's axial prestretch), `passes: 2`, a finer slave, a smaller `penalty`.
std::string contact_convergence_hint(const System& system, const Eigen::VectorXd& u, const Step& step, int step_index,
                                     const NewtonResult& last);

}  // namespace tunica
