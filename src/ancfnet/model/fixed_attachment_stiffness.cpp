#include "ancfnet/model/fixed_attachment_stiffness.hpp"

namespace ancfnet {

double CalcFixedAttachmentStiffness(double reduced_mass, double time_step) {
  const double omega = 10.0 / time_step;
  return reduced_mass * omega * omega;
}

}  // namespace ancfnet
