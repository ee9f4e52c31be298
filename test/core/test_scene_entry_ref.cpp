// The rules the scene check and the nearest-partner search share (src/core/scene_entry_ref.h):
// which pairs are wanted, how a pair is ordered, how an entry is refused, and the distance
// bound that rules pairs out, against circles' exact distances.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>

#include "random_source.h"
#include "scene_entry_ref.h"

namespace ellipse_collision::core::detail {
namespace {

struct Entry {
  std::string name;
  EllipseRole role;
  Ellipse ellipse{{0.0, 0.0}, 1.0, 1.0, 0.0};
  EntryRef ref() const { return {&name, role, &ellipse}; }
};

TEST(SceneEntryRef, PairsOfRolesAreWantedAsTheSceneRulesSay) {
  const Entry query{"q", EllipseRole::Query}, query2{"q2", EllipseRole::Query};
  const Entry link{"l", EllipseRole::Link}, link2{"l2", EllipseRole::Link};
  const Entry rock{"o", EllipseRole::Obstacle}, rock2{"o2", EllipseRole::Obstacle};
  SceneRules rules;
  const std::set<std::string> all;
  EXPECT_TRUE(wanted(link.ref(), rock.ref(), rules, all));
  EXPECT_TRUE(wanted(rock.ref(), link.ref(), rules, all));
  EXPECT_TRUE(wanted(link.ref(), link2.ref(), rules, all));
  EXPECT_FALSE(wanted(rock.ref(), rock2.ref(), rules, all));
  EXPECT_TRUE(wanted(query.ref(), link.ref(), rules, all));
  EXPECT_TRUE(wanted(rock.ref(), query.ref(), rules, all));
  EXPECT_FALSE(wanted(query.ref(), query2.ref(), rules, all));
  rules.self_collision = false;
  EXPECT_FALSE(wanted(link.ref(), link2.ref(), rules, all));
  EXPECT_TRUE(wanted(query.ref(), link.ref(), rules, all)) << "a query meets links regardless";
  rules.allowed.add("o", "l");
  EXPECT_FALSE(wanted(link.ref(), rock.ref(), rules, all)) << "allowed either way round";
  EXPECT_TRUE(wanted(link2.ref(), rock.ref(), rules, all));
  // Only pairs with a named entry.
  const std::set<std::string> only{"o2"};
  EXPECT_FALSE(wanted(link2.ref(), rock.ref(), rules, only));
  EXPECT_TRUE(wanted(link2.ref(), rock2.ref(), rules, only));
  EXPECT_TRUE(wanted(rock2.ref(), query.ref(), rules, only));
}

TEST(SceneEntryRef, APairIsWrittenLowerRoleFirstThenLowerName) {
  const Entry a_rock{"a", EllipseRole::Obstacle}, z_link{"z", EllipseRole::Link};
  const Entry b_link{"b", EllipseRole::Link}, q{"zz", EllipseRole::Query};
  EXPECT_TRUE(comesFirst(z_link.ref(), a_rock.ref()));
  EXPECT_FALSE(comesFirst(a_rock.ref(), z_link.ref()));
  EXPECT_TRUE(comesFirst(b_link.ref(), z_link.ref()));
  EXPECT_TRUE(comesFirst(q.ref(), b_link.ref()));
  EXPECT_FALSE(comesFirst(b_link.ref(), b_link.ref())) << "strict";
}

TEST(SceneEntryRef, EntriesAreRefusedNamingIndexNameAndReason) {
  NameSet names(8);
  Entry good{"arm", EllipseRole::Link};
  EXPECT_EQ(entryProblem(0, good.ref(), names), "");
  EXPECT_EQ(entryProblem(1, Entry{"", EllipseRole::Link}.ref(), names),
            "ellipses[1].name is empty");
  EXPECT_EQ(entryProblem(2, good.ref(), names), "ellipses[2].name = 'arm' is a duplicate");
  Entry bad{"rock", EllipseRole::Obstacle, Ellipse{{0.0, 0.0}, -1.0, 1.0, 0.0}};
  const std::string problem = entryProblem(3, bad.ref(), names);
  EXPECT_EQ(problem, "ellipses[3] ('rock'): " + invalidReason(bad.ellipse));
  EXPECT_NE(problem.find("radius_x = -1"), std::string::npos) << problem;
  // A refused entry's name is taken all the same: it is a duplicate next time.
  EXPECT_EQ(entryProblem(4, bad.ref(), names), "ellipses[4].name = 'rock' is a duplicate");
}

TEST(SceneEntryRef, TheWarningDistanceMustBeFiniteAndNotNegative) {
  SceneRules rules;
  EXPECT_EQ(warningDistanceProblem(rules), "");
  rules.warning_distance = 1e300;
  EXPECT_EQ(warningDistanceProblem(rules), "");
  rules.warning_distance = -1.0;
  EXPECT_EQ(warningDistanceProblem(rules), "warning_distance = -1 must be finite and >= 0");
  rules.warning_distance = NAN;
  EXPECT_EQ(warningDistanceProblem(rules), "warning_distance = nan must be finite and >= 0");
  rules.warning_distance = INFINITY;
  EXPECT_EQ(warningDistanceProblem(rules), "warning_distance = inf must be finite and >= 0");
}

TEST(SceneEntryRef, TheDistanceBoundIsBelowTheExactDistanceOfCirclesAndClose) {
  test::RandomSource random(5);
  for (int i = 0; i < 2000; ++i) {
    const double scale = random.logUniform(1e-3, 1e6);
    const double ra = random.uniform(0.01, 0.5) * scale, rb = random.uniform(0.01, 0.5) * scale;
    const Ellipse ca{{random.uniform(-1, 1) * scale, random.uniform(-1, 1) * scale}, ra, ra, 0.0};
    const Ellipse cb{{random.uniform(-1, 1) * scale, random.uniform(-1, 1) * scale}, rb, rb, 0.0};
    // The exact distance of two circles, in long double.
    const long double dx = (long double)cb.center.x() - ca.center.x();
    const long double dy = (long double)cb.center.y() - ca.center.y();
    const long double exact = std::sqrt(dx * dx + dy * dy) - ca.radius_x - cb.radius_x;
    const double bound = distanceLowerBound(ca, cb);
    EXPECT_LE(bound, exact) << i;
    EXPECT_GE(bound, exact - 4e-9L * (std::sqrt(dx * dx + dy * dy) + ca.radius_x + cb.radius_x))
        << "the margin is about 1e-9 of the lengths";
  }
  // An ellipse lies within its bounding circle: the bound holds for it too.
  const Ellipse needle{{0.0, 0.0}, 2.0, 0.01, 0.0};
  const Ellipse post{{0.0, 3.0}, 0.5, 0.5, 0.0};
  EXPECT_LE(distanceLowerBound(needle, post), 3.0 - 0.01 - 0.5);
  EXPECT_NEAR(distanceLowerBound(needle, post), 3.0 - 2.0 - 0.5, 1e-8);
}

}  // namespace
}  // namespace ellipse_collision::core::detail
