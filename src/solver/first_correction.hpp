#pragma once
// A strategy for the first correction of an increment, in place of Newton's plain one at the
// start state (solver/newton.hpp): the tangent predictor (solver/tangent_predictor.hpp).
#include <functional>
#include <optional>

#include <Eigen/Core>

namespace tunica {

class LinearSolver;
struct IterationRecord;

/// What Newton carries on from a first correction already taken (the problem's state moved by dx).
struct FirstCorrection {
  Eigen::VectorXd dx;            ///< the correction taken
  double reference_residual = 0; ///< R₀, the yardstick of the residual tolerance (7.2)
  double slope = 0;              ///< dx · R along it (line search (7.4)); |slope| is the energy yardstick
};

class FirstCorrectionStrategy {
public:
  virtual ~FirstCorrectionStrategy() = default;
  /// Takes the first correction, reporting it as iteration 0; std::nullopt (state untouched) when
  /// it does not apply, and Newton starts plainly.
  virtual std::optional<FirstCorrection> take(LinearSolver& solver,
                                              const std::function<void(const IterationRecord&)>& on_iteration) = 0;
};

}  // namespace tunica
