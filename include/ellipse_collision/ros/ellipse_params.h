#pragma once

#include <xmlrpcpp/XmlRpcValue.h>

#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "ellipse_collision/app/ellipse_spec.h"
#include "ellipse_collision/app/link_fitting.h"

namespace ellipse_collision {

/// Fits the link ellipses of `links_from_urdf`: the URDF in parameter `param`, the links and
/// padding of `options`. Throws a std::runtime_error naming the parameter (or link, mesh URI) on
/// failure. The node passes ros/urdf_links.h's reader (urdfLinkFitter()); tests pass their own.
using UrdfLinkFitter =
    std::function<app::LinkFitResult(const std::string& param, const app::LinkFitOptions& options)>;

/// Parses a list of ellipses as the node's `links` and `obstacles` are given: each entry a dict
/// {name, frame, x, y, angle, radius_x, radius_y, padding (optional)} [m, rad], its fields checked
/// with app::findInvalidPaddedField() and `global_padding` [m]. `key` names the list in messages
/// (`key[i]`). Names are not checked against each other. Throws ConfigError naming the entry, the
/// key, expected and actual value.
std::vector<app::EllipseSpec> parseEllipseList(const XmlRpc::XmlRpcValue& list,
                                               const std::string& key, double global_padding);

namespace params {

/// `allowed_pairs`: a list of [name_a, name_b], each a name in `defined` (name -> the entry that
/// defines it), the two different.
std::vector<std::pair<std::string, std::string>> readAllowedPairs(
    const XmlRpc::XmlRpcValue& list, const std::map<std::string, std::string>& defined);

/// `links_from_urdf: {param, links, padding, shape}` -> the ellipses `fit_urdf_links` fits.
app::LinkFitResult readLinksFromUrdf(const XmlRpc::XmlRpcValue& value,
                                     const UrdfLinkFitter& fit_urdf_links);

}  // namespace params
}  // namespace ellipse_collision
