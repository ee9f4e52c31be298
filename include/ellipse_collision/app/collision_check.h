#pragma once

#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "ellipse_collision/app/ellipse_registry.h"
#include "ellipse_collision/app/ellipse_spec.h"
#include "ellipse_collision/app/error_kind.h"
#include "ellipse_collision/app/placement_cache.h"
#include "ellipse_collision/app/transform_lookup.h"
#include "ellipse_collision/core/contact_prediction.h"
#include "ellipse_collision/core/indexed_obstacles.h"
#include "ellipse_collision/core/scene_check.h"

namespace ellipse_collision::app {

/// What every check shares: where ellipses are compared and the pair rules.
struct CheckSettings {
  std::string fixed_frame{"base_link"};
  double global_padding_m{0.0};  ///< added to both radii of every ellipse [m]
  core::SceneRules rules;
  /// A non-timeless transform older than this is stale (isStale()) [s]; 0 = off.
  double max_transform_age_s{0.0};
};

/// One ~check_collisions request, converted from its message. Empty names, query and
/// min_distance_of ask for every pair of the stored ellipses.
struct CheckRequest {
  std::vector<std::string> names;    ///< only pairs with one of these (stored or query names)
  std::vector<EllipseSpec> query;    ///< extra ellipses checked against links and obstacles
  std::string min_distance_of;       ///< also the nearest partner of this name, if not empty
};

/// The answer of one check.
struct CheckOutcome {
  /// Stored ellipses that could be placed: links, then obstacles, each by name.
  core::Scene placed;
  std::vector<std::string> unavailable_frames;  ///< sorted; their ellipses were skipped
  std::vector<std::string> stale_frames;        ///< sorted; transform too old, ellipses skipped
  std::vector<std::string> skipped;             ///< why each skipped ellipse was skipped
  std::vector<core::CollidingPair> collisions;
  std::vector<core::NearPair> warnings;
  std::optional<core::NearPair> nearest;  ///< of min_distance_of, when asked and measured
  std::string nearest_problem;            ///< why it was asked but not measured
  std::string error;                      ///< a bad request or a refused scene: nothing checked
  ErrorKind error_kind{ErrorKind::None};  ///< what kind of failure `error` is
  /// Every stored ellipse was placed from fresh data: none unavailable, stale or skipped, and no
  /// obstacle source silent. The one bit a safety consumer needs; false whenever the answer does
  /// not cover everything.
  bool complete{false};
  /// Obstacle sources silent past their timeout ("source 'rear_scan' silent for 0.8 s ...").
  std::vector<std::string> silent_sources;
  /// The transform each frame of this check had, looked up once (the prediction reuses them).
  std::map<std::string, FrameTransform> frames;
  /// The grid of `placed`'s obstacles (its entries from the first obstacle on) that the check
  /// looked its pairs up in, kept across checks while the obstacles stand still
  /// (StandingObstacles); null when the check streamed them. Built from exactly these
  /// obstacles, so the gate may find the ones near the robot there.
  std::shared_ptr<const core::IndexedObstacles> standing;
  /// Pairs apart now that touch within the prediction horizon (predictAfterCheck()), soonest first.
  std::vector<core::PredictedContact> predicted;
  /// Why a velocity could not be estimated or a pair not predicted (logged, in /diagnostics).
  std::vector<std::string> prediction_notes;
};

/// The request's own rules, before any frame is looked up: every query ellipse passes
/// findInvalidPaddedField(); query names are distinct and name no stored ellipse; `names` are
/// non-empty, distinct and name a stored or query ellipse; min_distance_of is empty or names one.
/// Returns the first violation as "query[1].name = 'x': expected ...", or "".
std::string validateCheckRequest(const CheckRequest& request, const EllipseRegistry& registry,
                                 double global_padding_m);

/// Places the query ellipses and every stored ellipse through `lookup`, checks the scene with the
/// core (core::checkScene(), core::nearestTo()) and collects the answer. A query ellipse whose
/// frame is unavailable or that projects to nothing makes the request fail; a stored one is
/// skipped and its frame listed. A frame whose transform is older than
/// settings.max_transform_age_s at `reference_time_s` (now for latest-transform checks, the
/// requested stamp otherwise; same clock as FrameTransform::stamp_s) is stale: a query ellipse in
/// it fails the request, stored ones are skipped and the frame is listed in stale_frames.
/// Expects a request that passed validateCheckRequest().
/// With a `cache` (kept from one check to the next, PlacementCache), stored ellipses whose frame
/// has the same transform as when they were last projected are not projected again; the answer
/// is the same bit for bit.
CheckOutcome runCheck(const CheckRequest& request, const EllipseRegistry& registry,
                      const CheckSettings& settings, const TransformLookup& lookup,
                      double reference_time_s = 0.0, PlacementCache* cache = nullptr);

/// For ellipses that are to be stored (~add_obstacles, the ~obstacles topic): field rules
/// (findInvalidPaddedField()) for all, then a transform to the fixed frame for each distinct
/// frame, asked of `lookup` once.
/// `field` names the list in messages ("obstacles" -> "obstacles[2].frame_id = ...").
std::string validateAttached(const std::vector<EllipseSpec>& specs, const std::string& field,
                             const CheckSettings& settings, const TransformLookup& lookup);

/// "a; b; c".
std::string joinText(const std::vector<std::string>& parts, const std::string& separator);

}  // namespace ellipse_collision::app
