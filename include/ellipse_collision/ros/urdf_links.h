#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "ellipse_collision/app/link_fitting.h"

namespace ellipse_collision {

/// A robot model that cannot be read or fitted; what() names the file or parameter, and the link
/// and mesh URI where one is at fault.
class UrdfError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// URDF reading lives in the ROS layer, not in src/app: urdf::Model comes from Debian's liburdf
// (a ROS package, with resource_retriever and assimp for meshes), and the application layer
// links no ROS library. What crosses into src/app is app::LinkGeometry (core types only); the
// rules (which links, padding, skipping links without geometry) live there, in link_fitting.h.

/// The text of a URDF file. Throws UrdfError naming the file.
std::string readUrdfFile(const std::string& path);

/// The URDF text in parameter `param` (resolved like robot_state_publisher's
/// `robot_description`: relative to the node's namespace). Throws UrdfError naming the parameter.
std::string readUrdfParam(const std::string& param);

/// Every link of the model in `urdf_xml` with its collision geometry in core types, for the links
/// named in `names` (in that order; empty: every link, sorted by name): boxes, cylinders, spheres
/// and meshes, each with its <origin>; meshes loaded through resource_retriever (package://,
/// file://) and assimp and placed where rviz draws them: node transforms, a Collada file's <unit>
/// and the URDF scale applied, its <up_axis> ignored (no turn to Y-up). `source` ("file 'x.urdf'",
/// "parameter 'robot_description'") starts every error. Throws UrdfError when the URDF does not
/// parse, a name is not a link, or a mesh cannot be loaded (naming link and URI).
std::vector<app::LinkGeometry> readUrdfLinks(const std::string& urdf_xml, const std::string& source,
                                             const std::vector<std::string>& names = {});

/// The link names of the model in `urdf_xml`, sorted. Throws UrdfError when it does not parse.
std::vector<std::string> urdfLinkNames(const std::string& urdf_xml, const std::string& source);

/// readUrdfLinks() for the links `options` selects, then app::fitLinkEllipses(). Throws
/// UrdfError (prefixed with `source`) for a bad model, selection or shape; the result's
/// `skipped` lists links without collision geometry.
app::LinkFitResult fitUrdfLinks(const std::string& urdf_xml, const std::string& source,
                                const app::LinkFitOptions& options);

/// The node's `links_from_urdf` reader: readUrdfParam(param), then fitUrdfLinks() with the source
/// "parameter 'PARAM'". Throws UrdfError.
app::LinkFitResult fitUrdfLinksFromParam(const std::string& param,
                                         const app::LinkFitOptions& options);

}  // namespace ellipse_collision
