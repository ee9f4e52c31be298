#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <string>
#include <vector>

#include "ellipse_collision/core/ellipse.h"
#include "ellipse_collision/core/free_space.h"

namespace ellipse_collision::core {

/// One sensor return [m] in the sensor's frame and the key it is named by: the beam index for
/// a LaserScan, the angular bin (cloudView()) for a point cloud.
struct SensorReturn {
  Eigen::Vector2d point{0.0, 0.0};
  std::size_t key{0};
};

/// What one LaserScan beam of range `r` [m] says (scanView() gives the rules).
enum class BeamReading { Return, NoReturn, Unknown };
BeamReading readBeam(double r, double range_min, double range_max);

/// What one sensor message says: its returns in angular order and the free part of its beams.
struct SensorView {
  std::vector<SensorReturn> returns;
  FreeSpace free_space;
  bool full_turn{false};  ///< the beams go all the way round: the last return neighbours the first
};

/// A LaserScan's fields as a SensorView (angles [rad], ranges [m]). Beam i at angle angle_min +
/// i angle_increment:
/// - a return when range_min <= r <= range_max (and within kMaxCoordinate): the point
///   (r cos a, r sin a), free from range_min to r - free_space_tolerance;
/// - no return when r > range_max or r = +inf: free from range_min to range_max;
/// - unknown (not free, no point) when r is NaN, below range_min or -inf: the sensor could not
///   tell (a NaN is a failed measurement, not a clear view; below range_min something may be too
///   near to measure).
/// range_min below 0 counts as 0. A beam whose angle is not finite is skipped; a NaN limit makes
/// every beam unknown. full_turn when the beams cover 2 pi to within half an increment.
SensorView scanView(const std::vector<float>& ranges, double angle_min, double angle_increment,
                    double range_min, double range_max, double free_space_tolerance);

/// The beams of one LaserScan geometry (beam i at angle_min + i angle_increment [rad]): whether
/// each angle is finite, its unit direction, the atan2 of that direction (the angle FreeSpace
/// orders by) and the finite beams in FreeSpace's order. A sensor's scans share their geometry:
/// kept from scan to scan, the trigonometry of scanView() is done once instead of per scan.
class ScanBeams {
 public:
  /// Recomputes for this geometry unless it holds it already (the same bits).
  void update(std::size_t count, double angle_min, double angle_increment);

  std::size_t size() const { return finite_.size(); }
  bool finite(std::size_t i) const { return finite_[i] != 0; }
  const Eigen::Vector2d& direction(std::size_t i) const { return directions_[i]; }
  double freeSpaceAngle(std::size_t i) const { return angles_[i]; }
  /// The beams with a finite angle by freeSpaceAngle(), ties in beam order.
  const std::vector<std::size_t>& order() const { return order_; }

