#pragma once

#include <ros/time.h>
#include <visualization_msgs/MarkerArray.h>

#include <cstdint>
#include <set>
#include <string>
#include <vector>

#include "ellipse_collision/app/marker_layout.h"
#include "ellipse_collision/app/marker_state.h"
#include "ellipse_collision/core/scene_check.h"

namespace ellipse_collision {

using app::kMarkerStates;
using app::MarkerState;
using app::MarkerStateStyle;

/// Builds the rviz view of a check, sending only what changed since the last array: the messages
/// of what app::MarkerLayout decides (which markers, ids, buckets and changes; see there).
///
/// Ellipses: the ellipses of one state in one bucket are drawn as filled polygons
/// (core::forEachTrianglePoint: inscribed, within 2 mm of the rim, 16 to 64 segments) in a
/// TRIANGLE_LIST marker of that state's colour (kMarkerStates, alpha kEllipseAlpha), flat at
/// z = 0. Clearance: one LINE_LIST segment per warning pair between its witness points, at
/// kLineHeight. A marker no longer shown is sent as DELETE.
///
/// No labels: a text marker per ellipse would be 100,000 markers at scale, and rviz warns about
/// text on other marker types; names are in ~collisions.
class CollisionMarkers {
 public:
  static constexpr double kLineWidth = 0.02;    ///< clearance lines [m]
  static constexpr double kLineHeight = 0.01;   ///< z of the clearance lines, above the fill [m]
  static constexpr float kEllipseAlpha = 0.6f;  ///< translucent: overlaps stay visible
  static constexpr std::size_t kEllipsesPerMarker = app::MarkerLayout::kEllipsesPerMarker;
  static constexpr std::int32_t kIdsPerState = app::MarkerLayout::kIdsPerState;
  static constexpr const char* kClearanceNamespace = app::MarkerLayout::kClearanceNamespace;
  static constexpr std::size_t kSweptLineDeletions = app::MarkerLayout::kSweptLineDeletions;

  /// The markers to publish after a check (app::MarkerLayout::update()): ADD for every marker
  /// whose content changed, DELETE for every marker that is no longer shown; empty when nothing
  /// changed. `placed` holds links and obstacles (queries are skipped) in `fixed_frame`;
  /// `collisions` and `warnings` the check's pairs among them. Remembers what it returned, so
  /// call it only for arrays that are actually published.
  visualization_msgs::MarkerArray update(const core::Scene& placed,
                                         const std::vector<core::CollidingPair>& collisions,
                                         const std::vector<core::NearPair>& warnings,
                                         const std::string& fixed_frame, const ros::Time& stamp,
                                         const std::set<std::string>& predicted = {});

  /// Everything the last update() left shown, after a DELETEALL: for a new subscriber, which may
  /// hold markers of an earlier run of the node (a respawn) or only the latched last update.
  visualization_msgs::MarkerArray fullArray() const;

  /// Appends to `array` (an update() about to be published) the next slice of the refresh sweep
  /// (app::MarkerLayout::refresh()), skipping markers `array` already holds. A subscriber that
  /// lost arrays (a publisher queue overflowing behind a slow rviz) is thus whole again once a
  /// sweep has passed, and nothing is sent twice in one array. Returns how many markers it
  /// appended.
  std::size_t appendRefresh(visualization_msgs::MarkerArray& array, double fraction);

  static const char* nameSpace(core::EllipseRole role) {
    return app::MarkerLayout::nameSpace(role);
  }
  static const MarkerStateStyle& style(MarkerState state) { return app::markerStyle(state); }
  /// The id of the marker of `state` and `bucket`.
  static std::int32_t fillId(MarkerState state, std::uint32_t bucket) {
    return app::MarkerLayout::fillId(state, bucket);
  }
  /// The id the clearance line of a warning pair gets when it appears (app::MarkerLayout).
  static std::int32_t preferredId(const std::string& name_a, const std::string& name_b) {
    return app::MarkerLayout::preferredId(name_a, name_b);
  }

 private:
  /// Appends the messages of `changes` to `array`, in their order, in the last update()'s frame
  /// and stamp.
  void render(const app::MarkerLayout::Changes& changes,
              visualization_msgs::MarkerArray& array) const;

  app::MarkerLayout layout_;
  std::string fixed_frame_;
  ros::Time stamp_;
};

}  // namespace ellipse_collision
