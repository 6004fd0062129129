#pragma once
// B-spline basis functions (Cox–de Boor recursion in the triangular form of The NURBS Book).
// Flat-array kernels: no allocation, any degree up to kMaxDegree.
#include "src/core/knots.hpp"

namespace cg {

/// Non-zero basis functions N[0..p] = N_{span-p..span, p}(u) (The NURBS Book A2.2).
void basis_funs(int span, double u, int p, const double* U, double* N);

/// Basis functions and derivatives up to order nd (The NURBS Book A2.3).
/// ders is row-major (nd+1) x (p+1): ders[k*(p+1) + j] = N^(k)_{span-p+j, p}(u). Orders k > p are zero.
void ders_basis_funs(int span, double u, int p, int nd, const double* U, double* ders);

/// All Bernstein polynomials B_{i,p}(t), i = 0..p (The NURBS Book A1.3).
void all_bernstein(int p, double t, double* B);

}  // namespace cg
