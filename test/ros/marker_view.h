#pragma once
// What rviz shows from a sequence of MarkerArrays, and which drawn triangles cover a given
// ellipse: the tests read the markers as a user sees them, not through the ids' structure.
#include <visualization_msgs/MarkerArray.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "ellipse_builders.h"
#include "ellipse_collision/core/ellipse.h"

namespace ellipse_collision {
namespace test {

using MarkerKey = std::pair<std::string, int>;  // (ns, id)

/// rviz's rule: ADD (= MODIFY) replaces the marker of its (ns, id), DELETE removes it, DELETEALL
/// removes every marker; arrays and the markers in them apply in order.
class MarkerView {
 public:
  MarkerView() = default;
  explicit MarkerView(const std::vector<visualization_msgs::MarkerArray>& arrays) {
    for (const auto& array : arrays) apply(array);
  }
  void apply(const visualization_msgs::MarkerArray& array) {
    for (const visualization_msgs::Marker& m : array.markers) {
      if (m.action == visualization_msgs::Marker::DELETEALL) {
        shown_.clear();
      } else if (m.action == visualization_msgs::Marker::DELETE) {
        shown_.erase({m.ns, m.id});
      } else {
        shown_[{m.ns, m.id}] = m;
      }
    }
  }
  const std::map<MarkerKey, visualization_msgs::Marker>& shown() const { return shown_; }
  const visualization_msgs::Marker* find(const std::string& ns, int id) const {
    const auto it = shown_.find({ns, id});
    return it == shown_.end() ? nullptr : &it->second;
  }

 private:
  std::map<MarkerKey, visualization_msgs::Marker> shown_;
};

/// The ellipse's implicit form at (x, y): 1 on its rim.
inline double implicitForm(const core::Ellipse& e, double x, double y) {
  const double dx = x - e.center.x();
  const double dy = y - e.center.y();
  const double u = (std::cos(e.angle) * dx + std::sin(e.angle) * dy) / e.radius_x;
  const double v = (-std::sin(e.angle) * dx + std::cos(e.angle) * dy) / e.radius_y;
  return u * u + v * v;
}

/// Area of the triangles of a TRIANGLE_LIST marker whose three vertices lie on the rim of `e`
/// (implicit form within 1e-6 of 1) [m^2].
inline double areaOnRim(const visualization_msgs::Marker& m, const core::Ellipse& e) {
  double area = 0.0;
  for (std::size_t i = 0; i + 2 < m.points.size(); i += 3) {
    const auto& a = m.points[i];
    const auto& b = m.points[i + 1];
    const auto& c = m.points[i + 2];
    bool on_rim = true;
    for (const auto* p : {&a, &b, &c}) {
      if (std::abs(implicitForm(e, p->x, p->y) - 1.0) > 1e-6) on_rim = false;
    }
    if (on_rim) area += std::abs((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x)) / 2;
  }
  return area;
}

/// The shown TRIANGLE_LIST markers of `ns` that draw `e` filled: their triangles on its rim cover
/// at least 95 % of its area (an inscribed 16-gon covers 97.4 %) and at most all of it (an
/// ellipse drawn twice in one marker fails), flat at z = 0 with an unscaled identity pose.
inline std::vector<const visualization_msgs::Marker*> fillsOf(const MarkerView& view,
                                                              const std::string& ns,
                                                              const core::Ellipse& e) {
  const double full = M_PI * e.radius_x * e.radius_y;
  std::vector<const visualization_msgs::Marker*> fills;
  for (const auto& [key, m] : view.shown()) {
    if (key.first != ns || m.type != visualization_msgs::Marker::TRIANGLE_LIST) continue;
    const double area = areaOnRim(m, e);
    if (area < 0.95 * full || area > full * (1 + 1e-6)) continue;
    const bool flat =
        std::all_of(m.points.begin(), m.points.end(), [](const auto& p) { return p.z == 0.0; });
    const bool plain = m.pose.position.x == 0 && m.pose.position.y == 0 && m.pose.position.z == 0 &&
                       m.pose.orientation.w == 1.0 && m.scale.x == 1.0 && m.scale.y == 1.0 &&
                       m.scale.z == 1.0;
    if (flat && plain) fills.push_back(&m);
  }
  return fills;
}

/// The one marker that draws `e` filled, or nullptr when none or several do.
inline const visualization_msgs::Marker* fillOf(const MarkerView& view, const std::string& ns,
                                                const core::Ellipse& e) {
  const auto fills = fillsOf(view, ns, e);
  return fills.size() == 1 ? fills[0] : nullptr;
}

inline bool isRed(const visualization_msgs::Marker& m) {
  return m.color.r > 0.5f && m.color.g < 0.5f;
}
inline bool isGreen(const visualization_msgs::Marker& m) {
  return m.color.g > 0.5f && m.color.r < 0.5f;
}
inline bool isYellow(const visualization_msgs::Marker& m) {
  return m.color.r > 0.5f && m.color.g > 0.5f && m.color.b < 0.5f;
}
inline bool isRed(const visualization_msgs::Marker* m) { return m && isRed(*m); }
inline bool isGreen(const visualization_msgs::Marker* m) { return m && isGreen(*m); }
inline bool isYellow(const visualization_msgs::Marker* m) { return m && isYellow(*m); }

/// The number of bytes the array takes on the wire.
inline std::size_t wireBytes(const visualization_msgs::MarkerArray& array) {
  return ros::serialization::serializationLength(array);
}

}  // namespace test
}  // namespace ellipse_collision
