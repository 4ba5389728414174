#pragma once
/// @file VtkSeriesWriter: the deformed cables as a series of VTK PolyData files for ParaView.

#include <filesystem>
#include <string>
#include <vector>

#include "ancfnet/io/vtk_collection.hpp"
#include "ancfnet/model/model.hpp"
#include "ancfnet/state/state.hpp"

namespace ancfnet {

/// Writes one VTK XML PolyData file (ASCII) per frame, `DIR/BASE_NNNNNN.vtp` (frames numbered
/// from 0), and keeps `DIR/BASE.pvd`, a VTK Collection listing every frame with its time, valid
/// after each frame (it is rewritten through a temporary file and a rename).
///
/// Each cable is one polyline along the deformed ANCF centre line r(ξ) = S(ξ) e, sampled at
/// `points_per_element` equal steps of ξ per element; the node shared by two elements appears
/// once, so a cable of n elements has n · points_per_element + 1 points. Point data:
///  - `velocity` ṙ(ξ) = S(ξ) ė (m/s), 3 components;
///  - `axial_strain` ε = (r'·r' − 1)/2 and `curvature` κ (1/m), from CalcCableStrain at the point
///    (ε there is the interpolation's: in a stiff element it oscillates about the true strain);
///  - `tension` T (N), the elastic section force along the tangent recovered from the elements'
///    resultant forces (CalcCableStationForces, CalcCableElementTension; docs/theory.md, "Tension
///    recovery"), never below 0 in a tension-only cable; along a beam cable the section's normal
///    force N (docs/theory.md, "Tension of a beam"). Kelvin–Voigt damping is not included.
///  - `section_d2`, `section_d3`: the cross-section directors d₂ = r_y(ξ), d₃ = r_z(ξ) of a beam
///    cable, linear in ξ (elements/beam_shape.hpp), for glyphs of its section frame; zero for
///    cables and bodies.
/// After the cables, each rigid body adds its frame: 4 points (its origin x_WB and the tips of its
/// body axes, drawn as long as its radius of gyration √(tr J_B / m)) and 3 two-point lines, with
/// their velocities and zero strain, curvature and tension.
class VtkSeriesWriter {
 public:
  /// Creates `directory` when missing. `base_name` names the files; `points_per_element` ≥ 1.
  /// Throws InputError when the directory cannot be created or points_per_element < 1.
  VtkSeriesWriter(const std::filesystem::path& directory, const std::string& base_name,
                  int points_per_element);

  /// Writes the next frame of `state` (time state.t) and rewrites the collection. Throws
  /// SolverError (at state.t), writing nothing, when a sampled value is NaN or infinite; throws
  /// InputError "cannot write FILE" when a file cannot be written.
  void WriteFrame(const Model& model, const State& state);

  /// Number of frames written so far.
  int num_frames() const { return collection_.num_frames(); }
  /// The .pvd collection file.
  std::filesystem::path collection_path() const { return collection_.collection_path(); }
  /// The series' frames and collection (VtkCollection::Resume continues a series).
  VtkCollection& collection() { return collection_; }
  /// The .vtp file of frame `index` (written or not).
  std::filesystem::path FramePath(int index) const { return collection_.FramePath(index); }

 private:
  // Values at one sample point of the centre line.
  struct Sample {
    Vector3d position;
    Vector3d velocity;
    double axial_strain;
    double curvature;
    double tension;
    Vector3d d2 = Vector3d::Zero();
    Vector3d d3 = Vector3d::Zero();
  };
  void CollectSamples(const Model& model, const State& state);
  // Throws SolverError at `time` for the first non-finite value in samples_.
  void CheckSamplesFinite(double time) const;
  std::string FormatPolyData(const Model& model) const;

  int points_per_element_;
  VtkCollection collection_;
  std::vector<Sample> samples_;  // all cables, cable after cable, then the bodies' frames
  std::size_t num_cable_samples_ = 0;
};

}  // namespace ancfnet
