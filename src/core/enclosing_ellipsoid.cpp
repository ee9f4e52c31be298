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
#include "khachiyan_weights.h"

namespace ellipse_collision::core {
namespace {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
using LD = long double;
using WeightSolver = detail::KhachiyanWeights<3>;

// The first pass only has to find a frame in which the ellipsoid is round; the second pass, in
// that frame, goes down to kEnclosingEllipsoidGapTolerance (as the 2D fit's passes).
constexpr double kCoarseGap = 1e-3;
// Rounds of the certification; one suffices unless rounding conspires.
constexpr int kCertificationRounds = 8;

/// An affine map x -> origin + linear * x, composed as the frames below are nested.
struct Affine {
  Vec3 origin{Vec3::Zero()};
  Mat3 linear{Mat3::Identity()};
  Vec3 apply(const Vec3& x) const { return origin + linear * x; }
  /// this o inner.
  Affine then(const Affine& inner) const { return {apply(inner.origin), linear * inner.linear}; }
};

/// The points in `frame` (p -> frame^-1 p); the solver's weights are affine-invariant, so it
/// continues where it was.
void moveInto(const Affine& frame, std::vector<Vec3>& points) {
  const Mat3 inverse = frame.linear.inverse();
  for (Vec3& p : points) p = inverse * (p - frame.origin);
}

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
void seedCore(const std::vector<Vec3>& z, const Mat3& principal, WeightSolver& weights) {
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
  WeightSolver weights(z.size(), detail::PointOrder::Unordered, kMaxEllipsoidOptimiserSteps);
  moveInto(axes, z);
  seedCore(z, Mat3::Identity(), weights);
  weights.spreadUniformlyOverCore();
  if (!weights.momentInvertible(z)) {  // the extreme points happen to be coplanar: take them all
    for (std::size_t i = 0; i < z.size(); ++i) weights.addToCore(i);
    weights.spreadUniformlyOverCore();
    if (!weights.momentInvertible(z)) return errorResult(flat);
  }
  weights.solve(z, kCoarseGap);
  const auto [coarse_centre, coarse_covariance] = detail::weightedMoments(z, weights.weights());
  const Affine round{coarse_centre, Eigen::LLT<Mat3>(coarse_covariance).matrixL()};
  moveInto(round, z);
  const double gap = weights.solve(z, kEnclosingEllipsoidGapTolerance);

  // {c + sqrt(reach) L y}, L L^T the weighted covariance, reach the largest Mahalanobis radius:
  // contains every point by construction (up to rounding, which the certification covers).
  const auto [c, s] = detail::weightedMoments(z, weights.weights());
  const Mat3 l = Eigen::LLT<Mat3>(s).matrixL();
  const Mat3 inverse = s.inverse();
  double reach = 0.0;
  for (const Vec3& p : z) reach = std::max(reach, (p - c).dot(inverse * (p - c)));
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
