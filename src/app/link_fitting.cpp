#include "ellipse_collision/app/link_fitting.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

#include "ellipse_collision/core/enclosing_ellipsoid.h"
#include "ellipse_collision/core/number_format.h"
#include "ellipse_collision/core/shape_hull.h"

namespace ellipse_collision::app {
namespace {

/// core::formatNumber() in a form YAML 1.1 readers (rosparam's PyYAML) take as a float: they
/// need a '.' in the mantissa and a sign in the exponent, so "1e-05" becomes "1.0e-05" (without
/// this it would read back as a string).
std::string yamlNumber(double value) {
  std::string text = core::formatNumber(value);
  const std::size_t e = text.find('e');
  if (e != std::string::npos) {
    if (text.find('.') == std::string::npos) text.insert(e, ".0");
    const std::size_t sign = text.find('e') + 1;
    if (sign < text.size() && text[sign] != '-' && text[sign] != '+') text.insert(sign, "+");
  }
  return text;
}

}  // namespace

std::string findLinkSelectionProblem(const std::vector<std::string>& model_links,
                                     const LinkFitOptions& options) {
  if (!(options.padding >= 0.0 && options.padding <= core::kMaxRadius)) {
    return "padding = " + core::formatNumber(options.padding) + ": expected a number within [0, " +
           core::formatNumber(core::kMaxRadius) + "] [m]";
  }
  const std::set<std::string> known(model_links.begin(), model_links.end());
  std::set<std::string> seen;
  for (std::size_t i = 0; i < options.links.size(); ++i) {
    const std::string& name = options.links[i];
    const std::string where = entryName("links", i) + " = '" + name + "'";
    if (name.empty()) return entryName("links", i) + ": expected a link name, got ''";
    if (!known.count(name)) return where + ": not a link of the robot model";
    if (!seen.insert(name).second) return where + ": named twice";
  }
  return "";
}

std::vector<std::string> selectedLinks(const std::vector<std::string>& model_links,
                                       const LinkFitOptions& options) {
  return options.links.empty() ? model_links : options.links;
}

namespace {

/// The spec of a fitted ellipsoid: yaw (angle), pitch and roll of R = Rz Ry Rx read from its
/// rotation, then the radii grown until the ellipsoid these fields describe holds every hull
/// point again (the angles carry rounding). False if the growth failed.
bool ellipsoidSpec(const core::Ellipsoid& fitted, const std::vector<Eigen::Vector3d>& hull,
                   EllipseSpec& spec) {
  const Eigen::Matrix3d r = fitted.orientation.toRotationMatrix();
  EllipsoidPart part;
  part.z = fitted.center.z();
  part.pitch = std::asin(std::clamp(-r(2, 0), -1.0, 1.0));
  if (std::abs(r(2, 0)) < 1.0 - 1e-9) {
    spec.angle = std::atan2(r(1, 0), r(0, 0));
    part.roll = std::atan2(r(2, 1), r(2, 2));
  } else {  // pitch = +-pi/2: only yaw -+ roll is defined; put it all in yaw
    spec.angle = std::atan2(-r(0, 1), r(1, 1));
    part.roll = 0.0;
  }
  spec.x = fitted.center.x();
  spec.y = fitted.center.y();
  spec.radius_x = fitted.radii.x();
  spec.radius_y = fitted.radii.y();
  part.radius_z = fitted.radii.z();
  spec.ellipsoid = part;
  EllipseSpec unpadded = spec;
  unpadded.padding = 0.0;
  core::Ellipsoid described = paddedEllipsoid(unpadded, 0.0);
  if (!core::growToContain(described, hull)) return false;
  spec.radius_x = described.radii.x();
  spec.radius_y = described.radii.y();
  spec.ellipsoid->radius_z = described.radii.z();
  return true;
}

}  // namespace

const char* nameOf(LinkShape shape) {
  switch (shape) {
    case LinkShape::Planar:
      return "planar";
    case LinkShape::Ellipsoid:
      return "ellipsoid";
    case LinkShape::Auto:
      break;
  }
  return "auto";
}

std::optional<LinkShape> linkShapeNamed(const std::string& name) {
  for (const LinkShape shape : {LinkShape::Auto, LinkShape::Planar, LinkShape::Ellipsoid}) {
    if (name == nameOf(shape)) return shape;
  }
  return std::nullopt;
}

LinkFitResult fitLinkEllipses(const std::vector<LinkGeometry>& links, double padding,
                              LinkShape shape) {
  LinkFitResult result;
  for (const LinkGeometry& link : links) {
    if (link.shapes.empty()) {
      result.skipped.push_back(link.name + ": no collision geometry");
      continue;
    }
    EllipseSpec spec;
    spec.name = link.name;
    spec.frame_id = link.name;
    spec.padding = padding;
    const bool ellipsoid =
        shape == LinkShape::Ellipsoid || (shape == LinkShape::Auto && link.tilts);
    if (ellipsoid) {
      const core::EnclosingEllipsoid fit = core::fitLinkEllipsoid(link.shapes);
      if (fit.ok) {
        if (!ellipsoidSpec(fit.ellipsoid, core::linkHullPoints(link.shapes).points, spec)) {
          result.links.clear();
          result.error = "link '" + link.name + "': the ellipsoid could not be certified";
          return result;
        }
        if (const auto invalid = findInvalidPaddedField(spec, 0.0, "frame")) {
          result.links.clear();
          result.error = describeFieldError("link '" + link.name + "'", *invalid);
          return result;
        }
        result.links.push_back(spec);
        continue;
      }
      // No volume (a flat plate) or an invalid shape: the planar fit below keeps or reports it.
    }
    core::EnclosingEllipse fit = core::fitLinkEllipse(link.shapes);
    if (fit.status == core::EnclosingStatus::Degenerate) {
      fit = core::enclosingEllipseWithMinRadius(core::linkOutline(link.shapes).points,
                                                kLinkMinRadius);
    }
    if (!fit.ok()) {
      result.links.clear();
      result.error = "link '" + link.name + "': " + fit.error;
      return result;
    }
    spec.x = fit.ellipse.center.x();
    spec.y = fit.ellipse.center.y();
    spec.angle = fit.ellipse.angle;
    spec.radius_x = fit.ellipse.radius_x;
    spec.radius_y = fit.ellipse.radius_y;
    if (const auto invalid = findInvalidPaddedField(spec, 0.0, "frame")) {
      result.links.clear();
      result.error = describeFieldError("link '" + link.name + "'", *invalid);
      return result;
    }
    result.links.push_back(spec);
  }
  return result;
}

std::string linksYaml(const std::vector<EllipseSpec>& specs,
                      const std::vector<std::string>& comments) {
  std::ostringstream out;
  for (const std::string& comment : comments) out << "# " << comment << "\n";
  if (specs.empty()) {
    out << "links: []\n";
    return out.str();
  }
  out << "links:\n";
  for (const EllipseSpec& s : specs) {
    // Link names are URDF names (letters, digits, '_', '-', '/'): quoted anyway, so that no name
    // reads back as a number or a bool.
    out << "  - {name: '" << s.name << "', frame: '" << s.frame_id << "', x: " << yamlNumber(s.x)
        << ", y: " << yamlNumber(s.y) << ", angle: " << yamlNumber(s.angle)
        << ", radius_x: " << yamlNumber(s.radius_x) << ", radius_y: " << yamlNumber(s.radius_y);
    if (s.ellipsoid) {
      out << ", z: " << yamlNumber(s.ellipsoid->z) << ", roll: " << yamlNumber(s.ellipsoid->roll)
          << ", pitch: " << yamlNumber(s.ellipsoid->pitch)
          << ", radius_z: " << yamlNumber(s.ellipsoid->radius_z);
    }
    out << ", padding: " << yamlNumber(s.padding) << "}\n";
  }
  return out.str();
}

}  // namespace ellipse_collision::app
