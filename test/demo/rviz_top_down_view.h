#pragma once

#include <Eigen/Core>
#include <array>
#include <string>

namespace ellipse_collision {
namespace test {

/// The camera of an rviz config whose current view is rviz/TopDownOrtho: it looks straight down on
/// the fixed frame's xy-plane with x to the right and y up, `scale` pixels per metre, and `focal`
/// at the centre of the render panel.
struct TopDownView {
  double scale_px_per_m{0.0};
  Eigen::Vector2d focal_m{0.0, 0.0};
  double angle_rad{0.0};
  std::array<int, 3> background{{0, 0, 0}};  ///< Global Options / Background Color, 0..255
};

/// Reads the view and the background colour from an .rviz file. Throws std::runtime_error naming
/// the key when the file holds no TopDownOrtho current view, or a value is missing or malformed.
TopDownView readTopDownView(const std::string& rviz_path);

/// A render panel on the screen, in pixels: the inclusive column and row range it covers.
struct PanelRect {
  int left{0};
  int top{0};
  int right{-1};
  int bottom{-1};
  int width() const { return right - left + 1; }
  int height() const { return bottom - top + 1; }
};

/// Where a point of the fixed frame's plane [m] appears on the screen [px, px]; only for
/// angle_rad = 0 (readTopDownView() refuses other angles).
Eigen::Vector2d toPixel(const TopDownView& view, const PanelRect& panel,
                        const Eigen::Vector2d& point_m);

/// The inverse of toPixel(): the point of the plane [m] shown at screen position `pixel` [px].
Eigen::Vector2d toPoint(const TopDownView& view, const PanelRect& panel,
                        const Eigen::Vector2d& pixel);

}  // namespace test
}  // namespace ellipse_collision
