#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "rviz_top_down_view.h"

namespace ellipse_collision {
namespace test {

using Rgb = std::array<std::uint8_t, 3>;

/// A picture of a whole X screen, 8 bits per channel.
class ScreenImage {
 public:
  /// The root window of the X display named by $DISPLAY. Throws std::runtime_error when there is
  /// no display or the image cannot be read.
  static ScreenImage grab();

  ScreenImage() = default;
  ScreenImage(int width, int height, const Rgb& fill)
      : width_(width), height_(height), pixels_(static_cast<std::size_t>(width) * height, fill) {}

  int width() const { return width_; }
  int height() const { return height_; }
  Rgb at(int x, int y) const { return pixels_[static_cast<std::size_t>(y) * width_ + x]; }
  void set(int x, int y, const Rgb& colour) {
    pixels_[static_cast<std::size_t>(y) * width_ + x] = colour;
  }

  /// Binary PPM (P6), readable by most image tools (`convert shot.ppm shot.png`).
  void savePpm(const std::string& path) const;

  /// The rows and columns holding at least `min_count` pixels of exactly `colour`: rviz's render
  /// panel when `colour` is its background. Empty (width() <= 0) when there are none.
  PanelRect findArea(const Rgb& colour, int min_count) const;

 private:
  int width_{0};
  int height_{0};
  std::vector<Rgb> pixels_;
};

}  // namespace test
}  // namespace ellipse_collision
