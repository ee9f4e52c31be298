#include "ellipse_collision/app/scan_obstacles.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "ellipse_collision/core/number_format.h"
#include "ellipse_collision/core/scan_contours.h"

namespace ellipse_collision::app {
namespace {

// A hinted cut is let go only when the runs on either side fit one ellipse with this many range
// noise sigmas to spare (core::contourEllipses()). Measured (test_scan_contours, 60 scans of the
// room at 1 cm noise): with 1, 14 names new to their scan (309 without hints) and as many
// ellipses as without; with 2, 6 new names but 11 % more ellipses, and more where the sensor moves.
constexpr double kHintMarginSigmas = 1.0;

SensorObstacles toSpecs(const core::ContourEllipses& fit, const std::string& frame_id,
                        const ScanObstacleSettings& settings, std::size_t key_ring) {
  SensorObstacles result;
  result.key_ring = std::max<std::size_t>(key_ring, 1);
  result.skipped = fit.skipped;
  result.unneeded_hints = fit.unneeded_hints;
  if (!fit.error.empty()) result.skipped.push_back(fit.error);
  result.ellipses.reserve(fit.ellipses.size());
  result.spans.reserve(fit.ellipses.size());
  std::unordered_map<std::size_t, std::size_t> starts;  // ellipses so far per key
  for (const core::ContourEllipse& contour : fit.ellipses) {
    const core::Ellipse& e = contour.ellipse;
    const std::size_t earlier = starts[contour.key]++;
    result.ellipses.push_back(
        planarSpec(e,
                   settings.name_prefix + std::to_string(contour.key) +
                       (earlier > 0 ? "_" + std::to_string(earlier) : std::string()),
                   frame_id));
    result.spans.push_back({contour.key, contour.last_key});
  }
  return result;
}

/// `result.objects`: each contour's centroid and extent, and the ellipses whose first return is
/// one of its returns.
void addObjects(const std::vector<std::vector<core::SensorReturn>>& contours,
                const core::ContourEllipses& fit, const std::vector<float>* ranges,
                double join_distance, SensorObstacles& result) {
  // A key in two contours (a cloud's angular bin holds points at several ranges) leaves the
  // ellipse starting there in no object: it stands.
  constexpr std::size_t kAmbiguous = static_cast<std::size_t>(-1);
  constexpr std::size_t kNone = kAmbiguous - 1;
  // Keys are beams or bins, below key_ring: a table, not a hash map of every return.
  std::vector<std::size_t> contour_of_key(result.key_ring, kNone);
  result.objects.reserve(contours.size());
  for (const std::vector<core::SensorReturn>& contour : contours) {
    SensorObject object;
    for (const core::SensorReturn& r : contour) {
      object.centroid += r.point;
      if (r.key >= contour_of_key.size()) contour_of_key.resize(r.key + 1, kNone);
      std::size_t& of_key = contour_of_key[r.key];
      if (of_key == kNone) {
        of_key = result.objects.size();
      } else if (of_key != result.objects.size()) {
        of_key = kAmbiguous;
      }
    }
    if (!contour.empty()) object.centroid /= static_cast<double>(contour.size());
    for (const core::SensorReturn& r : contour) {
      object.extent = std::max(object.extent, (r.point - object.centroid).norm());
    }
    if (ranges && !contour.empty() && !ranges->empty()) {
      // The beams beside the contour's ends (keys are beam indices, on a ring).
      const std::size_t n = ranges->size();
      const auto hides = [&](const core::SensorReturn& end, std::size_t beside) {
        const float r = (*ranges)[beside % n];
        return std::isnan(r) || r < end.point.norm() - join_distance;
      };
      object.occluded = hides(contour.front(), contour.front().key + n - 1) ||
                        hides(contour.back(), contour.back().key + 1);
    }
    result.objects.push_back(object);
  }
  for (std::size_t i = 0; i < fit.ellipses.size(); ++i) {
    const std::size_t key = fit.ellipses[i].key;
    const std::size_t of_key = key < contour_of_key.size() ? contour_of_key[key] : kNone;
    if (of_key != kNone && of_key != kAmbiguous) result.objects[of_key].ellipses.push_back(i);
  }
  // Contours that got no ellipse (too few returns) are no object.
  result.objects.erase(std::remove_if(result.objects.begin(), result.objects.end(),
                                      [](const SensorObject& o) { return o.ellipses.empty(); }),
                       result.objects.end());
}

}  // namespace

std::optional<FieldError> findInvalidSetting(const ScanObstacleSettings& s) {
  if (auto e = findOutsideRange("cluster_distance", s.cluster_distance, kMinClusterDistance,
                                kMaxClusterDistance)) {
    return e;
  }
  if (s.min_cluster_points < 1 || s.min_cluster_points > kMaxClusterPoints) {
    return FieldError{"min_cluster_points",
                      "an integer within [1, " + std::to_string(kMaxClusterPoints) + "]",
                      std::to_string(s.min_cluster_points)};
  }
  if (auto e = findOutsideRange("min_radius", s.min_radius, core::kMinRadius, core::kMaxRadius))
    return e;
  if (auto e = findOutsideRange("range_noise_sigma", s.range_noise_sigma, 0.0, kMaxRangeNoiseSigma))
    return e;
  if (auto e = findOutsideRange("free_space_tolerance", s.free_space_tolerance,
                                kMinFreeSpaceTolerance, kMaxFreeSpaceTolerance)) {
    return e;
  }
  if (!std::isfinite(s.z_min)) return FieldError{"z_min", "a finite number", core::formatNumber(s.z_min)};
  if (!std::isfinite(s.z_max)) return FieldError{"z_max", "a finite number", core::formatNumber(s.z_max)};
  if (s.z_max < s.z_min) {
    return FieldError{"z_max", "a number >= z_min = " + core::formatNumber(s.z_min),
                      core::formatNumber(s.z_max)};
  }
  if (s.name_prefix.empty()) return FieldError{"name_prefix", "a non-empty string", "''"};
  return std::nullopt;
}

SensorObstacles scanObstacles(const std::vector<float>& ranges, double angle_min,
                              double angle_increment, double range_min, double range_max,
                              const std::string& frame_id, const ScanObstacleSettings& settings,
                              const std::vector<std::size_t>& split_hints) {
  ScanBuffers buffers;
  return scanObstacles(ranges, angle_min, angle_increment, range_min, range_max, frame_id, settings,
                       split_hints, buffers);
}

SensorObstacles scanObstacles(const std::vector<float>& ranges, double angle_min,
                              double angle_increment, double range_min, double range_max,
                              const std::string& frame_id, const ScanObstacleSettings& settings,
                              const std::vector<std::size_t>& split_hints, ScanBuffers& buffers) {
  core::scanView(ranges, angle_min, angle_increment, range_min, range_max,
                 settings.free_space_tolerance, buffers.beams, buffers.view);
  const core::SensorView& view = buffers.view;
  const auto contours =
      core::breakContours(view, settings.range_noise_sigma, settings.cluster_distance,
                          static_cast<std::size_t>(settings.min_cluster_points));
  const core::ContourEllipses fit =
      core::contourEllipses(contours, view.free_space, settings.min_radius, split_hints,
                            kHintMarginSigmas * settings.range_noise_sigma);
  SensorObstacles result = toSpecs(fit, frame_id, settings, ranges.size());
  addObjects(contours, fit, &ranges, settings.cluster_distance, result);
  return result;
}

SensorObstacles cloudObstacles(const std::vector<Eigen::Vector3f>& points,
                               const std::string& frame_id, const ScanObstacleSettings& settings,
                              const std::vector<std::size_t>& split_hints) {
  std::vector<Eigen::Vector2d> band;
  band.reserve(points.size());
  for (const Eigen::Vector3f& p : points) {
    // NaN z fails both comparisons: dropped, like NaN x or y later.
    if (p.z() >= settings.z_min && p.z() <= settings.z_max) band.emplace_back(p.x(), p.y());
  }
  const core::SensorView view = core::cloudView(band, settings.free_space_tolerance);
  const auto contours = core::cloudContours(view, settings.cluster_distance,
                                            static_cast<std::size_t>(settings.min_cluster_points));
  const core::ContourEllipses fit =
      core::contourEllipses(contours, view.free_space, settings.min_radius, split_hints,
                            kHintMarginSigmas * settings.range_noise_sigma);
  SensorObstacles result = toSpecs(fit, frame_id, settings, core::kCloudBins);
  addObjects(contours, fit, nullptr, settings.cluster_distance, result);
  return result;
}

}  // namespace ellipse_collision::app
