#include "ellipse_collision/ros/urdf_links.h"

#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <ros/param.h>
#include <resource_retriever/retriever.h>
#include <urdf/model.h>

#include <assimp/Importer.hpp>
#include <fstream>
#include <sstream>

#include "ellipse_collision/app/joint_chain.h"

namespace ellipse_collision {
namespace {

urdf::Model parseModel(const std::string& urdf_xml, const std::string& source) {
  urdf::Model model;
  // urdfdom prints the parser's reason through console_bridge just before this.
  if (!model.initString(urdf_xml)) {
    throw UrdfError(source + ": not a valid URDF robot description (see the urdfdom error above)");
  }
  return model;
}

Eigen::Isometry3d toIsometry(const urdf::Pose& pose) {
  Eigen::Isometry3d result = Eigen::Isometry3d::Identity();
  result.linear() = Eigen::Quaterniond(pose.rotation.w, pose.rotation.x, pose.rotation.y,
                                       pose.rotation.z)
                        .normalized()
                        .toRotationMatrix();
  result.translation() = Eigen::Vector3d(pose.position.x, pose.position.y, pose.position.z);
  return result;
}

/// The extension of `uri` as assimp's format hint ("stl"), or "".
std::string extensionOf(const std::string& uri) {
  const std::size_t dot = uri.find_last_of('.');
  if (dot == std::string::npos || uri.find('/', dot) != std::string::npos) return "";
  return uri.substr(dot + 1);
}

/// The root node's transform as rviz draws meshes: its scale and translation, not its rotation
/// (rviz 1.14's mesh_loader.cpp, buildMesh(), the rviz Debian 12 ships; MoveIt's geometric_shapes
/// drops that rotation too). assimp 5.2's Collada importer puts the file's <unit meter> into the
/// root node as a scale and, for a Z_UP or X_UP file, a turn to Y-up: kept, it would lay a part
/// authored Z_UP on its side. So <up_axis> is ignored and <unit> applied, as by rviz; Y_UP
/// Collada, STL and OBJ have no root rotation and read as before.
aiMatrix4x4 rootTransformAsRvizDrawsIt(const aiMatrix4x4& root) {
  aiVector3D scaling;
  aiVector3D position;
  aiQuaternion rotation;
  root.Decompose(scaling, rotation, position);
  return aiMatrix4x4(scaling, aiQuaternion(), position);
}

/// Appends the vertices of `node` and its descendants, `mesh_from_node` being `node`'s transform
/// into the mesh file's frame, each vertex scaled by `scale` (the URDF scale) afterwards.
void collectVertices(const aiScene& scene, const aiNode& node, const aiMatrix4x4& mesh_from_node,
                     const Eigen::Vector3d& scale, std::vector<Eigen::Vector3d>& out) {
  for (unsigned m = 0; m < node.mNumMeshes; ++m) {
    const aiMesh& mesh = *scene.mMeshes[node.mMeshes[m]];
    for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
      const aiVector3D p = mesh_from_node * mesh.mVertices[v];
      out.emplace_back(scale.x() * p.x, scale.y() * p.y, scale.z() * p.z);
    }
  }
  for (unsigned c = 0; c < node.mNumChildren; ++c) {
    const aiNode& child = *node.mChildren[c];
    collectVertices(scene, child, mesh_from_node * child.mTransformation, scale, out);
  }
}

/// The mesh's vertices in the shape frame [m] where rviz draws them, URDF scale applied.
std::vector<Eigen::Vector3d> loadMeshVertices(const urdf::Mesh& mesh, const std::string& where) {
  const std::string& uri = mesh.filename;
  resource_retriever::MemoryResource resource;
  try {
    resource = resource_retriever::Retriever().get(uri);
  } catch (const resource_retriever::Exception& error) {
    throw UrdfError(where + ": cannot read mesh '" + uri + "': " + error.what());
  }
  Assimp::Importer importer;
  // Node transforms are applied by the traversal below; nothing that moves vertices is asked for.
  const aiScene* scene = importer.ReadFileFromMemory(resource.data.get(), resource.size,
                                                     aiProcess_SortByPType, extensionOf(uri).c_str());
  if (scene == nullptr || scene->mRootNode == nullptr) {
    throw UrdfError(where + ": cannot load mesh '" + uri + "': " + importer.GetErrorString());
  }
  std::vector<Eigen::Vector3d> vertices;
  collectVertices(*scene, *scene->mRootNode,
                  rootTransformAsRvizDrawsIt(scene->mRootNode->mTransformation),
                  Eigen::Vector3d(mesh.scale.x, mesh.scale.y, mesh.scale.z), vertices);
  if (vertices.empty()) throw UrdfError(where + ": mesh '" + uri + "' has no vertices");
  return vertices;
}

core::CollisionShape toShape(const urdf::Collision& collision, const std::string& where) {
  core::CollisionShape shape;
  shape.link_from_shape = toIsometry(collision.origin);
  const urdf::Geometry* geometry = collision.geometry.get();
  if (geometry == nullptr) throw UrdfError(where + ": collision element without geometry");
  switch (geometry->type) {
    case urdf::Geometry::BOX: {
      const auto& box = static_cast<const urdf::Box&>(*geometry);
      shape.type = core::CollisionShape::Box;
      shape.box_size = Eigen::Vector3d(box.dim.x, box.dim.y, box.dim.z);
      break;
    }
    case urdf::Geometry::CYLINDER: {
      const auto& cylinder = static_cast<const urdf::Cylinder&>(*geometry);
      shape.type = core::CollisionShape::Cylinder;
      shape.radius = cylinder.radius;
      shape.length = cylinder.length;
      break;
    }
    case urdf::Geometry::SPHERE:
      shape.type = core::CollisionShape::Sphere;
      shape.radius = static_cast<const urdf::Sphere&>(*geometry).radius;
      break;
    case urdf::Geometry::MESH:
      shape.type = core::CollisionShape::Mesh;
      shape.mesh_vertices = loadMeshVertices(static_cast<const urdf::Mesh&>(*geometry), where);
      break;
    default:
      throw UrdfError(where + ": unsupported collision geometry type " +
                      std::to_string(static_cast<int>(geometry->type)));
  }
  if (const std::string invalid = core::invalidReason(shape); !invalid.empty()) {
    throw UrdfError(where + ": " + invalid);
  }
  return shape;
}

/// The joints from the model's root down to `link`, root first, as app::jointChainTilts() reads
/// them.
std::vector<app::ChainJoint> chainFromRoot(const urdf::Model& model, const urdf::LinkConstSharedPtr& link) {
  std::vector<app::ChainJoint> chain;
  for (urdf::LinkConstSharedPtr at = link; at && at->parent_joint;
       at = model.getLink(at->parent_joint->parent_link_name)) {
    const urdf::Joint& joint = *at->parent_joint;
    app::ChainJoint step;
    step.origin_rotation = toIsometry(joint.parent_to_joint_origin_transform).linear();
    step.axis = Eigen::Vector3d(joint.axis.x, joint.axis.y, joint.axis.z);
    switch (joint.type) {
      case urdf::Joint::FIXED:
        step.motion = app::ChainJoint::Motion::Fixed;
        break;
      case urdf::Joint::REVOLUTE:
      case urdf::Joint::CONTINUOUS:
        step.motion = app::ChainJoint::Motion::Revolute;
        break;
      case urdf::Joint::PRISMATIC:
        step.motion = app::ChainJoint::Motion::Prismatic;
        break;
      default:  // floating, planar, unknown
        step.motion = app::ChainJoint::Motion::Free;
        break;
    }
    chain.insert(chain.begin(), step);
  }
  return chain;
}

std::vector<std::string> namesOf(const urdf::Model& model) {
  std::vector<std::string> names;
  for (const auto& entry : model.links_) names.push_back(entry.first);  // std::map: sorted
  return names;
}

}  // namespace

