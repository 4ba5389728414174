#include "ancfnet/io/vtk_writer.hpp"

#include <fmt/format.h>

#include <cmath>
#include <iterator>

#include "ancfnet/analysis/cable_tension.hpp"
#include "ancfnet/common/error.hpp"
#include "ancfnet/elements/ancf_cable.hpp"
#include "ancfnet/elements/hermite_shape.hpp"
#include "ancfnet/model/rigid_body_kinematics.hpp"
#include "ancfnet/state/rigid_body_state.hpp"

namespace ancfnet {
namespace {

int CheckedPointsPerElement(int points_per_element) {
  if (points_per_element < 1)
    throw InputError(
        fmt::format("VTK points per element must be at least 1 (got {})", points_per_element));
  return points_per_element;
}

}  // namespace

VtkSeriesWriter::VtkSeriesWriter(const std::filesystem::path& directory,
                                 const std::string& base_name, int points_per_element)
    : points_per_element_(CheckedPointsPerElement(points_per_element)),
      collection_(directory, base_name) {}

void VtkSeriesWriter::WriteFrame(const Model& model, const State& state) {
  CollectSamples(model, state);
  CheckSamplesFinite(state.t);
  collection_.AddFrame(state.t, FormatPolyData(model));
}

void VtkSeriesWriter::CollectSamples(const Model& model, const State& state) {
  samples_.clear();
  for (const Cable& cable : model.cables()) {
    for (Index k = 0; k < cable.num_elements; ++k) {
      const CableElement& element = model.elements()[cable.first_element + k];
      const CableElementParameters& p = element.parameters;
      const Vector12d e = model.Gather(element, state.q);
      const Vector12d e_dot = model.Gather(element, state.v);
      const CableStationForces forces = CalcCableStationForces(model, cable, k, state.q);
      // The last element also draws its end node; the others leave it to the next element.
      const int last = k + 1 == cable.num_elements ? points_per_element_ : points_per_element_ - 1;
      for (int i = 0; i <= last; ++i) {
        const double xi = static_cast<double>(i) / points_per_element_;
        const HermiteShape shape = CalcHermiteShape(xi, p.length);
        const CableStrain strain = CalcCableStrain(p, e, xi);
        const double tension = CalcCableElementTension(model, cable, k, state.q, forces, xi);
        samples_.push_back({InterpolatePosition(e, shape.s), InterpolatePosition(e_dot, shape.s),
                            strain.axial, strain.curvature, tension});
        if (element.beam >= 0) {
          const BeamElement& beam = model.beam_elements()[element.beam];
          // d = (1 − ξ) d_A + ξ d_B, blocks 2, 3 (node A) and 6, 7 (node B).
          const Vector24d b = model.Gather(beam, state.q);
          samples_.back().d2 = (1.0 - xi) * b.segment<3>(6) + xi * b.segment<3>(18);
          samples_.back().d3 = (1.0 - xi) * b.segment<3>(9) + xi * b.segment<3>(21);
        }
      }
    }
  }
  num_cable_samples_ = samples_.size();
  // Each body: its origin, then the tips of its axes, drawn as long as its radius of gyration
  // √(tr J / m); velocities ẋ + R (ω × s).
  const auto& bodies = model.rigid_bodies();
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    const BodyPose pose = CalcBodyPose(model, state, static_cast<Index>(b));
    const BodyVelocity velocity = CalcBodyVelocity(bodies[b], state.v);
    const double length = std::sqrt(bodies[b].inertia.trace() / bodies[b].mass);
    samples_.push_back({pose.p_WB, velocity.v_WB, 0.0, 0.0, 0.0});
    for (int k = 0; k < 3; ++k) {
      const Vector3d s_B = length * Vector3d::Unit(k);
      samples_.push_back({pose.PointInWorld(s_B),
                          velocity.v_WB + pose.R_WB * velocity.w_B.cross(s_B), 0.0, 0.0, 0.0});
    }
  }
}

void VtkSeriesWriter::CheckSamplesFinite(double time) const {
  for (std::size_t i = 0; i < samples_.size(); ++i) {
    const Sample& s = samples_[i];
    const char* field = nullptr;
    if (!s.position.allFinite()) {
      field = "position";
    } else if (!s.velocity.allFinite()) {
      field = "velocity";
    } else if (!std::isfinite(s.axial_strain) || !std::isfinite(s.curvature) ||
               !std::isfinite(s.tension)) {
      field = "strain or tension";
    }
    if (field != nullptr)
      throw SolverError(fmt::format("non-finite {} at VTK sample point {}", field, i), time);
  }
}

std::string VtkSeriesWriter::FormatPolyData(const Model& model) const {
  std::string out;
  auto it = std::back_inserter(out);
  out += kVtkPolyDataHeader;
  fmt::format_to(it,
                 "    <Piece NumberOfPoints=\"{}\" NumberOfVerts=\"0\" NumberOfLines=\"{}\" "
                 "NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n",
                 samples_.size(), model.cables().size() + 3 * model.rigid_bodies().size());

  out += "      <PointData Scalars=\"tension\" Vectors=\"velocity\">\n";
  AppendVtkDataArray(&out, "velocity", 3, samples_,
                     [&](const Sample& s, auto o) { WriteVtkVector(s.velocity, o); });
  AppendVtkDataArray(&out, "axial_strain", 1, samples_,
                     [](const Sample& s, auto o) { fmt::format_to(o, "{}", s.axial_strain); });
  AppendVtkDataArray(&out, "curvature", 1, samples_,
                     [](const Sample& s, auto o) { fmt::format_to(o, "{}", s.curvature); });
  AppendVtkDataArray(&out, "tension", 1, samples_,
                     [](const Sample& s, auto o) { fmt::format_to(o, "{}", s.tension); });
  AppendVtkDataArray(&out, "section_d2", 3, samples_,
                     [&](const Sample& s, auto o) { WriteVtkVector(s.d2, o); });
  AppendVtkDataArray(&out, "section_d3", 3, samples_,
                     [&](const Sample& s, auto o) { WriteVtkVector(s.d3, o); });
  out += "      </PointData>\n      <Points>\n";
  AppendVtkDataArray(&out, "position", 3, samples_,
                     [&](const Sample& s, auto o) { WriteVtkVector(s.position, o); });
  out += "      </Points>\n      <Lines>\n";

  // One polyline per cable over consecutive point indices.
  out += "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  for (std::size_t i = 0; i < num_cable_samples_; ++i)
    fmt::format_to(it, "{}{}", i % 16 == 0 ? "          " : " ", i);
  // Then three two-point lines per body, origin to each axis tip.
  for (std::size_t base = num_cable_samples_; base < samples_.size(); base += 4)
    fmt::format_to(it, "\n          {} {} {} {} {} {}", base, base + 1, base, base + 2, base,
                   base + 3);
  out +=
      "\n        </DataArray>\n"
      "        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n         ";
  Index offset = 0;
  for (const Cable& cable : model.cables()) {
    offset += cable.num_elements * points_per_element_ + 1;
    fmt::format_to(it, " {}", offset);
  }
  for (std::size_t line = 0; line < 3 * model.rigid_bodies().size(); ++line) {
    offset += 2;
    fmt::format_to(it, " {}", offset);
  }
  out +=
      "\n        </DataArray>\n"
      "      </Lines>\n"
      "    </Piece>\n"
      "  </PolyData>\n"
      "</VTKFile>\n";
  return out;
}

}  // namespace ancfnet
