#pragma once
// The constants a user coming from Abaqus or FEBio writes for a Tunica material (C10, C01, E, ν,
// D1): what they are here, for the unknown-key error.
#include <string>

namespace tunica {

/// "" if `key` is no known foreign spelling for material `type`, else a sentence that relates it to
/// the type's own constants (Abaqus' C10 is b1 of `mooney_rivlin`, E/3 is μ of an incompressible
/// neo-Hookean material, ν and D1 have no counterpart: the membranes are exactly incompressible).
std::string foreign_constant_hint(const std::string& type, const std::string& key);

}  // namespace tunica
