#include "ancfnet/study/local_case_pool.hpp"

#include <algorithm>
#include <map>

#include "ancfnet/common/interrupt.hpp"

namespace ancfnet {

bool RunCasesLocally(const CaseLauncher& launcher, const Study& study, const CaseTable& cases,
                     const std::vector<std::size_t>& pending, int workers,
                     StudyProgress* progress) {
  std::map<pid_t, std::size_t> running;  // process → case
  std::size_t next = 0;
  bool interrupt_passed_on = false;
  bool completed = true;
  while (true) {
    while (next < pending.size() && static_cast<int>(running.size()) < workers &&
           InterruptRequested() == 0) {
      const std::size_t index = pending[next++];
      running[StartCase(launcher, study, index, cases[index])] = index;
    }
    if (running.empty()) break;
    std::vector<pid_t> processes;
    for (const auto& [pid, index] : running) processes.push_back(pid);
    const auto [pid, status] = WaitForCase(processes, &interrupt_passed_on);
    const std::size_t index = running.at(pid);
    running.erase(pid);
    if (const auto result = FinishCase(launcher, index, cases[index], status))
      progress->Record(*result);
    else
      completed = false;
  }
  return completed && next == pending.size();
}

}  // namespace ancfnet
