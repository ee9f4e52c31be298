#!/usr/bin/env python3
"""A rospy client of ellipse_collision_node: adds an obstacle, checks it and prints the answers.

Run it against the node started with the example configuration:
    roslaunch ellipse_collision ellipse_collision.launch
    rosrun ellipse_collision check_collisions_client.py [--node /ellipse_collision]

It calls ~add_obstacles with a 0.2 m circle named `box` 0.6 m ahead of base_link, then
~check_collisions for that name (every pair with `box`, plus its nearest partner), and prints
both answers. The exit status is 0 when both calls succeeded.
"""
import argparse
import sys

import rospy
from ellipse_collision.msg import Ellipse
from ellipse_collision.srv import AddObstacles, AddObstaclesRequest
from ellipse_collision.srv import CheckCollisions, CheckCollisionsRequest


def call(node, name, service_class, request, timeout_s):
    """Waits for the service `node`/`name`, calls it and returns the response."""
    service = node.rstrip("/") + "/" + name
    rospy.wait_for_service(service, timeout=timeout_s)
    return rospy.ServiceProxy(service, service_class)(request)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--node", default="/ellipse_collision",
                        help="the node's name (default /ellipse_collision)")
    parser.add_argument("--timeout", type=float, default=10.0,
                        help="how long to wait for each service [s] (default 10)")
    args = parser.parse_args(rospy.myargv()[1:])
    rospy.init_node("check_collisions_client", anonymous=True)

    box = Ellipse(name="box", frame_id="base_link", x=0.6, y=0.0, angle=0.0,
                  radius_x=0.2, radius_y=0.2, padding=0.0)
    added = call(args.node, "add_obstacles", AddObstacles,
                 AddObstaclesRequest(obstacles=[box]), args.timeout)
    print("add_obstacles: success=%s message=%r" % (added.success, added.message))

    checked = call(args.node, "check_collisions", CheckCollisions,
                   CheckCollisionsRequest(names=["box"], min_distance_of="box"), args.timeout)
    print("check_collisions: success=%s in_collision=%s message=%r"
          % (checked.success, checked.in_collision, checked.message))
    for pair in checked.collisions:
        print("  collision %s - %s, contact_scale %.6f" % (pair.name_a, pair.name_b,
                                                           pair.contact_scale))
    for pair in checked.warnings:
        print("  warning   %s - %s, distance %.6f m" % (pair.name_a, pair.name_b, pair.distance))
    if checked.has_min_distance:
        print("  nearest to %s: %s at %.6f m" % (checked.nearest.name_a, checked.nearest.name_b,
                                                  checked.nearest.distance))
    for frame in checked.unavailable_frames:
        print("  frame unavailable: %s" % frame)
    return 0 if added.success and checked.success else 1


if __name__ == "__main__":
    sys.exit(main())
