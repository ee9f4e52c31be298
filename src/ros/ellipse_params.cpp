#include "ellipse_collision/ros/ellipse_params.h"

#include <optional>

#include "ellipse_collision/app/collision_check.h"
#include "ellipse_collision/app/tunable_settings.h"
#include "ellipse_collision/ros/param_reading.h"

namespace ellipse_collision {

using params::describeValue;
using params::fail;
using params::readInRange;
using params::readNumber;
using params::readString;
using params::unknownKey;
using XmlRpc::XmlRpcValue;

namespace {

// Links and obstacles alike; radius_z makes an ellipsoid (app::EllipsoidPart), z, roll, pitch
// optional with it.
const std::vector<std::string> kEllipseKeys = {"name",  "frame",    "x",        "y",
                                               "angle", "radius_x", "radius_y", "padding",
                                               "z",     "roll",     "pitch",    "radius_z"};

app::EllipseSpec readEllipse(const XmlRpcValue& entry, const std::string& where,
                             double global_padding) {
  if (entry.getType() != XmlRpcValue::TypeStruct) {
    throw ConfigError(where + ": expected a dict with keys " + app::joinText(kEllipseKeys, ", ") +
                      ", got " + describeValue(entry));
  }
  // Name the entry by its name as soon as there is one, so the message points at the YAML.
  std::string label = where;
  if (entry.hasMember("name") && entry["name"].getType() == XmlRpcValue::TypeString) {
    label = where + " (name '" + readString(entry["name"], where, "name") + "')";
  }
  if (const auto key = unknownKey(entry, kEllipseKeys)) {
    throw ConfigError(label + ": unknown key '" + *key + "' (expected one of " +
                      app::joinText(kEllipseKeys, ", ") + ")");
  }
  const bool ellipsoid = entry.hasMember("z") || entry.hasMember("roll") ||
                         entry.hasMember("pitch") || entry.hasMember("radius_z");
  if (ellipsoid && !entry.hasMember("radius_z")) {
    throw ConfigError(label +
                      ": missing key 'radius_z' (z, roll and pitch describe an ellipsoid, "
                      "which needs radius_z)");
  }
  for (const char* key : {"name", "frame", "x", "y", "angle", "radius_x", "radius_y"}) {
    if (!entry.hasMember(key)) {
      throw ConfigError(label + ": missing key '" + key +
                        "' (required: name, frame, x, y, angle, radius_x, radius_y; padding is "
                        "optional, radius_z with optional z, roll, pitch makes an ellipsoid)");
    }
  }

  app::EllipseSpec spec;
  spec.name = readString(entry["name"], label, "name");
  spec.frame_id = readString(entry["frame"], label, "frame");
  spec.x = readNumber(entry["x"], label, "x");
  spec.y = readNumber(entry["y"], label, "y");
  spec.angle = readNumber(entry["angle"], label, "angle");
  spec.radius_x = readNumber(entry["radius_x"], label, "radius_x");
  spec.radius_y = readNumber(entry["radius_y"], label, "radius_y");
  if (entry.hasMember("padding")) spec.padding = readNumber(entry["padding"], label, "padding");
  if (ellipsoid) {
    app::EllipsoidPart part;
    part.radius_z = readNumber(entry["radius_z"], label, "radius_z");
    if (entry.hasMember("z")) part.z = readNumber(entry["z"], label, "z");
    if (entry.hasMember("roll")) part.roll = readNumber(entry["roll"], label, "roll");
    if (entry.hasMember("pitch")) part.pitch = readNumber(entry["pitch"], label, "pitch");
    spec.ellipsoid = part;
  }
  if (const auto invalid = app::findInvalidPaddedField(spec, global_padding, "frame")) {
    fail(label, invalid->key, invalid->expected, invalid->actual);
  }
  return spec;
}

}  // namespace

std::vector<app::EllipseSpec> parseEllipseList(const XmlRpcValue& list, const std::string& key,
                                               double global_padding) {
  if (list.getType() != XmlRpcValue::TypeArray) {
    fail("parameter ~" + key, key, "a list of ellipses", describeValue(list));
  }
  std::vector<app::EllipseSpec> specs;
  for (int i = 0; i < list.size(); ++i) {
    specs.push_back(readEllipse(list[i], app::entryName(key, i), global_padding));
  }
  return specs;
}

namespace params {

std::vector<std::pair<std::string, std::string>> readAllowedPairs(
    const XmlRpcValue& list, const std::map<std::string, std::string>& defined) {
  const std::string key = "allowed_pairs";
  if (list.getType() != XmlRpcValue::TypeArray) {
    fail("parameter ~" + key, key, "a list of [name_a, name_b]", describeValue(list));
  }
  std::vector<std::pair<std::string, std::string>> pairs;
  for (int i = 0; i < list.size(); ++i) {
    const std::string where = app::entryName(key, i);
    const XmlRpcValue& pair = list[i];
    if (pair.getType() != XmlRpcValue::TypeArray || pair.size() != 2) {
      throw ConfigError(where + ": expected a list of two names [name_a, name_b], got " +
                        describeValue(pair));
    }
    std::string names[2];
    for (int k = 0; k < 2; ++k) {
      const std::string element = app::entryName(where, k);
      XmlRpcValue copy = pair[k];
      if (copy.getType() != XmlRpcValue::TypeString) {
        throw ConfigError(element + ": expected a link or obstacle name, got " +
                          describeValue(copy));
      }
      names[k] = static_cast<std::string&>(copy);
      if (!defined.count(names[k])) {
        throw ConfigError(
            element + " = '" + names[k] +
            "': expected the name of a configured link or obstacle, got an unknown name");
      }
    }
    if (names[0] == names[1]) {
      throw ConfigError(where + ": expected two different names, got '" + names[0] + "' twice");
    }
    pairs.emplace_back(names[0], names[1]);
  }
  return pairs;
}

app::LinkFitResult readLinksFromUrdf(const XmlRpcValue& value,
                                     const UrdfLinkFitter& fit_urdf_links) {
  const std::string where = "parameter ~links_from_urdf";
  if (value.getType() != XmlRpcValue::TypeStruct) {
    throw ConfigError(where + ": expected a dict {param, links, padding, shape}, got " +
                      describeValue(value));
  }
  static const std::vector<std::string> kUrdfKeys = {"param", "links", "padding", "shape"};
  if (const auto key = unknownKey(value, kUrdfKeys)) {
    throw ConfigError(where + ": unknown key '" + *key + "' (expected one of " +
                      app::joinText(kUrdfKeys, ", ") + ")");
  }
  std::string param = "robot_description";
  if (value.hasMember("param")) {
    param = readString(value["param"], where, "param");
    if (param.empty()) fail(where, "param", "a parameter name", "''");
  }
  app::LinkFitOptions options;
  if (value.hasMember("links")) {
    const XmlRpcValue& links = value["links"];
    if (links.getType() != XmlRpcValue::TypeArray) {
      fail(where, "links", "a list of link names", describeValue(links));
    }
    for (int i = 0; i < links.size(); ++i) {
      options.links.push_back(readString(links[i], where, app::entryName("links", i)));
    }
  }
  if (value.hasMember("padding")) {
    // The links' own padding keeps the range of the global one.
    const app::SettingRange& padding = app::settingRange("padding");
    options.padding = readInRange(value["padding"], where, "padding", padding.min, padding.max);
  }
  if (value.hasMember("shape")) {
    const std::string name = readString(value["shape"], where, "shape");
    const std::optional<app::LinkShape> shape = app::linkShapeNamed(name);
    if (!shape) fail(where, "shape", app::kLinkShapeNames, "'" + name + "'");
    options.shape = *shape;
  }
  if (!fit_urdf_links) throw ConfigError(where + ": no URDF reader in this program");
  try {
    return fit_urdf_links(param, options);
  } catch (const std::runtime_error& error) {
    throw ConfigError(where + ": " + error.what());
  }
}
}  // namespace params
}  // namespace ellipse_collision
