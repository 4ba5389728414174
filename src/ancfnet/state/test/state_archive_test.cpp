// A State written to a checkpoint and read back is the same bit for bit; one of another model,
// or a payload cut short, is refused with InputError and never read past its end.

#include <gtest/gtest.h>

#include <cstring>

#include "ancfnet/common/error.hpp"
#include "ancfnet/state/state_archive.hpp"

namespace ancfnet {
namespace {

// A state with every field set to values whose bits matter (no round numbers).
State MakeState() {
  State state;
  state.t = 0.1 + 0.2;
  state.q = VectorXd::LinSpaced(7, -1.0 / 3.0, 2.0 / 7.0);
  state.v = VectorXd::LinSpaced(7, 1e-300, 1e300);
  state.a = VectorXd::LinSpaced(7, -5e-17, 3.0);
  state.link_broken = {0, 1, 0};
  state.contact_history = {{.speed = -0.25, .bristle = Vector3d(1e-9, -2e-9, 1.0 / 3.0)},
                           {.speed = 0.125, .bristle = Vector3d::Zero()}};
  state.self_contact_history = {{.first = 2, .second = 5, .history = {.speed = 1.0 / 7.0}}};
  state.joint_history = {{.speed = 3.5}};
  state.body_rotation = {Eigen::AngleAxisd(0.3, Vector3d(1, 2, 3).normalized()).toRotationMatrix()};
  state.multipliers = VectorXd::Constant(2, -1.0 / 9.0);
  return state;
}

// A state of the same model before any step: the sizes MakeInitialState gives.
State SizedLike(const State& state) {
  State sized;
  sized.q = VectorXd::Zero(state.q.size());
  sized.v = VectorXd::Zero(state.v.size());
  sized.a = VectorXd::Zero(state.a.size());
  sized.link_broken.assign(state.link_broken.size(), 0);
  sized.contact_history.resize(state.contact_history.size());
  sized.joint_history.resize(state.joint_history.size());
  sized.body_rotation.assign(state.body_rotation.size(), Matrix3d::Identity());
  sized.multipliers = VectorXd::Zero(state.multipliers.size());
  return sized;
}

bool SameBits(const VectorXd& a, const VectorXd& b) {
  return a.size() == b.size() &&
         std::memcmp(a.data(), b.data(), sizeof(double) * static_cast<std::size_t>(a.size())) == 0;
}

TEST(StateArchive, RoundTripIsBitForBit) {
  const State state = MakeState();
  ArchiveWriter out;
  SaveState(state, &out);
  State read = SizedLike(state);
  ArchiveReader in(out.bytes().data(), out.bytes().size(), "test");
  LoadState(&in, &read);
  in.ExpectEnd();
  EXPECT_EQ(std::memcmp(&read.t, &state.t, sizeof(double)), 0);
  EXPECT_TRUE(SameBits(read.q, state.q));
  EXPECT_TRUE(SameBits(read.v, state.v));
  EXPECT_TRUE(SameBits(read.a, state.a));
  EXPECT_TRUE(SameBits(read.multipliers, state.multipliers));
  EXPECT_EQ(read.link_broken, state.link_broken);
  ASSERT_EQ(read.contact_history.size(), 2u);
  EXPECT_EQ(read.contact_history[0].speed, -0.25);
  EXPECT_EQ(read.contact_history[0].bristle, state.contact_history[0].bristle);
  ASSERT_EQ(read.self_contact_history.size(), 1u);
  EXPECT_EQ(read.self_contact_history[0].first, 2);
  EXPECT_EQ(read.self_contact_history[0].second, 5);
  EXPECT_EQ(read.self_contact_history[0].history.speed, 1.0 / 7.0);
  EXPECT_EQ(read.joint_history[0].speed, 3.5);
  EXPECT_EQ(read.body_rotation[0], state.body_rotation[0]);
}

TEST(StateArchive, AStateOfAnotherModelIsRefused) {
  const State state = MakeState();
  ArchiveWriter out;
  SaveState(state, &out);
  State other = SizedLike(state);
  other.q = VectorXd::Zero(8);
  ArchiveReader in(out.bytes().data(), out.bytes().size(), "other.bin");
  try {
    LoadState(&in, &other);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("other.bin"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("wrong length"), std::string::npos) << e.what();
  }
}

TEST(StateArchive, EveryTruncationIsRefused) {
  const State state = MakeState();
  ArchiveWriter out;
  SaveState(state, &out);
  for (std::size_t size = 0; size < out.bytes().size(); ++size) {
    State read = SizedLike(state);
    ArchiveReader in(out.bytes().data(), size, "cut.bin");
    EXPECT_THROW(LoadState(&in, &read), InputError) << size << " bytes";
  }
}

TEST(StateArchive, LeftoverBytesAreRefused) {
  ArchiveWriter out;
  SaveState(MakeState(), &out);
  out.Write(1.0);
  State read = SizedLike(MakeState());
  ArchiveReader in(out.bytes().data(), out.bytes().size(), "long.bin");
  LoadState(&in, &read);
  EXPECT_THROW(in.ExpectEnd(), InputError);
}

}  // namespace
}  // namespace ancfnet
