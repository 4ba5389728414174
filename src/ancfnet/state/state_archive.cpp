#include "ancfnet/state/state_archive.hpp"

namespace ancfnet {
namespace {

void SaveHistory(ArchiveWriter& out, const ContactPairHistory& h) {
  out.Write(h.speed);
  out.Write(h.bristle);
}

void LoadHistory(ArchiveReader& in, ContactPairHistory* h) {
  h->speed = in.Read<double>();
  in.Read(&h->bristle);
}

// A vector read back must have the length the model gives it.
void LoadSized(ArchiveReader* in, VectorXd* v) {
  const Index size = v->size();
  in->Read(v);
  if (v->size() != size) in->Fail("a state vector of the wrong length for this scene");
}

template <class Item, class ReadItem>
void LoadSizedSequence(ArchiveReader* in, std::vector<Item>* items, std::size_t min_item_bytes,
                       ReadItem read_item) {
  const std::size_t size = items->size();
  in->ReadSequence(items, min_item_bytes, read_item);
  if (items->size() != size) in->Fail("a state list of the wrong length for this scene");
}

// A pair history's bytes: its speed, then its bristle's two sizes and three values.
constexpr std::size_t kHistoryBytes = sizeof(double) * 6;

}  // namespace

void SaveState(const State& state, ArchiveWriter* out) {
  out->Write(state.t);
  out->Write(state.q);
  out->Write(state.v);
  out->Write(state.a);
  out->Write(state.link_broken);
  out->WriteSequence(state.contact_history, SaveHistory);
  out->WriteSequence(state.self_contact_history,
                     [](ArchiveWriter& w, const SelfContactPairHistory& h) {
                       w.Write(h.first);
                       w.Write(h.second);
                       SaveHistory(w, h.history);
                     });
  out->WriteSequence(state.joint_history, SaveHistory);
  out->WriteSequence(state.body_rotation,
                     [](ArchiveWriter& w, const Matrix3d& r) { w.Write(r); });
  out->Write(state.multipliers);
}

void LoadState(ArchiveReader* in, State* state) {
  state->t = in->Read<double>();
  LoadSized(in, &state->q);
  LoadSized(in, &state->v);
  LoadSized(in, &state->a);
  in->Read(&state->link_broken, static_cast<std::int64_t>(state->link_broken.size()));
  LoadSizedSequence(in, &state->contact_history, kHistoryBytes, LoadHistory);
  in->ReadSequence(&state->self_contact_history, kHistoryBytes,
                   [](ArchiveReader& r, SelfContactPairHistory* h) {
                     h->first = r.Read<int>();
                     h->second = r.Read<int>();
                     LoadHistory(r, &h->history);
                   });
  LoadSizedSequence(in, &state->joint_history, kHistoryBytes, LoadHistory);
  LoadSizedSequence(in, &state->body_rotation, sizeof(double) * 9,
                    [](ArchiveReader& r, Matrix3d* m) { r.Read(m); });
  LoadSized(in, &state->multipliers);
}

}  // namespace ancfnet
