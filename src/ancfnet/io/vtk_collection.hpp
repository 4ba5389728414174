#pragma once
/// @file Pieces shared by the VTK writers: writing a text file, a `<DataArray>` in ASCII, and a
/// series of frames listed in a VTK Collection (.pvd) for ParaView.

#include <fmt/format.h>

#include <filesystem>
#include <iterator>
#include <string>
#include <vector>

namespace ancfnet {

/// Writes `text` to `path` (truncating it). Throws InputError "cannot write PATH" on failure.
void WriteTextFile(const std::filesystem::path& path, const std::string& text);

/// The opening of a VTK XML PolyData file, up to and including `<PolyData>`.
inline constexpr const char* kVtkPolyDataHeader =
    "<?xml version=\"1.0\"?>\n"
    "<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\" "
    "header_type=\"UInt64\">\n"
    "  <PolyData>\n";

/// Writes "x y z" of v to an output iterator (a DataArray value of 3 components).
template <typename Vector, typename Iterator>
void WriteVtkVector(const Vector& v, Iterator it) {
  fmt::format_to(it, "{} {} {}", v.x(), v.y(), v.z());
}

/// Appends `<DataArray type="Float64" Name=NAME NumberOfComponents=N format="ascii">` to `out`,
/// one line per item of `items`, written by `write_value(item, output_iterator)`.
template <typename Items, typename Writer>
void AppendVtkDataArray(std::string* out, const char* name, int components, const Items& items,
                        Writer write_value) {
  auto it = std::back_inserter(*out);
  fmt::format_to(it,
                 "        <DataArray type=\"Float64\" Name=\"{}\" NumberOfComponents=\"{}\" "
                 "format=\"ascii\">\n",
                 name, components);
  for (const auto& item : items) {
    *out += "          ";
    write_value(item, it);
    *out += '\n';
  }
  *out += "        </DataArray>\n";
}

/// A series of VTK XML files `DIR/BASE_NNNNNN.vtp` (frames numbered from 0) and their collection
/// `DIR/BASE.pvd`, which lists every frame with its time and is valid after each frame (it is
/// rewritten through a temporary file and a rename).
class VtkCollection {
 public:
  /// Creates `directory` when missing; throws InputError when it cannot.
  VtkCollection(const std::filesystem::path& directory, const std::string& base_name);

  /// Writes `text` as the next frame, at `time` (s), and rewrites the collection. Throws
  /// InputError "cannot write FILE" when a file cannot be written.
  void AddFrame(double time, const std::string& text);

  int num_frames() const { return static_cast<int>(frames_.size()); }
  /// The time of each frame listed, in order.
  std::vector<double> frame_times() const;
  /// Continues a series an earlier run wrote: lists the frames 0 … n − 1 at `times` and rewrites
  /// the collection (later frames are overwritten as they come).
  void Resume(const std::vector<double>& times);
  std::filesystem::path collection_path() const { return directory_ / (base_name_ + ".pvd"); }
  /// The file of frame `index` (written or not).
  std::filesystem::path FramePath(int index) const;

 private:
  struct Frame {
    double time;
    std::string file_name;
  };
  void WriteCollection() const;

  std::filesystem::path directory_;
  std::string base_name_;
  std::vector<Frame> frames_;
};

}  // namespace ancfnet
