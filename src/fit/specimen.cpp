#include "fit/specimen.hpp"

#include <filesystem>

namespace tunica {

const ComponentSpec& specimen_spec() {
  static const ComponentSpec s{
      "specimen",
      "",
      "The tested tube: load-free geometry and loading convention. Bare lengths are in mm; any value may "
      "carry a unit (`1.648 mm`).",
      {positive(number("outer_diameter", Dimension::length, "load-free outer diameter D (R = (D − H)/2)")),
       positive(number("radius", Dimension::length, "load-free mid-surface radius R (instead of outer_diameter)")),
       required(positive(number("thickness", Dimension::length, "load-free wall thickness H"))),
       with_default(one_of(text("ends",
                                "`open`: force F = N (no end caps, as the FE model); `closed`: "
                                "F = N − π r² p (pressure on end caps)"),
                           {"open", "closed"}),
                    "open"),
       positive(number("axial_stretch", Dimension::dimensionless,
                       "axial stretch λz of every point, when the data have no stretch column"))}};
  return s;
}

Specimen read_specimen(const DeckNode& node) {
  if (!node.is_map()) node.fail("expected a specimen map {outer_diameter or radius, thickness, ends, axial_stretch}");
  const Params p = read_params(node, specimen_spec(), UnitSystem("mm", "N"));
  Specimen s;
  s.where = node.where();
  s.geometry.H = p.number("thickness");
  if (p.has("outer_diameter") == p.has("radius"))
    p.fail("radius",
           "give exactly one of `outer_diameter` (load-free outer diameter D) and `radius` "
           "(load-free mid-surface radius R)");
  if (p.has("radius")) {
    s.geometry.R = p.number("radius");
  } else {
    s.geometry.R = 0.5 * (p.number("outer_diameter") - s.geometry.H);  // R = (D − H)/2
    if (!(s.geometry.R > 0)) p.fail("outer_diameter", "the outer diameter must exceed the wall thickness");
  }
  s.geometry.ends = p.text("ends") == "closed" ? TubeEnds::closed : TubeEnds::open;
  if (p.has("axial_stretch")) s.axial_stretch = p.number("axial_stretch");
  return s;
}

DeckNode specimen_node_from_argument(const std::string& argument) {
  const bool is_file = std::filesystem::is_regular_file(argument);
  const std::string file = is_file ? argument : std::string("--specimen");
  try {
    const YAML::Node n = is_file ? YAML::LoadFile(argument) : YAML::Load(argument);
    return DeckNode(n, file, "specimen", {file, 1, 1, "specimen"});
  } catch (const YAML::Exception& e) {
    throw InputError(
        {file, e.mark.is_null() ? 0 : e.mark.line + 1, e.mark.is_null() ? 0 : e.mark.column + 1, "specimen"},
        "YAML syntax error: " + e.msg + (is_file ? "" : " (not a file either)"));
  }
}

}  // namespace tunica
