// The paper's objective (Eq. 3): E(Q; R, beta) = E_s(Q) + beta E_r(Q; R).
#pragma once

#include "energies/arap_energy.h"
#include "energies/stretch_energy.h"

namespace unfold {

/// E_s(Q) + beta E_r(Q; R), with its gradient at fixed R when grad is not null.
double unfold_energy(const EdgeGraph& graph, const Eigen::MatrixX3d& P, const Eigen::MatrixX3d& Q,
                     const Rotations& R, double beta, Eigen::MatrixX3d* grad = nullptr);

}  // namespace unfold
