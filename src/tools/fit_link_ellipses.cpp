// fit_link_ellipses: the minimum-area ellipse (or, with --shape ellipsoid, the minimum-volume
// ellipsoid) of each link's collision geometry in a URDF, printed as the `links:` block of the node's configuration (config/ellipse_collision.yaml).

#include <ros/ros.h>

#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "ellipse_collision/core/number_format.h"
#include "ellipse_collision/ros/urdf_links.h"

namespace {

constexpr const char* kUsage =
    "usage: fit_link_ellipses [--param NAME | FILE.urdf] [--links a,b,...] [--padding M]\n"
    "                         [--shape planar|ellipsoid]\n"
    "\n"
    "Reads a URDF (the expanded XML, as robot_state_publisher takes it) from FILE.urdf or from\n"
    "the ROS parameter NAME (needs a running master; default robot_description), projects each\n"
    "link's collision geometry (box, cylinder, sphere, mesh, each with its <origin>) along the\n"
    "link's z axis onto its xy-plane and prints the minimum-area ellipse containing it, as a\n"
    "`links:` YAML block for the ellipse_collision node's configuration. Frames and names are\n"
    "the link names.\n"
    "\n"
    "  --links a,b,...  only these links, in this order (default: every link, sorted by name)\n"
    "  --padding M      written as each entry's padding [m] (default 0)\n"
    "  --shape S        auto (default): ellipsoid for the links whose frames can tilt (a\n"
    "                   joint on the way from the root turns about a non-vertical axis, or a\n"
    "                   fixed origin tilts the frame), planar for the others;\n"
    "                   planar: the ellipse above; ellipsoid: the minimum-volume ellipsoid of\n"
    "                   the geometry in 3D (entries with z, roll, pitch, radius_z), whose\n"
    "                   shadow covers the link however its frame tilts (arms)\n"
    "\n"
    "Links without collision geometry are reported on standard error and skipped.\n"
    "Exit status: 0 success, 1 the URDF or a mesh cannot be read, 2 usage error.\n";

struct Arguments {
  std::string file;
  std::string param;
  ellipse_collision::app::LinkFitOptions options;
};

std::vector<std::string> splitComma(const std::string& text) {
  std::vector<std::string> parts;
  std::stringstream stream(text);
  for (std::string part; std::getline(stream, part, ',');) parts.push_back(part);
  return parts;
}

/// What the printed entries are, for the comment above them.
std::string shapeComment(ellipse_collision::app::LinkShape shape) {
  switch (shape) {
    case ellipse_collision::app::LinkShape::Planar:
      return "minimum-area ellipses of the links' collision geometry, projected along each "
             "link's z";
    case ellipse_collision::app::LinkShape::Ellipsoid:
      return "minimum-volume ellipsoids of the links' collision geometry";
    case ellipse_collision::app::LinkShape::Auto:
      break;
  }
  return "minimum-volume ellipsoids of the links whose frames can tilt, minimum-area ellipses "
         "(along each link's z) of the others";
}

/// Parses the command line; returns false (after printing why) on a usage error.
bool parseArguments(const std::vector<std::string>& args, Arguments& out) {
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    const bool has_value = i + 1 < args.size();
    if (arg == "--param" && has_value) {
      out.param = args[++i];
    } else if (arg == "--links" && has_value) {
      out.options.links = splitComma(args[++i]);
    } else if (arg == "--shape" && has_value) {
      const std::string& name = args[++i];
      const auto shape = ellipse_collision::app::linkShapeNamed(name);
      if (!shape) {
        std::cerr << "fit_link_ellipses: --shape '" << name << "': expected "
                  << ellipse_collision::app::kLinkShapeNames << "\n";
        return false;
      }
      out.options.shape = *shape;
    } else if (arg == "--padding" && has_value) {
      const std::string& text = args[++i];
      std::size_t used = 0;
      try {
        out.options.padding = std::stod(text, &used);
      } catch (const std::exception&) {
        used = 0;
      }
      if (used == 0 || used != text.size()) {
        std::cerr << "fit_link_ellipses: --padding '" << text << "': expected a number [m]\n";
        return false;
      }
    } else if (!arg.empty() && arg[0] != '-' && out.file.empty()) {
      out.file = arg;
    } else {
      std::cerr << "fit_link_ellipses: unexpected argument '" << arg << "'\n" << kUsage;
      return false;
    }
  }
  if (!out.file.empty() && !out.param.empty()) {
    std::cerr << "fit_link_ellipses: give either --param or a file, not both\n";
    return false;
  }
  if (out.file.empty() && out.param.empty()) out.param = "robot_description";
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  for (const std::string& arg : args) {
    if (arg == "--help" || arg == "-h") {
      std::cout << kUsage;
      return 0;
    }
  }
  Arguments arguments;
  if (!parseArguments(args, arguments)) return 2;
  try {
    std::string xml;
    std::string source;
    if (!arguments.param.empty()) {
      ros::init(argc, argv, "fit_link_ellipses",
                ros::init_options::AnonymousName | ros::init_options::NoRosout);
      if (!ros::master::check()) {
        std::cerr << "fit_link_ellipses: parameter '" << arguments.param
                  << "': no ROS master is running (give a URDF file instead)\n";
        return 1;
      }
      xml = ellipse_collision::readUrdfParam(arguments.param);
      source = "parameter '" + arguments.param + "'";
    } else {
      xml = ellipse_collision::readUrdfFile(arguments.file);
      source = "file '" + arguments.file + "'";
    }
    const auto result = ellipse_collision::fitUrdfLinks(xml, source, arguments.options);
    for (const std::string& skipped : result.skipped) {
      std::cerr << "fit_link_ellipses: skipped " << skipped << "\n";
    }
    std::cout << ellipse_collision::app::linksYaml(
        result.links,
        {"fit_link_ellipses " + source + ": " + shapeComment(arguments.options.shape),
                       "padding " + ellipse_collision::core::formatNumber(arguments.options.padding) +
                           " m; skipped: " + std::to_string(result.skipped.size()) + " links"});
  } catch (const ellipse_collision::UrdfError& error) {
    std::cerr << "fit_link_ellipses: " << error.what() << "\n";
    return 1;
  }
  return 0;
}
