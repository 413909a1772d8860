#pragma once
// A material built through the registry from deck text, as a user's deck would build it.
#include <memory>
#include <string>

#include "io/read_params.hpp"
#include "materials/membrane_material.hpp"
#include "materials/solid_material.hpp"

namespace tunica::test {

inline std::unique_ptr<MembraneMaterial> material_from_yaml(const std::string& yaml) {
  const YAML::Node node = YAML::Load(yaml);
  const auto& type = material_types().at(node["type"].as<std::string>());
  return type.make(read_params(DeckNode(node, "test", "materials.m"), type.spec, UnitSystem("mm", "N"), {"type"}));
}

inline std::unique_ptr<SolidMaterial> solid_from_yaml(const std::string& yaml) {
  const YAML::Node node = YAML::Load(yaml);
  const auto& type = solid_material_types().at(node["type"].as<std::string>());
  return type.make(read_params(DeckNode(node, "test", "solid_materials.m"), type.spec, UnitSystem("mm", "N"), {"type"}));
}

}  // namespace tunica::test
