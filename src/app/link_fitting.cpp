#include "ellipse_collision/app/link_fitting.h"

#include <cmath>
#include <set>
#include <sstream>

#include "ellipse_collision/core/number_format.h"

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

LinkFitResult fitLinkEllipses(const std::vector<LinkGeometry>& links, double padding) {
  LinkFitResult result;
  for (const LinkGeometry& link : links) {
    if (link.shapes.empty()) {
      result.skipped.push_back(link.name + ": no collision geometry");
      continue;
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
    EllipseSpec spec;
    spec.name = link.name;
    spec.frame_id = link.name;
    spec.x = fit.ellipse.center.x();
    spec.y = fit.ellipse.center.y();
    spec.angle = fit.ellipse.angle;
    spec.radius_x = fit.ellipse.radius_x;
    spec.radius_y = fit.ellipse.radius_y;
    spec.padding = padding;
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
        << ", radius_x: " << yamlNumber(s.radius_x) << ", radius_y: " << yamlNumber(s.radius_y)
        << ", padding: " << yamlNumber(s.padding) << "}\n";
  }
  return out.str();
}

}  // namespace ellipse_collision::app
