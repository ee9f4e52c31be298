#pragma once

#include <ros/time.h>
#include <visualization_msgs/MarkerArray.h>

#include <array>
#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "ellipse_collision/core/median_partition.h"
#include "ellipse_collision/core/scene_check.h"

namespace ellipse_collision {

/// The states an ellipse's marker shows, in rank order: an ellipse that qualifies for several
/// shows the highest. Index into kMarkerStates.
enum class MarkerState : std::uint8_t { Free, Warning, Predicted, Collision };

/// How one state is drawn. To add a state: add it to MarkerState at its rank, add its row here at the same position with a
/// new `code`, and give update() the input that puts ellipses in it.
struct MarkerStateStyle {
  MarkerState state;
  const char* name;  ///< for logs and the README legend
  /// Fixed part of the state's marker ids (id = code * kIdsPerState + bucket); never reused, so
  /// a state's markers keep their ids when states are added or re-ranked.
  std::int32_t code;
  float r, g, b;  ///< colour in [0, 1]
};
inline constexpr std::array<MarkerStateStyle, 4> kMarkerStates{{
    {MarkerState::Free, "free", 0, 0.1f, 0.8f, 0.1f},            // green
    {MarkerState::Warning, "warning", 1, 0.9f, 0.85f, 0.1f},     // yellow
    {MarkerState::Predicted, "predicted", 3, 1.0f, 0.5f, 0.0f},  // orange: touches within ~prediction_horizon
    {MarkerState::Collision, "collision", 2, 0.9f, 0.1f, 0.1f},  // red
}};

/// Builds the rviz view of a check, sending only what changed since the last array.
///
/// Ellipses: namespaces `links` and `obstacles`; in each, the ellipses of one state are drawn as
/// filled polygons (core::forEachTrianglePoint: inscribed, within 2 mm of the rim, 16 to 64
/// segments) in TRIANGLE_LIST markers of that state's colour (kMarkerStates, alpha
/// kEllipseAlpha), flat at z = 0. So that a change does not re-send a namespace's every ellipse,
/// a namespace's ellipses are split by place into B buckets: the cells of a core::MedianPartition
/// of their centres, rectangles holding about equal shares (B a power of two, about
/// kEllipsesPerMarker ellipses per bucket; it changes only when the count leaves
/// [kEllipsesPerMarker / 4 B, kEllipsesPerMarker B]; at most 1,024, since rviz spends a draw
/// call per marker and frame, so beyond that the buckets grow); one marker per (state, bucket)
/// with id code * kIdsPerState + bucket. Being by place, a bucket's marker is small on screen:
/// rviz culls the markers out of view (a view of one part of 100,000 obstacles draws a few dozen
/// of 1,024), and the changes around a robot touch the few buckets there. The cells are cut where
/// the ellipses are when B changes; where one cell has come to hold more than twice what the
/// fullest held then, the smallest part around it that can take them is cut anew, re-sending
/// that part's markers only; an ellipse that moves into another cell moves to its marker. A
/// marker is sent when an ellipse in it appeared, moved, changed state or went away, and DELETEd
/// when its bucket holds no ellipse of its state any more.
///
/// Clearance: namespace `clearance`, one LINE_LIST segment per warning pair between its witness
/// points, id from preferredId(name_a, name_b), re-sent when the points move, DELETEd when the
/// pair goes away.
///
/// No labels: a text marker per ellipse would be 100,000 markers at scale, and rviz warns about
/// text on other marker types; names are in ~collisions.
class CollisionMarkers {
 public:
  static constexpr double kLineWidth = 0.02;    ///< clearance lines [m]
  static constexpr double kLineHeight = 0.01;   ///< z of the clearance lines, above the fill [m]
  static constexpr float kEllipseAlpha = 0.6f;  ///< translucent: overlaps stay visible
  static constexpr std::size_t kEllipsesPerMarker = 32;
  static constexpr std::int32_t kIdsPerState = 1 << 16;  ///< more than B can reach
  static constexpr const char* kClearanceNamespace = "clearance";

  /// The markers to publish after a check: ADD for every marker whose content changed, DELETE for
  /// every marker that is no longer shown; empty when nothing changed. `placed` holds links and
  /// obstacles (queries are skipped) in `fixed_frame`; `collisions` and `warnings` the check's
  /// pairs among them. Remembers what it returned, so call it only for arrays that are actually
  /// published.
  visualization_msgs::MarkerArray update(const core::Scene& placed,
                                         const std::vector<core::CollidingPair>& collisions,
                                         const std::vector<core::NearPair>& warnings,
                                         const std::string& fixed_frame, const ros::Time& stamp,
                                         const std::set<std::string>& predicted = {});

  /// Everything the last update() left shown, after a DELETEALL: for a new subscriber, which may
  /// hold markers of an earlier run of the node (a respawn) or only the latched last update.
  visualization_msgs::MarkerArray fullArray() const;

