#pragma once
/// @file A byte buffer that values are written to and read back from in the same order: the
/// payload of a checkpoint (io/checkpoint_file.hpp). Numbers are stored as their bytes in memory,
/// so a value read back is the one written, bit for bit, on the machine that wrote it.

#include <cstddef>
#include <cstdint>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "ancfnet/common/types.hpp"

namespace ancfnet {

/// Appends values to a byte buffer.
class ArchiveWriter {
 public:
  /// A number, a bool or an enum, as its bytes.
  template <class T>
    requires std::is_arithmetic_v<T> || std::is_enum_v<T>
  void Write(T value) {
    WriteBytes(&value, sizeof(T));
  }
  /// Its size, then its entries.
  template <class Derived>
  void Write(const Eigen::MatrixBase<Derived>& m) {
    Write(static_cast<std::int64_t>(m.rows()));
    Write(static_cast<std::int64_t>(m.cols()));
    for (Index j = 0; j < m.cols(); ++j)
      for (Index i = 0; i < m.rows(); ++i) Write(static_cast<double>(m(i, j)));
  }
  void Write(const std::string& s) {
    Write(static_cast<std::uint64_t>(s.size()));
    WriteBytes(s.data(), s.size());
  }
  /// Its size, then each item with `write_item(ArchiveWriter&, const Item&)`.
  template <class Item, class WriteItem>
  void WriteSequence(const std::vector<Item>& items, WriteItem write_item) {
    Write(static_cast<std::uint64_t>(items.size()));
    for (const Item& item : items) write_item(*this, item);
  }
  /// A vector of numbers (its size, then its entries).
  template <class T>
    requires std::is_arithmetic_v<T>
  void Write(const std::vector<T>& items) {
    Write(static_cast<std::uint64_t>(items.size()));
    WriteBytes(items.data(), items.size() * sizeof(T));
  }
  void WriteBytes(const void* data, std::size_t size);

  const std::vector<std::byte>& bytes() const { return bytes_; }

 private:
  std::vector<std::byte> bytes_;
};

/// Reads values back in the order an ArchiveWriter wrote them. Every read checks what is left
/// and every size against what it must be: a payload that ends early or does not fit throws
/// InputError naming `what` (the checkpoint file), never reads past the end.
class ArchiveReader {
 public:
  ArchiveReader(const std::byte* data, std::size_t size, std::string what)
      : data_(data), size_(size), what_(std::move(what)) {}

  template <class T>
    requires std::is_arithmetic_v<T> || std::is_enum_v<T>
  T Read() {
    T value;
    ReadBytes(&value, sizeof(T));
    return value;
  }
  /// A matrix written by ArchiveWriter::Write; a fixed-size one must have the size written.
  template <class Derived>
  void Read(Eigen::PlainObjectBase<Derived>* m) {
    const auto rows = Read<std::int64_t>();
    const auto cols = Read<std::int64_t>();
    CheckCount(static_cast<std::uint64_t>(rows) * static_cast<std::uint64_t>(cols),
               sizeof(double));
    if ((Derived::RowsAtCompileTime != Eigen::Dynamic && rows != Derived::RowsAtCompileTime) ||
        (Derived::ColsAtCompileTime != Eigen::Dynamic && cols != Derived::ColsAtCompileTime))
      Fail("a matrix of the wrong size");
    m->resize(rows, cols);
    for (Index j = 0; j < cols; ++j)
      for (Index i = 0; i < rows; ++i) (*m)(i, j) = Read<double>();
  }
  /// A vector of numbers; with `expected_size` ≥ 0 it must have that many entries.
  template <class T>
    requires std::is_arithmetic_v<T>
  void Read(std::vector<T>* items, std::int64_t expected_size = -1) {
    const auto size = Read<std::uint64_t>();
    CheckCount(size, sizeof(T));
    if (expected_size >= 0 && size != static_cast<std::uint64_t>(expected_size))
      Fail("a list of the wrong length for this scene");
    items->resize(size);
    ReadBytes(items->data(), size * sizeof(T));
  }
  std::string ReadString();
  /// A sequence written by WriteSequence, each item read by `read_item(ArchiveReader&, Item*)`;
  /// each item takes at least `min_item_bytes` (> 0) of the payload.
  template <class Item, class ReadItem>
  void ReadSequence(std::vector<Item>* items, std::size_t min_item_bytes, ReadItem read_item) {
    const auto size = Read<std::uint64_t>();
    CheckCount(size, min_item_bytes);
    items->resize(size);
    for (Item& item : *items) read_item(*this, &item);
  }
  void ReadBytes(void* data, std::size_t size);
  /// Bytes read so far, and bytes left.
  std::size_t position() const { return position_; }
  std::size_t remaining() const { return size_ - position_; }
  /// Throws InputError unless every byte was read.
  void ExpectEnd() const;
  /// Throws InputError "WHAT: checkpoint does not fit: REASON".
  [[noreturn]] void Fail(const std::string& reason) const;

 private:
  // Throws unless `count` items of at least `item_bytes` each can still be read.
  void CheckCount(std::uint64_t count, std::size_t item_bytes) const;

  const std::byte* data_;
  std::size_t size_;
  std::size_t position_ = 0;
  std::string what_;
};

}  // namespace ancfnet
