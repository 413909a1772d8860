#include "contributions/element_type.hpp"

#include <fmt/format.h>

#include <map>
#include <stdexcept>

namespace tunica {

namespace {

std::map<ElementKind, ElementType>& registry() {
  static std::map<ElementKind, ElementType> types;
  return types;
}

}  // namespace

void BlockContribution::start_stiffness(const StartTension&, const Eigen::VectorXd&, Eigen::VectorXd&, TangentMatrix&) const {}
void BlockContribution::assemble_inverse(const Eigen::VectorXd&, double, Eigen::VectorXd&, TangentMatrix*,
                                         double&) const {
  throw std::logic_error("this element type has no inverse element (ElementType::inverse)");
}

void BlockContribution::inverse_points(const Eigen::VectorXd&, std::vector<MembranePoint>&) const {}

void BlockContribution::membrane_points(const Eigen::VectorXd&, std::vector<MembranePoint>&) const {}
void BlockContribution::solid_points(const Eigen::VectorXd&, std::vector<SolidPoint>&) const {}

void register_element_type(ElementType type) {
  const ElementKind kind = type.kind;
  if (type.nodes != nodes_per_element(kind))
    throw std::logic_error(fmt::format("element type {} declares {} nodes, the model's kind has {}", type.name,
                                       type.nodes, nodes_per_element(kind)));
  if (!registry().emplace(kind, std::move(type)).second)
    throw std::logic_error(fmt::format("element kind {} registered twice", static_cast<int>(kind)));
}

const ElementType& element_type(ElementKind kind) {
  const auto it = registry().find(kind);
  if (it == registry().end())
    throw std::logic_error(fmt::format("no element type registered for kind {}", static_cast<int>(kind)));
  return it->second;
}

std::vector<const ElementType*> element_types() {
  std::vector<const ElementType*> out;
  for (const auto& [kind, type] : registry()) out.push_back(&type);
  return out;
}

std::uint8_t vtk_cell_type(ElementKind k) {
  const std::uint8_t cell = element_type(k).vtk_cell;
  if (cell == 0) throw std::logic_error(fmt::format("element {} has no VTK cell type", element_type(k).name));
  return cell;
}

std::uint8_t vtk_revolved_cell_type(ElementKind k) {
  const std::uint8_t cell = element_type(k).vtk_revolved_cell;
  if (cell == 0) throw std::logic_error(fmt::format("element {} is not axisymmetric: no revolved cell", element_type(k).name));
  return cell;
}

}  // namespace tunica
