#include "ellipse_collision/core/path_check.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "ellipse_collision/core/broadphase.h"
#include "ellipse_collision/core/distance.h"

namespace ellipse_collision::core {
namespace {

bool moves(const Motion& m) {
  return m.velocity.x() != 0.0 || m.velocity.y() != 0.0 || m.angular_velocity != 0.0;
}

/// Which obstacles each link may be reported with (all, unless allowed pairs say otherwise).
class PairFilter {
 public:
  explicit PairFilter(const PathScene& scene) : obstacles_(scene.obstacles.size()) {
    if (scene.allowed.size() == 0) return;
    allowed_.assign(scene.links.size() * obstacles_, 0);
    for (std::size_t l = 0; l < scene.links.size(); ++l) {
      for (std::size_t o = 0; o < obstacles_; ++o) {
        allowed_[l * obstacles_ + o] =
            scene.allowed.contains(scene.links[l].name, scene.obstacles[o].name);
      }
    }
  }
  bool wanted(std::size_t link, std::size_t obstacle) const {
    return allowed_.empty() || !allowed_[link * obstacles_ + obstacle];
  }

 private:
  std::size_t obstacles_;
  std::vector<char> allowed_;
};

BoundingBox unite(const BoundingBox& a, const BoundingBox& b) {
  return {std::min(a.min_x, b.min_x), std::min(a.min_y, b.min_y), std::max(a.max_x, b.max_x),
          std::max(a.max_y, b.max_y)};
}

struct Candidate {
  double time{std::numeric_limits<double>::infinity()};
  std::size_t link{0};
  std::size_t obstacle{0};
  bool found{false};
};

}  // namespace

PathCheckResult checkPath(const PathScene& scene, const std::vector<PathPose>& poses, bool timed) {
  PathCheckResult result;
  if (poses.empty()) {
    result.error = "a path needs at least one pose";
    return result;
  }
  const std::size_t n_links = scene.links.size();
  const std::size_t n_obstacles = scene.obstacles.size();
  const PairFilter filter(scene);

  // Standing obstacles in a grid, moving ones (timed paths only) apart.
  std::vector<std::size_t> standing, moving;
  for (std::size_t o = 0; o < n_obstacles; ++o) {
    (timed && moves(scene.obstacle_motions[o]) ? moving : standing).push_back(o);
  }
  std::vector<BoundingBox> standing_boxes;
  standing_boxes.reserve(standing.size());
  for (std::size_t o : standing)
    standing_boxes.push_back(boundingCircleBox(scene.obstacles[o].ellipse));
  const BoxGrid grid(standing_boxes);
  const Motion no_motion;
  const auto obstacleAt = [&](std::size_t o, double time) {
    return timed ? movedBy(scene.obstacles[o].ellipse, scene.obstacle_motions[o], time)
                 : scene.obstacles[o].ellipse;
  };
  const auto motionOf = [&](std::size_t o) -> const Motion& {
    return timed ? scene.obstacle_motions[o] : no_motion;
  };

  // ---- first contact, segment by segment ------------------------------------------------------
  std::vector<std::size_t> hits;
  std::vector<BoundingBox> link_boxes(n_links);
  std::vector<std::pair<std::size_t, BoundingBox>> near_moving;
  std::size_t last_pose = poses.size() - 1;  // clearance is measured up to here
  for (std::size_t s = 0; s + 1 < poses.size() && result.collision_free; ++s) {
    const PathPose& from = poses[s];
    const PathPose& to = poses[s + 1];
    const double duration = timed ? to.time - from.time : 1.0;
    const SegmentMotion motion = segmentMotion(from, to, duration);
    Candidate best;
    const auto test = [&](std::size_t l, std::size_t o) {
      if (!filter.wanted(l, o)) return;
      const Ellipse obstacle = obstacleAt(o, from.time);
      if (timed && moves(motionOf(o))) {
        const std::string invalid = invalidSegmentReason(obstacle, motionOf(o), duration);
        if (!invalid.empty()) {
          result.error = "obstacle '" + scene.obstacles[o].name + "' on segment " +
                         std::to_string(s) + ": " + invalid;
          return;
        }
      }
      ++result.pair_tests;
      const FirstContact contact =
          segmentContact(scene.links[l].ellipse, motion, obstacle, motionOf(o));
      if (!contact.contact) return;
      const bool earlier =
          !best.found || contact.time < best.time ||
          (contact.time == best.time &&
           std::make_pair(scene.links[l].name, scene.obstacles[o].name) <
               std::make_pair(scene.links[best.link].name, scene.obstacles[best.obstacle].name));
      if (earlier) best = {contact.time, l, o, true};
    };
    // Swept boxes of the links, and of the moving obstacles that come near the robot's.
    BoundingBox robot{1.0, 1.0, 0.0, 0.0};
    for (std::size_t l = 0; l < n_links; ++l) {
      link_boxes[l] = sweptLinkBox(scene.links[l].ellipse, motion);
      robot = l == 0 ? link_boxes[l] : unite(robot, link_boxes[l]);
    }
    near_moving.clear();
    for (std::size_t o : moving) {
      const BoundingBox box = sweptBox(obstacleAt(o, from.time), motionOf(o), duration);
      if (boxesOverlap(robot, box)) near_moving.push_back({o, box});
    }
    for (std::size_t l = 0; l < n_links; ++l) {
      grid.overlapping(link_boxes[l], &hits);
      for (std::size_t h : hits) test(l, standing[h]);
      for (const auto& [o, box] : near_moving) {
        if (boxesOverlap(link_boxes[l], box)) test(l, o);
      }
      if (!result.ok()) return result;
    }
    if (best.found) {
      result.collision_free = false;
      result.segment = s;
      result.fraction = std::clamp(best.time / duration, 0.0, 1.0);
      result.time = timed ? from.time + best.time : 0.0;
      result.link = scene.links[best.link].name;
      result.obstacle = scene.obstacles[best.obstacle].name;
      last_pose = s;
    }
  }

  // ---- minimum clearance at poses[0 .. last_pose] ---------------------------------------------
  // An upper bound first, from the inscribed circles at the first pose (each circle lies in its
  // ellipse, so the ellipses are no farther apart than their circles): pairs whose bounding
  // circles are farther apart than the bound can never be the nearest, at any pose.
  double bound = std::numeric_limits<double>::infinity();
  for (std::size_t l = 0; l < n_links; ++l) {
    const Ellipse link = placeAt(scene.links[l].ellipse, {poses[0].x, poses[0].y}, poses[0].yaw);
    for (std::size_t o = 0; o < n_obstacles; ++o) {
      if (!filter.wanted(l, o)) continue;
      const Ellipse& obstacle = scene.obstacles[o].ellipse;
      const double gap = (link.center - obstacle.center).norm() - inscribedRadius(link) -
                         inscribedRadius(obstacle);
      bound = std::min(bound, std::max(0.0, gap) * (1.0 + 1e-9) + 1e-12);
    }
  }
  const auto measure = [&](std::size_t pose, std::size_t l, const Ellipse& link, std::size_t o,
                           const Ellipse& obstacle) {
    if (!filter.wanted(l, o)) return;
    const double lower =
        (link.center - obstacle.center).norm() - boundingRadius(link) - boundingRadius(obstacle);
    if (lower > bound || (result.has_clearance && lower >= result.min_clearance)) return;
    ++result.pair_tests;
    const Clearance c = distance(link, obstacle);
    const double d = c.separated ? c.distance : 0.0;
    if (!result.has_clearance || d < result.min_clearance) {
      result.has_clearance = true;
      result.min_clearance = d;
      result.min_clearance_pose = pose;
      result.clearance_link = scene.links[l].name;
      result.clearance_obstacle = scene.obstacles[o].name;
      bound = std::min(bound, d);
    }
  };
  const auto grown = [&bound](BoundingBox box) {
    if (std::isfinite(bound))
      box.min_x -= bound, box.min_y -= bound, box.max_x += bound, box.max_y += bound;
    return box;
  };
  std::vector<Ellipse> links_at(n_links);
  std::vector<std::pair<std::size_t, Ellipse>> moving_near;
  for (std::size_t p = 0; p <= last_pose; ++p) {
    BoundingBox robot{1.0, 1.0, 0.0, 0.0};
    for (std::size_t l = 0; l < n_links; ++l) {
      links_at[l] = placeAt(scene.links[l].ellipse, {poses[p].x, poses[p].y}, poses[p].yaw);
      const BoundingBox box = boundingCircleBox(links_at[l]);
      robot = l == 0 ? box : unite(robot, box);
    }
    // The moving obstacles at this pose's time that can be nearer than the bound to the robot.
    moving_near.clear();
    const BoundingBox reach = grown(robot);
    for (std::size_t o : moving) {
      const Ellipse obstacle = obstacleAt(o, poses[p].time);
      if (boxesOverlap(reach, boundingCircleBox(obstacle))) moving_near.push_back({o, obstacle});
    }
    for (std::size_t l = 0; l < n_links; ++l) {
      grid.overlapping(grown(boundingCircleBox(links_at[l])), &hits);
      for (std::size_t h : hits)
        measure(p, l, links_at[l], standing[h], scene.obstacles[standing[h]].ellipse);
      for (const auto& [o, obstacle] : moving_near) measure(p, l, links_at[l], o, obstacle);
    }
  }
  return result;
}

}  // namespace ellipse_collision::core
