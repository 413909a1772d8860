#pragma once
// Naming what exists when a deck names something that does not: the list of the
// names there are, and for a likely typo the nearest of them ("did you mean").
#include <string>
#include <string_view>
#include <vector>

namespace tunica {

/// The name in `known` nearest to `name` by edit distance (a swap of two neighbouring letters
/// counts as one edit), if it is near enough to be a typo: at most 1 edit for names of up to
/// 5 characters, 2 for longer ones, and fewer edits than the name has characters; a name
/// differing only in letter case always is. Names that share a prefix up to a dot (the node sets
/// of one part, `wall.x0` and `wall.y0`) are compared by the rest, with the rule of
/// nearest_file_name's stems: `wall.y0` is not offered for `wall.x0`. A name without a dot that no
/// typo matches is offered the one known name that ends in it after a dot (`wall.start` for
/// `start`), if only one does. "" if none is.
std::string nearest_name(std::string_view name, const std::vector<std::string>& known);

/// The file name in `files` that `name` (a file name without folder) is likely a typo of, or ""
/// if none is really close. Names are compared without letter case. First those with the
/// same extension, by their stems (the name without the extension): at most one edit for a
/// stem of 3 to 6 characters, two from 7 on, none below 3 (about one edit in four
/// characters), and the same digits in the same order (`tube_1mm` and `tube_2mm` are two
/// meshes, not a typo). Then one whose stem is the same with another extension (`wall.msh` for
/// `wall.geo`). The caller passes only the files that could be meant (e.g. meshes).
std::string nearest_file_name(std::string_view name, const std::vector<std::string>& files);

/// "(the <what> are: a, b, c; did you mean 'b'?)" for an undefined `name`: at most
/// `max_listed` names, then how many there are in all; "(there are no <what>)" for none.
/// Names are quoted through printable().
std::string known_names(std::string_view name, const std::vector<std::string>& known, std::string_view what,
                        std::size_t max_listed = 30);

/// "; did you mean 'b'?" when nearest_name finds one, else "".
std::string did_you_mean(std::string_view name, const std::vector<std::string>& known);

}  // namespace tunica
