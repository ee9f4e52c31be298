#include "ellipse_collision/app/collision_check.h"

#include <algorithm>
#include <iterator>
#include <string_view>
#include <unordered_set>
#include <utility>

#include "ellipse_collision/app/frame_placer.h"
#include "ellipse_collision/app/stored_placement.h"
#include "ellipse_collision/core/unique_names.h"

namespace ellipse_collision::app {

std::string joinText(const std::vector<std::string>& parts, const std::string& separator) {
  std::string joined;
  for (const std::string& part : parts) joined += (joined.empty() ? "" : separator) + part;
  return joined;
}

std::string validateCheckRequest(const CheckRequest& request, const EllipseRegistry& registry,
                                 double global_padding_m) {
  std::set<std::string> query_names;
  for (std::size_t i = 0; i < request.query.size(); ++i) {
    const EllipseSpec& spec = request.query[i];
    if (const auto invalid = findInvalidPaddedField(spec, global_padding_m)) {
      return describeFieldError(entryName("query", i), *invalid);
    }
    if (registry.contains(spec.name) || !query_names.insert(spec.name).second) {
      return entryName("query", i) + ".name = '" + spec.name +
             "': expected a name used by no link, obstacle or other query, got a duplicate";
    }
  }
  const auto known = [&](const std::string& name) {
    return registry.contains(name) || query_names.count(name) != 0;
  };
  if (const auto problem = core::findNameProblem(request.names)) {
    const std::string where =
        entryName("names", problem->index) + " = '" + request.names[problem->index] + "': expected ";
    // An unknown name before the problem is reported first, as a reader meets it.
    for (std::size_t i = 0; i < problem->index; ++i) {
      if (!known(request.names[i])) {
        return entryName("names", i) + " = '" + request.names[i] +
               "': expected the name of a link, obstacle or query, got an unknown name";
      }
    }
    if (problem->kind == core::NameProblem::Kind::Empty) return where + "a non-empty name";
    if (!known(request.names[problem->index])) {
      return where + "the name of a link, obstacle or query, got an unknown name";
    }
    return where + "each name once, got a duplicate";
  }
  for (std::size_t i = 0; i < request.names.size(); ++i) {
    if (!known(request.names[i])) {
      return entryName("names", i) + " = '" + request.names[i] +
             "': expected the name of a link, obstacle or query, got an unknown name";
    }
  }
  if (!request.min_distance_of.empty() && !known(request.min_distance_of)) {
    return "min_distance_of = '" + request.min_distance_of +
           "': expected the name of a link, obstacle or query (or empty), got an unknown name";
  }
  return {};
}

namespace {

/// The request's query ellipses placed in the fixed frame, or the outcome's error when one cannot
/// be: a query whose frame is unavailable or stale, or that projects to nothing, fails the request.
bool placeQueries(const CheckRequest& request, const CheckSettings& settings,
                  FramePlacer& placement, std::vector<core::NamedEllipse>* queries,
                  CheckOutcome* outcome) {
  for (std::size_t i = 0; i < request.query.size(); ++i) {
    const EllipseSpec& spec = request.query[i];
    const FramePlacer::Placement placed = placement.place(spec, core::EllipseRole::Query);
    switch (placed.status) {
      case FramePlacer::Status::Placed:
        queries->push_back(placed.ellipse);
        continue;
      case FramePlacer::Status::FrameUnavailable:
        outcome->error_kind = ErrorKind::FrameUnavailable;
        outcome->error = entryName("query", i) + ".frame_id = '" + spec.frame_id +
                         "': expected a frame with a transform to '" + settings.fixed_frame +
                         "', got none (" + placed.error + ")";
        return false;
      case FramePlacer::Status::Stale:
        outcome->error_kind = ErrorKind::FrameUnavailable;
        outcome->error = entryName("query", i) + ".frame_id = '" + spec.frame_id +
                         "': expected a transform to '" + settings.fixed_frame +
                         "' within max_transform_age, got a stale one (" + placed.error + ")";
        return false;
      case FramePlacer::Status::Degenerate:
        outcome->error_kind = ErrorKind::InvalidRequest;
        outcome->error = entryName("query", i) + ": " + placed.error;
        return false;
    }
  }
  return true;
}

/// The pairs of `scene` (movers first, from index 0 to `first_obstacle`) that the request asks
/// for. Obstacles that stood still since the last check (`standing`, or null) need not stream past
/// the movers again: the cache's grid of them answers the same bits (core::checkMoversAgainst()).
core::SceneCheckResult checkPlacedScene(const core::Scene& scene, std::size_t first_obstacle,
                                        const core::IndexedObstacles* standing,
                                        const CheckRequest& request,
                                        const CheckSettings& settings) {
  const std::set<std::string> only_names(request.names.begin(), request.names.end());
  // Every entry was validated where it was made (FramePlacer refuses an invalid projection,
  // the registry and validateCheckRequest() duplicate names) and the movers come first: the
  // core need not test every entry again on every check.
  if (!standing) {
    return core::checkValidatedScene(scene, first_obstacle, settings.rules, only_names);
  }
  std::vector<core::NamedEllipse> movers;
  movers.reserve(first_obstacle);
  for (std::size_t i = 0; i < first_obstacle; ++i) movers.push_back(scene.entry(i));
  return core::checkMoversAgainst(movers, *standing, settings.rules, only_names);
}

/// The nearest partner of request.min_distance_of in `scene`, into the outcome.
void measureNearest(const core::Scene& scene, const CheckRequest& request,
                    const CheckSettings& settings, CheckOutcome* outcome) {
  const std::string& of = request.min_distance_of;
  bool placed = false;
  for (std::size_t i = 0; i < scene.size() && !placed; ++i) placed = scene.name(i) == of;
  if (!placed) {
    outcome->nearest_problem =
        "min_distance_of = '" + of + "': not measured, the ellipse could not be placed";
    return;
  }
  const core::NearestResult nearest = core::nearestTo(scene, settings.rules, of);
  if (!nearest.ok()) {
    outcome->error_kind = ErrorKind::Internal;
    outcome->error = "internal error: " + nearest.error;
  } else if (!nearest.found) {
    outcome->nearest_problem = "min_distance_of = '" + of +
                               "': no placed ellipse that the pair rules measure it against";
  } else {
    outcome->nearest = nearest.nearest;
  }
}

}  // namespace

CheckOutcome runCheck(const CheckRequest& request, const EllipseRegistry& registry,
                      const CheckSettings& settings, const TransformLookup& lookup,
                      double reference_time_s, PlacementCache* cache) {
  CheckOutcome outcome;
  FramePlacer placement(lookup, settings.global_padding_m,
                        Freshness{settings.max_transform_age_s, reference_time_s});
  std::vector<core::NamedEllipse> queries;
  if (!placeQueries(request, settings, placement, &queries, &outcome)) return outcome;

  StoredPlacement stored =
      placeStoredEllipses(registry, placement, settings.global_padding_m, cache, queries.size());
  outcome.placed = std::move(stored.scene);
  outcome.skipped = std::move(stored.skipped);
  outcome.unavailable_frames = std::move(stored.unavailable_frames);
  outcome.stale_frames = std::move(stored.stale_frames);
  outcome.complete = outcome.skipped.empty();

  // The scene is the queries followed by the placed stored ellipses (movers before obstacles;
  // the answer does not depend on the order), checked in place and the queries dropped again, so
  // no name is copied twice. Names were checked where they came in (the registry,
  // validateCheckRequest()), so the core does not hash them all again on every check.
  core::Scene& scene = outcome.placed;
  scene.insertFront(queries);
  std::size_t first_obstacle = 0;
  while (first_obstacle < scene.size() &&
         scene.role(first_obstacle) != core::EllipseRole::Obstacle) {
    ++first_obstacle;
  }
  if (cache) {
    outcome.standing = cache->standingObstacles().update(
        stored.reused_obstacles == stored.obstacles, scene, first_obstacle);
  }
  core::SceneCheckResult result =
      checkPlacedScene(scene, first_obstacle, outcome.standing.get(), request, settings);
  if (!result.ok()) {
    // Requests are validated before they get here, so this is a bug: say so.
    outcome.error_kind = ErrorKind::Internal;
    outcome.error = "internal error: " + result.error;
  } else {
    outcome.collisions = std::move(result.collisions);
    outcome.warnings = std::move(result.warnings);
    if (!request.min_distance_of.empty()) measureNearest(scene, request, settings, &outcome);
  }
  scene.eraseFront(queries.size());
  outcome.frames = placement.takeFrames();
  return outcome;
}

std::string validateAttached(const std::vector<EllipseSpec>& specs, const std::string& field,
                             const CheckSettings& settings, const TransformLookup& lookup) {
  for (std::size_t i = 0; i < specs.size(); ++i) {
    if (const auto invalid = findInvalidPaddedField(specs[i], settings.global_padding_m)) {
      return describeFieldError(entryName(field, i), *invalid);
    }
  }
  // Each frame is asked for once: a message of 10,000 obstacles in a sensor frame asked tf
  // 10,000 times for the same transform. Only found frames are remembered (the first missing
  // one refuses the message).
  std::unordered_set<std::string_view> found;
  for (std::size_t i = 0; i < specs.size(); ++i) {
    const std::string& name = specs[i].frame_id;
    if ((i > 0 && name == specs[i - 1].frame_id) || found.count(name)) continue;
    const FrameTransform frame = lookup(name);
    if (!frame.ok) {
      return entryName(field, i) + ".frame_id = '" + specs[i].frame_id +
             "': expected a known tf frame with a transform to '" + settings.fixed_frame +
             "', got none (" + frame.error + ")";
    }
    found.insert(name);
  }
  return {};
}

}  // namespace ellipse_collision::app
