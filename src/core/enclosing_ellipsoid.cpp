#include "ellipse_collision/core/enclosing_ellipsoid.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/SVD>
#include <Eigen/LU>
#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>

#include "ellipse_collision/core/number_format.h"
#include "ellipsoid_detail.h"

namespace ellipse_collision::core {
namespace {

using Vec3 = Eigen::Vector3d;
using Vec4 = Eigen::Vector4d;
using Mat3 = Eigen::Matrix3d;
using Mat4 = Eigen::Matrix4d;
using LD = long double;

// The first pass only has to find a frame in which the ellipsoid is round; the second pass, in
// that frame, goes down to kEnclosingEllipsoidGapTolerance (as the 2D fit's passes).
constexpr double kCoarseGap = 1e-3;
// The lifted dimension of Khachiyan's algorithm: points (x, y, z, 1) in R^4.
constexpr double kLifted = 4.0;
// Violators added to the core per round at most, worst first.
constexpr std::size_t kCoreAdditions = 16;
// Recompute the moment matrix from the weights this often, against drift in the rank-one updates.
constexpr int kRefreshInterval = 32;
// Rounds of the certification; one suffices unless rounding conspires.
constexpr int kCertificationRounds = 8;

Vec4 lift(const Vec3& p) { return {p.x(), p.y(), p.z(), 1.0}; }

/// An affine map x -> origin + linear * x, composed as the frames below are nested.
struct Affine {
  Vec3 origin{Vec3::Zero()};
  Mat3 linear{Mat3::Identity()};
  Vec3 apply(const Vec3& x) const { return origin + linear * x; }
  /// this o inner.
  Affine then(const Affine& inner) const { return {apply(inner.origin), linear * inner.linear}; }
};

/// Khachiyan's dual problem, max log det X(u), X(u) = sum u_i q_i q_i^T, restricted to a growing
/// core set: the 3D form of the 2D fit's WeightSolver (khachiyan_weights.h) without its polygon
/// ordering. Steps: Todd–Yildirim (towards the core point of largest omega, or away from the
/// weighted one of smallest omega, by the exact line maximiser of log det X).
class EllipsoidWeights {
 public:
  explicit EllipsoidWeights(std::vector<Vec3> points)
      : points_(std::move(points)), u_(points_.size(), 0.0), in_core_(points_.size(), 0) {}

  void addToCore(std::size_t i) {
    if (in_core_[i]) return;
    in_core_[i] = 1;
    core_.push_back(i);
  }
  std::size_t coreSize() const { return core_.size(); }
  const std::vector<double>& weights() const { return u_; }
  const std::vector<Vec3>& points() const { return points_; }

  /// The weighted centre c and covariance S of the points.
  std::pair<Vec3, Mat3> moments() const {
    Vec3 c = Vec3::Zero();
    for (const std::size_t i : core_) c += u_[i] * points_[i];
    Mat3 s = Mat3::Zero();
    for (const std::size_t i : core_) {
      if (u_[i] > 0.0) s.noalias() += u_[i] * (points_[i] - c) * (points_[i] - c).transpose();
    }
    return {c, s};
  }

  /// Moves the points into `frame` (p -> frame^-1 p). The weights are affine-invariant, so the
  /// optimiser continues where it was.
  void moveInto(const Affine& frame) {
    const Mat3 inverse = frame.linear.inverse();
    for (Vec3& p : points_) p = inverse * (p - frame.origin);
  }

  /// Uniform weights on the core; false if its lifted points do not span R^4.
  bool start() {
    for (const std::size_t i : core_) u_[i] = 1.0 / static_cast<double>(core_.size());
    return Eigen::FullPivLU<Mat4>(moment()).rank() == 4;
  }

  /// Runs until every point has omega_i <= 4 (1 + gap) or the step budget is spent; returns the
  /// achieved max omega_i / 4 - 1 over all points.
  double solve(double gap) {
    for (;;) {
      solveCore(gap);
      const Mat4 inverse = moment().inverse();
      std::vector<std::pair<double, std::size_t>> violators;
      double worst = 0.0;
      for (std::size_t i = 0; i < points_.size(); ++i) {
        const Vec4 q = lift(points_[i]);
        const double omega = q.dot(inverse * q);
        worst = std::max(worst, omega);
        if (!in_core_[i] && omega > kLifted * (1.0 + gap)) violators.emplace_back(omega, i);
      }
      if (violators.empty() || steps_ >= kMaxEllipsoidOptimiserSteps) return worst / kLifted - 1.0;
      const std::size_t count = std::min(kCoreAdditions, violators.size());
      std::partial_sort(violators.begin(), violators.begin() + count, violators.end(),
                        [](const auto& a, const auto& b) { return a.first > b.first; });
      for (std::size_t k = 0; k < count; ++k) addToCore(violators[k].second);
    }
  }

