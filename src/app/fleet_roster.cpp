#include "ellipse_collision/app/fleet_roster.h"

namespace ellipse_collision::app {

std::optional<std::string> FleetRoster::receive(double now_s,
                                                const std::vector<EllipseSpec>& ellipses) {
  std::map<std::string, std::vector<EllipseSpec>> by_robot;
  for (std::size_t i = 0; i < ellipses.size(); ++i) {
    const EllipseSpec& e = ellipses[i];
    const std::string entry = entryName("ellipses", i);
    const std::size_t slash = e.name.find('/');
    if (slash == std::string::npos || slash == 0 || slash + 1 == e.name.size()) {
      return describeFieldError(entry, {"name", "'<robot>/<link>'", "'" + e.name + "'"});
    }
    if (const auto error = findInvalidField(e)) return describeFieldError(entry, *error);
    const std::string robot = e.name.substr(0, slash);
    if (robot != own_name_) by_robot[robot].push_back(e);
  }
  for (auto& [robot, links] : by_robot) robots_[robot] = {now_s, std::move(links)};
  return std::nullopt;
}

std::vector<std::string> FleetRoster::dropSilent(double now_s) {
  std::vector<std::string> dropped;
  for (auto it = robots_.begin(); it != robots_.end();) {
    if (now_s - it->second.heard_s > timeout_s_) {
      dropped.push_back(it->first);
      it = robots_.erase(it);
    } else {
      ++it;
    }
  }
  return dropped;
}

std::vector<EllipseSpec> FleetRoster::obstacles() const {
  std::vector<EllipseSpec> all;
  for (const auto& [robot, kept] : robots_) all.insert(all.end(), kept.links.begin(), kept.links.end());
  return all;
}

std::vector<FleetRoster::Robot> FleetRoster::robots(double now_s) const {
  std::vector<Robot> list;
  for (const auto& [robot, kept] : robots_) {
    list.push_back({robot, now_s - kept.heard_s, kept.links.size()});
  }
  return list;
}

}  // namespace ellipse_collision::app
