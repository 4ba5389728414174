#include "ancfnet/assembly/system_matrix.hpp"

#include <algorithm>
#include <cassert>

#include "ancfnet/model/model.hpp"

namespace ancfnet {
namespace {

// Index of entry (row, col) in the compressed storage of a column-major matrix.
int FindSlot(const SparseMatrixd& m, Index row, Index col) {
  const int* begin = m.innerIndexPtr() + m.outerIndexPtr()[col];
  const int* end = m.innerIndexPtr() + m.outerIndexPtr()[col + 1];
  const int* it = std::lower_bound(begin, end, static_cast<int>(row));
  assert(it != end && *it == row);
  return static_cast<int>(it - m.innerIndexPtr());
}

// The coordinates of a group of 3-blocks, in order.
std::vector<Index> GroupCoordinates(const std::vector<Index>& blocks) {
  std::vector<Index> coordinates;
  for (Index first : blocks)
    for (int k = 0; k < 3; ++k) coordinates.push_back(first + k);
  return coordinates;
}

}  // namespace

SystemMatrix::SystemMatrix(const Model& model, const DofMap& dofs)
    : dofs_(&dofs),
      num_elements_(static_cast<Index>(model.elements().size())),
      num_point_masses_(static_cast<Index>(model.point_masses().size())),
      num_links_(static_cast<Index>(model.links().size())),
      num_bodies_(static_cast<Index>(model.rigid_bodies().size())) {
  for (const CableElement& element : model.elements())
    group_blocks_.push_back({element.dofs[0], element.dofs[3], element.dofs[6], element.dofs[9]});
  for (const PointMass& point : model.point_masses()) group_blocks_.push_back({point.dof});
  for (const SpringDamperLink& link : model.links()) {
    std::vector<Index> group;
    for (const PointLocation* point : {&link.first, &link.second})
      for (int b = 0; b < point->num_blocks; ++b) group.push_back(point->dof[b]);
    group_blocks_.push_back(group);
  }
  for (const RigidBody& body : model.rigid_bodies())
    group_blocks_.push_back({body.position_dof(), body.rotation_dof()});
  for (const BodyAttachment& attachment : model.body_attachments()) {
    std::vector<Index> group(attachment.point.dof.begin(),
                             attachment.point.dof.begin() + attachment.point.num_blocks);
    const RigidBody& body = model.rigid_bodies()[attachment.body];
    group.push_back(body.position_dof());
    group.push_back(body.rotation_dof());
    group_blocks_.push_back(group);
  }
  num_model_groups_ = group_blocks_.size();
  Rebuild();
}

void SystemMatrix::Rebuild() {
  const DofMap& dofs = *dofs_;
  std::vector<Eigen::Triplet<double, int>> triplets;
  for (const auto& group : group_blocks_) {
    const std::vector<Index> coordinates = GroupCoordinates(group);
    for (Index c : coordinates)
      for (Index r : coordinates)
        if (dofs.unknown(r) >= 0 && dofs.unknown(c) >= 0)
          triplets.emplace_back(dofs.unknown(r), dofs.unknown(c), 0.0);
  }
  matrix_ = SparseMatrixd(dofs.num_unknowns(), dofs.num_unknowns());
  matrix_.setFromTriplets(triplets.begin(), triplets.end());
  matrix_.makeCompressed();

  groups_.clear();
  slot_.clear();
  for (const auto& group : group_blocks_) {
    const std::vector<Index> coordinates = GroupCoordinates(group);
    groups_.push_back({static_cast<int>(group.size()), slot_.size()});
    for (Index c : coordinates)
      for (Index r : coordinates) {
        const Index row = dofs.unknown(r);
        const Index col = dofs.unknown(c);
        slot_.push_back(row >= 0 && col >= 0 ? FindSlot(matrix_, row, col) : -1);
      }
  }
}

bool SystemMatrix::AddContactCouplings(const std::vector<std::pair<Index, Index>>& owners) {
  bool changed = false;
  for (auto [a, b] : owners) {
    if (a > b) std::swap(a, b);
    const std::uint64_t key = (static_cast<std::uint64_t>(a) << 32) | static_cast<std::uint64_t>(b);
    const int index = static_cast<int>(group_blocks_.size() - num_model_groups_);
    if (!contact_coupling_.emplace(key, index).second) continue;
    std::vector<Index> group = group_blocks_[a];
    group.insert(group.end(), group_blocks_[b].begin(), group_blocks_[b].end());
    group_blocks_.push_back(std::move(group));
    changed = true;
  }
  if (changed) Rebuild();
  return changed;
}

int SystemMatrix::FindContactCoupling(Index a, Index b) const {
  const auto it =
      contact_coupling_.find((static_cast<std::uint64_t>(a) << 32) | static_cast<std::uint64_t>(b));
  return it == contact_coupling_.end() ? -1 : it->second;
}

void SystemMatrix::AddContactBlock(int coupling, int i, int j, const Matrix3d& block,
                                   double scale) {
  AddGroupBlock(groups_[num_model_groups_ + coupling], i, j, block, scale);
}

void SystemMatrix::SetZero() {
  std::fill(matrix_.valuePtr(), matrix_.valuePtr() + matrix_.nonZeros(), 0.0);
}

void SystemMatrix::AddElementBlock(Index element, const Matrix12d& block, double scale) {
  double* values = matrix_.valuePtr();
  const int* slots = slot_.data() + groups_[element].first_slot;
  for (int j = 0; j < kCableElementDofs; ++j)
    for (int i = 0; i < kCableElementDofs; ++i)
      if (slots[12 * j + i] >= 0) values[slots[12 * j + i]] += scale * block(i, j);
}

void SystemMatrix::AddGroupBlock(const Group& group, int i, int j, const Matrix3d& block,
                                 double scale) {
  double* values = matrix_.valuePtr();
  const int stride = 3 * group.num_blocks;
  const int* slots = slot_.data() + group.first_slot + stride * 3 * j + 3 * i;
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r)
      if (slots[stride * c + r] >= 0) values[slots[stride * c + r]] += scale * block(r, c);
}

void SystemMatrix::AddPointMassBlock(Index point, const Matrix3d& block, double scale) {
  AddGroupBlock(groups_[num_elements_ + point], 0, 0, block, scale);
}

void SystemMatrix::AddLinkBlock(Index link, int i, int j, const Matrix3d& block, double scale) {
  AddGroupBlock(groups_[num_elements_ + num_point_masses_ + link], i, j, block, scale);
}

void SystemMatrix::AddBodyBlock(Index body, int i, int j, const Matrix3d& block, double scale) {
  AddGroupBlock(groups_[num_elements_ + num_point_masses_ + num_links_ + body], i, j, block, scale);
}

void SystemMatrix::AddAttachmentBlock(Index attachment, int i, int j, const Matrix3d& block,
                                      double scale) {
  AddGroupBlock(groups_[num_elements_ + num_point_masses_ + num_links_ + num_bodies_ + attachment],
                i, j, block, scale);
}

void SystemMatrix::AddBlock3(Index row, Index col, const Matrix3d& block, double scale) {
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) {
      const Index r = dofs_->unknown(row + i);
      const Index c = dofs_->unknown(col + j);
      if (r >= 0 && c >= 0) matrix_.valuePtr()[FindSlot(matrix_, r, c)] += scale * block(i, j);
    }
}

}  // namespace ancfnet
