#include "ellipse_collision/app/obstacle_source.h"

#include <map>

#include "ellipse_collision/core/number_format.h"

namespace ellipse_collision::app {
namespace {

bool isSourceName(const std::string& name) {
  if (name.empty()) return false;
  for (const char c : name) {
    const bool ok =
        (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
    if (!ok) return false;
  }
  return true;
}

}  // namespace

const char* toString(SourceType type) {
  switch (type) {
    case SourceType::Scan:
      return "scan";
    case SourceType::Cloud:
      return "cloud";
    case SourceType::Range:
      return "range";
    case SourceType::Robots:
      return "robots";
    case SourceType::Ellipses:
      break;
  }
  return "ellipses";
}

std::optional<FieldError> parseSourceType(const std::string& text, const std::string& key,
                                          SourceType* type) {
  for (const SourceType candidate : {SourceType::Ellipses, SourceType::Scan, SourceType::Cloud,
                                     SourceType::Range, SourceType::Robots}) {
    if (text == toString(candidate)) {
      *type = candidate;
      return std::nullopt;
    }
  }
  return FieldError{key, "'ellipses', 'scan', 'cloud', 'range' or 'robots'", "'" + text + "'"};
}

std::optional<FieldError> findInvalidSources(const std::vector<SourceSpec>& sources) {
  // Where each name and topic is first used: the default source holds its own.
  std::map<std::string, std::string> names{{kDefaultSourceName, "the default source ~obstacles"}};
  std::map<std::string, std::string> topics{{"obstacles", "the default source ~obstacles"},
                                            {"~obstacles", "the default source ~obstacles"}};
  for (std::size_t i = 0; i < sources.size(); ++i) {
    const SourceSpec& source = sources[i];
    const std::string entry = entryName("sources", i);
    if (!isSourceName(source.name)) {
      return FieldError{entry + ".name", "a non-empty name of letters, digits and '_'",
                        "'" + source.name + "'"};
    }
    if (const auto used = names.find(source.name); used != names.end()) {
      return FieldError{entry + ".name", "a name used by no other source",
                        "'" + source.name + "', the name of " + used->second};
    }
    names.emplace(source.name, entry);
    if (source.topic.empty()) return FieldError{entry + ".topic", "a non-empty topic", "''"};
    if (const auto used = topics.find(source.topic); used != topics.end()) {
      return FieldError{entry + ".topic", "a topic used by no other source",
                        "'" + source.topic + "', the topic of " + used->second};
    }
    topics.emplace(source.topic, entry);
    if (auto invalid =
            findOutsideRange(entry + ".timeout", source.timeout_s, 0.0, kMaxSourceTimeoutS)) {
      return invalid;
    }
    // A robots source's timeout drops a silent robot: without one a robot would never leave.
    if (source.type == SourceType::Robots) {
      if (auto invalid = findOutsideRange(entry + ".timeout", source.timeout_s, 0.0,
                                          kMaxSourceTimeoutS, true)) {
        return invalid;
      }
      if (auto invalid =
              findOutsideRange(entry + ".padding", source.padding_m, 0.0, kMaxRobotsPaddingM)) {
        return invalid;
      }
    } else if (source.required) {
      return FieldError{entry + ".required", "no 'required' (type robots only)", "true"};
    } else if (source.padding_m != 0.0) {
      return FieldError{entry + ".padding", "no 'padding' (type robots only)",
                        core::formatNumber(source.padding_m)};
    }
    if (source.type == SourceType::Scan || source.type == SourceType::Cloud) {
      if (auto invalid = findInvalidSetting(source.tracking)) {
        invalid->key = entry + "." + invalid->key;
        return invalid;
      }
    }
    if (source.type != SourceType::Ellipses && source.type != SourceType::Robots) {
      if (auto invalid = findInvalidSetting(source.scan)) {
        invalid->key = entry + "." + invalid->key;
        return invalid;
      }
    }
  }
  return std::nullopt;
}

bool watchesSilence(const SourceSpec& source) {
  return source.type != SourceType::Robots || source.required;
}

std::string sourceObstacleName(const std::string& source, const std::string& obstacle) {
  return source + "/" + obstacle;
}

}  // namespace ellipse_collision::app
