#include "rviz_top_down_view.h"

#include <fstream>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace ellipse_collision {
namespace test {
namespace {

struct Line {
  int indent;
  std::string key;
  std::string value;
};

/// The "key: value" lines of a YAML file written by rviz (block style, two-space indents).
std::vector<Line> readLines(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read rviz config '" + path + "'");
  std::vector<Line> lines;
  std::string text;
  while (std::getline(in, text)) {
    const std::size_t first = text.find_first_not_of(' ');
    if (first == std::string::npos || text[first] == '#') continue;
    std::size_t start = first;
    if (text.compare(first, 2, "- ") == 0) start += 2;  // a list item is one level deeper
    const std::size_t colon = text.find(':', start);
    if (colon == std::string::npos) continue;
    std::string value = text.substr(colon + 1);
    value.erase(0, value.find_first_not_of(' '));
    lines.push_back({static_cast<int>(start), text.substr(start, colon - start), value});
  }
  return lines;
}

/// The value of `path` (keys from the top level down), or throws. Only direct children of the
/// section found so far are compared, so a deeper key of the same name cannot match.
std::string valueAt(const std::vector<Line>& lines, const std::vector<std::string>& path,
                    const std::string& file) {
  std::size_t level = 0;
  int parent_indent = -1;
  int child_indent = 0;  // top-level keys start in column 0
  for (const Line& line : lines) {
    if (line.indent <= parent_indent) break;  // left the section without finding the key
    if (child_indent < 0) child_indent = line.indent;
    if (line.indent != child_indent || line.key != path[level]) continue;
    if (level + 1 == path.size()) return line.value;
    parent_indent = line.indent;
    child_indent = -1;  // the next line's indent
    ++level;
  }
  std::string joined;
  for (const std::string& key : path) joined += (joined.empty() ? "" : "/") + key;
  throw std::runtime_error(file + ": no key " + joined);
}

double number(const std::vector<Line>& lines, const std::vector<std::string>& path,
              const std::string& file) {
  const std::string text = valueAt(lines, path, file);
  std::istringstream in(text);
  double value = 0.0;
  if (!(in >> value))
    throw std::runtime_error(file + ": " + path.back() + " = '" + text + "' is not a number");
  return value;
}

}  // namespace

TopDownView readTopDownView(const std::string& rviz_path) {
  const std::vector<Line> lines = readLines(rviz_path);
  const std::vector<std::string> view = {"Visualization Manager", "Views", "Current"};
  auto in_view = [&view](const std::string& key) {
    std::vector<std::string> path = view;
    path.push_back(key);
    return path;
  };
  const std::string view_class = valueAt(lines, in_view("Class"), rviz_path);
  if (view_class != "rviz/TopDownOrtho") {
    throw std::runtime_error(rviz_path + ": current view is '" + view_class +
                             "', expected rviz/TopDownOrtho");
  }
  TopDownView result;
  result.scale_px_per_m = number(lines, in_view("Scale"), rviz_path);
  result.focal_m = {number(lines, in_view("X"), rviz_path), number(lines, in_view("Y"), rviz_path)};
  result.angle_rad = number(lines, in_view("Angle"), rviz_path);
  if (result.angle_rad != 0.0) throw std::runtime_error(rviz_path + ": view Angle must be 0");
  if (!(result.scale_px_per_m > 0.0))
    throw std::runtime_error(rviz_path + ": view Scale must be > 0");

  const std::string colour =
      valueAt(lines, {"Visualization Manager", "Global Options", "Background Color"}, rviz_path);
  std::istringstream in(colour);
  char separator = 0;
  if (!(in >> result.background[0] >> separator >> result.background[1] >> separator >>
        result.background[2])) {
    throw std::runtime_error(rviz_path + ": Background Color = '" + colour + "' is not 'r; g; b'");
  }
  return result;
}

namespace {
// Pixel (x, y) covers [x, x + 1) x [y, y + 1); the focal point is the panel's centre.
Eigen::Vector2d panelCentre(const PanelRect& panel) {
  return {panel.left + 0.5 * panel.width(), panel.top + 0.5 * panel.height()};
}
}  // namespace

Eigen::Vector2d toPixel(const TopDownView& view, const PanelRect& panel,
                        const Eigen::Vector2d& point_m) {
  // Screen rows grow downwards, y grows upwards.
  const Eigen::Vector2d offset = (point_m - view.focal_m) * view.scale_px_per_m;
  return panelCentre(panel) + Eigen::Vector2d(offset.x(), -offset.y());
}

Eigen::Vector2d toPoint(const TopDownView& view, const PanelRect& panel,
                        const Eigen::Vector2d& pixel) {
  const Eigen::Vector2d offset = pixel - panelCentre(panel);
  return view.focal_m + Eigen::Vector2d(offset.x(), -offset.y()) / view.scale_px_per_m;
}

}  // namespace test
}  // namespace ellipse_collision
