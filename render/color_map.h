// Colour maps for per-vertex values (e.g. the rigidity error).
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "render/image.h"

namespace unfold {

/// A perceptually ordered map (dark blue -> teal -> yellow, viridis-like) of t in [0, 1];
/// t is clamped, NaN maps to grey. Returns RGB in [0, 1].
Eigen::Vector3f color_map(double t);

/// color_map((values - low) / (high - low)) per row; all rows map to 0 when high <= low.
Eigen::MatrixX3f color_map(const Eigen::VectorXd& values, double low, double high);

/// The top of a colour scale for `values`: their 98th percentile (0 for none),
/// so that a few extreme vertices do not push every other one into the
/// darkest colours (higher values take the top colour).
double color_scale_top(std::vector<double> values);

/// The colour map's legend in the bottom-right corner of `image`: a bar from
/// t = 0 to 1 with `label` (e.g. the values' range) to its left.
void draw_color_bar(const std::string& label, Image* image);

}  // namespace unfold
