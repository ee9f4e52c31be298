#!/usr/bin/env python3
"""A fleet on one master, for scripts/fleet_load.sh: N collision nodes in namespaces r1..rN, each
with L links, publishing itself on /fleet/footprints (the defaults) and taking the others in
through a robots source, checking at 10 Hz with a 2 s prediction horizon. This process moves
every robot on a circle of its own (tf map -> r<k>/base_link at 30 Hz), counts the footprint
traffic (messages and bytes on /fleet/footprints, as serialised) and measures each node's CPU in
% of one core from /proc/<pid>/stat over the window. Prints one line per node count."""
import argparse
import math
import os
import statistics
import subprocess
import sys
import tempfile
import threading
import time

import rospy
from geometry_msgs.msg import TransformStamped
from diagnostic_msgs.msg import DiagnosticArray
from tf2_msgs.msg import TFMessage

CLK_TCK = os.sysconf("SC_CLK_TCK")


def node_yaml(robot, links, fleet):
    lines = [
        "fixed_frame: map",
        f"robot_frame: {robot}/base_link",
        "rate: 10.0",
        "prediction_horizon: 2.0",
        "self_collision: false",
        'obstacle_store: ""',
    ]
    if fleet:
        lines += ["sources:", "  - {name: robots, type: robots, timeout: 1.0}"]
    else:
        lines += ["fleet: {enabled: false}"]
    lines.append("links:")
    for k in range(links):
        # L circles along the robot, 1 m long in all.
        x = -0.5 + (k + 0.5) / links
        lines.append(f"  - {{name: link_{k}, frame: {robot}/base_link, x: {x:.4f}, y: 0.0, "
                     "angle: 0.0, radius_x: 0.3, radius_y: 0.3}")
    return "\n".join(lines) + "\n"


def cpu_seconds(pid):
    with open(f"/proc/{pid}/stat") as f:
        fields = f.read().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / CLK_TCK  # utime, stime


class SeenByR1:
    """How many other robots r1's robots source keeps (its /diagnostics fleet status)."""

    def __init__(self):
        self.robots = None
        self.sub = rospy.Subscriber("/diagnostics", DiagnosticArray, self.on_message)

    def on_message(self, msg):
        for status in msg.status:
            if status.name != "/r1/ellipse_collision: fleet":
                continue
            for kv in status.values:
                if kv.key == "source 'robots' robots":
                    self.robots = 0 if kv.value == "none" else len(kv.value.split("), "))


class Traffic:
    def __init__(self, topic):
        self.lock = threading.Lock()
        self.messages = 0
        self.bytes = 0
        self.sub = rospy.Subscriber(topic, rospy.AnyMsg, self.on_message, queue_size=1000)

    def on_message(self, msg):
        with self.lock:
            self.messages += 1
            self.bytes += len(msg._buff)

    def take(self):
        with self.lock:
            out = (self.messages, self.bytes)
            self.messages = self.bytes = 0
            return out


def run(node_bin, robots, links, seconds, warmup, workdir, fleet):
    names = [f"r{k + 1}" for k in range(robots)]
    procs = []
    for name in names:
        path = os.path.join(workdir, f"{name}.yaml")
        with open(path, "w") as f:
            f.write(node_yaml(name, links, fleet))
        # A fresh namespace: the previous run's keys (fleet off, sources) must not linger.
        subprocess.run(["rosparam", "delete", f"/{name}/ellipse_collision"],
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        subprocess.run(["rosparam", "load", path, f"/{name}/ellipse_collision"], check=True)
        procs.append(subprocess.Popen(
            [node_bin, f"__ns:=/{name}", "__name:=ellipse_collision"],
            stdout=subprocess.DEVNULL, stderr=open(os.path.join(workdir, f"{name}.log"), "w")))
    tf_pub = rospy.Publisher("/tf", TFMessage, queue_size=10)
    traffic = Traffic("/fleet/footprints")
    seen = SeenByR1()
    stop = threading.Event()

    def move():
        rate = rospy.Rate(30)
        start = time.time()
        while not stop.is_set() and not rospy.is_shutdown():
            t = time.time() - start
            stamp = rospy.Time.now()
            out = []
            for k, name in enumerate(names):
                # Robots 4 m apart on a grid, each on a 1 m circle at 0.5 m/s.
                cx, cy = 4.0 * (k % 5), 4.0 * (k // 5)
                a = 0.5 * t + k
                msg = TransformStamped()
                msg.header.stamp = stamp
                msg.header.frame_id = "map"
                msg.child_frame_id = f"{name}/base_link"
                msg.transform.translation.x = cx + math.cos(a)
                msg.transform.translation.y = cy + math.sin(a)
                yaw = a + math.pi / 2
                msg.transform.rotation.z = math.sin(yaw / 2)
                msg.transform.rotation.w = math.cos(yaw / 2)
                out.append(msg)
            tf_pub.publish(TFMessage(transforms=out))
            rate.sleep()

    mover = threading.Thread(target=move, daemon=True)
    mover.start()
    try:
        time.sleep(warmup)
        traffic.take()
        before = [cpu_seconds(p.pid) for p in procs]
        t0 = time.time()
        time.sleep(seconds)
        elapsed = time.time() - t0
        after = [cpu_seconds(p.pid) for p in procs]
        messages, size = traffic.take()
        alive = [p.poll() is None for p in procs]
    finally:
        stop.set()
        mover.join()
        traffic.sub.unregister()
        seen.sub.unregister()
        for p in procs:
            p.terminate()
        for p in procs:
            p.wait(timeout=10)
    shares = [100.0 * (a - b) / elapsed for a, b in zip(after, before)]
    if not all(alive):
        print(f"{robots} robots: a node died, see {workdir}", file=sys.stderr)
        sys.exit(1)
    print(f"{'fleet' if fleet else 'alone'}: robots {robots} links {links}: node CPU median {statistics.median(shares):.2f} % "
          f"(min {min(shares):.2f}, max {max(shares):.2f}) of one core, all nodes "
          f"{sum(shares):.1f} %; footprints {messages / elapsed:.1f} msg/s, "
          f"{size / elapsed / 1000.0:.1f} kB/s ({size / max(messages, 1):.0f} B each); r1 keeps "
          f"{seen.robots} other robots",
          flush=True)


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--node", required=True, help="the ellipse_collision_node binary")
    parser.add_argument("--robots", type=int, nargs="+", default=[8, 20])
    parser.add_argument("--links", type=int, default=20)
    parser.add_argument("--seconds", type=float, default=20.0)
    parser.add_argument("--warmup", type=float, default=5.0)
    parser.add_argument("--runs", type=int, default=1)
    parser.add_argument("--alone", action="store_true",
                        help="also each run without the fleet (fleet off, no robots source)")
    args = parser.parse_args()
    rospy.init_node("fleet_load", anonymous=True, disable_signals=True)
    with tempfile.TemporaryDirectory() as workdir:
        for _ in range(args.runs):
            for robots in args.robots:
                run(args.node, robots, args.links, args.seconds, args.warmup, workdir, True)
                if args.alone:
                    run(args.node, robots, args.links, args.seconds, args.warmup, workdir, False)


if __name__ == "__main__":
    main()
