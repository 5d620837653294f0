// Runs the TetGen library in a child process. TetGen reports failure by
// throwing an int, and Debian's TetGen 1.5 frees its memory pools twice on that
// path (terminatetetgen frees them, then the unwinding tetgenmesh destructor
// frees them again), which aborts the process; it can also crash outright on
// some inputs. In a forked child none of that can take the caller down.
#pragma once

#include <tetgen.h>

#include <Eigen/Core>
#include <functional>
#include <string>

namespace unfold {

struct TetgenOutput {
  Eigen::MatrixX3d points;  ///< TetGen's output points (input points first)
  Eigen::MatrixX4i tets;    ///< 0-based corner indices
};

/// tetrahedralize(switches, in) in a forked child; the result comes back over a pipe.
/// @param switches TetGen command-line switches; must include 'z' (0-based) and 'Q'
/// @param in       the input (points, facets)
/// @param what     name of the caller's route, for error messages
/// @param give_up  if set, asked before TetGen starts and every few
///                 milliseconds while it runs: true ends TetGen's process (the
///                 caller learnt meanwhile that the result will not be used)
/// @throws NumericalError naming TetGen's error kind, or the signal if it
///         crashed, or that it was given up
TetgenOutput run_tetgen(const std::string& switches, tetgenio& in, const std::string& what,
                        const std::function<bool()>& give_up = {});

}  // namespace unfold
