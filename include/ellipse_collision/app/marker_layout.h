#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "ellipse_collision/app/marker_state.h"
#include "ellipse_collision/core/median_partition.h"
#include "ellipse_collision/core/scene_check.h"

namespace ellipse_collision::app {

/// Which markers show a check and which of them changed since the last update(): the ROS-free
/// half of the node's rviz view (ros::CollisionMarkers renders what it returns into messages).
///
/// Ellipses: namespaces `links` and `obstacles`; in each, the ellipses of one state share a fill
/// marker. So that a change does not re-send a namespace's every ellipse, a namespace's ellipses
/// are split by place into B buckets: the cells of a core::MedianPartition of their centres,
/// rectangles holding about equal shares (B a power of two, about kEllipsesPerMarker ellipses per
/// bucket; it changes only when the count leaves [kEllipsesPerMarker / 4 B, kEllipsesPerMarker
/// B]; at most 1,024, since rviz spends a draw call per marker and frame, so beyond that the
/// buckets grow); one marker per (state, bucket) with id code * kIdsPerState + bucket. Being by
/// place, a bucket's marker is small on screen: rviz culls the markers out of view (a view of one
/// part of 100,000 obstacles draws a few dozen of 1,024), and the changes around a robot touch
/// the few buckets there. The cells are cut where the ellipses are when B changes; where one cell
/// has come to hold more than twice what the fullest held then, the smallest part around it that
/// can take them is cut anew, re-sending that part's markers only; an ellipse that moves into
/// another cell moves to its marker. A marker is sent when an ellipse in it appeared, moved,
/// changed state or went away, and deleted when its bucket holds no ellipse of its state any more.
///
/// Clearance: namespace `clearance`, one line per warning pair between its witness points, id
/// from preferredId(name_a, name_b), re-sent when the points move, deleted when the pair goes away.
class MarkerLayout {
 private:
  /// One drawn ellipse, as last sent.
  struct Entry {
    std::string name;
    core::Ellipse ellipse;
    MarkerState state{MarkerState::Free};
    std::uint32_t cell{0};  ///< of its centre in the layer's partition: its marker's bucket
    std::uint64_t generation{0};  ///< the update() that last saw it
  };

 public:
  static constexpr std::size_t kEllipsesPerMarker = 32;
  static constexpr std::int32_t kIdsPerState = 1 << 16;  ///< more than B can reach
  static constexpr const char* kClearanceNamespace = "clearance";
  /// The refresh sweep keeps sending deletions for the clearance lines deleted last, up to this
  /// many: pairs come and go without end (tracked obstacles with ever new names), and neither
  /// memory nor the sweep may grow with every pair that ever came near.
  static constexpr std::size_t kSweptLineDeletions = 1024;

  enum class Action : std::uint8_t { Show, Delete };

  /// The ellipses of one fill marker, in drawing order, as this object holds them: valid until
  /// the next update().
  class FillEllipses {
   public:
    std::size_t size() const { return members_ ? members_->size() : 0; }
    const core::Ellipse& operator[](std::size_t i) const { return (*members_)[i]->ellipse; }

   private:
    friend class MarkerLayout;
    const std::vector<Entry*>* members_{nullptr};
  };

  /// One fill marker to send: shown with its state's colour and its ellipses, or deleted.
  struct FillChange {
    core::EllipseRole role;  ///< Link or Obstacle: the namespace nameSpace(role)
    std::int32_t id;
    Action action;
    MarkerState state;      ///< Show only
    FillEllipses ellipses;  ///< Show only
  };
  /// One clearance line (namespace kClearanceNamespace) to send: shown between the pair's witness
  /// points, or deleted.
  struct LineChange {
    std::int32_t id;
    Action action;
    Eigen::Vector2d point_a, point_b;  ///< Show only [m]
  };
  /// What to send, in this order: every fill, then every line.
  struct Changes {
    std::vector<FillChange> fills;
    std::vector<LineChange> lines;
  };

  /// The markers whose content changed after a check (Show) and those no longer shown (Delete);
  /// empty when nothing changed. `placed` holds links and obstacles (queries are skipped);
  /// `collisions` and `warnings` the check's pairs among them, `predicted` the names in a
  /// predicted contact. Remembers what it returned, so call it only for changes that are actually
  /// sent. The fills' ellipses stay valid until the next update().
  Changes update(const core::Scene& placed, const std::vector<core::CollidingPair>& collisions,
                 const std::vector<core::NearPair>& warnings,
                 const std::set<std::string>& predicted = {});

  /// Every marker the last update() left shown (all Show): for a new subscriber.
  Changes full() const;

