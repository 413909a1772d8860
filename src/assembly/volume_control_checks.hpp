#pragma once
// Volume control of a load whose pressure pushes its surface inward. The controlled volume is the
// one on the side the pressure pushes away from (theory manual (6.6)–(6.7), §7.1), and its target is
// positive; a load whose reference volume is negative (normals into the volume, or `flip: true` on
// normals that point out) can only reach it through zero: the run turns the surface inside out,
// passing the membrane through itself, and ends at an everted state without an error. Such a step
// is refused before the run, at its `volume_control.volume`.
#include <string>
#include <vector>

#include "assembly/system.hpp"

namespace tunica {

/// Throws InputError at the `volume_control.volume` of the first step that controls the volume of
/// a load whose enclosed volume at the reference state is negative (below −10⁻⁹ of the cube of its
/// part's size: round-off of a flat surface is not), naming the step, the load, both volumes in the
/// deck's unit and the fix (`flip`, or the mesh's orientation).
void check_volume_control_sides(const System& system);

/// One warning per step that controls the volume of a load towards a target below the load's
/// enclosed volume at the stress-free reference state, V₀ (theory manual (6.6)–(6.7)), at its
/// `volume_control.volume`: the stored energy W(V) is least at V₀, so along the path the pressure
/// p = dW/dV (theory manual (7.13)) is negative below V₀, a suction that a membrane held at its
/// reference boundary carries only in compression (it wrinkles or buckles, which the membrane
/// model does not follow). Names the step, the load, the target and V₀ in the deck's unit.
std::vector<std::string> volume_control_warnings(const System& system);

}  // namespace tunica
