// The typed readers every parameter section shares (src/ros/param_reading.cpp): what each
// accepts, and each refusal's one format naming the place, the key, expected and actual value; no
// ROS master needed.
#include <gtest/gtest.h>

#include <limits>
#include <string>

#include "ellipse_collision/ros/param_reading.h"
#include "node_config_fixture.h"

namespace ellipse_collision {
namespace {

using test::refusalOf;
using XmlRpc::XmlRpcValue;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(ParamReading, ValuesAreDescribedAsTheYamlWroteThem) {
  XmlRpcValue list;
  list[0] = 1;
  list[1] = 2;
  XmlRpcValue dict;
  dict["a"] = 1;
  EXPECT_EQ(params::describeValue(XmlRpcValue(true)), "true (a bool)");
  EXPECT_EQ(params::describeValue(XmlRpcValue(-3)), "-3 (an int)");
  EXPECT_EQ(params::describeValue(XmlRpcValue(0.1)), "0.1 (a double)");
  EXPECT_EQ(params::describeValue(XmlRpcValue(kNaN)), "nan (a double)");
  EXPECT_EQ(params::describeValue(XmlRpcValue("x")), "'x' (a string)");
  EXPECT_EQ(params::describeValue(list), "a list of 2");
  EXPECT_EQ(params::describeValue(dict), "a dict");
  EXPECT_EQ(params::describeValue(XmlRpcValue()), "nothing");
}

TEST(ParamReading, NumbersAcceptIntsAndRefuseEverythingElseNamingPlaceAndKey) {
  EXPECT_EQ(params::readNumber(XmlRpcValue(2), "parameter ~rate", "rate"), 2.0);
  EXPECT_EQ(params::readNumber(XmlRpcValue(0.25), "parameter ~rate", "rate"), 0.25);
  EXPECT_EQ(refusalOf([] { params::readNumber(XmlRpcValue("2"), "parameter ~rate", "rate"); }),
            "parameter ~rate, key 'rate': expected a number, got '2' (a string)");
  EXPECT_EQ(refusalOf([] { params::readNumber(XmlRpcValue(true), "links[0]", "x"); }),
            "links[0], key 'x': expected a number, got true (a bool)");
}

TEST(ParamReading, StringsBoolsAndFramesAreTypeChecked) {
  EXPECT_EQ(params::readString(XmlRpcValue("map"), "w", "k"), "map");
  EXPECT_EQ(refusalOf([] { params::readString(XmlRpcValue(1.5), "w", "k"); }),
            "w, key 'k': expected a string, got 1.5 (a double)");
  EXPECT_TRUE(params::readBool(XmlRpcValue(true), "w", "k"));
  EXPECT_EQ(refusalOf([] { params::readBool(XmlRpcValue("true"), "w", "k"); }),
            "w, key 'k': expected true or false, got 'true' (a string)");
  EXPECT_EQ(params::readFrame(XmlRpcValue("odom"), "w", "k"), "odom");
  EXPECT_EQ(refusalOf([] { params::readFrame(XmlRpcValue(""), "w", "k"); }),
            "w, key 'k': expected a non-empty tf frame id, got ''");
  EXPECT_EQ(refusalOf([] { params::readFrame(XmlRpcValue("/odom"), "w", "k"); }),
            "w, key 'k': expected a tf2 frame id without a leading '/', got '/odom'");
  EXPECT_EQ(refusalOf([] { params::readFrame(XmlRpcValue(3), "w", "k"); }),
            "w, key 'k': expected a string, got 3 (an int)");
}

TEST(ParamReading, RangesRefuseNaNInfinityNegativeAndOutsideValuesNeverClamping) {
  const auto read = [](double value, bool zero_allowed = false) {
    return refusalOf(
        [&] { params::readInRange(XmlRpcValue(value), "w", "k", 1.0, 10.0, zero_allowed); });
  };
  EXPECT_EQ(params::readInRange(XmlRpcValue(10), "w", "k", 1.0, 10.0), 10.0);
  EXPECT_EQ(params::readInRange(XmlRpcValue(1.0), "w", "k", 1.0, 10.0), 1.0);
  EXPECT_EQ(read(kNaN), "w, key 'k': expected a finite number >= 0, got nan");
  EXPECT_EQ(read(kInf), "w, key 'k': expected a finite number >= 0, got inf");
  EXPECT_EQ(read(-2.0), "w, key 'k': expected a finite number >= 0, got -2");
  EXPECT_EQ(read(10.5), "w, key 'k': expected a number within [1, 10], got 10.5");
  EXPECT_EQ(read(0.0), "w, key 'k': expected a number within [1, 10], got 0");
  EXPECT_EQ(read(0.0, true), "");
  EXPECT_EQ(read(0.5, true), "w, key 'k': expected 0 or a number within [1, 10], got 0.5");
}

TEST(ParamReading, WholeNumbersAreWithinOneAndTheirMaximum) {
  EXPECT_EQ(params::readWhole(XmlRpcValue(100000), "w", "k", 1e6), 100000.0);
  EXPECT_EQ(params::readWhole(XmlRpcValue(1e5), "w", "k", 1e6), 1e5) << "a whole double";
  EXPECT_EQ(refusalOf([] { params::readWhole(XmlRpcValue(2.5), "w", "k", 1e6); }),
            "w, key 'k': expected a whole number, got 2.5");
  EXPECT_EQ(refusalOf([] { params::readWhole(XmlRpcValue(0), "w", "k", 1e6); }),
            "w, key 'k': expected a number within [1, 1e+06], got 0");
  EXPECT_EQ(refusalOf([] { params::readWhole(XmlRpcValue(2e6), "w", "k", 1e6); }),
            "w, key 'k': expected a number within [1, 1e+06], got 2e+06");
  EXPECT_EQ(refusalOf([] { params::readWhole(XmlRpcValue(kNaN), "w", "k", 1e6); }),
            "w, key 'k': expected a finite number >= 0, got nan");
}

TEST(ParamReading, ASettingIsReadInItsRangeFromTheOneTable) {
  XmlRpcValue root;
  root["rate"] = 0;
  EXPECT_EQ(params::readSetting(root, "rate"), 0.0) << "0: off";
  root["rate"] = 1e-4;
  EXPECT_EQ(refusalOf([&] { params::readSetting(root, "rate"); }),
            "parameter ~rate, key 'rate': expected 0 or a number within [0.001, 1000], got 1e-04");
  root["warning_distance"] = 1e12;
  EXPECT_EQ(params::readSetting(root, "warning_distance"), 1e12) << "no upper bound";
  root["warning_distance"] = kNaN;
  EXPECT_EQ(refusalOf([&] { params::readSetting(root, "warning_distance"); }),
            "parameter ~warning_distance, key 'warning_distance': expected a finite number >= 0, "
            "got nan");
}

TEST(ParamReading, UnknownKeysAreNamedWithTheKeysExpected) {
  XmlRpcValue dict;
  dict["rate"] = 1;
  dict["rte"] = 2;
  EXPECT_EQ(params::unknownKey(dict, {"rate", "rte"}), std::nullopt);
  EXPECT_EQ(params::unknownKey(dict, {"rate"}), std::optional<std::string>("rte"));
  EXPECT_EQ(refusalOf([&] {
              params::refuseUnknownKeys(dict, {"rate", "padding"}, "parameter ~gate/");
            }),
            "parameter ~gate/rte: unknown key (expected one of rate, padding)");
  EXPECT_EQ(refusalOf([&] {
              params::refuseUnknownKeys(dict, {"rate", "rte"}, "parameter ~");
            }),
            "");
}

TEST(ParamReading, AppLayerViolationsAreRenderedInTheOneFormat) {
  EXPECT_EQ(describeConfigError("links[2]", {"radius_x", "a finite number > 0", "0"}),
            "links[2], key 'radius_x': expected a finite number > 0, got 0");
  EXPECT_EQ(refusalOf([] { params::failOn(std::nullopt, "w"); }), "");
  EXPECT_EQ(refusalOf([] {
              params::failOn(app::FieldError{"k", "e", "a"}, "w");
            }),
            "w, key 'k': expected e, got a");
}

}  // namespace
}  // namespace ellipse_collision
