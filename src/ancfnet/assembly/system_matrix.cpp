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

// The unknowns of the coordinates of a group of 3-blocks, in order (−1 for a fixed one).
void GroupUnknowns(const DofMap& dofs, const std::vector<Index>& blocks, std::vector<Index>* out) {
  out->clear();
  for (Index first : blocks)
    for (int k = 0; k < 3; ++k) out->push_back(dofs.unknown(first + k));
}

// Entries (row, col) of every free row of `rows` and free column of `cols`.
void AddPatternEntries(const std::vector<Index>& rows, const std::vector<Index>& cols,
                       std::vector<Eigen::Triplet<double, int>>* triplets) {
  for (Index col : cols)
    for (Index row : rows)
      if (row >= 0 && col >= 0) triplets->emplace_back(row, col, 0.0);
}

// The blocks of a joint: those of its first anchor, then of its second (a body's x and ψ, a
// point's blocks, none for the ground).
std::vector<Index> JointBlocks(const Model& model, const JointAnchor& first,
                               const JointAnchor& second) {
  std::vector<Index> group;
  for (const JointAnchor* anchor : {&first, &second}) {
    if (anchor->kind == JointAnchor::Kind::kBody) {
      const RigidBody& body = model.rigid_bodies()[anchor->body];
      group.push_back(body.position_dof());
      group.push_back(body.rotation_dof());
    } else if (anchor->kind == JointAnchor::Kind::kPoint) {
      group.insert(group.end(), anchor->dof.begin(), anchor->dof.begin() + anchor->num_blocks);
    }
  }
  return group;
}

// values[slots[n j + i]] += scale · block(i, j) over a whole group of n coordinates (a slot of −1:
// a fixed row or column, skipped).
template <int N>
void AddDenseBlock(const int* slots, const Eigen::Matrix<double, N, N>& block, double scale,
                   double* values) {
  for (int j = 0; j < N; ++j)
    for (int i = 0; i < N; ++i)
      if (slots[N * j + i] >= 0) values[slots[N * j + i]] += scale * block(i, j);
}

std::uint64_t PairKey(Index a, Index b) {
  return (static_cast<std::uint64_t>(a) << 32) | static_cast<std::uint64_t>(b);
}

}  // namespace

SystemMatrix::SystemMatrix(const Model& model, const DofMap& dofs)
    : dofs_(&dofs),
      num_elements_(static_cast<Index>(model.elements().size())),
      num_point_masses_(static_cast<Index>(model.point_masses().size())),
      num_links_(static_cast<Index>(model.links().size())),
      num_bodies_(static_cast<Index>(model.rigid_bodies().size())),
      num_attachments_(static_cast<Index>(model.body_attachments().size())),
      num_clearance_joints_(static_cast<Index>(model.clearance_joints().size())),
      num_ideal_joints_(static_cast<Index>(model.ideal_joints().size())),
      num_beam_elements_(static_cast<Index>(model.beam_elements().size())) {
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
  for (const ClearanceJoint& joint : model.clearance_joints())
    group_blocks_.push_back(JointBlocks(model, joint.journal, joint.bearing));
  for (const IdealJoint& joint : model.ideal_joints())
    group_blocks_.push_back(JointBlocks(model, joint.first, joint.second));
  for (const BeamElement& beam : model.beam_elements()) {
    std::vector<Index> group;
    for (int b = 0; b < kBeamElementBlocks; ++b) group.push_back(beam.dofs[3 * b]);
    group_blocks_.push_back(group);
  }
  for (const SectionLock& lock : model.section_locks()) {
    const Index first = model.nodes()[lock.first_node].section_dof;
    const Index second = model.nodes()[lock.second_node].section_dof;
    group_blocks_.push_back({first, first + 3, second, second + 3});
  }
  Rebuild();
}

void SystemMatrix::Rebuild() {
  ++num_pattern_builds_;
  const DofMap& dofs = *dofs_;
  std::vector<Index> rows, cols;
  std::vector<Eigen::Triplet<double, int>> triplets;
  for (const auto& group : group_blocks_) {
    GroupUnknowns(dofs, group, &rows);
    AddPatternEntries(rows, rows, &triplets);
  }
  // The diagonal blocks of a coupling are its owners' own groups: only those between them are new.
  for (const ContactCoupling& c : couplings_) {
    GroupUnknowns(dofs, group_blocks_[c.a], &rows);
    GroupUnknowns(dofs, group_blocks_[c.b], &cols);
    AddPatternEntries(rows, cols, &triplets);
    AddPatternEntries(cols, rows, &triplets);
  }
  matrix_ = SparseMatrixd(dofs.num_unknowns(), dofs.num_unknowns());
  matrix_.setFromTriplets(triplets.begin(), triplets.end());
  matrix_.makeCompressed();

  groups_.clear();
  slot_.clear();
  auto add_group = [&](const std::vector<Index>& unknowns) {
    groups_.push_back({static_cast<int>(unknowns.size() / 3), slot_.size()});
    for (Index col : unknowns)
      for (Index row : unknowns)
        slot_.push_back(row >= 0 && col >= 0 ? FindSlot(matrix_, row, col) : -1);
  };
  for (const auto& group : group_blocks_) {
    GroupUnknowns(dofs, group, &rows);
    add_group(rows);
  }
  for (const ContactCoupling& c : couplings_) {
    GroupUnknowns(dofs, group_blocks_[c.a], &rows);
    GroupUnknowns(dofs, group_blocks_[c.b], &cols);
    rows.insert(rows.end(), cols.begin(), cols.end());
    add_group(rows);
  }
}

