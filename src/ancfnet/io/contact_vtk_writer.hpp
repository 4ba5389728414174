#pragma once
/// @file ContactVtkWriter: the active contact points of each output frame as a series of VTK
/// PolyData files for ParaView, beside the cables' series.

#include <filesystem>
#include <string>
#include <vector>

#include "ancfnet/contact/contact_point.hpp"
#include "ancfnet/io/vtk_collection.hpp"

namespace ancfnet {

/// Writes one VTK XML PolyData file (ASCII) per frame, `DIR/BASE_NNNNNN.vtp`, with one vertex per
/// active contact at its point on the target's surface (ContactPoint::point_W), and keeps
/// `DIR/BASE.pvd` (VtkCollection). A frame without contact has no points. Point data:
///  - `normal_force` F_n (N), scalar;
///  - `force` f = F_n n + f_t (N), the total force on the probe (the target feels −f), 3
///  components;
///  - `normal` n, from the target towards the probe, 3 components;
///  - `penetration` δ (m).
class ContactVtkWriter {
 public:
  /// Creates `directory` when missing; throws InputError when it cannot.
  ContactVtkWriter(const std::filesystem::path& directory, const std::string& base_name);

  /// Writes the next frame, at `time` (s), and rewrites the collection. Throws SolverError (at
  /// `time`), writing nothing, when a value is NaN or infinite; InputError when a file cannot be
  /// written.
  void WriteFrame(double time, const std::vector<ContactPoint>& contacts);

  int num_frames() const { return collection_.num_frames(); }
  std::filesystem::path collection_path() const { return collection_.collection_path(); }
  /// The series' frames and collection (VtkCollection::Resume continues a series).
  VtkCollection& collection() { return collection_; }
  std::filesystem::path FramePath(int index) const { return collection_.FramePath(index); }

 private:
  VtkCollection collection_;
};

}  // namespace ancfnet
