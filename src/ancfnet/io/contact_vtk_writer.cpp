#include "ancfnet/io/contact_vtk_writer.hpp"

#include <fmt/format.h>

#include <cmath>
#include <iterator>

#include "ancfnet/common/error.hpp"

namespace ancfnet {
namespace {

bool IsFinite(const ContactPoint& c) {
  return c.point_W.allFinite() && c.normal_W.allFinite() && c.force_W.allFinite() &&
         std::isfinite(c.normal_force) && std::isfinite(c.penetration);
}

}  // namespace

ContactVtkWriter::ContactVtkWriter(const std::filesystem::path& directory,
                                   const std::string& base_name)
    : collection_(directory, base_name) {}

void ContactVtkWriter::WriteFrame(double time, const std::vector<ContactPoint>& contacts) {
  for (std::size_t i = 0; i < contacts.size(); ++i)
    if (!IsFinite(contacts[i]))
      throw SolverError(fmt::format("non-finite value at contact point {}", i), time);
  std::string out;
  auto it = std::back_inserter(out);
  out += kVtkPolyDataHeader;
  fmt::format_to(it,
                 "    <Piece NumberOfPoints=\"{0}\" NumberOfVerts=\"{0}\" NumberOfLines=\"0\" "
                 "NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n",
                 contacts.size());
  out += "      <PointData Scalars=\"normal_force\" Vectors=\"force\">\n";
  AppendVtkDataArray(&out, "normal_force", 1, contacts, [](const ContactPoint& c, auto o) {
    fmt::format_to(o, "{}", c.normal_force);
  });
  AppendVtkDataArray(&out, "force", 3, contacts,
                     [&](const ContactPoint& c, auto o) { WriteVtkVector(c.force_W, o); });
  AppendVtkDataArray(&out, "normal", 3, contacts,
                     [&](const ContactPoint& c, auto o) { WriteVtkVector(c.normal_W, o); });
  AppendVtkDataArray(&out, "penetration", 1, contacts,
                     [](const ContactPoint& c, auto o) { fmt::format_to(o, "{}", c.penetration); });
  out += "      </PointData>\n      <Points>\n";
  AppendVtkDataArray(&out, "position", 3, contacts,
                     [&](const ContactPoint& c, auto o) { WriteVtkVector(c.point_W, o); });
  out += "      </Points>\n      <Verts>\n";
  // One vertex cell per point.
  out += "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n         ";
  for (std::size_t i = 0; i < contacts.size(); ++i) fmt::format_to(it, " {}", i);
  out +=
      "\n        </DataArray>\n"
      "        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n         ";
  for (std::size_t i = 0; i < contacts.size(); ++i) fmt::format_to(it, " {}", i + 1);
  out +=
      "\n        </DataArray>\n"
      "      </Verts>\n"
      "    </Piece>\n"
      "  </PolyData>\n"
      "</VTKFile>\n";
  collection_.AddFrame(time, out);
}

}  // namespace ancfnet