bool SystemMatrix::MarkNear(Index a, Index b) {
  if (a > b) std::swap(a, b);
  const auto it = contact_coupling_.find(PairKey(a, b));
  if (it == contact_coupling_.end()) return false;
  couplings_[it->second].last_near = num_updates_;
  return true;
}

bool SystemMatrix::UpdateContactCouplings(const std::vector<std::pair<Index, Index>>& required,
                                          const std::vector<std::pair<Index, Index>>& near) {
  ++num_updates_;
  for (const auto& [a, b] : near) MarkNear(a, b);
  bool missing = false;
  for (const auto& [a, b] : required) missing = !MarkNear(a, b) || missing;
  const int keep = coupling_settings_.keep_updates;
  if (!missing) {
    if (keep < 0) return false;
    const auto stale = std::count_if(couplings_.begin(), couplings_.end(), [&](const auto& c) {
      return num_updates_ - c.last_near > keep;
    });
    if (stale == 0 || static_cast<double>(stale) <= coupling_settings_.max_stale_fraction *
                                                        static_cast<double>(couplings_.size()))
      return false;
  }
  RebuildContactCouplings(required, near);
  return true;
}

void SystemMatrix::RebuildContactCouplings(const std::vector<std::pair<Index, Index>>& required,
                                           const std::vector<std::pair<Index, Index>>& near) {
  const int keep = coupling_settings_.keep_updates;
  if (keep >= 0)
    std::erase_if(couplings_,
                  [&](const ContactCoupling& c) { return num_updates_ - c.last_near > keep; });
  IndexContactCouplings();
  for (const auto* owners : {&required, &near})
    for (auto [a, b] : *owners) {
      if (a > b) std::swap(a, b);
      if (contact_coupling_.emplace(PairKey(a, b), static_cast<int>(couplings_.size())).second)
        couplings_.push_back({a, b, num_updates_});
    }
  Rebuild();
}

void SystemMatrix::IndexContactCouplings() {
  contact_coupling_.clear();
  for (std::size_t i = 0; i < couplings_.size(); ++i)
    contact_coupling_.emplace(PairKey(couplings_[i].a, couplings_[i].b), static_cast<int>(i));
}

void SystemMatrix::SaveContactCouplings(ArchiveWriter* out) const {
  out->Write(num_updates_);
  out->WriteSequence(couplings_, [](ArchiveWriter& w, const ContactCoupling& c) {
    w.Write(static_cast<std::int64_t>(c.a));
    w.Write(static_cast<std::int64_t>(c.b));
    w.Write(c.last_near);
  });
}

void SystemMatrix::LoadContactCouplings(ArchiveReader* in) {
  num_updates_ = in->Read<long>();
  const Index num_owners = BodyOwner(num_bodies_);
  const auto read = [&](ArchiveReader& r, ContactCoupling* c) {
    c->a = static_cast<Index>(r.Read<std::int64_t>());
    c->b = static_cast<Index>(r.Read<std::int64_t>());
    c->last_near = r.Read<long>();
    if (c->a < 0 || c->a > c->b || c->b >= num_owners) r.Fail("a contact coupling of no owner");
  };
  in->ReadSequence(&couplings_, 3 * sizeof(std::int64_t), read);
  IndexContactCouplings();
  Rebuild();
}

int SystemMatrix::FindContactCoupling(Index a, Index b) const {
  const auto it = contact_coupling_.find(PairKey(a, b));
  return it == contact_coupling_.end() ? -1 : it->second;
}

void SystemMatrix::AddContactBlock(int coupling, int i, int j, const Matrix3d& block,
                                   double scale) {
  AddGroupBlock(groups_[group_blocks_.size() + coupling], i, j, block, scale);
}

void SystemMatrix::SetZero() {
  std::fill(matrix_.valuePtr(), matrix_.valuePtr() + matrix_.nonZeros(), 0.0);
}

void SystemMatrix::AddElementBlock(Index element, const Matrix12d& block, double scale) {
  AddDenseBlock(slot_.data() + groups_[element].first_slot, block, scale, matrix_.valuePtr());
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

void SystemMatrix::AddClearanceJointBlock(Index joint, int i, int j, const Matrix3d& block,
                                          double scale) {
  AddGroupBlock(groups_[num_elements_ + num_point_masses_ + num_links_ + num_bodies_ +
                        num_attachments_ + joint],
                i, j, block, scale);
}

void SystemMatrix::AddIdealJointBlock(Index joint, int i, int j, const Matrix3d& block,
                                      double scale) {
  AddGroupBlock(groups_[num_elements_ + num_point_masses_ + num_links_ + num_bodies_ +
                        num_attachments_ + num_clearance_joints_ + joint],
                i, j, block, scale);
}

void SystemMatrix::AddBeamElementBlock(Index beam, const Matrix24d& block, double scale) {
  const Group& group =
      groups_[num_elements_ + num_point_masses_ + num_links_ + num_bodies_ + num_attachments_ +
              num_clearance_joints_ + num_ideal_joints_ + beam];
  AddDenseBlock(slot_.data() + group.first_slot, block, scale, matrix_.valuePtr());
}

void SystemMatrix::AddSectionLockBlock(Index lock, const Matrix12d& block, double scale) {
  const Group& group =
      groups_[num_elements_ + num_point_masses_ + num_links_ + num_bodies_ + num_attachments_ +
              num_clearance_joints_ + num_ideal_joints_ + num_beam_elements_ + lock];
  AddDenseBlock(slot_.data() + group.first_slot, block, scale, matrix_.valuePtr());
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
