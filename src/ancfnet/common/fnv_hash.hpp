#pragma once
/// @file The 64-bit FNV-1a hash of a byte string (Fowler, Noll & Vo): the name of a scene's text
/// and the checksum of a checkpoint's payload. Not cryptographic; it finds accidental changes
/// (a truncated or damaged file, another scene), not deliberate ones.

#include <cstddef>
#include <cstdint>

namespace ancfnet {

/// FNV-1a over `size` bytes at `data`, continuing from `hash` (the offset basis by default).
inline std::uint64_t Fnv1aHash(const void* data, std::size_t size,
                               std::uint64_t hash = 0xcbf29ce484222325ULL) {
  const auto* bytes = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < size; ++i) {
    hash ^= bytes[i];
    hash *= 0x100000001b3ULL;
  }
  return hash;
}

}  // namespace ancfnet
