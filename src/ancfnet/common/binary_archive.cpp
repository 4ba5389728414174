#include "ancfnet/common/binary_archive.hpp"

#include <cstring>

#include "ancfnet/common/error.hpp"

namespace ancfnet {

void ArchiveWriter::WriteBytes(const void* data, std::size_t size) {
  const auto* bytes = static_cast<const std::byte*>(data);
  bytes_.insert(bytes_.end(), bytes, bytes + size);
}

std::string ArchiveReader::ReadString() {
  const auto size = Read<std::uint64_t>();
  CheckCount(size, 1);
  std::string s(size, '\0');
  ReadBytes(s.data(), size);
  return s;
}

void ArchiveReader::ReadBytes(void* data, std::size_t size) {
  if (size > size_ - position_) Fail("it ends early");
  if (size > 0) std::memcpy(data, data_ + position_, size);
  position_ += size;
}

void ArchiveReader::ExpectEnd() const {
  if (position_ != size_) Fail("bytes left over at its end");
}

void ArchiveReader::Fail(const std::string& reason) const {
  throw InputError(what_ + ": checkpoint does not fit this scene or this build: " + reason);
}

void ArchiveReader::CheckCount(std::uint64_t count, std::size_t item_bytes) const {
  if (count > (size_ - position_) / item_bytes) Fail("it ends early");
}

}  // namespace ancfnet
