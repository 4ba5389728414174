#pragma once
/// @file The cases of a study handed out to the ranks of an MPI job (`mpirun -n N ancfnet
/// study …`, Debian's OpenMPI): rank 0 gives one case at a time to each rank that asks, so that
/// a slow case holds up no other; every rank runs its case as a child process (case_process.hpp)
/// in the shared output folder.

#include <cstddef>
#include <vector>

#include "ancfnet/study/case_process.hpp"
#include "ancfnet/study/study_progress.hpp"

namespace ancfnet {

/// True when the process was started by mpirun (its environment names the job's size).
bool StartedByMpirun();

/// True when the library was built with MPI (CMake found it).
bool BuiltWithMpi();

/// The MPI job, from MPI_Init in the constructor to MPI_Finalize in the destructor.
class MpiCaseDispatch {
 public:
  /// Throws InputError when the library was built without MPI.
  MpiCaseDispatch();
  ~MpiCaseDispatch();
  MpiCaseDispatch(const MpiCaseDispatch&) = delete;
  MpiCaseDispatch& operator=(const MpiCaseDispatch&) = delete;

  int rank() const { return rank_; }
  int size() const { return size_; }

  /// Rank 0: hands the cases `pending` out to ranks 1 … size − 1 as they ask, records each
  /// result (read from its case.json) in `progress`, and tells every rank to stop at the end.
  /// Returns false when a rank reported an interrupted case or an interrupt is pending: then
  /// no more cases are handed out.
  bool HandOut(const CaseLauncher& launcher, const CaseTable& cases,
               const std::vector<std::size_t>& pending, StudyProgress* progress);

  /// Ranks > 0: asks rank 0 for a case, runs it, and so on until told to stop.
  void Serve(const CaseLauncher& launcher, const Study& study, const CaseTable& cases);

 private:
  int rank_ = 0;
  int size_ = 1;
};

}  // namespace ancfnet
