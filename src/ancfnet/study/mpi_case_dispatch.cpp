#include "ancfnet/study/mpi_case_dispatch.hpp"

#include <cstdint>
#include <cstdlib>
#include <exception>

#include "ancfnet/common/error.hpp"
#include "ancfnet/common/interrupt.hpp"

#ifdef ANCFNET_WITH_MPI
#include <mpi.h>
#endif

namespace ancfnet {

bool StartedByMpirun() {
  for (const char* variable : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"})
    if (std::getenv(variable) != nullptr) return true;
  return false;
}

#ifdef ANCFNET_WITH_MPI

namespace {

// A message between ranks: {case, outcome}. A worker sends {case it ran or kNone, outcome};
// rank 0 answers {case to run, 0} or {kNone, 0} to stop.
constexpr std::int64_t kNone = -1;
enum Outcome : std::int64_t { kRequest = 0, kFinished = 1, kInterrupted = 2 };
constexpr int kTag = 15;

}  // namespace

bool BuiltWithMpi() { return true; }

MpiCaseDispatch::MpiCaseDispatch() {
  MPI_Init(nullptr, nullptr);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

// Unwinding from an error, the other ranks may still wait for a message: no MPI_Finalize, which
// would wait for them; mpirun ends the job when this process exits with its error.
MpiCaseDispatch::~MpiCaseDispatch() {
  if (std::uncaught_exceptions() == 0) MPI_Finalize();
}

bool MpiCaseDispatch::HandOut(const CaseLauncher& launcher, const CaseTable& cases,
                              const std::vector<std::size_t>& pending, StudyProgress* progress) {
  std::size_t next = 0;
  int serving = size_ - 1;
  bool interrupted = false;
  while (serving > 0) {
    std::int64_t message[2];
    MPI_Status status;
    MPI_Recv(message, 2, MPI_INT64_T, MPI_ANY_SOURCE, kTag, MPI_COMM_WORLD, &status);
    if (message[1] == kFinished) {
      const auto index = static_cast<std::size_t>(message[0]);
      if (const auto result = ReadCaseResult(launcher.study_dir, index, cases[index]))
        progress->Record(*result);
    }
    interrupted = interrupted || message[1] == kInterrupted || InterruptRequested() != 0;
    std::int64_t answer[2] = {kNone, 0};
    if (next < pending.size() && !interrupted)
      answer[0] = static_cast<std::int64_t>(pending[next++]);
    else
      --serving;
    MPI_Send(answer, 2, MPI_INT64_T, status.MPI_SOURCE, kTag, MPI_COMM_WORLD);
  }
  return !interrupted && next == pending.size();
}

void MpiCaseDispatch::Serve(const CaseLauncher& launcher, const Study& study,
                            const CaseTable& cases) {
  std::int64_t message[2] = {kNone, kRequest};
  while (true) {
    MPI_Send(message, 2, MPI_INT64_T, 0, kTag, MPI_COMM_WORLD);
    std::int64_t answer[2];
    MPI_Recv(answer, 2, MPI_INT64_T, 0, kTag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    if (answer[0] == kNone) return;
    const auto index = static_cast<std::size_t>(answer[0]);
    const bool finished = RunCase(launcher, study, index, cases[index]).has_value();
    message[0] = answer[0];
    message[1] = finished ? kFinished : kInterrupted;
  }
}

#else

bool BuiltWithMpi() { return false; }

MpiCaseDispatch::MpiCaseDispatch() {
  throw InputError(
      "started by mpirun, but this ancfnet was built without MPI: install Debian's "
      "libopenmpi-dev (scripts/install-deps.sh) and build again, or run the study without "
      "mpirun (-j N workers on this machine)");
}

MpiCaseDispatch::~MpiCaseDispatch() = default;

bool MpiCaseDispatch::HandOut(const CaseLauncher&, const CaseTable&,
                              const std::vector<std::size_t>&, StudyProgress*) {
  return false;
}

void MpiCaseDispatch::Serve(const CaseLauncher&, const Study&, const CaseTable&) {}

#endif

}  // namespace ancfnet
