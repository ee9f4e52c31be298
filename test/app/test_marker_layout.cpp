// Which markers show a check and what changes between checks, without ROS (app/marker_layout.h):
// the changes are applied to a model of what a viewer holds (View), and the expectations come
// from the scene itself and the documented rules, written out by hand.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "ellipse_collision/app/marker_layout.h"
#include "scene_test_helpers.h"

namespace ellipse_collision::app {
namespace {

using core::scene_test::ellipse;
using Key = std::pair<std::string, std::int32_t>;  // namespace, id
using Changes = MarkerLayout::Changes;

constexpr core::EllipseRole kLink = core::EllipseRole::Link;
constexpr core::EllipseRole kObstacle = core::EllipseRole::Obstacle;
const std::string kObstacles = "obstacles";
const std::string kLinks = "links";
const std::string kLines = MarkerLayout::kClearanceNamespace;

bool sameEllipse(const core::Ellipse& a, const core::Ellipse& b) {
  return a.center == b.center && a.radius_x == b.radius_x && a.radius_y == b.radius_y &&
         a.angle == b.angle;
}
bool byPlace(const core::Ellipse& a, const core::Ellipse& b) {
  return std::make_pair(a.center.x(), a.center.y()) < std::make_pair(b.center.x(), b.center.y());
}
std::vector<core::Ellipse> sortedByPlace(std::vector<core::Ellipse> ellipses) {
  std::sort(ellipses.begin(), ellipses.end(), byPlace);
  return ellipses;
}
bool sameEllipses(std::vector<core::Ellipse> a, std::vector<core::Ellipse> b) {
  a = sortedByPlace(std::move(a));
  b = sortedByPlace(std::move(b));
  return std::equal(a.begin(), a.end(), b.begin(), b.end(), sameEllipse);
}

std::vector<core::Ellipse> ellipsesOf(const MarkerLayout::FillChange& fill) {
  std::vector<core::Ellipse> out;
  for (std::size_t i = 0; i < fill.ellipses.size(); ++i) out.push_back(fill.ellipses[i]);
  return out;
}

/// What a viewer holds after applying every change sent to it, and what was ever shown.
struct View {
  struct Fill {
    MarkerState state;
    std::vector<core::Ellipse> ellipses;
  };
  std::map<Key, Fill> fills;
  std::map<std::int32_t, std::pair<Eigen::Vector2d, Eigen::Vector2d>> lines;
  std::set<Key> ever_shown_fills;

