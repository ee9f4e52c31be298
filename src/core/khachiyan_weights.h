#pragma once

// The dual problem of the minimum-volume enclosing ellipse (minimumAreaEllipse(),
// enclosing_ellipse.cpp) and ellipsoid (minimumVolumeEllipsoid(), enclosing_ellipsoid.cpp), one
// solver for both dimensions, solved on a core set of points. Internal to the core (src/core).

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace ellipse_collision::core::detail {

// Points added to the core set per round at most: the worst violators (of a polygon, the peaks of
// the violating runs), so that a round settles several contact regions while the core stays small.
constexpr std::size_t kCoreAdditions = 16;

// Recompute the moment matrix from the weights this often, so that rounding in the rank-one
// updates cannot accumulate.
constexpr int kRefreshInterval = 32;

/// How the points given to KhachiyanWeights::solve() are arranged: it decides which violators
/// join the core.
enum class PointOrder {
  /// The vertices of a convex polygon in order: the violators come in runs around each place where
  /// the ellipse is too small, and only each run's peak joins (a dense polygon would otherwise
  /// fill the core with neighbours of one contact point).
  ConvexPolygon,
  /// Any set (a 3D hull's vertices): the worst violators join.
  Unordered,
};

/// Weighted centre and covariance of `points` under the weights `u` (summing to 1).
template <int Dim>
std::pair<Eigen::Matrix<double, Dim, 1>, Eigen::Matrix<double, Dim, Dim>> weightedMoments(
    const std::vector<Eigen::Matrix<double, Dim, 1>>& points, const std::vector<double>& u) {
  Eigen::Matrix<double, Dim, 1> c = Eigen::Matrix<double, Dim, 1>::Zero();
  for (std::size_t i = 0; i < points.size(); ++i) c += u[i] * points[i];
  Eigen::Matrix<double, Dim, Dim> s = Eigen::Matrix<double, Dim, Dim>::Zero();
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (u[i] > 0.0) {
      const Eigen::Matrix<double, Dim, 1> d = points[i] - c;
      s.noalias() += u[i] * d * d.transpose();
    }
  }
  return {c, s};
}

/// The weights of Khachiyan's dual problem, max log det X(u), X(u) = sum u_i q_i q_i^T over the
/// lifted points q_i = (p_i, 1) in R^(Dim+1), sum u_i = 1, u >= 0, restricted to a core set of
/// indices.
///
/// On the core, Khachiyan's algorithm with Todd–Yildirim away steps runs first: cheap steps that
/// converge fast on most sets. When the optimal weights are not unique (many points on the
/// optimal ellipse, as on co-circular sets or a sphere's mesh) its linear rate can be poor; then a
/// dual interior-point method finishes: Newton steps on log det X(u) + mu sum log u_i subject to
/// sum u_i = 1, with mu driven to gap / core size, each step a Cholesky solve of the k x k Hessian
/// (k the core size, which stays small: the core only gains the worst violators of each round).
template <int Dim>
class KhachiyanWeights {
 public:
  using Point = Eigen::Matrix<double, Dim, 1>;
  using Lifted = Eigen::Matrix<double, Dim + 1, 1>;
  using Moment = Eigen::Matrix<double, Dim + 1, Dim + 1>;
  /// The lifted dimension, the value of omega_i = q_i^T X^-1 q_i at every contact point.
  static constexpr double kLifted = Dim + 1;

  /// For `size` points in `order`; solve() stops after `max_steps` steps in all.
  KhachiyanWeights(std::size_t size, PointOrder order, int max_steps)
      : u_(size, 0.0), in_core_(size, 0), order_(order), max_steps_(max_steps) {}

  void addToCore(std::size_t i) {
    if (in_core_[i]) return;
    in_core_[i] = 1;
    core_.push_back(i);
  }
  void spreadUniformlyOverCore() {
    for (const std::size_t i : core_) u_[i] = 1.0 / static_cast<double>(core_.size());
  }
  const std::vector<double>& weights() const { return u_; }
  /// Whether the moment matrix of the weighted core is invertible (its lifted points span
  /// R^(Dim+1)).
  bool momentInvertible(const std::vector<Point>& points) const {
    return Eigen::FullPivLU<Moment>(moment(points)).rank() == Dim + 1;
  }

