#!/usr/bin/env python3
"""The node as a user runs it (issue 16): 20 links on their own tf frames moving at 30 Hz, N
obstacles in `map` (added through ~add_obstacles, or with --stream HZ published on ~obstacles at HZ
as a perception node would, each message moving them a little), warnings on, a subscriber on
~markers as rviz would be. Measures the node's CPU (% of one core, utime + stime from /proc/<pid>/stat) and RSS
over a window after a warm-up, and prints one line:

  obstacles=N rate=R cpu_percent=C rss_mb=M markers_per_s=K checks_per_s=S

Usage (roscore and the node running, the node's ~links on frames link_0..link_19 in `map`):
  node_load.py --node /ellipse_collision --pid PID --obstacles N [--seconds 20] [--warmup 3]
               [--no-markers] [--stream HZ] [--stream-frame FRAME]

--stream-frame puts the streamed obstacles in FRAME instead of `map`, e.g. link_0: a sensor on
the moving robot, whose obstacles move with it in `map` and are all placed anew every check.
"""
import argparse
import math
import os
import random
import sys
import threading
import time

import rospy
from geometry_msgs.msg import TransformStamped
from tf2_msgs.msg import TFMessage
from visualization_msgs.msg import MarkerArray

from ellipse_collision.msg import CollisionState, Ellipse, EllipseArray
from ellipse_collision.srv import AddObstacles

LINKS = 20
TF_RATE_HZ = 30.0
WORLD_M = 50.0  # obstacles' centres in [-25, 25]^2 m; the robot moves near the origin


def cpu_seconds(pid):
    with open(f"/proc/{pid}/stat") as f:
        fields = f.read().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")  # utime + stime


def rss_mb(pid):
    with open(f"/proc/{pid}/status") as f:
        for line in f:
            if line.startswith("VmRSS:"):
                return int(line.split()[1]) / 1024.0
    return float("nan")


def publish_tf(stop):
    # What tf2_ros.TransformBroadcaster does (Debian has no python3 tf2_ros): publish on /tf.
    publisher = rospy.Publisher("/tf", TFMessage, queue_size=10)
    rate = rospy.Rate(TF_RATE_HZ)
    start = time.time()
    while not stop.is_set() and not rospy.is_shutdown():
        t = time.time() - start
        now = rospy.Time.now()
        msgs = []
        for i in range(LINKS):
            m = TransformStamped()
            m.header.stamp = now
            m.header.frame_id = "map"
            m.child_frame_id = f"link_{i}"
            phase = 0.5 * t + 2 * math.pi * i / LINKS
            m.transform.translation.x = 0.5 * t % 10.0 - 5.0 + 0.8 * math.cos(phase)
            m.transform.translation.y = 0.8 * math.sin(phase)
            m.transform.rotation.z = math.sin(phase / 2)
            m.transform.rotation.w = math.cos(phase / 2)
            msgs.append(m)
        publisher.publish(TFMessage(transforms=msgs))
        rate.sleep()


def random_obstacles(count, rng, frame_id="map"):
    obstacles = []
    for i in range(count):
        obstacles.append(Ellipse(name=f"obstacle_{i}", frame_id=frame_id,
                                 x=rng.uniform(-WORLD_M / 2, WORLD_M / 2),
                                 y=rng.uniform(-WORLD_M / 2, WORLD_M / 2),
                                 angle=rng.uniform(-3.14, 3.14), radius_x=rng.uniform(0.05, 0.3),
                                 radius_y=rng.uniform(0.02, 0.05)))
    return obstacles


def stream_obstacles(node, count, rate_hz, frame_id, rng, stop):
    # A perception node's output: the same obstacles, moved by a few millimetres from one message
    # to the next (two alternating arrays, built once, so that this script's own CPU stays low).
    publisher = rospy.Publisher(node + "/obstacles", EllipseArray, queue_size=1)
    first = random_obstacles(count, rng, frame_id)
    second = [Ellipse(name=e.name, frame_id=e.frame_id, x=e.x + 0.003, y=e.y - 0.002,
                      angle=e.angle, radius_x=e.radius_x, radius_y=e.radius_y) for e in first]
    arrays = [EllipseArray(ellipses=first), EllipseArray(ellipses=second)]
    rate = rospy.Rate(rate_hz)
    sent = 0
    while not stop.is_set() and not rospy.is_shutdown():
        array = arrays[sent % 2]
        array.header.stamp = rospy.Time.now()
        array.header.frame_id = frame_id
        publisher.publish(array)
        sent += 1
        rate.sleep()


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--node", default="/ellipse_collision")
    parser.add_argument("--pid", type=int, required=True)
    parser.add_argument("--obstacles", type=int, required=True)
    parser.add_argument("--seconds", type=float, default=20.0)
    parser.add_argument("--warmup", type=float, default=3.0)
    parser.add_argument("--no-markers", action="store_true",
                        help="no ~markers subscriber: the node's own cycle without marker output")
    parser.add_argument("--stream", type=float, default=0.0, metavar="HZ",
                        help="publish the obstacles on ~obstacles at HZ instead of adding them once")
    parser.add_argument("--stream-frame", default="map", metavar="FRAME",
                        help="the streamed obstacles' frame (map, or link_0..link_19)")
    args = parser.parse_args(rospy.myargv()[1:])
    rospy.init_node("node_load", anonymous=True)

    stop = threading.Event()
    tf_thread = threading.Thread(target=publish_tf, args=(stop,), daemon=True)
    tf_thread.start()

    rng = random.Random(16)
    if args.stream > 0:
        stream_thread = threading.Thread(
            target=stream_obstacles,
            args=(args.node, args.obstacles, args.stream, args.stream_frame, rng, stop),
            daemon=True)
        stream_thread.start()
    else:
        rospy.wait_for_service(args.node + "/add_obstacles", timeout=30)
        add = rospy.ServiceProxy(args.node + "/add_obstacles", AddObstacles)
        everything = random_obstacles(args.obstacles, rng)
        chunk = 10000
        for first in range(0, args.obstacles, chunk):
            answer = add(everything[first:first + chunk])
            if not answer.success:
                sys.exit(f"~add_obstacles refused: {answer.message}")

    counts = {"markers": 0, "checks": 0}
    if not args.no_markers:
        rospy.Subscriber(args.node + "/markers", MarkerArray,
                         lambda _: counts.__setitem__("markers", counts["markers"] + 1),
                         queue_size=1, buff_size=2 ** 26)
    rospy.Subscriber(args.node + "/collisions", CollisionState,
                     lambda _: counts.__setitem__("checks", counts["checks"] + 1), queue_size=1)
    time.sleep(args.warmup)
    cpu0, markers0, checks0, t0 = cpu_seconds(args.pid), counts["markers"], counts["checks"], time.time()
    time.sleep(args.seconds)
    cpu1, t1 = cpu_seconds(args.pid), time.time()
    elapsed = t1 - t0
    stream = f"stream_hz={args.stream:g} stream_frame={args.stream_frame} " if args.stream > 0 else ""
    print(f"obstacles={args.obstacles} {stream}cpu_percent={100.0 * (cpu1 - cpu0) / elapsed:.1f} "
          f"rss_mb={rss_mb(args.pid):.1f} markers_per_s={(counts['markers'] - markers0) / elapsed:.1f} "
          f"checks_per_s={(counts['checks'] - checks0) / elapsed:.1f}", flush=True)
    stop.set()


if __name__ == "__main__":
    main()
