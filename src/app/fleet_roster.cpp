#include "ellipse_collision/app/fleet_roster.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "ellipse_collision/app/collision_check.h"
#include "ellipse_collision/core/number_format.h"

namespace ellipse_collision::app {

std::optional<std::string> FleetRoster::receive(double now_s,
                                                const std::vector<EllipseSpec>& ellipses,
                                                double stamp_s) {
  std::map<std::string, std::vector<EllipseSpec>> by_robot;
  std::set<std::string> names;
  for (std::size_t i = 0; i < ellipses.size(); ++i) {
    const EllipseSpec& e = ellipses[i];
    const std::string entry = entryName("ellipses", i);
    const std::size_t slash = e.name.find('/');
    if (slash == std::string::npos || slash == 0 || slash + 1 == e.name.size()) {
      return describeFieldError(entry, {"name", "'<robot>/<link>'", "'" + e.name + "'"});
    }
    if (const auto error = findInvalidField(e)) return describeFieldError(entry, *error);
    // Two links of one name would be two obstacles claiming one name in the store.
    if (!names.insert(e.name).second) {
      return describeFieldError(entry, {"name", "a name used once", "'" + e.name + "'"});
    }
    const std::string robot = e.name.substr(0, slash);
    if (robot != own_name_) by_robot[robot].push_back(e);
  }
  for (auto& [robot, links] : by_robot) {
    robots_[robot] = {now_s, stamp_s > 0.0 ? stamp_s : now_s, std::move(links)};
    dropped_.erase(robot);
  }
  return std::nullopt;
}

std::vector<std::string> FleetRoster::dropSilent(double now_s) {
  std::vector<std::string> dropped;
  for (auto it = robots_.begin(); it != robots_.end();) {
    // Heard "after" now: the clock jumped back (a simulation restarted). Its footprint is kept, as
    // the node keeps what it cannot disprove, but its silence counts from now, so a robot that is
    // not heard from again goes after one timeout instead of after the jump's length.
    if (it->second.heard_s > now_s) it->second.heard_s = now_s;
    if (now_s - it->second.heard_s > timeout_s_) {
      dropped.push_back(it->first);
      dropped_.insert(it->first);
      it = robots_.erase(it);
    } else {
      ++it;
    }
  }
  return dropped;
}

std::vector<EllipseSpec> FleetRoster::obstacles() const {
  const double newest_s = stamp();
  std::vector<EllipseSpec> all;
  for (const auto& [robot, kept] : robots_) {
    const double since_s = newest_s - kept.stamp_s;
    for (EllipseSpec link : kept.links) {
      // The motion the node predicts with (a straight line, turning about its centre), over the
      // time this robot's footprint is older than the newest.
      link.x += link.vx * since_s;
      link.y += link.vy * since_s;
      link.angle += link.angular_velocity * since_s;
      all.push_back(std::move(link));
    }
  }
  return all;
}

double FleetRoster::stamp() const {
  double newest_s = 0.0;
  for (const auto& [robot, kept] : robots_) newest_s = std::max(newest_s, kept.stamp_s);
  return newest_s;
}

std::vector<FleetRoster::Robot> FleetRoster::robots(double now_s) const {
  std::vector<Robot> list;
  for (const auto& [robot, kept] : robots_) {
    list.push_back({robot, now_s - kept.heard_s, kept.links.size()});
  }
  return list;
}

std::vector<std::pair<std::string, std::string>> FleetRoster::healthValues(double now_s) const {
  std::vector<std::string> kept;
  for (const Robot& robot : robots(now_s)) {
    kept.push_back(robot.name + " (" + core::formatNumber(std::round(robot.age_s * 100) / 100) +
                   " s ago, " + std::to_string(robot.links) + " links)");
  }
  const std::vector<std::string> dropped(dropped_.begin(), dropped_.end());
  return {{"robots", kept.empty() ? std::string("none") : joinText(kept, ", ")},
          {"dropped (silent past " + core::formatNumber(timeout_s_) + " s)",
           dropped.empty() ? std::string("none") : joinText(dropped, ", ")}};
}

}  // namespace ellipse_collision::app