  /// Runs until every point satisfies omega_i <= kLifted (1 + gap) (or the step budget is spent);
  /// returns the achieved max omega_i / kLifted - 1 over all points, arranged as `order` says.
  double solve(const std::vector<Point>& points, double gap) {
    for (;;) {
      if (!solveCoreByKhachiyan(points, gap)) solveCoreByInteriorPoint(points, gap);
      const Moment inverse = moment(points).inverse();
      omega_.resize(points.size());
      double worst = 0.0;
      for (std::size_t i = 0; i < points.size(); ++i) {
        const Lifted q = lift(points[i]);
        omega_[i] = q.dot(inverse * q);
        worst = std::max(worst, omega_[i]);
      }
      std::vector<std::pair<double, std::size_t>> violators;
      const std::size_t n = points.size();
      if (order_ == PointOrder::ConvexPolygon) {  // each run's peak
        for (std::size_t i = 0; i < n; ++i) {
          const double before = omega_[(i + n - 1) % n], after = omega_[(i + 1) % n];
          if (!in_core_[i] && omega_[i] > kLifted * (1.0 + gap) && omega_[i] > before &&
              omega_[i] >= after) {
            violators.emplace_back(omega_[i], i);
          }
        }
      }
      // Unordered points, or a run of equal values without a strict peak: take them all.
      if (violators.empty()) {
        for (std::size_t i = 0; i < n; ++i) {
          if (!in_core_[i] && omega_[i] > kLifted * (1.0 + gap)) violators.emplace_back(omega_[i], i);
        }
      }
      if (violators.empty() || steps_ >= max_steps_) return worst / kLifted - 1.0;
      const std::size_t count = std::min(kCoreAdditions, violators.size());
      std::partial_sort(violators.begin(), violators.begin() + count, violators.end(),
                        [](const auto& a, const auto& b) { return a.first > b.first; });
      for (std::size_t k = 0; k < count; ++k) addToCore(violators[k].second);
    }
  }

 private:
  /// The lifted point (p, 1).
  static Lifted lift(const Point& p) {
    Lifted q;
    q << p, 1.0;
    return q;
  }

  Moment moment(const std::vector<Point>& points) const {
    Moment x = Moment::Zero();
    for (const std::size_t i : core_) {
      if (u_[i] > 0.0) {
        const Lifted q = lift(points[i]);
        x.noalias() += u_[i] * q * q.transpose();
      }
    }
    return x;
  }

  /// Todd–Yildirim: move weight towards the core point with the largest omega, or away from the
  /// weighted one with the smallest, whichever is further from optimality, by the step that
  /// maximises log det X exactly. True when the core is optimal to `gap` within
  /// kKhachiyanSteps steps.
  bool solveCoreByKhachiyan(const std::vector<Point>& points, double gap) {
    Moment x = moment(points);
    int since_refresh = 0;
    for (int round = 0; round < kKhachiyanSteps && steps_ < max_steps_; ++round) {
      ++steps_;
      const Moment inverse = x.inverse();
      std::size_t up = core_.front(), down = core_.front();
      double omega_up = -1.0, omega_down = std::numeric_limits<double>::infinity();
      for (const std::size_t i : core_) {
        const Lifted q = lift(points[i]);
        const double omega = q.dot(inverse * q);
        if (omega > omega_up) omega_up = omega, up = i;
        if (u_[i] > 0.0 && omega < omega_down) omega_down = omega, down = i;
      }
      const double gap_up = omega_up / kLifted - 1.0;
      const double gap_down = 1.0 - omega_down / kLifted;
      if (gap_up <= gap && gap_down <= gap) return true;

      std::size_t index;
      double step;  // u <- (1 - step) u + step e_index; negative for an away step
      bool drop = false;
      if (gap_up > gap_down) {
        index = up;
        step = (omega_up - kLifted) / (kLifted * (omega_up - 1.0));
      } else {
        index = down;
        const double limit = -u_[down] / (1.0 - u_[down]);  // takes u_down to exactly 0
        step = omega_down > 1.0 ? (omega_down - kLifted) / (kLifted * (omega_down - 1.0)) : limit;
        if (step <= limit) step = limit, drop = true;
      }
      for (const std::size_t i : core_) u_[i] *= 1.0 - step;
      u_[index] = drop ? 0.0 : u_[index] + step;
      const Lifted q = lift(points[index]);
      x = (1.0 - step) * x + step * q * q.transpose();
      if (drop || ++since_refresh == kRefreshInterval) {
        normaliseWeights();
        x = moment(points);
        since_refresh = 0;
      }
    }
    return false;
  }

  void normaliseWeights() {
    double sum = 0.0;
    for (const std::size_t i : core_) sum += u_[i];
    for (const std::size_t i : core_) u_[i] /= sum;
  }

  /// log det X(v) + mu sum log v_i for core weights `v` (rows of `q` the lifted core points),
  /// or -inf outside the domain.
  static double barrier(const Eigen::MatrixXd& q, const Eigen::VectorXd& v, double mu) {
    if (v.minCoeff() <= 0.0) return -std::numeric_limits<double>::infinity();
    Moment x = Moment::Zero();
    for (Eigen::Index i = 0; i < q.rows(); ++i) {
      x.noalias() += v[i] * q.row(i).transpose() * q.row(i);
    }
    const double det = x.determinant();
    if (!(det > 0.0)) return -std::numeric_limits<double>::infinity();
    return std::log(det) + mu * v.array().log().sum();
  }

