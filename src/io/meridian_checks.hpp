#pragma once
// A generated meridian (an axisymmetric part's `mesh: {type: line|arc}`) that cannot be meant: an
// arc that turns more than once, or a node at r < 0. Where an angle written without a unit (read in
// radians) explains it, the error stands at that angle's key with the fix that makes the meridian
// valid: the angle where the arc meets the axis when the value is close to it (`1.571` for π/2),
// else the number in degrees if that stays at r ≥ 0.
#include "io/deck_node.hpp"
#include "mesh/meridian.hpp"
#include "params/units.hpp"

namespace tunica {

/// A bare angle this close to one where an arc meets the axis (in radians) is taken as meant to end
/// there: 1.571 for π/2.
constexpr double kNearAxisAngle = 0.01;

/// Refuses a generated meridian that turns more than once (an arc of more than 360°: its nodes
/// overlap) or reaches r < 0, at a bare angle's key if one explains it.
void check_meridian(const DeckNode& mesh, const MeridianType& type, const Params& mp, const Meridian& points,
                    const UnitSystem& units);

}  // namespace tunica