  void apply(const Changes& changes) {
    for (const MarkerLayout::FillChange& fill : changes.fills) {
      const Key key{MarkerLayout::nameSpace(fill.role), fill.id};
      if (fill.action == MarkerLayout::Action::Delete) {
        fills.erase(key);
        continue;
      }
      fills[key] = {fill.state, ellipsesOf(fill)};
      ever_shown_fills.insert(key);
    }
    for (const MarkerLayout::LineChange& line : changes.lines) {
      if (line.action == MarkerLayout::Action::Delete) {
        lines.erase(line.id);
      } else {
        lines[line.id] = {line.point_a, line.point_b};
      }
    }
  }
  std::vector<core::Ellipse> allOf(const std::string& ns) const {
    std::vector<core::Ellipse> out;
    for (const auto& [key, fill] : fills) {
      if (key.first == ns) out.insert(out.end(), fill.ellipses.begin(), fill.ellipses.end());
    }
    return out;
  }
  std::size_t markersIn(const std::string& ns) const {
    return static_cast<std::size_t>(std::count_if(
        fills.begin(), fills.end(), [&](const auto& entry) { return entry.first.first == ns; }));
  }
  /// The fill marker drawing `e` (none: a null key id of -1).
  Key holding(const std::string& ns, const core::Ellipse& e) const {
    for (const auto& [key, fill] : fills) {
      if (key.first != ns) continue;
      for (const core::Ellipse& drawn : fill.ellipses) {
        if (sameEllipse(drawn, e)) return key;
      }
    }
    return {ns, -1};
  }
};

/// `count` obstacles in a row along x, 1 m apart.
std::vector<core::NamedEllipse> row(std::size_t count) {
  std::vector<core::NamedEllipse> out;
  for (std::size_t i = 0; i < count; ++i) {
    out.push_back(
        ellipse("o" + std::to_string(i), kObstacle, static_cast<double>(i), 0.0, 0.3, 0.2));
  }
  return out;
}
std::vector<core::NamedEllipse> everyOther(const std::vector<core::NamedEllipse>& scene) {
  std::vector<core::NamedEllipse> out;
  for (std::size_t i = 0; i < scene.size(); i += 2) out.push_back(scene[i]);
  return out;
}
/// side x side obstacles on a grid 1 m apart.
std::vector<core::NamedEllipse> grid(std::size_t side) {
  std::vector<core::NamedEllipse> out;
  for (std::size_t i = 0; i < side * side; ++i) {
    out.push_back(ellipse("o" + std::to_string(i), kObstacle, static_cast<double>(i % side),
                          static_cast<double>(i / side), 0.3, 0.2, 0.1));
  }
  return out;
}
std::vector<core::Ellipse> ellipsesOf(const std::vector<core::NamedEllipse>& scene,
                                      core::EllipseRole role) {
  std::vector<core::Ellipse> out;
  for (const core::NamedEllipse& e : scene) {
    if (e.role == role) out.push_back(e.ellipse);
  }
  return out;
}
Changes update(MarkerLayout& layout, const std::vector<core::NamedEllipse>& scene,
               const std::vector<core::NearPair>& warnings = {},
               const std::vector<core::CollidingPair>& collisions = {}) {
  return layout.update(core::Scene(scene), collisions, warnings);
}
core::NearPair nearPair(const std::string& a, const std::string& b, double x) {
  return core::NearPair{a, b, 0.5, {x, 0.0}, {x, 0.5}};
}

TEST(MarkerLayout, BucketsDoubleAboveThirtyTwoEllipsesEachAndHalveBelowAQuarterOfThat) {
  ASSERT_EQ(MarkerLayout::kEllipsesPerMarker, 32u);
  MarkerLayout layout;
  View view;
  // B is kept while the count stays within [8 B, 32 B]; it is a power of two. Where B stays, the
  // fewer ellipses are spread over the row so that every cell cut before still holds some.
  const std::vector<std::pair<std::vector<core::NamedEllipse>, std::size_t>> steps = {
      {row(32), 1}, {row(33), 2},
      {row(65), 4}, {everyOther(row(64)), 4},
      {row(31), 2}, {everyOther(row(32)), 2},
      {row(15), 1}, {row(100), 4},
      {row(1), 1}};
  for (const auto& [scene, buckets] : steps) {
    const std::size_t count = scene.size();
    view.apply(update(layout, scene));
    // Exactly B markers, ids 0..B-1 of the free state: every other one was deleted.
    ASSERT_EQ(view.markersIn(kObstacles), buckets) << count << " ellipses";
    for (std::uint32_t b = 0; b < buckets; ++b) {
      EXPECT_TRUE(view.fills.count({kObstacles, MarkerLayout::fillId(MarkerState::Free, b)}))
          << count << " ellipses, bucket " << b;
    }
    EXPECT_TRUE(sameEllipses(view.allOf(kObstacles), ellipsesOf(scene, kObstacle)));
    // By place: along the row, the buckets' stretches do not interleave.
    std::vector<std::pair<double, double>> stretches;
    for (const auto& [key, fill] : view.fills) {
      const std::vector<core::Ellipse> sorted = sortedByPlace(fill.ellipses);
      stretches.emplace_back(sorted.front().center.x(), sorted.back().center.x());
      EXPECT_GE(fill.ellipses.size() * buckets * 2, count) << "about equal shares";
    }
    std::sort(stretches.begin(), stretches.end());
    for (std::size_t i = 1; i < stretches.size(); ++i) {
      EXPECT_LT(stretches[i - 1].second, stretches[i].first) << count << " ellipses";
    }
  }
}

TEST(MarkerLayout, AMovedEllipseReSendsOnlyItsBucketAndNothingChangedSendsNothing) {
  MarkerLayout layout;
  View view;
  std::vector<core::NamedEllipse> scene = grid(16);  // 256: 8 buckets
  view.apply(update(layout, scene));
  ASSERT_EQ(view.markersIn(kObstacles), 8u);
  const Changes same = update(layout, scene);
  EXPECT_TRUE(same.fills.empty());
  EXPECT_TRUE(same.lines.empty());

  // A nudge within its cell: one marker, the one that drew it, with the ellipse where it is now.
  const Key before = view.holding(kObstacles, scene[37].ellipse);
  std::vector<core::Ellipse> expected = view.fills.at(before).ellipses;
  const core::Ellipse old = scene[37].ellipse;
  scene[37].ellipse.center.x() += 0.01;
  std::replace_if(
      expected.begin(), expected.end(), [&](const core::Ellipse& e) { return sameEllipse(e, old); },
      scene[37].ellipse);
  Changes moved = update(layout, scene);
  ASSERT_EQ(moved.fills.size(), 1u);
  EXPECT_EQ(moved.fills[0].action, MarkerLayout::Action::Show);
  EXPECT_EQ(moved.fills[0].id, before.second);
  EXPECT_EQ(moved.fills[0].role, kObstacle);
  EXPECT_TRUE(sameEllipses(ellipsesOf(moved.fills[0]), expected));
  EXPECT_TRUE(moved.lines.empty());
  view.apply(moved);

  // Across the field: its old marker and the marker of its new place, nothing else.
  const Key from = view.holding(kObstacles, scene[0].ellipse);
  const Key to = view.holding(kObstacles, scene[255].ellipse);
  ASSERT_NE(from, to);
  scene[0].ellipse.center = Eigen::Vector2d(15.25, 15.25);
  moved = update(layout, scene);
  ASSERT_EQ(moved.fills.size(), 2u);
  std::set<std::int32_t> ids;
  for (const MarkerLayout::FillChange& fill : moved.fills) {
    EXPECT_EQ(fill.action, MarkerLayout::Action::Show);
    ids.insert(fill.id);
  }
  EXPECT_EQ(ids, (std::set<std::int32_t>{from.second, to.second}));
  view.apply(moved);
  EXPECT_EQ(view.holding(kObstacles, scene[0].ellipse), to);
  EXPECT_TRUE(sameEllipses(view.allOf(kObstacles), ellipsesOf(scene, kObstacle)));
}

TEST(MarkerLayout, ABucketEmptiedOfAStateOrOfEveryEllipseIsDeleted) {
  MarkerLayout layout;
  View view;
  std::vector<core::NamedEllipse> scene = grid(16);
  view.apply(update(layout, scene));

  // o0 and o1 turn yellow: their warning marker(s) appear beside the free ones.
  view.apply(update(layout, scene, {nearPair("o0", "o1", 0.5)}));
  std::set<std::int32_t> warning_ids;
  for (const auto& [key, fill] : view.fills) {
    if (fill.state == MarkerState::Warning) warning_ids.insert(key.second);
  }
  ASSERT_FALSE(warning_ids.empty());
  ASSERT_EQ(view.lines.size(), 1u);
  const std::int32_t line = view.lines.begin()->first;

  // The warning goes: each warning marker is deleted, and so is the line.
  const Changes cleared = update(layout, scene);
  std::set<std::int32_t> deleted;
  for (const MarkerLayout::FillChange& fill : cleared.fills) {
    if (fill.action == MarkerLayout::Action::Delete) deleted.insert(fill.id);
  }
  EXPECT_EQ(deleted, warning_ids);
  ASSERT_EQ(cleared.lines.size(), 1u);
  EXPECT_EQ(cleared.lines[0].id, line);
  EXPECT_EQ(cleared.lines[0].action, MarkerLayout::Action::Delete);
  view.apply(cleared);
  EXPECT_TRUE(view.lines.empty());
  EXPECT_TRUE(sameEllipses(view.allOf(kObstacles), ellipsesOf(scene, kObstacle)));

  // Every ellipse of one bucket goes (224 left: still 8 buckets): that marker alone, deleted.
  const Key emptied = view.holding(kObstacles, scene[0].ellipse);
  const std::vector<core::Ellipse> gone = view.fills.at(emptied).ellipses;
  std::vector<core::NamedEllipse> rest;
  for (const core::NamedEllipse& e : scene) {
    if (std::none_of(gone.begin(), gone.end(),
                     [&](const core::Ellipse& g) { return sameEllipse(g, e.ellipse); })) {
      rest.push_back(e);
    }
  }
  ASSERT_EQ(rest.size(), 256u - gone.size());
  const Changes removed = update(layout, rest);
  ASSERT_EQ(removed.fills.size(), 1u);
  EXPECT_EQ(removed.fills[0].id, emptied.second);
  EXPECT_EQ(removed.fills[0].action, MarkerLayout::Action::Delete);
  EXPECT_TRUE(removed.lines.empty());
}

/// Two ordered name pairs (x, "box") whose preferred ids are the same, a hash clash: the first
/// among ("n0", "box"), ("n1", "box"), ... (found by a search over 1.4 million names, too slow to
/// repeat in every run; the test asserts that they clash).
std::pair<std::string, std::string> clashingNames() { return {"n1229599", "n1432382"}; }

TEST(MarkerLayout, AClearanceLineWhosePreferredIdIsShownTakesTheNextFreeIdAndKeepsIt) {
  const auto [a, b] = clashingNames();
  const std::int32_t preferred = MarkerLayout::preferredId(a, "box");
  ASSERT_EQ(MarkerLayout::preferredId(b, "box"), preferred);
  const std::int32_t next = static_cast<std::int32_t>((preferred + 1u) & 0x7fffffffu);
  const std::vector<core::NamedEllipse> scene = {ellipse(a, kLink, 0, 0, 0.3, 0.2),
                                                 ellipse(b, kLink, 2, 0, 0.3, 0.2),
                                                 ellipse("box", kObstacle, 1, 0, 0.3, 0.2)};
  MarkerLayout layout;
  View view;
  view.apply(update(layout, scene, {nearPair(a, "box", 0.0)}));
  EXPECT_EQ(view.lines.count(preferred), 1u);

  // b listed first: its preferred id is still a's, shown in the last update.
  Changes changes = update(layout, scene, {nearPair(b, "box", 2.0), nearPair(a, "box", 0.0)});
  ASSERT_EQ(changes.lines.size(), 1u) << "a's line did not change";
  EXPECT_EQ(changes.lines[0].id, next);
  EXPECT_EQ(changes.lines[0].point_a, Eigen::Vector2d(2.0, 0.0));
  view.apply(changes);

  // a goes; b keeps its id while its line stays shown.
  changes = update(layout, scene, {nearPair(b, "box", 2.0)});
  ASSERT_EQ(changes.lines.size(), 1u);
  EXPECT_EQ(changes.lines[0].id, preferred);
  EXPECT_EQ(changes.lines[0].action, MarkerLayout::Action::Delete);
  // a comes back to its free preferred id.
  changes = update(layout, scene, {nearPair(b, "box", 2.0), nearPair(a, "box", 0.0)});
  ASSERT_EQ(changes.lines.size(), 1u);
  EXPECT_EQ(changes.lines[0].id, preferred);
  EXPECT_EQ(changes.lines[0].point_a, Eigen::Vector2d(0.0, 0.0));

  // Both new in one update: the first listed takes the preferred id.
  update(layout, scene);
  changes = update(layout, scene, {nearPair(b, "box", 2.0), nearPair(a, "box", 0.0)});
  ASSERT_EQ(changes.lines.size(), 2u);
  std::map<std::int32_t, double> x_by_id;
  for (const MarkerLayout::LineChange& line : changes.lines) x_by_id[line.id] = line.point_a.x();
  EXPECT_EQ(x_by_id, (std::map<std::int32_t, double>{{preferred, 2.0}, {next, 0.0}}));
}

/// The lines of a full sweep (fraction 1): id -> action.
std::map<std::int32_t, MarkerLayout::Action> sweptLines(MarkerLayout& layout) {
  std::map<std::int32_t, MarkerLayout::Action> out;
  for (const MarkerLayout::LineChange& line : layout.refresh(1.0, {}).lines) {
    EXPECT_TRUE(out.emplace(line.id, line.action).second) << "line " << line.id << " twice";
  }
  return out;
}

TEST(MarkerLayout, TheSweepRemembersTheLastKSweptLineDeletionsAndForgetsOlderOnes) {
  const std::size_t kept = MarkerLayout::kSweptLineDeletions;
  ASSERT_EQ(kept, 1024u);
  const std::size_t pairs = kept + 10;
  std::vector<core::NamedEllipse> scene = {ellipse("box", kObstacle, 0, 0, 0.3, 0.2)};
  std::vector<core::NearPair> warnings;
  for (std::size_t i = 0; i < pairs; ++i) {
    scene.push_back(ellipse("l" + std::to_string(i), kLink, static_cast<double>(i), 1, 0.3, 0.2));
    warnings.push_back(nearPair("l" + std::to_string(i), "box", static_cast<double>(i)));
  }
  MarkerLayout layout;
  View view;
  view.apply(update(layout, scene, warnings));
  ASSERT_EQ(view.lines.size(), pairs);
  std::vector<std::int32_t> id_of(pairs);
  for (const auto& [id, points] : view.lines) {
    id_of[static_cast<std::size_t>(points.first.x())] = id;
  }

  // The first 10 pairs go, then pair 10, then all the others: the 10 oldest deletions are
  // forgotten.
  for (const std::size_t first_kept : {10, 11}) {
    view.apply(update(layout, scene,
                      std::vector<core::NearPair>(warnings.begin() + first_kept, warnings.end())));
  }
  view.apply(update(layout, scene));
  EXPECT_TRUE(view.lines.empty());
  std::map<std::int32_t, MarkerLayout::Action> expected;
  for (std::size_t i = 10; i < pairs; ++i) expected[id_of[i]] = MarkerLayout::Action::Delete;
  EXPECT_EQ(sweptLines(layout), expected);

  // A pair shown again leaves the deletions: the sweep shows it instead.
  view.apply(update(layout, scene, {warnings[500]}));
  expected[id_of[500]] = MarkerLayout::Action::Show;
  EXPECT_EQ(sweptLines(layout), expected);
  // An old one shown again and deleted is remembered anew, pushing out the oldest now kept
  // (pair 10, deleted alone before all the others).
  view.apply(update(layout, scene, {warnings[3]}));
  view.apply(update(layout, scene));
  expected[id_of[500]] = MarkerLayout::Action::Delete;
  expected[id_of[3]] = MarkerLayout::Action::Delete;
  // 1,025 deletions now: the oldest kept (pair 10) goes.
  expected.erase(id_of[10]);
  EXPECT_EQ(sweptLines(layout), expected);
}

TEST(MarkerLayout, TheRefreshSweepCoversEveryIdOnceWithinOneSweepAsItIsNow) {
  std::vector<core::NamedEllipse> scene = grid(12);  // 144 obstacles: 8 buckets
  for (int i = 0; i < 40; ++i) {
    scene.push_back(ellipse("l" + std::to_string(i), kLink, i * 0.3, -3.0, 0.1, 0.1));
  }
  MarkerLayout layout;
  View view;
  std::set<std::int32_t> lines_ever;
  const auto apply = [&](const Changes& changes) {
    view.apply(changes);
    for (const auto& [id, points] : view.lines) lines_ever.insert(id);
  };
  apply(update(layout, scene, {nearPair("l0", "o0", 0.0), nearPair("l1", "o5", 1.0)},
               {{"l20", "o100", 0.5}}));
  apply(update(layout, scene, {nearPair("l1", "o5", 1.5), nearPair("l2", "o7", 2.0)}));
  scene.resize(scene.size() - 30);  // 10 links: from 2 buckets to 1
  apply(update(layout, scene, {nearPair("l2", "o7", 2.0)}));
  ASSERT_LT(lines_ever.size(), MarkerLayout::kSweptLineDeletions);

  // What a sweep must cover: every fill marker ever shown, every line shown or deleted.
  std::set<Key> expected(view.ever_shown_fills.begin(), view.ever_shown_fills.end());
  for (const std::int32_t id : lines_ever) expected.insert({kLines, id});
  ASSERT_GT(expected.size(), view.fills.size() + view.lines.size()) << "some deleted ones too";
  // One marker the array holds already counts as refreshed and is not sent again.
  const Key already = view.fills.begin()->first;
  const std::set<Key> in_array = {already};

  for (int sweep = 0; sweep < 2; ++sweep) {
    std::map<Key, int> times;
    for (int call = 0; call < 4; ++call) {
      const Changes slice = layout.refresh(0.25, in_array);
      for (const MarkerLayout::FillChange& fill : slice.fills) {
        const Key key{MarkerLayout::nameSpace(fill.role), fill.id};
        ++times[key];
        const auto shown = view.fills.find(key);
        if (shown == view.fills.end()) {
          EXPECT_EQ(fill.action, MarkerLayout::Action::Delete) << key.first << " " << key.second;
          continue;
        }
        EXPECT_EQ(fill.action, MarkerLayout::Action::Show);
        EXPECT_EQ(fill.state, shown->second.state);
        EXPECT_TRUE(sameEllipses(ellipsesOf(fill), shown->second.ellipses));
      }
      for (const MarkerLayout::LineChange& line : slice.lines) {
        ++times[{kLines, line.id}];
        const auto shown = view.lines.find(line.id);
        if (shown == view.lines.end()) {
          EXPECT_EQ(line.action, MarkerLayout::Action::Delete);
          continue;
        }
        EXPECT_EQ(line.action, MarkerLayout::Action::Show);
        EXPECT_EQ(line.point_a, shown->second.first);
        EXPECT_EQ(line.point_b, shown->second.second);
      }
    }
    std::set<Key> covered;
    for (const auto& [key, count] : times) {
      EXPECT_EQ(count, 1) << key.first << " " << key.second << " in sweep " << sweep;
      covered.insert(key);
    }
    EXPECT_EQ(covered.count(already), 0u);
    covered.insert(already);
    EXPECT_EQ(covered, expected) << "sweep " << sweep;
  }
  // A long gap owes one sweep, not several.
  EXPECT_EQ(layout.refresh(5.0, {}).fills.size() + layout.refresh(0.0, {}).fills.size() +
                layout.refresh(5.0, {}).fills.size(),
            2 * view.ever_shown_fills.size());
}

}  // namespace
}  // namespace ellipse_collision::app