  /// Appends to `array` (an update() about to be published) the next slice of the refresh sweep:
  /// every fill id this object ever sent (at most 4 states x 1,024 buckets per namespace) and the
  /// clearance lines shown or among the last kSweptLineDeletions deleted, in turn, again as they
  /// are now (ADD with its content if shown, DELETE if not). `fraction` of them per call (the
  /// share of the refresh period since the last call; fractions of a marker carry over, at most
  /// one whole sweep is owed), skipping ids `array` already holds. A subscriber that lost arrays
  /// (a publisher queue overflowing behind a slow rviz) is thus whole again once a sweep has
  /// passed, and nothing is sent twice in one array. Returns how many markers it appended.
  std::size_t appendRefresh(visualization_msgs::MarkerArray& array, double fraction);

  static const char* nameSpace(core::EllipseRole role);
  static const MarkerStateStyle& style(MarkerState state);
  /// The id of the marker of `state` and `bucket`.
  static std::int32_t fillId(MarkerState state, std::uint32_t bucket);

  /// The id the clearance line of a warning pair (names in the pair's order) gets when it appears.
  /// Only if a line shown holds it (a hash clash) does the pair get the next free id instead, and
  /// keeps that while its line stays shown.
  static std::int32_t preferredId(const std::string& name_a, const std::string& name_b);

  /// The refresh sweep keeps sending DELETE for the clearance lines deleted last, up to this many:
  /// pairs come and go without end (tracked obstacles with ever new names), and neither memory
  /// nor the sweep may grow with every pair that ever came near.
  static constexpr std::size_t kSweptLineDeletions = 1024;

 private:
  /// One drawn ellipse, as last sent.
  struct Entry {
    std::string name;
    core::Ellipse ellipse;
    MarkerState state{MarkerState::Free};
    std::uint32_t cell{0};  ///< of its centre in the layer's partition: its marker's bucket
    std::uint64_t generation{0};  ///< the update() that last saw it
  };
  /// One namespace's ellipses.
  struct Layer {
    std::unordered_map<std::string, Entry> entries;
    std::vector<Entry*> by_position;  ///< entry at each index of the last `placed` (a fast path)
    std::uint32_t buckets{1};         ///< B
    core::MedianPartition partition;  ///< B cells, cut where the ellipses were (recutCrowdedCells())
    std::size_t largest_cell_when_cut{0};  ///< ellipses in the fullest cell, all states, when cut
    std::set<std::int32_t> shown;     ///< ids of its markers rviz holds
    std::set<std::int32_t> ever_sent;  ///< ids ever sent as ADD: the refresh sweep's fill ids
    /// The entries of each marker, by state index * B + cell: a changed marker is rebuilt from
    /// its own ellipses, not by a pass over the whole namespace.
    std::vector<std::vector<Entry*>> members;
  };
  static constexpr std::size_t kLayers = 2;  // links, obstacles

  /// The ellipses of every state in each of the layer's cells.
  static std::vector<std::size_t> ellipsesPerCell(const Layer& layer);
  /// Ellipses crowding into one place: a cell holding more than twice what the fullest held
  /// when the layer was cut would re-send that many on each change there. The smallest part of
  /// the tree around it whose ellipses fit its cells at that size is cut anew (MedianPartition::
  /// recut()), and only that part's markers are marked in `dirty` (by state index * B + cell).
  static void recutCrowdedCells(Layer& layer, std::vector<char>& dirty);

  std::vector<visualization_msgs::Marker> fills(std::size_t layer,
                                                const std::vector<char>& wanted) const;
  visualization_msgs::Marker emptyMarker(const std::string& ns, std::int32_t id) const;
  std::int32_t lineId(const std::string& key, std::int32_t preferred,
                      const std::map<std::string, std::int32_t>& ids_now,
                      const std::map<std::int32_t, visualization_msgs::Marker>& lines_now) const;
  void noteLineDeleted(std::int32_t id);

  std::array<Layer, kLayers> layers_;
  std::uint64_t generation_{0};
  std::string fixed_frame_;
  ros::Time stamp_;

  // Clearance lines shown: each pair's id (by pairKey()) and each id's line. Only lines shown are
  // remembered.
  std::map<std::string, std::int32_t> line_ids_;
  std::map<std::int32_t, visualization_msgs::Marker> lines_shown_;
  // The last kSweptLineDeletions clearance lines deleted and not shown again, for the sweep, by
  // deletion number both ways (forgotten oldest first).
  std::map<std::int32_t, std::uint64_t> line_deletion_number_;
  std::map<std::uint64_t, std::int32_t> line_deleted_by_number_;
  std::uint64_t line_deletions_{0};

  // The refresh sweep's position: the last id refreshed in part refresh_part_ (0, 1: the layers'
  // fills, 2: clearance lines), and the fraction of a marker owed to the next call.
  std::size_t refresh_part_{0};
  std::int64_t refresh_after_{-1};
  double refresh_owed_{0.0};
};

}  // namespace ellipse_collision
