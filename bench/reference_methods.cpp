#include "reference_methods.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace ellipse_collision::core::bench {
namespace {

std::unique_ptr<fcl::CollisionObjectd> fclObject(const Ellipse& e) {
  auto shape =
      std::make_shared<fcl::Ellipsoidd>(e.radius_x, e.radius_y, std::min(e.radius_x, e.radius_y));
  fcl::Transform3d pose = fcl::Transform3d::Identity();
  pose.translation() = fcl::Vector3d(e.center.x(), e.center.y(), 0.0);
  pose.linear() = fcl::AngleAxisd(e.angle, fcl::Vector3d::UnitZ()).toRotationMatrix();
  return std::make_unique<fcl::CollisionObjectd>(shape, pose);
}

/// Quadratic-form matrix A of {x : (x - c)^T A (x - c) <= 1}.
Eigen::Matrix2d quadraticForm(const Ellipse& e) {
  const Eigen::Matrix2d rotation = Eigen::Rotation2Dd(e.angle).toRotationMatrix();
  const Eigen::Vector2d inverse_squares(1.0 / (e.radius_x * e.radius_x),
                                        1.0 / (e.radius_y * e.radius_y));
  return rotation * inverse_squares.asDiagonal() * rotation.transpose();
}

// The demo's optimiser settings.
constexpr double kDifferenceStep = 1e-4;
constexpr double kLearningRate = 1e-2;
constexpr double kGradientTolerance = 1e-3;
constexpr int kMaxIterations = 100;

}  // namespace

FclEllipse::FclEllipse(const Ellipse& ellipse) : object_(fclObject(ellipse)) {}

bool fclCollide(const FclEllipse& a, const FclEllipse& b) {
  fcl::CollisionRequestd request;
  fcl::CollisionResultd result;
  fcl::collide(a.object(), b.object(), request, result);
  return result.isCollision();
}

bool seedReadmeOverlap(const Ellipse& a, const Ellipse& b) {
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::Matrix2d> solver(
      quadraticForm(a).inverse(), quadraticForm(b).inverse());
  const Eigen::Array2d lambda = solver.eigenvalues().array();
  const Eigen::Array2d v_squared =
      (solver.eigenvectors().transpose() * (a.center - b.center)).array().square();
  const auto k = [&](double s) {
    return 1.0 - (v_squared * (s * (1.0 - s) / (1.0 + s * (lambda - 1.0)))).sum();
  };
  const auto gradient = [&](double s) { return (k(s + kDifferenceStep) - k(s)) / kDifferenceStep; };

  double s = 0.5;
  double slope = gradient(s);
  for (int i = 0; i < kMaxIterations && std::abs(slope) > kGradientTolerance; ++i) {
    // Kept inside (0, 1), where K is defined.
    s = std::clamp(s - kLearningRate * slope, kDifferenceStep, 1.0 - 2.0 * kDifferenceStep);
    slope = gradient(s);
  }
  return k(s) >= 0.0;
}

}  // namespace ellipse_collision::core::bench
