// Colour maps for per-vertex values (e.g. the rigidity error).
#pragma once

#include <Eigen/Core>

namespace unfold {

/// A perceptually ordered map (dark blue -> teal -> yellow, viridis-like) of t in [0, 1];
/// t is clamped, NaN maps to grey. Returns RGB in [0, 1].
Eigen::Vector3f color_map(double t);

/// color_map((values - low) / (high - low)) per row; all rows map to 0 when high <= low.
Eigen::MatrixX3f color_map(const Eigen::VectorXd& values, double low, double high);

}  // namespace unfold
