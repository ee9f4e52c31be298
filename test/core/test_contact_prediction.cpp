// Time to contact of a scene (core/contact_prediction.h) against brute force over every pair and
// the quad-precision first-contact oracle.
#include <gtest/gtest.h>

#include <random>

#include "ellipse_collision/core/contact_prediction.h"
#include "ellipse_collision/core/overlap.h"
#include "first_contact_oracle.h"

namespace ellipse_collision::core {
namespace {

TEST(PredictContacts, SweptBroadphaseFindsExactlyTheBruteForcePairsAtTheOracleTimes) {
  std::mt19937 rng(141);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<NamedEllipse> scene;
  std::vector<Motion> motions;
  for (int i = 0; i < 120; ++i) {
    Ellipse e;
    e.center = {10.0 * u(rng), 10.0 * u(rng)};
    e.radius_x = 0.3 + 0.2 * u(rng);
    e.radius_y = 0.1 + 0.05 * u(rng);
    e.angle = 3.0 * u(rng);
    const EllipseRole role = i < 20 ? EllipseRole::Link : EllipseRole::Obstacle;
    scene.push_back({(role == EllipseRole::Link ? "l" : "o") + std::to_string(i), role, e});
    motions.push_back(i % 4 == 0 ? Motion{} : Motion{{u(rng), u(rng)}, i % 3 == 0 ? u(rng) : 0.0});
  }
  SceneRules rules;
  const double horizon = 3.0;
  const PredictionResult result = predictContacts(scene, motions, rules, {}, horizon);
  ASSERT_TRUE(result.refused.empty());
  // Brute force over every wanted pair.
  std::size_t expected = 0;
  for (std::size_t i = 0; i < scene.size(); ++i) {
    for (std::size_t j = i + 1; j < scene.size(); ++j) {
      if (!pairWanted(scene[i], scene[j], rules, {}) || overlap(scene[i].ellipse, scene[j].ellipse))
        continue;
      const FirstContact c =
          firstContact(scene[i].ellipse, motions[i], scene[j].ellipse, motions[j], horizon);
      if (!c.contact) continue;
      ++expected;
      bool found = false;
      for (const PredictedContact& p : result.predicted) {
        if ((p.name_a == scene[i].name && p.name_b == scene[j].name) ||
            (p.name_a == scene[j].name && p.name_b == scene[i].name)) {
          found = true;
          EXPECT_EQ(p.time, c.time);
          const bool translating =
              motions[i].angular_velocity == 0.0 && motions[j].angular_velocity == 0.0;
          if (translating) {
            const auto oracle = test::oracleFirstContact(scene[i].ellipse, motions[i],
                                                         scene[j].ellipse, motions[j], horizon);
            EXPECT_NEAR(p.time, static_cast<double>(oracle.time), 1e-9);
          }
        }
      }
      EXPECT_TRUE(found) << scene[i].name << " / " << scene[j].name;
    }
  }
  EXPECT_EQ(result.predicted.size(), expected);
  EXPECT_GT(expected, 5u);
  EXPECT_LT(result.pair_tests, 20u * 100u / 4u);  // far fewer than the 1990 wanted pairs
  for (std::size_t k = 1; k < result.predicted.size(); ++k) {
    EXPECT_LE(result.predicted[k - 1].time, result.predicted[k].time);
  }
  std::printf("prediction: %zu contacts, %zu firstContact calls for %d wanted pairs\n",
              result.predicted.size(), result.pair_tests, 20 * 100 + 190);
}

TEST(PredictContacts, PairsInCollisionNowAreNotRepeated) {
  Ellipse a;
  a.radius_x = a.radius_y = 1.0;
  Ellipse b = a;
  b.center = {1.5, 0.0};
  const std::vector<NamedEllipse> scene = {{"link", EllipseRole::Link, a},
                                           {"wall", EllipseRole::Obstacle, b}};
  const PredictionResult r =
      predictContacts(scene, {Motion{{1.0, 0.0}, 0.0}, Motion{}}, SceneRules{}, {}, 2.0);
  EXPECT_TRUE(r.predicted.empty());
}

}  // namespace
}  // namespace ellipse_collision::core
