#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include "ellipse_collision/app/scan_obstacles.h"

namespace ellipse_collision::app {

/// Where one laser's last scans cut their contours, kept so that range noise does not make the
/// split flicker (a wall stretch cut in one scan and not in the next, an end return peeled off
/// alone and then not): a cut is offered to the next scan as a hint (core::contourEllipses())
/// where the scene did not change, that is where the two beams on either side of it read the
/// same as in the last scan within the noise (kSameRangeSigmas range_noise_sigma, and the same
/// kind of reading: a return, no return, unknown). A cut is let go once the runs on either side
/// of it were one ellipse together, with noise to spare, in kUnneededMessages scans in a row. So
/// a cut that noise needs now and then stays, and where the sensor moved (other ranges) the scan
/// is split afresh. The guarantees of every scan hold whatever the hints.
class ScanCutMemory {
 public:
  static constexpr std::size_t kUnneededMessages = 2;
  /// Two readings of one unchanged surface differ by sqrt(2) sigma (one standard deviation):
  /// three of those cover 99.7 % of them.
  static constexpr double kSameRangeSigmas = 3.0 * 1.4142135623730951;

  /// The hints for a scan of `ranges` [m] in `frame_id`, with range noise `range_noise_sigma`
  /// [m] (ascending beam indices); none when the last scan was of another beam count or frame.
  std::vector<std::size_t> hints(const std::vector<float>& ranges, const std::string& frame_id,
                                 double range_noise_sigma) const;

  /// Remembers the cuts of `obstacles` (the first beam of each ellipse), which hints it did not
  /// need (SensorObstacles::unneeded_hints) and its `ranges`.
  void update(const SensorObstacles& obstacles, const std::vector<float>& ranges);

 private:
  std::map<std::size_t, std::size_t> unneeded_for_;  ///< cut beam -> scans in a row not needed
  std::vector<float> ranges_;
  std::string frame_id_;
};

}  // namespace ellipse_collision::app
