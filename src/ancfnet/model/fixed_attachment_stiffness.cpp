#include "ancfnet/model/fixed_attachment_stiffness.hpp"

#include <algorithm>

namespace ancfnet {

double CalcFixedAttachmentStiffness(double reduced_mass, double time_step, double held_stiffness) {
  const double omega = 10.0 / time_step;
  return std::max(reduced_mass * omega * omega, 100.0 * held_stiffness);
}

}  // namespace ancfnet
