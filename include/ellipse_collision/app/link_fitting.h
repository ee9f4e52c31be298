#pragma once

#include <optional>
#include <string>
#include <vector>

#include "ellipse_collision/app/ellipse_spec.h"
#include "ellipse_collision/core/shape_outline.h"

namespace ellipse_collision::app {

/// One link of a robot model with its collision geometry, already in core types (the ROS layer
/// reads URDFs and meshes into this; see ros/urdf_links.h).
struct LinkGeometry {
  std::string name;                           ///< link name, also its tf frame
  std::vector<core::CollisionShape> shapes;   ///< empty: the link has no collision geometry
  /// Its frame can tilt against the model's root at some joint value (jointChainTilts()).
  bool tilts{false};
};

/// The form of a fitted link: Planar, the minimum-area ellipse of the geometry projected along
/// the link's z axis (right for links that only turn about z: a mobile base); Ellipsoid, the
/// minimum-volume ellipsoid of the geometry in 3D, whose shadow covers the link however its frame
/// tilts at run time (an arm's links); Auto, Ellipsoid for the links that can tilt
/// (LinkGeometry::tilts) and Planar, the tighter fit, for the others.
enum class LinkShape { Auto, Planar, Ellipsoid };

/// The names of the link shapes in configurations and on command lines: "auto", "planar",
/// "ellipsoid".
const char* nameOf(LinkShape shape);
/// The shape called `name` (nameOf()), or nothing.
std::optional<LinkShape> linkShapeNamed(const std::string& name);
/// The accepted names, for messages: "'auto', 'planar' or 'ellipsoid'".
constexpr const char* kLinkShapeNames = "'auto', 'planar' or 'ellipsoid'";

/// What to fit: `links` names the links to fit, in this order (empty: every link of the model, in
/// the model's order); `padding` [m] is written into every fitted entry's own padding field, so
/// the radii stay the exact fit and the margin stays visible in the configuration.
struct LinkFitOptions {
  std::vector<std::string> links;
  double padding{0.0};
  LinkShape shape{LinkShape::Auto};
};

/// The fitted link ellipses, the links that were skipped and why, or an error.
struct LinkFitResult {
  std::vector<EllipseSpec> links;    ///< name = frame = link name, centre/angle/radii in the link frame
  std::vector<std::string> skipped;  ///< "base_footprint: no collision geometry"
  std::string error;                 ///< empty on success; names the link and the problem
  bool ok() const { return error.empty(); }
};

/// Smallest radius [m] given to a link whose projected geometry spans no area (a plate seen
/// edge-on, a cylinder lying along z seen as a point is not one: it has area): the thin ellipse
/// keeps this half-width, small beside any robot part and far above core::kMinRadius.
constexpr double kLinkMinRadius = 1e-4;

/// Why `options` cannot be applied to a model whose links are `model_links` (in model order), or
/// "": padding not finite, < 0 or > core::kMaxRadius; a requested name empty, repeated or not a
/// link of the model ("links[2] = 'gripper': not a link of the robot model").
std::string findLinkSelectionProblem(const std::vector<std::string>& model_links,
                                     const LinkFitOptions& options);

/// The names to fit: options.links, or every model link when it is empty.
std::vector<std::string> selectedLinks(const std::vector<std::string>& model_links,
                                       const LinkFitOptions& options);

/// Fits one ellipse per link with core::fitLinkEllipse() (the minimum-area ellipse containing the
/// link's collision geometry projected along the link's z): links without collision geometry are
/// skipped and reported; a projection that spans no area gets the thin ellipse of
/// core::enclosingEllipseWithMinRadius() with kLinkMinRadius. An invalid shape is an error naming
/// the link. `links` holds exactly the links to fit (selectedLinks()).
///
/// LinkShape::Ellipsoid fits core::fitLinkEllipsoid() instead (EllipseSpec::ellipsoid set; its
/// orientation written as yaw = angle, pitch, roll, then grown by core::growToContain() so that
/// the ellipsoid the fields describe is still certified); a link whose geometry spans no volume (a
/// flat plate) gets the planar fit. LinkShape::Auto fits the links that tilt so and the others
/// planar.
LinkFitResult fitLinkEllipses(const std::vector<LinkGeometry>& links, double padding,
                              LinkShape shape = LinkShape::Auto);

/// The `links:` YAML block of config/ellipse_collision.yaml for `specs`: one flow mapping per
/// entry (ellipsoid links with z, roll, pitch and radius_z too) with every number printed so that it reads back to the same double
/// (core::formatNumber()). `comments` are written as `# ` lines above the block.
std::string linksYaml(const std::vector<EllipseSpec>& specs,
                      const std::vector<std::string>& comments = {});

}  // namespace ellipse_collision::app
