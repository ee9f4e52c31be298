// ellipse_collision/CollisionNodelet: the collision node (ellipse_collision_node) as a nodelet.
#include <pluginlib/class_list_macros.hpp>

#include "ellipse_collision/ros/collision_node.h"
#include "node_nodelet.h"

namespace ellipse_collision {

/// CollisionNode in a nodelet manager: EllipseArray messages published in the same manager (by
/// ScanObstaclesNodelet) reach its ~obstacles as the publisher's shared_ptr, not serialised.
class CollisionNodelet final : public NodeNodelet<CollisionNode> {};

}  // namespace ellipse_collision

PLUGINLIB_EXPORT_CLASS(ellipse_collision::CollisionNodelet, nodelet::Nodelet)
