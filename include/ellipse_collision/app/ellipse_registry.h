#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "ellipse_collision/app/ellipse_spec.h"
#include "ellipse_collision/app/obstacle_store.h"
#include "ellipse_collision/core/scene_check.h"

namespace ellipse_collision::app {

/// Where a stored ellipse came from; it decides who may replace or remove it.
enum class EllipseSource { ConfiguredLink, ConfiguredObstacle, ServiceObstacle, TopicObstacle };

struct StoredEllipse {
  EllipseSpec spec;
  EllipseSource source{EllipseSource::ConfiguredLink};
  /// A topic obstacle's source (0 = ~obstacles, i = the node's sources[i - 1]); its messages
  /// replace the obstacles of that source alone. 0 for every other entry.
  std::size_t topic_source{0};
  core::EllipseRole role() const {
    return source == EllipseSource::ConfiguredLink ? core::EllipseRole::Link : core::EllipseRole::Obstacle;
  }
};

/// Memory limits on what requests and messages may store. Refused beyond them, naming the limit.
struct RegistryLimits {
  std::size_t max_obstacles{100000};   ///< runtime obstacles (service + topic) at any time
  std::size_t max_name_length{256};    ///< characters in the name of a runtime obstacle
};

/// The named ellipses the node keeps, by name. Every change is all-or-nothing: a refused request
/// leaves the registry as it was and returns a message naming the field and value; an accepted one
/// returns an empty string. Field values are validated by the caller (findInvalidPaddedField(),
/// the frame lookup);
/// the registry owns the rules about names.
///
/// Names are unique across links and obstacles. Links come only from the configuration and are
/// never replaced or removed. The service may add, replace and remove obstacles, except those owned
/// by the topic; each topic message replaces the topic obstacles of its source (0 = ~obstacles) and
/// may not reuse another name, another source's included. Stamp, expiry and the store's topic
/// obstacles are those of source 0: a sensor source is not restored after a restart (its next
/// message brings it back, and its watchdog covers the time until then).
class EllipseRegistry {
 public:
  /// Configured links and obstacles; throws std::invalid_argument on an empty or duplicate name.
  EllipseRegistry(const std::vector<EllipseSpec>& links, const std::vector<EllipseSpec>& obstacles,
                  RegistryLimits limits = {});

  /// `field` prefixes messages ("obstacles" -> "obstacles[1].name = ...").
  std::string addObstacles(const std::vector<EllipseSpec>& obstacles, const std::string& field);
  std::string removeObstacles(const std::vector<std::string>& names, const std::string& field);
  /// `stamp_s` is the message's observation time [s] (see dropExpiredTopicObstacles());
  /// `topic_source` the source whose obstacles it replaces (StoredEllipse::topic_source).
  std::string replaceTopicObstacles(const std::vector<EllipseSpec>& obstacles,
                                    const std::string& field, double stamp_s = 0.0,
                                    std::size_t topic_source = 0);

  /// The obstacle-timeout rule: when `timeout_s` > 0 and the topic obstacles' stamp is more than
  /// `timeout_s` before `now_s` (or the stamp is 0, unknown), every topic obstacle of source 0
  /// (~obstacles) is dropped.
  /// Returns how many were dropped (0 when nothing expired or there were none).
  std::size_t dropExpiredTopicObstacles(double now_s, double timeout_s);
  /// The runtime obstacles (service and source 0's topic obstacles, with the topic stamp) for the
  /// obstacle store.
  StoredObstacles runtimeObstacles() const;
  /// The service obstacles alone (no topic obstacles, no stamp): the store's service record.
  StoredObstacles serviceObstacles() const;
  /// Whether any of `names` is a topic obstacle: removing those changes more than the service
  /// record holds, so the whole store must be written.
  bool anyTopicObstacle(const std::vector<std::string>& names) const;
  /// Puts back what runtimeObstacles() returned (after a restart), through the same rules as the
  /// service and the topic; "" or why it was refused (then nothing is restored).
  std::string restore(const StoredObstacles& stored);
  /// The stamp [s] of the message that brought the topic obstacles of `topic_source` (0 = none
  /// or unstamped): where a moving one was when it was seen.
  double topicStamp(std::size_t topic_source = 0) const {
    return topic_source < topic_stamps_s_.size() ? topic_stamps_s_[topic_source] : 0.0;
  }

