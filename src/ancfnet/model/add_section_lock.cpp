// ModelBuilder (model/model_builder.hpp): section locks between beam nodes, the knots of beam
// threads that carry torsion and bending across (forces/section_lock.hpp).

#include <fmt/format.h>

#include <algorithm>
#include <tuple>

#include "ancfnet/common/error.hpp"
#include "ancfnet/model/builder_checks.hpp"
#include "ancfnet/model/model_builder.hpp"

namespace ancfnet {
namespace {

// max(GJ, EI_y, EI_z)/L_e of a beam element (N m/rad).
double RotationalStiffness(const BeamElementParameters& p) {
  return std::max({p.torsional_stiffness, p.bending_stiffness_y, p.bending_stiffness_z}) / p.length;
}

}  // namespace

void ModelBuilder::AddSectionLock(const std::string& name, const CablePointRef& first,
                                  const CablePointRef& second, std::optional<double> stiffness) {
  SectionLock lock{.name = name};
  double default_stiffness = 0.0;
  for (const auto& [at, node, frame] :
       {std::tuple{&first, &lock.first_node, &lock.first_frame},
        std::tuple{&second, &lock.second_node, &lock.second_frame}}) {
    const Index cable_index = model_.FindCable(at->cable);
    const Cable& cable = model_.cables_[cable_index];
    *node = model_.LocateCableNode(cable_index, at->s);
    const CableNode& n = model_.nodes_[*node];
    if (cable.element != ElementKind::kBeam || n.section_dof < 0)
      throw InputError(fmt::format(
          "section lock '{}': cable '{}' is not made of ancf_beam elements (a cable's section has "
          "no orientation to hold)",
          name, at->cable));
    const Vector3d d2 = model_.initial_positions_.segment<3>(n.section_dof);
    const Vector3d d3 = model_.initial_positions_.segment<3>(n.section_dof + 3);
    *frame << d2.cross(d3), d2, d3;
    const Index element =
        cable.first_element + std::min<Index>(*node - cable.first_node, cable.num_elements - 1);
    default_stiffness = std::max(
        default_stiffness,
        RotationalStiffness(model_.beam_elements_[model_.elements_[element].beam].parameters));
  }
  if (lock.first_node == lock.second_node)
    throw InputError(fmt::format("section lock '{}' joins a node to itself", name));
  if (stiffness) RequirePositive(*stiffness, "stiffness of a section lock");
  lock.stiffness = stiffness.value_or(kSectionLockStiffnessFactor * default_stiffness);
  model_.section_locks_.push_back(std::move(lock));
}

}  // namespace ancfnet
