// A ranger's reading as an obstacle: the cone's arc at the measured range covered, a free
// reading free, a broken one refused naming the field.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "ellipse_collision/app/range_obstacle.h"

namespace ellipse_collision::app {
namespace {

RangeReading sonar(double range, double field_of_view = 0.5) {
  RangeReading reading;
  reading.range = range;
  reading.min_range = 0.02;
  reading.max_range = 4.0;
  reading.field_of_view = field_of_view;
  reading.frame_id = "sonar_front";
  return reading;
}

/// Whether (x, y) lies in the axis-aligned ellipse of `spec` (angle 0), with 1e-12 of slack.
bool inside(const EllipseSpec& spec, double x, double y) {
  const double u = (x - spec.x) / spec.radius_x;
  const double v = (y - spec.y) / spec.radius_y;
  return u * u + v * v <= 1.0 + 1e-12;
}

TEST(RangeObstacle, TheConesArcAtTheRangeIsCovered) {
  for (const double fov : {0.01, 0.1, 0.5, 1.0, 2.0, M_PI}) {
    for (const double range : {0.05, 0.3, 1.0, 3.99}) {
      SensorObstacles out;
      ASSERT_FALSE(rangeObstacles(sonar(range, fov), 0.05, &out));
      ASSERT_EQ(out.ellipses.size(), 1u) << fov << " " << range;
      const EllipseSpec& spec = out.ellipses[0];
      EXPECT_EQ(spec.name, "range");
      EXPECT_EQ(spec.frame_id, "sonar_front");
      EXPECT_EQ(spec.angle, 0.0);
      EXPECT_GE(spec.radius_x, 0.05);
      EXPECT_GE(spec.radius_y, 0.05);
      for (int i = 0; i <= 1000; ++i) {
        const double t = -fov / 2 + fov * i / 1000.0;
        EXPECT_TRUE(inside(spec, range * std::cos(t), range * std::sin(t)))
            << "fov " << fov << ", range " << range << ", t " << t;
      }
      // Not much more than the arc: the reading's point straight ahead is inside, a point twice
      // as far is not.
      EXPECT_FALSE(inside(spec, 2.0 * range + 0.2, 0.0));
    }
  }
}

TEST(RangeObstacle, AReadingAtMaxRangeIsFreeAndOneTooCloseIsAtMinRange) {
  SensorObstacles out;
  ASSERT_FALSE(rangeObstacles(sonar(4.0), 0.05, &out));
  EXPECT_TRUE(out.ellipses.empty()) << "at max_range";
  ASSERT_FALSE(rangeObstacles(sonar(std::numeric_limits<double>::infinity()), 0.05, &out));
  EXPECT_TRUE(out.ellipses.empty()) << "+inf";
  ASSERT_FALSE(rangeObstacles(sonar(-std::numeric_limits<double>::infinity()), 0.05, &out));
  ASSERT_EQ(out.ellipses.size(), 1u) << "-inf: too close";
  EXPECT_TRUE(inside(out.ellipses[0], 0.02, 0.0));
  ASSERT_FALSE(rangeObstacles(sonar(0.001), 0.05, &out));
  ASSERT_EQ(out.ellipses.size(), 1u);
  EXPECT_TRUE(inside(out.ellipses[0], 0.02 * std::cos(0.25), 0.02 * std::sin(0.25)));
}

TEST(RangeObstacle, ABrokenReadingIsRefusedNamingTheField) {
  const auto refused = [](RangeReading reading) {
    SensorObstacles out;
    const auto error = rangeObstacles(reading, 0.05, &out);
    EXPECT_TRUE(out.ellipses.empty());
    return error ? error->key + " = " + error->actual : std::string();
  };
  EXPECT_EQ(refused(sonar(NAN)), "range = nan");
  EXPECT_EQ(refused(sonar(1.0, 0.0)), "field_of_view = 0");
  EXPECT_EQ(refused(sonar(1.0, NAN)), "field_of_view = nan");
  EXPECT_EQ(refused(sonar(1.0, 4.0)), "field_of_view = 4");
  RangeReading reading = sonar(1.0);
  reading.max_range = 0.01;
  EXPECT_EQ(refused(reading), "max_range = 0.01");
  reading = sonar(1.0);
  reading.min_range = -1.0;
  EXPECT_EQ(refused(reading), "min_range = -1");
  reading = sonar(1.0);
  reading.max_range = INFINITY;
  EXPECT_EQ(refused(reading), "max_range = inf");
}

}  // namespace
}  // namespace ellipse_collision::app