  void solveCoreByInteriorPoint(const std::vector<Point>& points, double gap) {
    const Eigen::Index k = static_cast<Eigen::Index>(core_.size());
    const double size = static_cast<double>(k);
    normaliseWeights();
    Eigen::MatrixXd q(k, Dim + 1);
    for (Eigen::Index i = 0; i < k; ++i) q.row(i) = lift(points[core_[i]]).transpose();
    // Warm start: mu from the current gap (omega_i <= kLifted + k mu on the central path), weights
    // moved off the simplex's faces by about mu (where inactive weights sit on the path).
    const Moment start_inverse = moment(points).inverse();
    double worst = 0.0;
    for (Eigen::Index i = 0; i < k; ++i) {
      worst = std::max(worst, q.row(i).dot(start_inverse * q.row(i).transpose()));
    }
    // Stop at mu with k mu / kLifted = gap / 10: the margin absorbs the inexact centring.
    const double final_mu = (kLifted / 10.0) * gap / size;
    double mu = std::clamp(kLifted * (worst / kLifted - 1.0) / size, final_mu, 1e-2 / size);
    Eigen::VectorXd v(k);
    for (Eigen::Index i = 0; i < k; ++i) v[i] = u_[core_[i]] + mu;
    v /= v.sum();

    // Newton on max f(v) = log det X(v) + mu sum log v_i subject to sum v_i = 1: with
    // M = G o G + diag(mu / v^2) (G_ij = q_i^T X^-1 q_j, o the elementwise product), positive
    // definite, the step is d = M^-1 grad - nu M^-1 1 with nu making sum d_i = 0.
    Eigen::MatrixXd qi(Dim + 1, k), g(k, k), m(k, k);
    Eigen::VectorXd grad(k), a(k), b(k), d(k), md(k), trial(k);
    const Eigen::VectorXd ones = Eigen::VectorXd::Ones(k);
    Eigen::LLT<Eigen::MatrixXd> llt(k);
    for (;; mu = std::max(mu * kMuReduction, final_mu)) {
      for (int newton = 0; newton < kNewtonStepsPerStage && steps_ < max_steps_;
           ++newton) {
        ++steps_;
        Moment x = Moment::Zero();
        for (Eigen::Index i = 0; i < k; ++i) x.noalias() += v[i] * q.row(i).transpose() * q.row(i);
        qi.noalias() = x.inverse() * q.transpose();
        g.noalias() = q * qi;
        m = g.cwiseAbs2();
        m.diagonal().array() += mu / v.array().square();
        grad = g.diagonal().array() + mu / v.array();
        llt.compute(m);
        if (llt.info() != Eigen::Success) break;
        a = llt.solve(grad);
        b = llt.solve(ones);
        d = a - (a.sum() / b.sum()) * b;
        md.noalias() = m * d;
        const double ascent = d.dot(md);  // the squared Newton decrement, = grad . d
        // Intermediate stages only need rough centring; the last one must bring the spread of
        // omega well below the gap, which a decrement relative to mu does not ensure when every
        // weight is large (then the barrier term hardly curves f).
        const double tolerance = mu <= final_mu ? kFinalCentring * gap * gap : kCentringTolerance * mu;
        if (!(ascent > tolerance)) break;
        double alpha = 1.0;
        for (Eigen::Index i = 0; i < k; ++i) {
          if (d[i] < 0.0) alpha = std::min(alpha, -0.95 * v[i] / d[i]);
        }
        // -f / mu is self-concordant with Newton decrement^2 = ascent / mu: below 1/16 the full
        // step is safe and converges quadratically, so no line search on f, whose changes there
        // drown in its rounding.
        if (ascent > kFullStepDecrement * mu) {
          const double f0 = barrier(q, v, mu);
          int halvings = 0;
          for (;; alpha *= 0.5) {
            trial = v + alpha * d;
            if (barrier(q, trial, mu) >= f0 + 0.25 * alpha * ascent || ++halvings > kMaxHalvings) {
              break;
            }
          }
          if (halvings > kMaxHalvings) break;  // rounding floor
        } else {
          trial = v + alpha * d;
        }
        v = trial / trial.sum();
      }
      if (mu <= final_mu || steps_ >= max_steps_) break;
    }
    for (Eigen::Index i = 0; i < k; ++i) u_[core_[i]] = v[i];
  }

  // Khachiyan steps per core round before the interior-point method takes over: enough for the
  // sets where its linear rate is good, few enough not to waste time where it is not.
  static constexpr int kKhachiyanSteps = 100;
  static constexpr double kMuReduction = 0.1;
  static constexpr int kNewtonStepsPerStage = 50;
  // Newton stops when the decrement of f / mu is below this: centred far more closely than the
  // stage's gap needs.
  static constexpr double kCentringTolerance = 1e-3;
  // ... and in the last stage below this times gap^2.
  static constexpr double kFinalCentring = 1e-4;
  static constexpr int kMaxHalvings = 60;
  static constexpr double kFullStepDecrement = 1.0 / 16.0;

  std::vector<double> u_;
  std::vector<double> omega_;
  std::vector<char> in_core_;
  std::vector<std::size_t> core_;
  PointOrder order_;
  int max_steps_;
  int steps_{0};
};

}  // namespace ellipse_collision::core::detail
