#!/usr/bin/env python3
"""The scene of the rviz frame-rate measurement (scripts/rviz_fps.sh), as a user's system would
run it: 20 links on their own frames circling through a field of N obstacles in `map`, their
transforms on /tf at 30 Hz; the obstacles sent once on the node's ~obstacles topic (latched). It
also counts what the node publishes on ~markers (messages and serialized bytes) during the
measurement window and writes them as JSON.

  rviz_fps_scene.py --obstacles 10000 --warmup 20 --window 30 --stats out.json
"""
import argparse
import json
import math
import random
import time

import rospy
import tf2_msgs.msg
from geometry_msgs.msg import TransformStamped
from ellipse_collision.msg import Ellipse, EllipseArray

LINKS = 20
SPACING = 0.6  # obstacle grid [m]


def grid_side(count):
    return int(math.ceil(math.sqrt(count)))


def obstacles(count):
    rng = random.Random(16)
    side = grid_side(count)
    msg = EllipseArray()
    msg.header.frame_id = "map"
    for i in range(count):
        e = Ellipse()
        e.name = "obstacle_%d" % i
        e.x = (i % side) * SPACING
        e.y = (i // side) * SPACING
        e.angle = rng.uniform(0, math.pi)
        e.radius_x = rng.uniform(0.1, 0.2)
        e.radius_y = rng.uniform(0.05, 0.1)
        msg.ellipses.append(e)
    return msg


def link_transforms(t, count):
    """Link i circles about a point of the field at 0.2 rad/s (about 2 m/s on the outer circles)."""
    side = grid_side(count) * SPACING
    transforms = []
    for i in range(LINKS):
        centre_x = side * (0.25 + 0.5 * (i % 4) / 3.0)
        centre_y = side * (0.25 + 0.5 * (i // 4) / 4.0)
        radius = 1.0 + 0.25 * i
        phase = 0.2 * t + i
        tf = TransformStamped()
        tf.header.frame_id = "map"
        tf.child_frame_id = "link_%d" % i
        tf.transform.translation.x = centre_x + radius * math.cos(phase)
        tf.transform.translation.y = centre_y + radius * math.sin(phase)
        tf.transform.rotation.z = math.sin(phase / 2)
        tf.transform.rotation.w = math.cos(phase / 2)
        transforms.append(tf)
    return transforms


class ByteCounter:
    def __init__(self):
        self.messages = 0
        self.bytes = 0
        self.counting = False

    def __call__(self, msg):
        if self.counting:
            self.messages += 1
            self.bytes += len(msg._buff)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--obstacles", type=int, default=10000)
    parser.add_argument("--warmup", type=float, default=20.0)
    parser.add_argument("--window", type=float, default=30.0)
    parser.add_argument("--stats", required=True)
    parser.add_argument("--still", action="store_true", help="links stand still: no marker changes")
    args = parser.parse_args(rospy.myargv()[1:])
    rospy.init_node("rviz_fps_scene")
    tf_pub = rospy.Publisher("/tf", tf2_msgs.msg.TFMessage, queue_size=10)
    obstacles_pub = rospy.Publisher("/ellipse_collision/obstacles", EllipseArray, queue_size=1, latch=True)
    counter = ByteCounter()
    rospy.Subscriber("/ellipse_collision/markers", rospy.AnyMsg, counter, queue_size=1000)
    obstacles_pub.publish(obstacles(args.obstacles))
    rate = rospy.Rate(30)
    start = time.monotonic()
    while not rospy.is_shutdown():
        now = time.monotonic() - start
        stamp = rospy.Time.now()
        transforms = link_transforms(0.0 if args.still else now, args.obstacles)
        for tf in transforms:
            tf.header.stamp = stamp
        tf_pub.publish(tf2_msgs.msg.TFMessage(transforms))
        if now >= args.warmup and not counter.counting and counter.messages == 0:
            counter.counting = True
            window_start = time.monotonic()
        if counter.counting and time.monotonic() - window_start >= args.window:
            counter.counting = False
            with open(args.stats, "w") as out:
                json.dump({"marker_messages": counter.messages, "marker_bytes": counter.bytes,
                           "window_s": time.monotonic() - window_start}, out)
        rate.sleep()


if __name__ == "__main__":
    main()
