// ellipse_collision/ScanObstaclesNodelet: scan_obstacles as a nodelet.
#include <pluginlib/class_list_macros.hpp>

#include "ellipse_collision/ros/scan_obstacles.h"
#include "node_nodelet.h"

namespace ellipse_collision {

/// ScanObstaclesNode in a nodelet manager: a LaserScan published in the same manager arrives
/// without a copy, and its obstacles go to a collision nodelet there the same way.
class ScanObstaclesNodelet final : public NodeNodelet<ScanObstaclesNode> {};

}  // namespace ellipse_collision

PLUGINLIB_EXPORT_CLASS(ellipse_collision::ScanObstaclesNodelet, nodelet::Nodelet)
