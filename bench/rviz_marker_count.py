#!/usr/bin/env python3
"""rviz's cost per marker drawn (scripts/rviz_fps.sh --synthetic): MARKERS TRIANGLE_LIST markers
of TRIANGLES tiny triangles each (5 cm, 0.6 m apart on a grid in `map`, so software OpenGL has
next to nothing to rasterise), published once, latched, on the topic the node's markers use.
The same triangles in more markers cost rviz more per frame: one draw call, with its state
changes, per marker.

  rviz_marker_count.py MARKERS TRIANGLES
"""
import math
import sys

import rospy
from geometry_msgs.msg import Point
from std_msgs.msg import ColorRGBA
from visualization_msgs.msg import Marker, MarkerArray

SPACING = 0.6  # [m], as the obstacles of rviz_fps_scene.py
SIZE = 0.05  # [m]


def markers(count, triangles):
    side = int(math.ceil(math.sqrt(count * triangles)))
    array = MarkerArray()
    k = 0
    for i in range(count):
        m = Marker()
        m.header.frame_id = "map"
        m.ns = "obstacles"
        m.id = i
        m.type = Marker.TRIANGLE_LIST
        m.action = Marker.ADD
        m.pose.orientation.w = 1.0
        m.scale.x = m.scale.y = m.scale.z = 1.0
        m.color = ColorRGBA(0.2, 0.8, 0.2, 0.6)
        for _ in range(triangles):
            x, y = (k % side) * SPACING, (k // side) * SPACING
            k += 1
            m.points += [Point(x, y, 0.0), Point(x + SIZE, y, 0.0), Point(x, y + SIZE, 0.0)]
        array.markers.append(m)
    return array


def main():
    count, triangles = (int(a) for a in rospy.myargv()[1:3])
    rospy.init_node("rviz_marker_count")
    publisher = rospy.Publisher("/ellipse_collision/markers", MarkerArray, queue_size=1, latch=True)
    publisher.publish(markers(count, triangles))
    rospy.spin()


if __name__ == "__main__":
    main()