 private:
  Mat4 moment() const {
    Mat4 x = Mat4::Zero();
    for (const std::size_t i : core_) {
      if (u_[i] > 0.0) {
        const Vec4 q = lift(points_[i]);
        x.noalias() += u_[i] * q * q.transpose();
      }
    }
    return x;
  }

  void normaliseWeights() {
    double sum = 0.0;
    for (const std::size_t i : core_) sum += u_[i];
    for (const std::size_t i : core_) u_[i] /= sum;
  }

  void solveCore(double gap) {
    Mat4 x = moment();
    int since_refresh = 0;
    while (steps_ < kMaxEllipsoidOptimiserSteps) {
      ++steps_;
      const Mat4 inverse = x.inverse();
      std::size_t up = core_.front(), down = core_.front();
      double omega_up = -1.0, omega_down = std::numeric_limits<double>::infinity();
      for (const std::size_t i : core_) {
        const Vec4 q = lift(points_[i]);
        const double omega = q.dot(inverse * q);
        if (omega > omega_up) omega_up = omega, up = i;
        if (u_[i] > 0.0 && omega < omega_down) omega_down = omega, down = i;
      }
      const double gap_up = omega_up / kLifted - 1.0;
      const double gap_down = 1.0 - omega_down / kLifted;
      if (gap_up <= gap && gap_down <= gap) return;

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
      const Vec4 q = lift(points_[index]);
      x = (1.0 - step) * x + step * q * q.transpose();
      if (drop || ++since_refresh == kRefreshInterval) {
        normaliseWeights();
        x = moment();
        since_refresh = 0;
      }
    }
  }

