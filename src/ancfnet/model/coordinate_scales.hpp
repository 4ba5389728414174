#pragma once
/// @file The size each coordinate of a model is measured against when Newton's increments are
/// judged converged (solvers/solve_result.hpp, WeightedRmsNorm): one scale per kind of unknown,
/// the same wherever the model sits or how it is turned (docs/theory.md, "Convergence of
/// Newton's method").

#include "ancfnet/common/types.hpp"
#include "ancfnet/model/model.hpp"

namespace ancfnet {

/// The model's length scale L (m): the mean reference length of its cable and beam elements,
/// the resolution at which its geometry is described; without elements, the diagonal of the box
/// round the initial positions of its point masses and bodies; 1 m when that is zero too.
double CalcModelLengthScale(const Model& model);

/// Per coordinate of `model`: L (CalcModelLengthScale) for positions (nodes, point masses, body
/// centres), 1 for the dimensionless gradients (slopes r′ and section gradients r_y, r_z, unit
/// vectors in the reference configuration) and 1 rad for body rotations ψ.
VectorXd CalcCoordinateScales(const Model& model);

}  // namespace ancfnet
