// The one number formatter of messages (core/number_format.h): the shortest text that reads back
// to the same double.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <random>
#include <string>

#include "ellipse_collision/core/number_format.h"

namespace ellipse_collision::core {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(NumberFormat, NumbersAreFormattedShortestAndReadBackExactly) {
  EXPECT_EQ(formatNumber(0.1), "0.1");
  EXPECT_EQ(formatNumber(-2), "-2");
  EXPECT_EQ(formatNumber(20), "20");
  EXPECT_EQ(formatNumber(1234.5), "1234.5");
  EXPECT_EQ(formatNumber(kNaN), "nan");
  EXPECT_EQ(formatNumber(-kInf), "-inf");
  const double third = 1.0 / 3.0;
  EXPECT_EQ(std::stod(formatNumber(third)), third);
}

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof(double)) == 0; }

TEST(NumberFormat, RandomBitPatternsReadBackBitForBit) {
  std::mt19937_64 bits(20261128);
  for (int i = 0; i < 100000; ++i) {
    const std::uint64_t pattern = bits();
    double value;
    std::memcpy(&value, &pattern, sizeof(value));
    if (!std::isfinite(value)) continue;
    const std::string text = formatNumber(value);
    EXPECT_TRUE(sameBits(std::strtod(text.c_str(), nullptr), value)) << text;
  }
}

TEST(NumberFormat, NoShorterTextReadsBackToTheSameDouble) {
  // With 17 significant digits every double reads back; the formatter must use the fewest that
  // do (0.1 is "0.1", not "0.10000000000000001"). Up to 1e15, so that an integer written without
  // an exponent has no digits beyond the shortest (77771352453355648 is 17 digits, shorter as text
  // than its 16-digit scientific form).
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> mantissa(1.0, 10.0);
  std::uniform_int_distribution<int> exponent(-30, 14);
  for (int i = 0; i < 2000; ++i) {
    const double value = mantissa(rng) * std::pow(10.0, exponent(rng));
    const std::string text = formatNumber(value);
    int shortest = 17;
    for (int digits = 1; digits <= 17; ++digits) {
      char buffer[64];
      std::snprintf(buffer, sizeof(buffer), "%.*e", digits - 1, value);
      if (std::strtod(buffer, nullptr) == value) {
        shortest = digits;
        break;
      }
    }
    int digits_used = 0;
    bool leading = true;
    std::string mantissa_text = text.substr(0, text.find('e'));
    // Significant digits: trailing zeros of an integer written without exponent do not count.
    if (mantissa_text.find('.') == std::string::npos) {
      while (mantissa_text.size() > 1 && mantissa_text.back() == '0') mantissa_text.pop_back();
    }
    for (const char c : mantissa_text) {
      if (c < '0' || c > '9') continue;
      if (leading && c == '0') continue;
      leading = false;
      ++digits_used;
    }
    EXPECT_EQ(digits_used, shortest) << value << " as " << text;
  }
}

TEST(NumberFormat, ExtremesAndSignsAreKept) {
  EXPECT_EQ(formatNumber(0.0), "0");
  EXPECT_EQ(formatNumber(-0.0), "-0");
  EXPECT_EQ(formatNumber(5e-324), "5e-324");
  EXPECT_EQ(formatNumber(std::numeric_limits<double>::max()), "1.7976931348623157e+308");
  EXPECT_EQ(formatNumber(1e9), "1e+09");
  EXPECT_EQ(formatNumber(-kNaN), "nan") << "the sign of a NaN is not shown";
  EXPECT_EQ(formatNumber(kInf), "inf");
}

TEST(NumberFormat, AppendAddsTheSameTextAfterWhatIsThere) {
  std::string out = "x=";
  appendNumber(out, 0.1);
  out += ' ';
  appendNumber(out, -kInf);
  out += ' ';
  appendNumber(out, 1.0 / 3.0);
  EXPECT_EQ(out, "x=0.1 -inf " + formatNumber(1.0 / 3.0));
}

}  // namespace
}  // namespace ellipse_collision::core