  const std::map<std::string, StoredEllipse>& entries() const { return entries_; }
  bool contains(const std::string& name) const { return entries_.count(name) != 0; }
  std::size_t count(EllipseSource source) const { return counts_[static_cast<std::size_t>(source)]; }
  /// The topic obstacles of source `topic_source` (StoredEllipse::topic_source).
  std::size_t topicCount(std::size_t topic_source) const {
    return topic_source < topic_counts_.size() ? topic_counts_[topic_source] : 0;
  }
  /// The entries with an own velocity (vx, vy or angular_velocity not 0): the velocity gate looks
  /// these up by name, and every other obstacle stands (an empty set for most scenes).
  const std::set<std::string>& movingNames() const { return moving_names_; }
  /// Changes with every change of entries(): while it is the same, the entries are the same
  /// objects with the same specs (what PlacementCache relies on).
  std::uint64_t revision() const { return revision_; }

 private:
  /// The limits' rule for one request or message: a name longer than max_name_length, or more
  /// than max_obstacles runtime obstacles after it (`runtime_after`). "" when within them.
  std::string checkLimits(const std::vector<EllipseSpec>& obstacles, const std::string& field,
                          std::size_t runtime_after) const;

  using Entries = std::map<std::string, StoredEllipse>;
  /// `spec` under its name, from `source`, in place of any entry of that name; keeps counts_.
  /// Returns the entry.
  Entries::iterator put(const EllipseSpec& spec, EllipseSource source,
                        std::size_t topic_source = 0);
  /// Keeps topic_counts_ when a topic obstacle of `topic_source` comes (+1) or goes (-1).
  void countTopic(std::size_t topic_source, int change);
  /// Keeps moving_names_ for an entry just written.
  void trackOwnMotion(const Entries::value_type& entry);
  /// Erases the entry at `it` and returns the next; keeps counts_.
  Entries::iterator erase(Entries::iterator it);

  Entries entries_;
  /// Entries per EllipseSource: every request checks the runtime obstacles against max_obstacles,
  /// and counting them in the map took 2 ms each at 100,000.
  std::array<std::size_t, 4> counts_{};
  std::vector<std::size_t> topic_counts_;  ///< topic obstacles per topic_source
  /// The service obstacles' names, for serviceObstacles(): a service call's record is written
  /// from them without walking a perception stream's 100,000 topic obstacles (1.4-4 ms).
  std::set<std::string> service_names_;
  std::set<std::string> moving_names_;  ///< movingNames()
  RegistryLimits limits_;
  std::vector<double> topic_stamps_s_{0.0};  ///< topicStamp() per topic_source
  std::uint64_t revision_{0};
  /// The topic obstacles' entries in the order of the last accepted message, valid while
  /// revision_ is `revision` (every other change of the entries moves revision_ on). A stream
  /// mostly repeats its names in the same order: a name found at its place costs one comparison,
  /// where a search of the map was half of a message's time at 100,000. A copy of the registry
  /// starts without it: its iterators point into the original's map (a move takes the map's
  /// nodes along, and they stay valid).
  struct TopicOrder {
    std::vector<Entries::iterator> entries;
    std::uint64_t revision{0};
    TopicOrder() = default;
    TopicOrder(const TopicOrder& /*other*/) {}
    TopicOrder& operator=(const TopicOrder& /*other*/) {
      entries.clear();
      return *this;
    }
    TopicOrder(TopicOrder&&) = default;
    TopicOrder& operator=(TopicOrder&&) = default;
  };
  /// Per topic_source; valid only while no other change came between two messages of it.
  std::vector<TopicOrder> topic_orders_;
};

}  // namespace ellipse_collision::app
