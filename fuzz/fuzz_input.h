#pragma once

// Turns fuzzer bytes into the values the targets feed to the code under test, reading front to
// back (so that fuzz/make_seeds.py can write meaningful seeds). Raw bit patterns alone would almost
// never make a valid ellipse, so each double starts with a tag byte choosing its recipe:
//   tag % 4 == 0  hostileValues()[byte]: NaN, inf, subnormals, 1e300, the edges of the core's
//   ranges tag % 4 == 1  8 bytes, little-endian: any bit pattern tag % 4 == 2 hostileValues()[byte]
//   moved by (byte % 9 - 4) ulps tag % 4 == 3  int32 mantissa / 2^31 * 2^(byte % 81 - 40): physical
//   magnitudes
// Past the end of the input every read gives 0.

#include <Eigen/Core>
#include <array>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <string>

#include "ellipse_collision/core/ellipse.h"

namespace ellipse_collision::fuzz {

inline constexpr double kQuietNaN = std::numeric_limits<double>::quiet_NaN();
inline constexpr double kInf = std::numeric_limits<double>::infinity();

// Keep in step with make_seeds.py, which names these by index.
inline const std::array<double, 40>& hostileValues() {
  static const std::array<double, 40> values = {0.0,
                                                -0.0,
                                                1.0,
                                                -1.0,
                                                0.5,
                                                2.0,
                                                3.0,
                                                10.0,
                                                M_PI / 2,
                                                M_PI,
                                                -M_PI,
                                                2 * M_PI,
                                                1e300,
                                                -1e300,
                                                1e-300,
                                                -1e-300,
                                                DBL_MAX,
                                                -DBL_MAX,
                                                DBL_MIN,
                                                -DBL_MIN,
                                                std::numeric_limits<double>::denorm_min(),
                                                -std::numeric_limits<double>::denorm_min(),
                                                2.2250738585072009e-308 /* largest subnormal */,
                                                kInf,
                                                -kInf,
                                                kQuietNaN,
                                                -kQuietNaN,
                                                core::kMinRadius,
                                                std::nextafter(core::kMinRadius, 0.0),
                                                core::kMaxRadius,
                                                std::nextafter(core::kMaxRadius, kInf),
                                                core::kMaxCoordinate,
                                                -core::kMaxCoordinate,
                                                std::nextafter(core::kMaxCoordinate, kInf),
                                                1e-12,
                                                1e12,
                                                1e-6,
                                                1e6,
                                                1e18,
                                                0.1};
  return values;
}

class FuzzInput {
 public:
  FuzzInput(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}

  double number() {
    const auto& table = hostileValues();
    switch (byte() % 4) {
      case 0:
        return table[byte() % table.size()];
      case 1: {
        std::uint64_t bits = 0;
        for (int i = 0; i < 8; ++i) bits |= static_cast<std::uint64_t>(byte()) << (8 * i);
        double value;
        std::memcpy(&value, &bits, sizeof value);
        return value;
      }
      case 2: {
        double value = table[byte() % table.size()];
        const int steps = byte() % 9 - 4;
        for (int i = 0; i < std::abs(steps); ++i)
          value = std::nextafter(value, steps > 0 ? kInf : -kInf);
        return value;
      }
      default: {
        std::uint32_t bits = 0;
        for (int i = 0; i < 4; ++i) bits |= static_cast<std::uint32_t>(byte()) << (8 * i);
        const double mantissa = static_cast<std::int32_t>(bits) / 2147483648.0;
        return std::ldexp(mantissa, byte() % 81 - 40);
      }
    }
  }

  /// Five numbers: center.x, center.y, radius_x, radius_y, angle.
  core::Ellipse ellipse() {
    core::Ellipse e;
    e.center.x() = number();
    e.center.y() = number();
    e.radius_x = number();
    e.radius_y = number();
    e.angle = number();
    return e;
  }

  /// One byte mapped onto [lo, hi] (hi - lo < 256).
  int integer(int lo, int hi) { return lo + byte() % (hi - lo + 1); }
  bool flag() { return byte() & 1; }
  std::uint8_t byte() { return position_ < size_ ? data_[position_++] : 0; }
  std::size_t remaining() const { return size_ - position_; }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t position_{0};
};

/// The core's validity rule restated from ellipse.h's documentation, independently of
/// invalidReason(): the targets check that the two agree.
inline bool documentedValid(const core::Ellipse& e) {
  const double fields[] = {e.center.x(), e.center.y(), e.radius_x, e.radius_y, e.angle};
  for (double v : fields) {
    if (!std::isfinite(v)) return false;
  }
  for (double r : {e.radius_x, e.radius_y}) {
    if (!(r >= core::kMinRadius && r <= core::kMaxRadius)) return false;
  }
  for (double c : {e.center.x(), e.center.y()}) {
    if (!(std::fabs(c) <= core::kMaxCoordinate)) return false;
  }
  return true;
}

/// A double with all 17 significant digits, so that a failure message reproduces it exactly.
inline std::string text(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", value);
  return buffer;
}

inline std::string describe(const core::Ellipse& e) {
  char buffer[160];
  std::snprintf(buffer, sizeof buffer, "{%.17g, %.17g, %.17g, %.17g, %.17g}", e.center.x(),
                e.center.y(), e.radius_x, e.radius_y, e.angle);
  return buffer;
}

/// A broken invariant: print what and why, then abort so that libFuzzer saves the input.
[[noreturn]] inline void fail(const std::string& what) {
  std::fprintf(stderr, "INVARIANT VIOLATED: %s\n", what.c_str());
  std::fflush(stderr);
  std::abort();
}

}  // namespace ellipse_collision::fuzz

/// Checks an invariant; the message expression is only evaluated when it is broken.
#define FUZZ_REQUIRE(condition, message)                        \
  do {                                                          \
    if (!(condition)) ::ellipse_collision::fuzz::fail(message); \
  } while (false)
