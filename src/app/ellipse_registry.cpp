#include "ellipse_collision/app/ellipse_registry.h"

#include <algorithm>
#include <stdexcept>
#include <unordered_set>

#include "ellipse_collision/core/unique_names.h"

namespace ellipse_collision::app {
namespace {

const char* describe(EllipseSource source) {
  switch (source) {
    case EllipseSource::ConfiguredLink:
      return "a configured link";
    case EllipseSource::ConfiguredObstacle:
      return "a configured obstacle";
    case EllipseSource::ServiceObstacle:
      return "an obstacle added by ~add_obstacles";
    case EllipseSource::TopicObstacle:
      return "an obstacle from the ~obstacles topic";
  }
  return "an ellipse";
}

/// Names in one request must be non-empty and distinct; returns the first violation, naming it
/// as field[i] + suffix ("obstacles[2].name"). `name_of(i)` is the name of entry i < count.
template <class NameOf>
std::string checkRequestNames(std::size_t count, NameOf&& name_of, const std::string& field,
                              const std::string& suffix) {
  const auto problem = core::findNameProblem(count, name_of);
  if (!problem) return {};
  const std::string where = entryName(field, problem->index) + suffix;
  if (problem->kind == core::NameProblem::Kind::Empty) {
    return where + " = '': expected a non-empty name";
  }
  return where + " = '" + std::string(name_of(problem->index)) +
         "': expected each name once, got a duplicate";
}

/// The same for the names of `specs`, without copying them (a message may carry 100,000).
std::string checkSpecNames(const std::vector<EllipseSpec>& specs, const std::string& field) {
  return checkRequestNames(
      specs.size(), [&specs](std::size_t i) -> const std::string& { return specs[i].name; },
      field, ".name");
}

}  // namespace

EllipseRegistry::EllipseRegistry(const std::vector<EllipseSpec>& links,
                                 const std::vector<EllipseSpec>& obstacles, RegistryLimits limits)
    : limits_(limits) {
  const auto add = [this](const EllipseSpec& spec, EllipseSource source) {
    if (spec.name.empty()) throw std::invalid_argument("ellipse with an empty name");
    if (entries_.count(spec.name) != 0) {
      throw std::invalid_argument("duplicate ellipse name '" + spec.name + "'");
    }
    put(spec, source);
  };
  for (const EllipseSpec& spec : links) add(spec, EllipseSource::ConfiguredLink);
  for (const EllipseSpec& spec : obstacles) add(spec, EllipseSource::ConfiguredObstacle);
}

void EllipseRegistry::countTopic(std::size_t topic_source, int change) {
  if (topic_source >= topic_counts_.size()) topic_counts_.resize(topic_source + 1, 0);
  topic_counts_[topic_source] += static_cast<std::size_t>(change);  // -1 wraps back exactly
}

EllipseRegistry::Entries::iterator EllipseRegistry::put(const EllipseSpec& spec,
                                                        EllipseSource source,
                                                        std::size_t topic_source) {
  const StoredEllipse stored{spec, source,
                             source == EllipseSource::TopicObstacle ? topic_source : 0};
  const auto [it, inserted] = entries_.try_emplace(spec.name, stored);
  if (!inserted) {
    --counts_[static_cast<std::size_t>(it->second.source)];
    if (it->second.source == EllipseSource::ServiceObstacle) service_names_.erase(spec.name);
    if (it->second.source == EllipseSource::TopicObstacle) countTopic(it->second.topic_source, -1);
    it->second = stored;
  }
  ++counts_[static_cast<std::size_t>(source)];
  if (source == EllipseSource::ServiceObstacle) service_names_.insert(spec.name);
  if (source == EllipseSource::TopicObstacle) countTopic(stored.topic_source, +1);
  trackOwnMotion(*it);
  return it;
}

void EllipseRegistry::trackOwnMotion(const Entries::value_type& entry) {
  const EllipseSpec& spec = entry.second.spec;
  if (spec.vx != 0.0 || spec.vy != 0.0 || spec.angular_velocity != 0.0) {
    moving_names_.insert(entry.first);
  } else if (!moving_names_.empty()) {
    moving_names_.erase(entry.first);
  }
}

EllipseRegistry::Entries::iterator EllipseRegistry::erase(Entries::iterator it) {
  --counts_[static_cast<std::size_t>(it->second.source)];
  if (it->second.source == EllipseSource::ServiceObstacle) service_names_.erase(it->first);
  if (it->second.source == EllipseSource::TopicObstacle) countTopic(it->second.topic_source, -1);
  if (!moving_names_.empty()) moving_names_.erase(it->first);
  return entries_.erase(it);
}

std::string EllipseRegistry::checkLimits(const std::vector<EllipseSpec>& obstacles,
                                         const std::string& field,
                                         std::size_t runtime_after) const {
  for (std::size_t i = 0; i < obstacles.size(); ++i) {
    if (obstacles[i].name.size() > limits_.max_name_length) {
      return entryName(field, i) + ".name: expected at most max_name_length = " +
             std::to_string(limits_.max_name_length) + " characters, got " +
             std::to_string(obstacles[i].name.size());
    }
  }
  if (runtime_after > limits_.max_obstacles) {
    return field + ": expected at most max_obstacles = " + std::to_string(limits_.max_obstacles) +
           " runtime obstacles (service and topic) in total, got " + std::to_string(runtime_after);
  }
  return {};
}

std::string EllipseRegistry::addObstacles(const std::vector<EllipseSpec>& obstacles,
                                          const std::string& field) {
  std::string error = checkSpecNames(obstacles, field);
  if (!error.empty()) return error;
  std::size_t runtime_after =
      count(EllipseSource::ServiceObstacle) + count(EllipseSource::TopicObstacle);
  for (const EllipseSpec& spec : obstacles) {
    const auto found = entries_.find(spec.name);
    if (found == entries_.end() || found->second.source != EllipseSource::ServiceObstacle) {
      ++runtime_after;  // new, or a configured obstacle that becomes a runtime one
    }
  }
  error = checkLimits(obstacles, field, runtime_after);
  if (!error.empty()) return error;
  for (std::size_t i = 0; i < obstacles.size(); ++i) {
    const auto found = entries_.find(obstacles[i].name);
    if (found == entries_.end()) continue;
    const EllipseSource source = found->second.source;
    if (source == EllipseSource::ConfiguredLink || source == EllipseSource::TopicObstacle) {
      return entryName(field, i) + ".name = '" + obstacles[i].name +
             "': expected a new or replaceable obstacle name, got " + describe(source);
    }
  }
  for (const EllipseSpec& spec : obstacles) {
    put(spec, EllipseSource::ServiceObstacle);
  }
  ++revision_;
  return {};
}

std::string EllipseRegistry::removeObstacles(const std::vector<std::string>& names,
                                             const std::string& field) {
  std::string error = checkRequestNames(
      names.size(), [&names](std::size_t i) -> const std::string& { return names[i]; }, field, "");
  if (!error.empty()) return error;
  for (std::size_t i = 0; i < names.size(); ++i) {
    const auto found = entries_.find(names[i]);
    if (found == entries_.end()) {
      return entryName(field, i) + " = '" + names[i] +
             "': expected an obstacle name, got an unknown name";
    }
    if (found->second.source == EllipseSource::ConfiguredLink) {
      return entryName(field, i) + " = '" + names[i] +
             "': expected an obstacle name, got a configured link (links cannot be removed)";
    }
  }
  for (const std::string& name : names) erase(entries_.find(name));
  ++revision_;
  return {};
}

std::string EllipseRegistry::replaceTopicObstacles(const std::vector<EllipseSpec>& obstacles,
                                                   const std::string& field, double stamp_s,
                                                   std::size_t topic_source) {
  std::string error = checkSpecNames(obstacles, field);
  if (!error.empty()) return error;
  // The other sources' topic obstacles stay: they count towards the limit.
  const std::size_t others = count(EllipseSource::TopicObstacle) - topicCount(topic_source);
  error = checkLimits(obstacles, field,
                      count(EllipseSource::ServiceObstacle) + others + obstacles.size());
  if (!error.empty()) return error;
  // One lookup per name, kept for the update below: a stream mostly repeats its names, and
  // those entries are rewritten in place. Erasing every topic obstacle and inserting them again
  // cost 30 ms per message of 100,000 (a node per name, the name copied, the tree rebalanced).
  std::vector<Entries::iterator> found(obstacles.size());
  std::size_t staying = 0;
  if (topic_source >= topic_orders_.size()) topic_orders_.resize(topic_source + 1);
  TopicOrder& topic_order = topic_orders_[topic_source];
  const std::vector<Entries::iterator>& last_order = topic_order.entries;
  const bool same_order_known = revision_ == topic_order.revision;
  for (std::size_t i = 0; i < obstacles.size(); ++i) {
    const std::string& name = obstacles[i].name;
    found[i] = same_order_known && i < last_order.size() && last_order[i]->first == name
                   ? last_order[i]
                   : entries_.find(name);
    if (found[i] == entries_.end()) continue;
    if (found[i]->second.source != EllipseSource::TopicObstacle) {
      return entryName(field, i) + ".name = '" + obstacles[i].name +
             "': expected a name not used outside the topic, got " + describe(found[i]->second.source);
    }
    if (found[i]->second.topic_source != topic_source) {
      return entryName(field, i) + ".name = '" + obstacles[i].name +
             "': expected a name not used outside the topic, got an obstacle of another source";
    }
    ++staying;
  }
  if (staying < topicCount(topic_source)) {
    // Topic obstacles this message does not name go. Erasing other entries leaves found[] valid.
    std::unordered_set<const StoredEllipse*> named;
    named.reserve(staying);
    for (const Entries::iterator& it : found) {
      if (it != entries_.end()) named.insert(&it->second);
    }
    for (auto it = entries_.begin(); it != entries_.end();) {
      const bool goes = it->second.source == EllipseSource::TopicObstacle &&
                        it->second.topic_source == topic_source && !named.count(&it->second);
      it = goes ? erase(it) : std::next(it);
    }
  }
  for (std::size_t i = 0; i < obstacles.size(); ++i) {
    if (found[i] == entries_.end()) {
      found[i] = put(obstacles[i], EllipseSource::TopicObstacle, topic_source);
    } else {
      found[i]->second.spec = obstacles[i];  // a topic obstacle already: the counts stay
      trackOwnMotion(*found[i]);
    }
  }
  if (topic_source >= topic_stamps_s_.size()) topic_stamps_s_.resize(topic_source + 1, 0.0);
  topic_stamps_s_[topic_source] = stamp_s;
  ++revision_;
  topic_order.entries = std::move(found);
  topic_order.revision = revision_;
  return {};
}

StoredObstacles EllipseRegistry::runtimeObstacles() const {
  StoredObstacles stored;
  for (const auto& named : entries_) {
    if (named.second.source == EllipseSource::ServiceObstacle) stored.service.push_back(named.second.spec);
    if (named.second.source == EllipseSource::TopicObstacle && named.second.topic_source == 0) {
      stored.topic.push_back(named.second.spec);
    }
  }
  stored.topic_stamp_s = topic_stamps_s_[0];
  return stored;
}

StoredObstacles EllipseRegistry::serviceObstacles() const {
  StoredObstacles stored;
  stored.service.reserve(service_names_.size());
  for (const std::string& name : service_names_) stored.service.push_back(entries_.at(name).spec);
  return stored;
}

bool EllipseRegistry::anyTopicObstacle(const std::vector<std::string>& names) const {
  return std::any_of(names.begin(), names.end(), [this](const std::string& name) {
    const auto found = entries_.find(name);
    return found != entries_.end() && found->second.source == EllipseSource::TopicObstacle;
  });
}

std::string EllipseRegistry::restore(const StoredObstacles& stored) {
  const Entries before = entries_;
  const std::array<std::size_t, 4> counts_before = counts_;
  const std::vector<std::size_t> topic_counts_before = topic_counts_;
  const std::set<std::string> service_names_before = service_names_;
  const double stamp_before = topic_stamps_s_[0];
  std::string error = addObstacles(stored.service, "service obstacles");
  if (error.empty()) error = replaceTopicObstacles(stored.topic, "topic obstacles", stored.topic_stamp_s);
  if (!error.empty()) {
    entries_ = before;
    counts_ = counts_before;
    topic_counts_ = topic_counts_before;
    service_names_ = service_names_before;
    topic_stamps_s_[0] = stamp_before;
    ++revision_;
  }
  return error;
}

std::size_t EllipseRegistry::dropExpiredTopicObstacles(double now_s, double timeout_s) {
  if (timeout_s <= 0.0 || now_s - topic_stamps_s_[0] <= timeout_s || topicCount(0) == 0) return 0;
  std::size_t dropped = 0;
  for (auto it = entries_.begin(); it != entries_.end();) {
    if (it->second.source == EllipseSource::TopicObstacle && it->second.topic_source == 0) {
      it = erase(it);
      ++dropped;
      ++revision_;
    } else {
      ++it;
    }
  }
  return dropped;
}

}  // namespace ellipse_collision::app
