#include "src/core/bezier_ops.hpp"

#include <algorithm>
#include <cstring>

#include "src/core/error.hpp"
#include "src/core/knots.hpp"

namespace cg {

namespace {

constexpr int kWork = (kMaxDegree + 1) * (kMaxDegree + 1);

void copy_poles(double* dst, const double* src, int count, int width) {
  std::memcpy(dst, src, sizeof(double) * static_cast<std::size_t>(count) * static_cast<std::size_t>(width));
}

}  // namespace

void span_bezier_poles(int p, const double* U, int span, const double* poles, int width, double* out) {
  const double a = U[span], b = U[span + 1];
  // The recursion runs on a stack buffer of (p+1) x chunk doubles; wide bundles (a surface's stacked
  // rows) go through it a chunk of components at a time (the alphas are the same for every column).
  const int chunk = std::max(1, kWork / (p + 1));
  double work[kWork];
  for (int c0 = 0; c0 < width; c0 += chunk) {
    const int cw = std::min(chunk, width - c0);
    for (int j = 0; j <= p; ++j) {
      // Blossom with arguments a (p - j times) and b (j times); de Boor level r uses argument t_r.
      for (int k = 0; k <= p; ++k)
        std::memcpy(work + k * cw, poles + k * width + c0, sizeof(double) * static_cast<std::size_t>(cw));
      for (int r = 1; r <= p; ++r) {
        const double t = r <= p - j ? a : b;
        for (int k = p; k >= r; --k) {
          const int i = span - p + k;
          const double alpha = (t - U[i]) / (U[i + p + 1 - r] - U[i]);
          double* dk = work + k * cw;
          const double* dk1 = work + (k - 1) * cw;
          for (int c = 0; c < cw; ++c) dk[c] = (1.0 - alpha) * dk1[c] + alpha * dk[c];
        }
      }
      std::memcpy(out + j * width + c0, work + p * cw, sizeof(double) * static_cast<std::size_t>(cw));
    }
  }
}

void de_casteljau_point(int p, int width, const double* poles, double t, double* out) {
  require(width <= kMaxDegree + 1, "de_casteljau_point supports at most 26 doubles per pole");
  double q[kWork];
  copy_poles(q, poles, p + 1, width);
  const double s = 1.0 - t;
  for (int k = 1; k <= p; ++k)
    for (int i = 0; i <= p - k; ++i)
      for (int c = 0; c < width; ++c) q[i * width + c] = s * q[i * width + c] + t * q[(i + 1) * width + c];
  std::memcpy(out, q, sizeof(double) * static_cast<std::size_t>(width));
}

void split_bezier(int p, int width, const double* in, double t, double* left, double* right) {
  // The triangle is built in place in `right`; left[k] takes the first entry of level k.
  copy_poles(right, in, p + 1, width);
  const double s = 1.0 - t;
  for (int k = 0; k <= p; ++k) {
    std::memcpy(left + k * width, right, sizeof(double) * static_cast<std::size_t>(width));
    for (int i = 0; i < p - k; ++i) {
      double* ri = right + i * width;
      const double* ri1 = ri + width;
      for (int c = 0; c < width; ++c) ri[c] = s * ri[c] + t * ri1[c];
    }
  }
  // Entry i of `right` was last updated on level p - i: it is the right half's pole i.
}

void restrict_bezier(int p, int width, double* q, double a, double b) {
  if (a > 0.0) {  // keep [a, 1]: the last entry of each de Casteljau level, computed in place
    for (int k = 1; k <= p; ++k)
      for (int i = 0; i <= p - k; ++i)
        for (int c = 0; c < width; ++c) q[i * width + c] = (1.0 - a) * q[i * width + c] + a * q[(i + 1) * width + c];
  }
  if (b < 1.0) {  // keep [0, t] of the remainder: the first entry of each level
    const double t = a > 0.0 ? (b - a) / (1.0 - a) : b;
    for (int k = 1; k <= p; ++k)
      for (int i = p; i >= k; --i)
        for (int c = 0; c < width; ++c) q[i * width + c] = (1.0 - t) * q[(i - 1) * width + c] + t * q[i * width + c];
  }
}

void split_bezier_patch(int pu, int pv, int width, const double* in, bool along_u, double t, double* left,
                        double* right) {
  require(width <= 8, "split_bezier_patch supports at most 8 doubles per pole");
  const int n_along = along_u ? pu : pv;
  const int n_across = along_u ? pv : pu;
  double line[(kMaxDegree + 1) * 8], l[(kMaxDegree + 1) * 8], r[(kMaxDegree + 1) * 8];
  for (int c = 0; c <= n_across; ++c) {
    for (int k = 0; k <= n_along; ++k) {
      const int idx = along_u ? k * (pv + 1) + c : c * (pv + 1) + k;
      std::memcpy(line + k * width, in + idx * width, sizeof(double) * static_cast<std::size_t>(width));
    }
    split_bezier(n_along, width, line, t, l, r);
    for (int k = 0; k <= n_along; ++k) {
      const int idx = along_u ? k * (pv + 1) + c : c * (pv + 1) + k;
      std::memcpy(left + idx * width, l + k * width, sizeof(double) * static_cast<std::size_t>(width));
      std::memcpy(right + idx * width, r + k * width, sizeof(double) * static_cast<std::size_t>(width));
    }
  }
}

}  // namespace cg