 private:
  bool set_{false};
  double angle_min_{0.0};
  double angle_increment_{0.0};
  std::vector<char> finite_;
  std::vector<Eigen::Vector2d> directions_;
  std::vector<double> angles_;
  std::vector<std::size_t> order_;
};

/// scanView() written into `view`, reusing its storage, with the trigonometry of `beams`
/// (updated to this scan's geometry first): the same view, bit for bit.
void scanView(const std::vector<float>& ranges, double angle_min, double angle_increment,
              double range_min, double range_max, double free_space_tolerance, ScanBeams& beams,
              SensorView& view);

/// The angular bins of cloudView(): 16384 a turn (0.022 degrees each), finer than the columns of
/// common 3D lidars, so that each bin's ray is one column's.
constexpr std::size_t kCloudBins = 16384;
constexpr double kCloudBinAngle = 2.0 * 3.14159265358979323846 / static_cast<double>(kCloudBins);

/// Points of a cloud projected onto the sensor's plane [m] (any order; non-finite points and
/// coordinates beyond kMaxCoordinate dropped) as a SensorView: the returns ordered by angle
/// about the origin (keyed by their bin of kCloudBinAngle), and per bin one free segment, along
/// the ray to its nearest point, from 0 to that point's range - free_space_tolerance. A cloud
/// says nothing about bins without points (unknown, not free), nor about the space behind a
/// bin's nearest point (a ray over a low obstacle projected onto the plane would cut through it).
SensorView cloudView(const std::vector<Eigen::Vector2d>& points, double free_space_tolerance);

/// The breakpoint rule for consecutive returns p, q (in angular order), after G. A. Borges and
/// M.-J. Aldon, "Line extraction in 2D range images for mobile robotics", J. Intelligent and
/// Robotic Systems 40, 2004: they belong to one contour when |p - q| <= r_p sin(dphi) /
/// sin(kBreakpointAngle - dphi) + 3 range_noise_sigma, dphi the angle between them as seen from
/// the origin (the largest gap a surface seen at kBreakpointAngle or steeper leaves at range
/// r_p), or when |p - q| < join_distance. A gap of kBreakpointAngle or more breaks always.
constexpr double kBreakpointAngle = 10.0 * 3.14159265358979323846 / 180.0;  // [rad]
bool sameContour(const Eigen::Vector2d& p, const Eigen::Vector2d& q, double range_noise_sigma,
                 double join_distance);

/// The returns cut into contours by sameContour() (a full turn joins the last contour to the
/// first when the rule links them). Contours of fewer than `min_points` returns are dropped (the
/// noise rule; 0 counts as 1, so nothing is dropped).
std::vector<std::vector<SensorReturn>> breakContours(const SensorView& view,
                                                     double range_noise_sigma, double join_distance,
                                                     std::size_t min_points);

/// A cloud's contours: its returns (cloudView(), in angular order) grouped by single linkage at
/// `join_distance` [m] (clusterUnorderedPoints()), each group in angular order; groups of fewer
/// than `min_points` returns are dropped (the noise rule, as breakContours()).
std::vector<std::vector<SensorReturn>> cloudContours(const SensorView& view, double join_distance,
                                                     std::size_t min_points);

/// One obstacle ellipse: it contains a run of consecutive returns of one contour.
struct ContourEllipse {
  Ellipse ellipse;
  std::size_t key{0};       ///< key of the run's first return: unique for a scan
  std::size_t points{0};    ///< returns in the run
  std::size_t last_key{0};  ///< key of the run's last return
  /// The run's ellipse of min_radius would enter the free space: its smaller radius is what the
  /// free space leaves (half the smallest clearance of its returns, or the wedge between the
  /// beams beside it), below min_radius.
  bool radius_reduced{false};
};

struct ContourEllipses {
  std::vector<ContourEllipse> ellipses;  ///< in contour order, runs in return order
  std::vector<std::string> skipped;      ///< runs that got no ellipse, and why
  std::string error;                     ///< set, with no ellipses, when min_radius is invalid
  /// The split hints that cut a contour where the two runs on either side would be one accepted
  /// ellipse together: cuts the scene no longer needs (ascending within each contour).
  std::vector<std::size_t> unneeded_hints;
};

/// Each contour split into as few runs of consecutive returns as the rules allow, one ellipse per
/// run, every return in exactly one run. A run whose chord already crosses free space
/// (FreeSpace::crossed(): every ellipse around the run contains the chord) is split at once:
/// between two consecutive returns when the crossing beam also crosses the segment between them
/// (a beam without return through an object: a cut the free space requires), else as below;
/// otherwise the run keeps the first of these ellipses that neither enters the free space nor
/// contains the origin (FreeSpace::entered(), exact):
/// 1. (3 or more returns) the circle fitted to the run by least squares (Kasa), grown to
///    contain it, when the run is round (every return within a fifth of the radius of it) and
///    the radius is within [min_radius, chord]: a round pillar is its own circle, also where
///    its arc is thin (a pole seen by many beams). When a round run's circle enters the free
///    space (beams grazing the object), no other candidate is tried: the run is split (at the
///    beam entered when the free space requires that cut), unless the run is thin or that beam
///    lies beyond an end of the run and passes within half the radius of the circle's centre
///    (half a pole beside a middle beam without return): then 2-5 are tried;
/// 2. enclosingEllipseWithMinRadius(run, min_radius), or for a thin run (its band across its
///    principal axis within min_radius / sqrt(2)) bandEllipse(), O(n);
/// 3. (3 or more returns, not thin) enclosingEllipseWithMinRadius() around the run and its
///    shadow, each return pushed back along its ray by the chord's length: a convex object gets
///    an ellipse round like it instead of one bulging out in front of it;
/// 4. (when 2's smaller radius is min_radius: one or two returns, a thin run) the same with the
///    smaller radius reduced to half the smallest clearance of its returns
///    (FreeSpace::clearance()): a face seen at a glancing angle, a lone return between beams that
///    saw far, stays an obstacle, thinner than min_radius (radius_reduced), never dropped;
/// 5. (2 or more returns) where the beams on either side of the run (FreeSpace::beside()) both
///    pass beyond its farthest return and one of them returned nothing: an ellipse inside the
///    wedge between them, its axes along and across the wedge, the shortest along it that
///    contains the run, at one of 17 places along the wedge (smallest area first), its radius
///    across possibly below min_radius (radius_reduced). Half a pole beside a dropped middle
///    beam at 1440 beams fits only there.
/// Else the run is split: a run of two into two runs of one; a longer one at the return farthest
/// from its chord (Douglas-Peucker; the middle one when all are on the chord), but when a
/// candidate entered a beam beyond one end of the run, that end's return is split off alone (at
/// most once per end of each run). A single return is always kept: when even 4 enters the free
/// space (another beam through the return itself), it is kept and reported in `skipped`.
/// `split_hints` (keys, ascending): each contour is first cut before every return whose key is a
/// hint (and differs from the key before it), then each part is split as above. A sensor's last
/// cuts given as hints keep the split from flickering under range noise (a stretch cut in one scan
/// and not in the next); the hints that are no longer needed are reported in unneeded_hints, so
/// that a caller can let them go (ScanCutMemory in the application layer): those where the runs on
/// either side would be one ellipse together that stays out of the free space even with both
/// radii grown by `hint_margin` [m] (the hysteresis: a cut that noise needs now and then is not
/// reported). The guarantees (every return in exactly one ellipse, none entering the free space)
/// hold for any hints.
/// Measured (test_scan_contours): a 720-beam 6 m x 4 m room with a box, a pillar and a doorway
/// is 10 ellipses; a straight wall seen at steep angles is one, a corner seen from inside two.
ContourEllipses contourEllipses(const std::vector<std::vector<SensorReturn>>& contours,
                                const FreeSpace& free_space, double min_radius,
                                const std::vector<std::size_t>& split_hints = {},
                                double hint_margin = 0.0);

}  // namespace ellipse_collision::core
