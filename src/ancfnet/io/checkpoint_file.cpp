#include "ancfnet/io/checkpoint_file.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <cstdio>
#include <cstring>
#include <fstream>
#include <memory>
#include <string>

#include "ancfnet/common/binary_archive.hpp"
#include "ancfnet/common/error.hpp"
#include "ancfnet/common/fnv_hash.hpp"

namespace ancfnet {
namespace {

constexpr char kMagic[8] = {'A', 'N', 'C', 'F', 'C', 'K', 'P', 'T'};
constexpr std::uint32_t kByteOrderMarker = 0x01020304;
// A scene's file name longer than this is not one a checkpoint wrote.
constexpr std::uint64_t kMaxSceneNameBytes = 4096;

struct FileCloser {
  void operator()(std::FILE* file) const { std::fclose(file); }
};

}  // namespace

void WriteCheckpointFile(const std::filesystem::path& path, const Scene& scene,
                         const std::vector<std::byte>& payload) {
  ArchiveWriter header;
  header.WriteBytes(kMagic, sizeof(kMagic));
  header.Write(kCheckpointVersion);
  header.Write(kByteOrderMarker);
  header.Write(scene.text_hash);
  header.Write(scene.source);
  header.Write(static_cast<std::uint64_t>(payload.size()));
  header.Write(Fnv1aHash(payload.data(), payload.size()));

  std::filesystem::path temporary = path;
  temporary += ".tmp";
  const auto fail = [&] { throw InputError(fmt::format("cannot write {}", temporary.string())); };
  {
    std::unique_ptr<std::FILE, FileCloser> file(std::fopen(temporary.c_str(), "wb"));
    if (!file) fail();
    // fwrite's buffer may not be null, which an empty vector's data() is.
    const auto write = [&](const std::vector<std::byte>& bytes) {
      return bytes.empty() ||
             std::fwrite(bytes.data(), 1, bytes.size(), file.get()) == bytes.size();
    };
    if (!write(header.bytes()) || !write(payload) || std::fflush(file.get()) != 0 ||
        ::fsync(::fileno(file.get())) != 0)
      fail();
    if (std::fclose(file.release()) != 0) fail();
  }
  std::error_code error;
  std::filesystem::rename(temporary, path, error);
  if (error) throw InputError(fmt::format("cannot write {}", path.string()));
}

std::vector<std::byte> ReadCheckpointFile(const std::filesystem::path& path, const Scene& scene) {
  const std::string name = path.string();
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error))
    throw InputError(fmt::format("{}: {}", name,
                                 std::filesystem::exists(path, error)
                                     ? "not a regular file (a checkpoint is a file)"
                                     : "no such checkpoint file"));
  std::ifstream in(path, std::ios::binary);
  std::vector<std::byte> bytes;
  if (in) {
    const std::uintmax_t size = std::filesystem::file_size(path, error);
    if (!error) {
      bytes.resize(size);
      in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(size));
    }
  }
  if (!in || error) throw InputError(fmt::format("{}: cannot read checkpoint file", name));

  const auto refuse = [&](const std::string& why) {
    throw InputError(fmt::format("{}: {}", name, why));
  };
  if (bytes.size() < sizeof(kMagic) || std::memcmp(bytes.data(), kMagic, sizeof(kMagic)) != 0)
    refuse("not an ancfnet checkpoint (no ANCFCKPT header)");
  ArchiveReader header(bytes.data(), bytes.size(), name);
  const auto truncated = [&](std::size_t needed) {
    if (header.remaining() < needed)
      refuse(fmt::format("truncated checkpoint: {} bytes, its header alone is longer",
                         bytes.size()));
  };
  std::byte magic[sizeof(kMagic)];
  header.ReadBytes(magic, sizeof(magic));
  truncated(2 * sizeof(std::uint32_t) + 2 * sizeof(std::uint64_t));
  const auto version = header.Read<std::uint32_t>();
  if (version != kCheckpointVersion)
    refuse(fmt::format("checkpoint format version {}; this build reads version {}", version,
                       kCheckpointVersion));
  if (header.Read<std::uint32_t>() != kByteOrderMarker)
    refuse("checkpoint written on a machine of another byte order");
  const auto scene_hash = header.Read<std::uint64_t>();
  const auto name_size = header.Read<std::uint64_t>();
  if (name_size > kMaxSceneNameBytes) refuse("damaged checkpoint: its header is not one");
  truncated(name_size + 2 * sizeof(std::uint64_t));
  std::string scene_name(name_size, '\0');
  header.ReadBytes(scene_name.data(), name_size);
  if (scene_hash != scene.text_hash)
    refuse(fmt::format(
        "checkpoint of the scene {} (text hash {:016x}), not of {} (text hash {:016x}): a run "
        "continues only from a checkpoint of the same scene text",
        scene_name.empty() ? "built in C++" : scene_name, scene_hash,
        scene.source.empty() ? "the scene built in C++" : scene.source, scene.text_hash));
  const auto length = header.Read<std::uint64_t>();
  const auto checksum = header.Read<std::uint64_t>();
  const std::size_t available = header.remaining();
  if (length != available)
    refuse(length > available
               ? fmt::format("truncated checkpoint: {} of its {} payload bytes", available, length)
               : fmt::format("damaged checkpoint: {} bytes after its {} payload bytes",
                             available - length, length));
  const std::byte* payload = bytes.data() + header.position();
  if (Fnv1aHash(payload, available) != checksum)
    refuse("damaged checkpoint: its checksum does not match its contents");
  return {payload, payload + available};
}

}  // namespace ancfnet
