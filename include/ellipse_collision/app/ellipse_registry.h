#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include "ellipse_collision/app/ellipse_spec.h"
#include "ellipse_collision/core/scene_check.h"

namespace ellipse_collision::app {

/// Where a stored ellipse came from; it decides who may replace or remove it.
enum class EllipseSource { ConfiguredLink, ConfiguredObstacle, ServiceObstacle, TopicObstacle };

struct StoredEllipse {
  EllipseSpec spec;
  EllipseSource source{EllipseSource::ConfiguredLink};
  core::EllipseRole role() const {
    return source == EllipseSource::ConfiguredLink ? core::EllipseRole::Link : core::EllipseRole::Obstacle;
  }
};

/// The named ellipses the node keeps, by name. Every change is all-or-nothing: a refused request
/// leaves the registry as it was and returns a message naming the field and value; an accepted one
/// returns an empty string. Field values are validated by the caller (findInvalidPaddedField(),
/// the frame lookup);
/// the registry owns the rules about names.
///
/// Names are unique across links and obstacles. Links come only from the configuration and are
/// never replaced or removed. The service may add, replace and remove obstacles, except those owned
/// by the topic; each topic message replaces all topic obstacles and may not reuse another name.
class EllipseRegistry {
 public:
  /// Configured links and obstacles; throws std::invalid_argument on an empty or duplicate name.
  EllipseRegistry(const std::vector<EllipseSpec>& links, const std::vector<EllipseSpec>& obstacles);

  /// `field` prefixes messages ("obstacles" -> "obstacles[1].name = ...").
  std::string addObstacles(const std::vector<EllipseSpec>& obstacles, const std::string& field);
  std::string removeObstacles(const std::vector<std::string>& names, const std::string& field);
  std::string replaceTopicObstacles(const std::vector<EllipseSpec>& obstacles,
                                    const std::string& field);

  const std::map<std::string, StoredEllipse>& entries() const { return entries_; }
  bool contains(const std::string& name) const { return entries_.count(name) != 0; }
  std::size_t count(EllipseSource source) const;

 private:
  std::map<std::string, StoredEllipse> entries_;
};

}  // namespace ellipse_collision::app
