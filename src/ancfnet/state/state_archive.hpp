#pragma once
/// @file A State written to and read back from a checkpoint (common/binary_archive.hpp).

#include "ancfnet/common/binary_archive.hpp"
#include "ancfnet/state/state.hpp"

namespace ancfnet {

/// Writes every field of `state`.
void SaveState(const State& state, ArchiveWriter* out);

/// Reads a state written by SaveState into `state`, which must already have the sizes of its
/// model (MakeInitialState): a field of another size throws InputError (the checkpoint belongs
/// to another model). The self-contact history may have any length.
void LoadState(ArchiveReader* in, State* state);

}  // namespace ancfnet
