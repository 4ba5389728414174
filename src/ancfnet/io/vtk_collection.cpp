#include "ancfnet/io/vtk_collection.hpp"

#include <cstdio>
#include <system_error>

#include "ancfnet/common/error.hpp"

namespace ancfnet {

void WriteTextFile(const std::filesystem::path& path, const std::string& text) {
  std::FILE* file = std::fopen(path.c_str(), "w");
  if (file == nullptr) throw InputError(fmt::format("cannot write {}", path.string()));
  const bool written = std::fwrite(text.data(), 1, text.size(), file) == text.size();
  if (std::fclose(file) != 0 || !written)
    throw InputError(fmt::format("cannot write {}", path.string()));
}

VtkCollection::VtkCollection(const std::filesystem::path& directory, const std::string& base_name)
    : directory_(directory), base_name_(base_name) {
  std::error_code error;
  std::filesystem::create_directories(directory_, error);
  if (error || !std::filesystem::is_directory(directory_))
    throw InputError(fmt::format("cannot create directory {}", directory_.string()));
}

std::filesystem::path VtkCollection::FramePath(int index) const {
  return directory_ / fmt::format("{}_{:06d}.vtp", base_name_, index);
}

void VtkCollection::AddFrame(double time, const std::string& text) {
  const std::filesystem::path path = FramePath(num_frames());
  WriteTextFile(path, text);
  frames_.push_back({time, path.filename().string()});
  WriteCollection();
}

std::vector<double> VtkCollection::frame_times() const {
  std::vector<double> times;
  for (const Frame& frame : frames_) times.push_back(frame.time);
  return times;
}

void VtkCollection::Resume(const std::vector<double>& times) {
  frames_.clear();
  for (double time : times)
    frames_.push_back({time, FramePath(num_frames()).filename().string()});
  WriteCollection();
}

void VtkCollection::WriteCollection() const {
  std::string out =
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      "  <Collection>\n";
  for (const Frame& frame : frames_) {
    fmt::format_to(std::back_inserter(out),
                   "    <DataSet timestep=\"{}\" group=\"\" part=\"0\" file=\"{}\"/>\n", frame.time,
                   frame.file_name);
  }
  out += "  </Collection>\n</VTKFile>\n";
  // Write beside the collection and rename, so a reader never sees a half-written file.
  const std::filesystem::path path = collection_path();
  std::filesystem::path temporary = path;
  temporary += ".tmp";
  WriteTextFile(temporary, out);
  std::error_code error;
  std::filesystem::rename(temporary, path, error);
  if (error) throw InputError(fmt::format("cannot write {}", path.string()));
}

}  // namespace ancfnet