std::string readUrdfFile(const std::string& path) {
  std::ifstream file(path);
  if (!file) throw UrdfError("file '" + path + "': cannot be opened");
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

std::string readUrdfParam(const std::string& param) {
  std::string xml;
  if (!ros::param::get(param, xml)) {
    throw UrdfError("parameter '" + param +
                    "': not set or not a string (load the URDF there, e.g. with xacro as for "
                    "robot_state_publisher)");
  }
  return xml;
}

std::vector<std::string> urdfLinkNames(const std::string& urdf_xml, const std::string& source) {
  return namesOf(parseModel(urdf_xml, source));
}

std::vector<app::LinkGeometry> readUrdfLinks(const std::string& urdf_xml, const std::string& source,
                                             const std::vector<std::string>& names) {
  const urdf::Model model = parseModel(urdf_xml, source);
  std::vector<app::LinkGeometry> links;
  for (const std::string& name : names.empty() ? namesOf(model) : names) {
    const auto link = model.getLink(name);
    if (!link) throw UrdfError(source + ": '" + name + "' is not a link of the robot model");
    app::LinkGeometry geometry{name, {}, app::jointChainTilts(chainFromRoot(model, link))};
    // urdfdom puts the single <collision> into collision_array as well.
    for (std::size_t i = 0; i < link->collision_array.size(); ++i) {
      const std::string where =
          source + ", link '" + name + "', collision[" + std::to_string(i) + "]";
      geometry.shapes.push_back(toShape(*link->collision_array[i], where));
    }
    links.push_back(std::move(geometry));
  }
  return links;
}

app::LinkFitResult fitUrdfLinks(const std::string& urdf_xml, const std::string& source,
                                const app::LinkFitOptions& options) {
  const std::vector<std::string> model_links = urdfLinkNames(urdf_xml, source);
  if (const std::string problem = app::findLinkSelectionProblem(model_links, options);
      !problem.empty()) {
    throw UrdfError(source + ": " + problem);
  }
  app::LinkFitResult result = app::fitLinkEllipses(
      readUrdfLinks(urdf_xml, source, app::selectedLinks(model_links, options)), options.padding,
      options.shape);
  if (!result.ok()) throw UrdfError(source + ": " + result.error);
  return result;
}

app::LinkFitResult fitUrdfLinksFromParam(const std::string& param,
                                         const app::LinkFitOptions& options) {
  return fitUrdfLinks(readUrdfParam(param), "parameter '" + param + "'", options);
}

}  // namespace ellipse_collision
