#include "ellipse_collision/app/collision_check.h"

#include <algorithm>
#include <iterator>
#include <string_view>
#include <unordered_set>
#include <utility>

#include "ellipse_collision/app/scene_placement.h"
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

CheckOutcome runCheck(const CheckRequest& request, const EllipseRegistry& registry,
                      const CheckSettings& settings, const TransformLookup& lookup,
                      double reference_time_s, PlacementCache* cache) {
  CheckOutcome outcome;
  ScenePlacement placement(lookup, settings.global_padding_m,
                           Freshness{settings.max_transform_age_s, reference_time_s});

  std::vector<core::NamedEllipse> queries;
  for (std::size_t i = 0; i < request.query.size(); ++i) {
    const EllipseSpec& spec = request.query[i];
    const ScenePlacement::Placement placed = placement.place(spec, core::EllipseRole::Query);
    if (placed.status == ScenePlacement::Status::FrameUnavailable) {
      outcome.error_kind = ErrorKind::FrameUnavailable;
      outcome.error = entryName("query", i) + ".frame_id = '" + spec.frame_id +
                      "': expected a frame with a transform to '" + settings.fixed_frame +
                      "', got none (" + placed.error + ")";
      return outcome;
    }
    if (placed.status == ScenePlacement::Status::Stale) {
      outcome.error_kind = ErrorKind::FrameUnavailable;
      outcome.error = entryName("query", i) + ".frame_id = '" + spec.frame_id +
                      "': expected a transform to '" + settings.fixed_frame +
                      "' within max_transform_age, got a stale one (" + placed.error + ")";
      return outcome;
    }
    if (placed.status == ScenePlacement::Status::Degenerate) {
      outcome.error_kind = ErrorKind::InvalidRequest;
      outcome.error = entryName("query", i) + ": " + placed.error;
      return outcome;
    }
    queries.push_back(placed.ellipse);
  }

  std::set<std::string> unavailable;
  std::set<std::string> stale;
  if (cache) {
    cache->begin(registry, settings.global_padding_m);
    outcome.placed = cache->takeRecycled();
  }
  // A recycled scene holds every stored ellipse's name and role in placing order: entry after
  // entry only the geometry is written, until an entry is not placed (then the rest is dropped
  // and appended as without one).
  std::size_t rewrite_end = outcome.placed.size();
  outcome.placed.reserve(registry.entries().size() + queries.size());
  std::size_t position = 0;
  using RegistryEntry = std::pair<const std::string, StoredEllipse>;
  const auto put = [&](const RegistryEntry& item, core::EllipseRole role,
                       const core::Ellipse& ellipse) {
    if (position < rewrite_end) {
      outcome.placed.ellipse(position++) = ellipse;
    } else {
      outcome.placed.push_back(item.first, role, ellipse);
      ++position;
    }
  };
  // Links before obstacles, so the core reads the scene once (checkScene()); each entry's index
  // counted in registry order for the cache. A reused entry in a recycled scene touches neither
  // its name nor its spec.
  std::size_t reused_obstacles = 0, obstacles = 0;
  // A projection made now, kept for the next check.
  const auto remember = [&](std::size_t entry, const EllipseSpec& spec,
                            const core::Ellipse& ellipse) {
    cache->store(entry, spec.frame_id, placement.lookup(spec.frame_id).fixed_from_frame, ellipse);
  };
  const auto place = [&](std::size_t entry, const RegistryEntry& item, core::EllipseRole role) {
    const bool obstacle = role == core::EllipseRole::Obstacle;
    obstacles += obstacle;
    if (const core::Ellipse* reused = cache ? cache->reuse(entry, placement) : nullptr) {
      put(item, role, *reused);
      reused_obstacles += obstacle;
      return;
    }
    const std::string& name = item.first;
    const StoredEllipse& stored = item.second;
    const ScenePlacement::Placement placed = placement.place(stored.spec, role);
    if (placed.status != ScenePlacement::Status::Placed && position < rewrite_end) {
      outcome.placed.truncate(position);
      rewrite_end = position;
    }
    switch (placed.status) {
      case ScenePlacement::Status::Placed:
        if (cache) remember(entry, stored.spec, placed.ellipse.ellipse);
        put(item, role, placed.ellipse.ellipse);
        break;
      case ScenePlacement::Status::FrameUnavailable:
        unavailable.insert(stored.spec.frame_id);
        outcome.skipped.push_back(name + ": frame '" + stored.spec.frame_id + "' unavailable");
        break;
      case ScenePlacement::Status::Stale:
        stale.insert(stored.spec.frame_id);
        outcome.skipped.push_back(name + ": frame '" + stored.spec.frame_id + "' stale (" +
                                  placed.error + ")");
        break;
      case ScenePlacement::Status::Degenerate:
        outcome.skipped.push_back(placed.error);
        break;
    }
  };
  // A recycled scene, frame by frame: the entries of frames that stood still are not visited.
  const auto project = [&](std::size_t at) {
    const PlacementCache::OrderedEntry& item = cache->placingOrder()[at];
    const EllipseSpec& spec = item.entry->second.spec;
    const ScenePlacement::Placement placed = placement.place(spec, item.role);
    if (placed.status != ScenePlacement::Status::Placed) return false;
    remember(item.index, spec, placed.ellipse.ellipse);
    outcome.placed.ellipse(at) = placed.ellipse.ellipse;
    return true;
  };
  if (cache && rewrite_end > 0 &&
      cache->refillByFrame(outcome.placed, placement, project, &reused_obstacles)) {
    obstacles = cache->obstacleCount();
  } else if (cache) {
    reused_obstacles = 0;  // the frame-by-frame refill may have counted some
    for (const PlacementCache::OrderedEntry& item : cache->placingOrder()) {
      place(item.index, *item.entry, item.role);
    }
  } else {
    for (const core::EllipseRole pass : {core::EllipseRole::Link, core::EllipseRole::Obstacle}) {
      std::size_t index = 0;
      for (const RegistryEntry& item : registry.entries()) {
        const std::size_t entry = index++;
        if (item.second.role() == pass) place(entry, item, pass);
      }
    }
  }
  if (cache && outcome.skipped.empty()) cache->produced(outcome.placed);
  outcome.unavailable_frames.assign(unavailable.begin(), unavailable.end());
  outcome.stale_frames.assign(stale.begin(), stale.end());
  outcome.complete = outcome.skipped.empty();

  // The scene is the queries followed by the placed stored ellipses (movers before obstacles;
  // the answer does not depend on the order), checked in place and the queries dropped again, so
  // no name is copied twice. Names were checked where they came in (the registry,
  // validateCheckRequest()), so the core does not hash them all again on every check.
  core::Scene& scene = outcome.placed;
  scene.insertFront(queries);
  const auto answer = [&]() -> CheckOutcome& {
    outcome.placed.eraseFront(queries.size());
    outcome.frames = placement.takeFrames();
    return outcome;
  };
  const std::set<std::string> only_names(request.names.begin(), request.names.end());
  // Obstacles that stood still since the last check need not stream past the links again: the
  // cache's grid of them answers the same bits (core::checkMoversAgainst()).
  const core::IndexedObstacles* standing = nullptr;
  std::size_t first_obstacle = 0;
  while (first_obstacle < scene.size() &&
         scene.role(first_obstacle) != core::EllipseRole::Obstacle) {
    ++first_obstacle;
  }
  if (cache) {
    standing = cache->standingObstacles().update(reused_obstacles == obstacles, scene,
                                                 first_obstacle);
  }
  // Every entry was validated where it was made (ScenePlacement refuses an invalid projection,
  // the registry and validateCheckRequest() duplicate names) and the movers come first: the
  // core need not test every entry again on every check.
  const auto movers = [&] {
    std::vector<core::NamedEllipse> entries;
    entries.reserve(first_obstacle);
    for (std::size_t i = 0; i < first_obstacle; ++i) entries.push_back(scene.entry(i));
    return entries;
  };
  core::SceneCheckResult result =
      standing ? core::checkMoversAgainst(movers(), *standing, settings.rules, only_names)
               : core::checkValidatedScene(scene, first_obstacle, settings.rules, only_names);
  if (!result.ok()) {
    // Requests are validated before they get here, so this is a bug: say so.
    outcome.error_kind = ErrorKind::Internal;
    outcome.error = "internal error: " + result.error;
    return std::move(answer());
  }
  outcome.collisions = std::move(result.collisions);
  outcome.warnings = std::move(result.warnings);

  const std::string& of = request.min_distance_of;
  if (of.empty()) return std::move(answer());
  bool placed = false;
  for (std::size_t i = 0; i < scene.size() && !placed; ++i) placed = scene.name(i) == of;
  if (!placed) {
    outcome.nearest_problem =
        "min_distance_of = '" + of + "': not measured, the ellipse could not be placed";
    return std::move(answer());
  }
  const core::NearestResult nearest = core::nearestTo(scene, settings.rules, of);
  if (!nearest.ok()) {
    outcome.error_kind = ErrorKind::Internal;
    outcome.error = "internal error: " + nearest.error;
  } else if (!nearest.found) {
    outcome.nearest_problem = "min_distance_of = '" + of +
                              "': no placed ellipse that the pair rules measure it against";
  } else {
    outcome.nearest = nearest.nearest;
  }
  return std::move(answer());
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
