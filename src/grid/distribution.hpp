#pragma once
// One-dimensional node distributions for structured grids. All return increasing positions, first 0
// and last the given length, cells + 1 values.
#include <string>
#include <vector>

namespace cg::grid {

/// Wall-normal distances: first cell `first`, then growth by `ratio` until the spacing reaches the
/// uniform spacing that fills the rest exactly, uniform from there (the last geometric cell and the
/// uniform ones differ by a factor in (1, ratio]). Every ratio of neighbouring cells lies in [1, ratio].
/// Throws InvalidGeometry naming the limits when `length` is not reachable: it must lie in
/// [cells * first, first (ratio^cells - 1) / (ratio - 1)].
std::vector<double> geometric_then_uniform(double first, double ratio, int cells, double length);

/// The largest length geometric_then_uniform can reach (all cells geometric).
double geometric_length(double first, double ratio, int cells);

/// Geometric distribution with first spacing `first` and the ratio solved so that `cells` cells fill
/// `length` exactly (ratio < 1 when the cells must shrink). Returns the ratio through `ratio_out`.
std::vector<double> geometric_fill(double first, int cells, double length, double* ratio_out = nullptr);

/// Two-sided stretching with end spacings d0 and d1 (Vinokur 1983, "On one-dimensional stretching
/// functions for finite-difference calculations", J. Comp. Phys. 50: tanh form when the ends are finer
/// than the mean spacing, tan form when coarser), the requested spacings corrected by fixed-point
/// iteration until the first and last cells match them to 1e-9 (when both fit into the length).
std::vector<double> two_sided_stretching(int cells, double length, double d0, double d1);

/// Periodic Gaussian smoothing of equally spaced samples (the sequence wraps): standard deviation `sigma`
/// in samples, kernel cut at 3 sigma.
std::vector<double> smooth_periodic(const std::vector<double>& values, double sigma);

/// Equidistribution of a positive density sampled at equally spaced points on [0, length] (piecewise
/// linear): node k sits where the integral of the density reaches k / cells of the total.
std::vector<double> equidistribute(const std::vector<double>& density, int cells, double length);

}  // namespace cg::grid