  std::vector<Vec3> points_;
  std::vector<double> u_;
  std::vector<char> in_core_;
  std::vector<std::size_t> core_;
  int steps_{0};
};

EnclosingEllipsoid errorResult(std::string message) {
  EnclosingEllipsoid result;
  result.error = std::move(message);
  return result;
}

std::string validationError(const std::vector<Vec3>& points) {
  if (points.empty()) return "points is empty";
  const char* const axes[] = {"x", "y", "z"};
  for (std::size_t i = 0; i < points.size(); ++i) {
    for (int axis = 0; axis < 3; ++axis) {
      if (auto violation = coordinateViolation(points[i][axis])) {
        return renderViolation(
            ("points[" + std::to_string(i) + "]." + axes[axis]).c_str(), *violation);
      }
    }
  }
  return {};
}

/// The largest normalised quadratic form |diag(r)^-1 R^T (p - c)|^2 over the points, in long
/// double from the double fields.
LD largestQuadraticForm(const Ellipsoid& e, const std::vector<Vec3>& points) {
  const detail::LongMat3 transposed = detail::rotationOf(e.orientation).transpose();
  const Eigen::Matrix<LD, 3, 1> inverse_radii = e.radii.cast<LD>().cwiseInverse();
  LD worst = 0.0L;
  for (const Vec3& p : points) {
    const Eigen::Matrix<LD, 3, 1> y =
        (transposed * (p.cast<LD>() - e.center.cast<LD>())).cwiseProduct(inverse_radii);
    worst = std::max(worst, y.squaredNorm());
  }
  return worst;
}

/// Seeds the core with the extreme points along the axes, the cube's diagonals and the set's
/// principal directions (so that the core spans the set's thinnest direction too).
void seedCore(const std::vector<Vec3>& z, const Mat3& principal, EllipsoidWeights& weights) {
  std::vector<Vec3> directions;
  for (int i = 0; i < 3; ++i) directions.push_back(Vec3::Unit(i)), directions.push_back(principal.col(i));
  for (const double sy : {-1.0, 1.0}) {
    for (const double sz : {-1.0, 1.0}) directions.push_back(Vec3(1.0, sy, sz));
  }
  for (const Vec3& d : directions) {
    for (const double sign : {-1.0, 1.0}) {
      std::size_t best = 0;
      for (std::size_t i = 1; i < z.size(); ++i) {
        if (sign * z[i].dot(d) > sign * z[best].dot(d)) best = i;
      }
      weights.addToCore(best);
    }
  }
}

}  // namespace

// The 2D fit's certify() in three dimensions: the long double evaluation's rounding (a few
// epsilons times the axis ratio) is kept as a margin below 1.
bool growToContain(Ellipsoid& e, const std::vector<Eigen::Vector3d>& points) {
  const LD eps = std::numeric_limits<LD>::epsilon();
  for (int round = 0; round < kCertificationRounds; ++round) {
    if (!e.radii.allFinite()) return false;
    const LD ratio = static_cast<LD>(e.radii.maxCoeff()) / e.radii.minCoeff();
    const LD limit = 1.0L - 64.0L * eps * (1.0L + ratio);
    const LD worst = largestQuadraticForm(e, points);
    if (worst <= limit) return true;
    const LD factor = std::sqrt(worst / limit) * (1.0L + 4.0L * DBL_EPSILON);
    for (int i = 0; i < 3; ++i) e.radii[i] = detail::roundedUp(e.radii[i] * factor);
  }
  return false;
}

EnclosingEllipsoid minimumVolumeEllipsoid(const std::vector<Eigen::Vector3d>& points) {
  if (std::string error = validationError(points); !error.empty()) return errorResult(error);

  // Unit frame: the bounding box's centre and half-extent, so that 1e6 offsets and 1e-4 sizes
  // look alike to the optimiser.
  Vec3 low = points.front(), high = points.front();
  for (const Vec3& p : points) low = low.cwiseMin(p), high = high.cwiseMax(p);
  const Vec3 origin = 0.5 * (low + high);
  const double scale = 0.5 * (high - low).maxCoeff();
  const std::string flat = "the points span no volume (flat or fewer than 4 independent points)";
  if (!(scale > 0.0)) return errorResult(flat);
  std::vector<Vec3> z;
  z.reserve(points.size());
  for (const Vec3& p : points) z.push_back((p - origin) / scale);

  // Thickness along the thinnest principal direction, in units of `scale` (the extent is 2..3.5).
  Vec3 mean = Vec3::Zero();
  for (const Vec3& p : z) mean += p;
  mean /= static_cast<double>(z.size());
  Mat3 covariance = Mat3::Zero();
  for (const Vec3& p : z) covariance.noalias() += (p - mean) * (p - mean).transpose();
  const Eigen::SelfAdjointEigenSolver<Mat3> principal(covariance);
  Vec3 extent = Vec3::Zero();
  for (const Vec3& p : z) {
    extent = extent.cwiseMax((principal.eigenvectors().transpose() * (p - mean)).cwiseAbs());
  }
  const double thickness = extent.minCoeff();
  if (thickness <= kDegenerateRelativeThickness || thickness * scale < kMinRadius) {
    return errorResult(flat + " (thickness " + formatNumber(2.0 * thickness * scale) + " m)");
  }

  // First pass in the frame of the principal axes scaled to the extents along them (thin sets
  // look round), second in the frame where the first estimate is a ball: there the moment matrix
  // is well conditioned however thin the set, so omega keeps full double precision.
  const Affine unit{origin, scale * Mat3::Identity()};
  const Affine axes{mean, principal.eigenvectors() * extent.asDiagonal()};
  EllipsoidWeights weights(std::move(z));
  weights.moveInto(axes);
  seedCore(weights.points(), Mat3::Identity(), weights);
  if (!weights.start()) {  // the extreme points happen to be coplanar: start from all of them
    for (std::size_t i = 0; i < points.size(); ++i) weights.addToCore(i);
    if (!weights.start()) return errorResult(flat);
  }
  weights.solve(kCoarseGap);
  const auto [coarse_centre, coarse_covariance] = weights.moments();
  const Affine round{coarse_centre, Eigen::LLT<Mat3>(coarse_covariance).matrixL()};
  weights.moveInto(round);
  const double gap = weights.solve(kEnclosingEllipsoidGapTolerance);

  // {c + sqrt(reach) L y}, L L^T the weighted covariance, reach the largest Mahalanobis radius:
  // contains every point by construction (up to rounding, which the certification covers).
  const auto [c, s] = weights.moments();
  const Mat3 l = Eigen::LLT<Mat3>(s).matrixL();
  const Mat3 inverse = s.inverse();
  double reach = 0.0;
  for (const Vec3& p : weights.points()) reach = std::max(reach, (p - c).dot(inverse * (p - c)));
  const Affine fitted{c, std::sqrt(reach) * l};
  const Affine total = unit.then(axes).then(round).then(fitted);
  // The ellipsoid {origin + G y : |y| <= 1}: radii and axes from G's singular value decomposition
  // (one-sided Jacobi: small singular values keep their relative precision).
  const Eigen::JacobiSVD<Mat3> svd(total.linear, Eigen::ComputeFullU);
  Mat3 rotation = svd.matrixU();
  if (rotation.determinant() < 0.0) rotation.col(2) = -rotation.col(2);

  EnclosingEllipsoid result;
  result.ellipsoid.center = total.origin;
  result.ellipsoid.orientation = Eigen::Quaterniond(rotation).normalized();
  result.ellipsoid.radii = svd.singularValues();
  // volume = (4/3) pi sqrt(det S) reach^(3/2) with det S <= det S* (dual optimality) and
  // reach <= 3 + 4 gap: volume / minimum <= (1 + 4 gap / 3)^(3/2), about 1 + 2 gap.
  result.volume_excess_bound = std::max(0.0, 2.0 * gap);
  if (!(result.ellipsoid.radii.minCoeff() > 0.0) || !growToContain(result.ellipsoid, points)) {
    return errorResult("the enclosing ellipsoid could not be certified");
  }
  if (std::string reason = invalidReason(result.ellipsoid); !reason.empty()) {
    return errorResult("the enclosing ellipsoid is out of range: " + reason);
  }
  result.ok = true;
  return result;
}

}  // namespace ellipse_collision::core
