#include "ancfnet/model/prescribed_motion.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>

namespace ancfnet {

std::array<double, 3> AngleProfile::Evaluate(double t) const {
  if (kind == Kind::kConstantRate) return {rate * t, rate, 0.0};
  const double T = ramp_time;
  if (t >= T) return {rate * (t - 0.5 * T), rate, 0.0};
  const double w = 2.0 * std::numbers::pi / T;
  // Kane, Ryan & Banerjee (1987), eq. 40, and its derivatives.
  return {(rate / T) * (0.5 * t * t + (std::cos(w * t) - 1.0) / (w * w)),
          (rate / T) * (t - std::sin(w * t) / w), (rate / T) * (1.0 - std::cos(w * t))};
}

void ApplyPrescribedMotion(const std::vector<PrescribedBlock>& blocks, double t, VectorXd* q,
                           VectorXd* v, VectorXd* a) {
  for (const PrescribedBlock& b : blocks) {
    Vector3d x, x_dot, x_ddot;
    if (b.kind == PrescribedBlock::Kind::kTranslation) {
      x = b.initial + t * b.velocity;
      x_dot = b.velocity;
      x_ddot.setZero();
    } else {
      const auto [theta, theta_dot, theta_ddot] = b.angle.Evaluate(t);
      const Vector3d arm0 = b.is_direction ? b.initial : Vector3d(b.initial - b.center);
      const Vector3d arm = Eigen::AngleAxisd(theta, b.axis) * arm0;
      x = b.is_direction ? arm : Vector3d(b.center + arm);
      // ẋ = θ̇ n × d, ẍ = θ̈ n × d + θ̇² n × (n × d).
      const Vector3d n_cross = b.axis.cross(arm);
      x_dot = theta_dot * n_cross;
      x_ddot = theta_ddot * n_cross + theta_dot * theta_dot * b.axis.cross(n_cross);
    }
    if (q) q->segment<3>(b.dof) = x;
    if (v) v->segment<3>(b.dof) = x_dot;
    if (a) a->segment<3>(b.dof) = x_ddot;
  }
}

}  // namespace ancfnet
