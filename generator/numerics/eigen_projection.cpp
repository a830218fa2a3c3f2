// SPDX-License-Identifier: MIT
#include "numerics/eigen_projection.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace admitgen::numerics {
namespace {

/// One implicit QR step with the Wilkinson shift on the unreduced block lo … hi of the tridiagonal matrix
/// (diagonal d, off-diagonal e, e_k = T(k, k+1)), each rotation also applied to w (Golub & Van Loan,
/// Algorithm 8.3.2). The rotation R = [c s; −s c] on rows and columns k, k+1 maps (x, z) to (r, 0): at k = lo
/// (x, z) = (d_lo − shift, e_lo), after that the entry T(k−1, k) and the bulge T(k−1, k+1).
void qr_step(double* d, double* e, int lo, int hi, double* w) {
  // Wilkinson shift: the eigenvalue of the trailing 2 × 2 block nearer to d_hi.
  const double delta = 0.5 * (d[hi - 1] - d[hi]), b = e[hi - 1];
  const double shift = d[hi] - b * b / (delta + std::copysign(std::sqrt(delta * delta + b * b), delta));
  double x = d[lo] - shift, z = e[lo];
  for (int k = lo; k < hi; ++k) {
    const double r = std::sqrt(x * x + z * z);
    const double c = r > 0.0 ? x / r : 1.0, s = r > 0.0 ? z / r : 0.0;
    if (k > lo) e[k - 1] = r;
    // R [a b; b f] Rᵀ of the 2 × 2 block.
    const double a = d[k], bb = e[k], f = d[k + 1];
    d[k] = c * c * a + 2.0 * c * s * bb + s * s * f;
    d[k + 1] = s * s * a - 2.0 * c * s * bb + c * c * f;
    e[k] = c * s * (f - a) + (c * c - s * s) * bb;
    if (k + 1 < hi) {  // rows k, k + 1 of column k + 2: the bulge moves down
      z = s * e[k + 1];
      e[k + 1] *= c;
    }
    x = e[k];
    const double wk = w[k], wk1 = w[k + 1];
    w[k] = c * wk + s * wk1;
    w[k + 1] = -s * wk + c * wk1;
  }
}

}  // namespace

bool EigenProjection::compute(const Eigen::MatrixXd& a, const Eigen::VectorXd& y) {
  const Eigen::Index n = a.rows();
  mu_.resize(n);
  h_.resize(n);
  if (n == 0) return true;
  if (n == 1) {
    mu_[0] = a(0, 0);
    h_[0] = y[0];
    return true;
  }
  // Scaled to a largest entry of 1 (as Eigen's own solver does), so that the squares in the rotations
  // (√(x² + z²) rather than the slower hypot) can neither overflow nor lose the entries that matter.
  const double scale = a.cwiseAbs().maxCoeff();
  if (!(scale > 0.0) || !std::isfinite(scale)) {
    if (scale != 0.0) return false;
    mu_.setZero();
    h_ = y;
    return true;
  }
  scaled_ = a / scale;
  tri_.compute(scaled_);
  mu_ = tri_.diagonal();
  sub_ = tri_.subDiagonal();
  h_ = tri_.matrixQ().adjoint() * y;
  double* d = mu_.data();
  double* e = sub_.data();
  // Deflation (§8.3.5): an off-diagonal entry below ε (|d_k| + |d_k+1|) is set to zero; the trailing
  // diagonal part grows until the whole matrix is diagonal.
  const auto negligible = [&](int k) {
    return std::abs(e[k]) <= std::numeric_limits<double>::epsilon() * (std::abs(d[k]) + std::abs(d[k + 1]));
  };
  int hi = static_cast<int>(n) - 1, sweeps = 0;
  while (hi > 0) {
    if (negligible(hi - 1)) {
      e[hi - 1] = 0.0;
      --hi;
      continue;
    }
    int lo = hi - 1;
    while (lo > 0 && !negligible(lo - 1)) --lo;
    if (++sweeps > 30 * static_cast<int>(n)) return false;
    qr_step(d, e, lo, hi, h_.data());
  }
  mu_ *= scale;
  // Ascending eigenvalues, the projections permuted with them (insertion sort: n is small, nothing allocated).
  for (Eigen::Index k = 1; k < n; ++k)
    for (Eigen::Index j = k; j > 0 && d[j] < d[j - 1]; --j) {
      std::swap(d[j], d[j - 1]);
      std::swap(h_[j], h_[j - 1]);
    }
  return true;
}

}  // namespace admitgen::numerics
