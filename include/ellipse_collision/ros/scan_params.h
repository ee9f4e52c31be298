#pragma once

#include <xmlrpcpp/XmlRpcValue.h>

#include <functional>
#include <string>
#include <vector>

#include "ellipse_collision/app/obstacle_tracker.h"
#include "ellipse_collision/app/scan_obstacles.h"

namespace ellipse_collision {

/// Parses scan_obstacles' private namespace (every key optional, documented defaults in
/// app::ScanObstacleSettings; unknown keys and wrong types are errors; ranges from
/// app::findInvalidSetting()). Throws ConfigError naming the key.
app::ScanObstacleSettings parseScanObstacleSettings(const XmlRpc::XmlRpcValue& private_namespace);

/// Parses the `tracking` dict of scan_obstacles' private namespace (every key optional, defaults
/// in app::TrackingSettings; ranges from app::findInvalidSetting()). Throws ConfigError naming
/// the key.
app::TrackingSettings parseTrackingSettings(const XmlRpc::XmlRpcValue& private_namespace);

namespace params {

/// scan_obstacles' keys, in its private namespace or in a scan or cloud source's entry.
const std::vector<std::string>& scanKeys();

/// The scan keys `root` holds into `settings` (types only: the ranges are findInvalidSetting()'s).
/// `where(key)` names the place in messages, `prefix` + key the key.
void readScanSettings(const XmlRpc::XmlRpcValue& root,
                      const std::function<std::string(const std::string&)>& where,
                      app::ScanObstacleSettings* settings, const std::string& prefix = "");

/// A `tracking` dict into `settings` (types only: the ranges are findInvalidSetting()'s); keys
/// read as `prefix` + "tracking/" + key, `where(that)` names the place.
void readTracking(const XmlRpc::XmlRpcValue& root,
                  const std::function<std::string(const std::string&)>& where,
                  const std::string& prefix, app::TrackingSettings* settings);

}  // namespace params
}  // namespace ellipse_collision