  /// The next slice of the refresh sweep: every fill id ever shown (at most 4 states x 1,024
  /// buckets per namespace) and the clearance lines shown or among the last kSweptLineDeletions
  /// deleted, in turn, as they are now (Show if shown, Delete if not). `fraction` of them per call
  /// (the share of the refresh period since the last call; fractions of a marker carry over, at
  /// most one whole sweep is owed), skipping the markers in `already_sent` (namespace, id), which
  /// go out with this slice anyway; they count as refreshed.
  Changes refresh(double fraction,
                  const std::set<std::pair<std::string, std::int32_t>>& already_sent);

  static const char* nameSpace(core::EllipseRole role);
  /// The id of the fill marker of `state` and `bucket`.
  static std::int32_t fillId(MarkerState state, std::uint32_t bucket);
  /// The id the clearance line of a warning pair (names in the pair's order) gets when it appears.
  /// Only if a line shown holds it (a hash clash) does the pair get the next free id instead, and
  /// keeps that while its line stays shown.
  static std::int32_t preferredId(const std::string& name_a, const std::string& name_b);

 private:
  /// One namespace's ellipses.
  struct Layer {
    std::unordered_map<std::string, Entry> entries;
    std::vector<Entry*> by_position;  ///< entry at each index of the last `placed` (a fast path)
    std::uint32_t buckets{1};         ///< B
    core::MedianPartition partition;  ///< B cells, cut where the ellipses were (recutCrowdedCells())
    std::size_t largest_cell_when_cut{0};  ///< ellipses in the fullest cell, all states, when cut
    std::set<std::int32_t> shown;     ///< ids of its markers rviz holds
    std::set<std::int32_t> ever_sent;  ///< ids ever shown: the refresh sweep's fill ids
    /// The entries of each marker, by state index * B + cell: a changed marker is rebuilt from
    /// its own ellipses, not by a pass over the whole namespace.
    std::vector<std::vector<Entry*>> members;

    // The update() under way: whether the layer is cut anew (all sent), the markers that
    // changed (by slot), and the distinct entries met.
    bool regroup{false};
    std::vector<char> dirty;
    std::size_t seen{0};

    /// Starts an update of `count` ellipses: B for them, and whether the layer is cut anew.
    void begin(std::size_t count);
    std::size_t slotOf(MarkerState state, std::uint32_t cell) const;
    void markDirty(MarkerState state, std::uint32_t cell);
    void join(Entry* entry);   ///< into its marker's members (not while cut anew)
    void leave(Entry* entry);  ///< out of its marker's members (not while cut anew)
  };
  static constexpr std::size_t kLayers = 2;  // links, obstacles
  using Points = std::pair<Eigen::Vector2d, Eigen::Vector2d>;  // a line's witness points

  /// The ellipses of every state in each of the layer's cells.
  static std::vector<std::size_t> ellipsesPerCell(const Layer& layer);
  /// Ellipses crowding into one place: a cell holding more than twice what the fullest held
  /// when the layer was cut would re-send that many on each change there. The smallest part of
  /// the tree around it whose ellipses fit its cells at that size is cut anew (MedianPartition::
  /// recut()), and only that part's markers are marked in `dirty` (by state index * B + cell).
  static void recutCrowdedCells(Layer& layer, std::vector<char>& dirty);

  /// The entry of `name`, found (at `position` as last time, else by name) or made, brought to
  /// `ellipse` and `state` with the markers it leaves and joins marked.
  Entry* meet(Layer& layer, std::size_t position, const std::string& name,
              const core::Ellipse& ellipse, MarkerState state);
  /// Ends a layer's update: drops the entries not met, cuts anew or recuts crowded cells, and
  /// appends the changed markers (Show) and the emptied ones (Delete) to `changes`.
  void finishLayer(std::size_t layer, std::vector<Entry*> positions, Changes& changes);
  /// The clearance lines of `warnings`, as changes against those shown.
  void updateLines(const std::vector<core::NearPair>& warnings, Changes& changes);
  /// Appends to `out` a Show for each non-empty slot of `layer` marked in `wanted`, in slot order.
  void appendFills(std::size_t layer, const std::vector<char>& wanted,
                   std::vector<FillChange>& out) const;
  std::int32_t lineId(const std::string& key, std::int32_t preferred,
                      const std::map<std::string, std::int32_t>& ids_now,
                      const std::map<std::int32_t, Points>& lines_now) const;
  void noteLineDeleted(std::int32_t id);

  std::array<Layer, kLayers> layers_;
  std::uint64_t generation_{0};

  // Clearance lines shown: each pair's id (by pairKey()) and each id's points. Only lines shown
  // are remembered.
  std::map<std::string, std::int32_t> line_ids_;
  std::map<std::int32_t, Points> lines_shown_;
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

}  // namespace ellipse_collision::app
