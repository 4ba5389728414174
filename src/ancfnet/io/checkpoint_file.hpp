#pragma once
/// @file The checkpoint file: a header that names its format and its scene, then a payload
/// (common/binary_archive.hpp) guarded by its length and a checksum.
///
/// Layout (numbers in the byte order of the machine that wrote it, which the marker checks):
/// "ANCFCKPT" · u32 version · u32 0x01020304 · u64 FNV-1a hash of the scene's text · u64 length
/// and bytes of the scene's file name · u64 payload length · u64 FNV-1a checksum of the payload ·
/// the payload.

#include <cstddef>
#include <filesystem>
#include <vector>

#include "ancfnet/io/scene.hpp"

namespace ancfnet {

/// The version of the layout and of the payload this build writes and reads.
inline constexpr std::uint32_t kCheckpointVersion = 2;

/// Writes `payload` as the checkpoint of `scene` to `path` atomically: to `path`.tmp in the same
/// directory, flushed to the disk, then renamed over `path`, so that `path` is always either
/// the previous checkpoint or the new one, whole. Throws InputError when it cannot.
void WriteCheckpointFile(const std::filesystem::path& path, const Scene& scene,
                         const std::vector<std::byte>& payload);

/// Reads the payload of the checkpoint at `path` after checking that it is one (its magic and
/// version, written on a machine of this byte order), that it belongs to `scene` (the hash of
/// its text; the message names both scenes) and that it is whole (length and checksum). Throws
/// InputError naming the file and what is wrong; never reads past what the file holds.
std::vector<std::byte> ReadCheckpointFile(const std::filesystem::path& path, const Scene& scene);

}  // namespace ancfnet
