// Tridiagonal linear systems with 2D right-hand sides: the O(n) solvers behind the natural spline.
//
// Row i reads  sub[i]·x[i−1] + diag[i]·x[i] + super[i]·x[i+1] = rhs[i].
// For the plain system sub[0] and super[n−1] are ignored; for the cyclic one they are the corner
// entries (row 0, column n−1) and (row n−1, column 0).
//
// No pivoting: both solvers are stable for strictly diagonally dominant matrices (|diag[i]| >
// |sub[i]| + |super[i]|), which every spline system here is; the tests compare them with a dense
// Gaussian elimination with partial pivoting on random dominant systems.
#pragma once

#include <vector>

#include "bezel/geometry.hpp"

namespace bezel::smooth_detail {

struct Tridiagonal {
    std::vector<double> sub, diag, super;  // all of the same size n
};

// Thomas algorithm: forward elimination, then back substitution; solves in place (rhs becomes x).
// Returns false, leaving rhs unspecified, when a pivot is zero or the result is not finite.
// Precondition: the three vectors and rhs have the same size n ≥ 1.
bool solve_tridiagonal(const Tridiagonal& m, std::vector<Vec2>& rhs);

// The cyclic system (corner entries included) by Sherman–Morrison: write A = T + u·vᵀ with T
// tridiagonal, solve T·y = rhs and T·z = u, then x = y − (v·y)/(1 + v·z)·z (Press et al.,
// Numerical Recipes §2.7, "cyclic"). Two Thomas passes, O(n). Precondition: n ≥ 3.
bool solve_cyclic_tridiagonal(const Tridiagonal& m, std::vector<Vec2>& rhs);

}  // namespace bezel::smooth_detail
