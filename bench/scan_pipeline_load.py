#!/usr/bin/env python3
"""The scan pipeline under a 720-beam LaserScan at 40 Hz (issue 33), started by
scripts/nodelet_cpu.sh as separate processes or as nodelets in one manager. Publishes
base_link -> laser on /tf_static and the scans on /scan (a room with posts, a wall and a box that
moves past the arm, a new position every scan, range noise), waits until the collision node's
~check_collisions names scanned obstacles, measures the CPU (% of one core, utime + stime from
/proc/<pid>/stat) of each given node over the window, checks the obstacles are still fresh after
it, and prints one line:

  mode=M scans_per_s=S total=C /node_a=A /node_b=B ...

No subscriber of its own on the obstacle ellipses: in one manager they would have to be
serialised for it, which is the very cost measured. --median FILE prints the medians per mode of
the lines in FILE, side by side.

Usage (roscore and the pipeline running, the collision node at /ellipse_collision):
  scan_pipeline_load.py --mode M --nodes /ellipse_collision /scan_obstacles [--seconds 30]
                        [--warmup 5]
  scan_pipeline_load.py --median FILE
"""
import argparse
import math
import random
import statistics
import sys
import time
import xmlrpc.client

BEAMS = 720
SCAN_HZ = 40.0
LASER_X = 0.2  # the scanner, 0.2 m ahead of base_link
RANGE_MAX = 10.0
NOISE_M = 0.005
CYCLE = 80  # distinct scans: the box's path takes 2 s and repeats


def circles_at(step):
    """(x, y, r) of the posts and the moving box (a circle) in the laser frame at `step`."""
    posts = [(3.0, 2.0, 0.15), (3.0, -2.0, 0.15), (-2.0, 2.5, 0.2), (-2.5, -1.5, 0.25),
             (1.0, 3.0, 0.1), (5.0, 0.5, 0.3)]
    phase = 2.0 * math.pi * step / CYCLE
    return posts + [(1.6 + 0.4 * math.cos(phase), 1.2 * math.sin(phase), 0.25)]


def ray(angle, circles):
    dx, dy = math.cos(angle), math.sin(angle)
    best = RANGE_MAX + 1.0
    for cx, cy, r in circles:
        b = dx * cx + dy * cy
        disc = b * b - (cx * cx + cy * cy - r * r)
        if disc >= 0.0 and b - math.sqrt(disc) > 0.0:
            best = min(best, b - math.sqrt(disc))
    if dx > 1e-9:  # a wall at x = 6 m
        best = min(best, 6.0 / dx)
    return best


def make_scans():
    from sensor_msgs.msg import LaserScan
    rng = random.Random(33)
    scans = []
    for step in range(CYCLE):
        scan = LaserScan()
        scan.header.frame_id = "laser"
        scan.angle_min = -math.pi
        scan.angle_increment = 2.0 * math.pi / BEAMS
        scan.angle_max = scan.angle_min + (BEAMS - 1) * scan.angle_increment
        scan.range_min = 0.05
        scan.range_max = RANGE_MAX
        scan.scan_time = 1.0 / SCAN_HZ
        circles = circles_at(step)
        ranges = []
        for i in range(BEAMS):
            r = ray(scan.angle_min + i * scan.angle_increment, circles)
            ranges.append(float("inf") if r > RANGE_MAX else r + rng.gauss(0.0, NOISE_M))
        scan.ranges = ranges
        scans.append(scan)
    return scans


def node_pid(master, caller, name):
    code, message, uri = master.lookupNode(caller, name)
    if code != 1:
        raise RuntimeError(f"node {name}: {message}")
    code, message, pid = xmlrpc.client.ServerProxy(uri).getPid(caller)
    if code != 1:
        raise RuntimeError(f"node {name}: {message}")
    return pid


def measure(args):
    import rosgraph
    import rospy
    from node_load import cpu_seconds  # the one /proc/<pid>/stat reader of the benches
    from geometry_msgs.msg import TransformStamped
    from sensor_msgs.msg import LaserScan
    from tf2_msgs.msg import TFMessage
    from ellipse_collision.msg import Ellipse
    from ellipse_collision.srv import CheckCollisions, CheckCollisionsRequest

    rospy.init_node("scan_pipeline_load", disable_signals=True)
    master = xmlrpc.client.ServerProxy(rosgraph.get_master_uri())
    pids = {name: node_pid(master, rospy.get_name(), name) for name in args.nodes}

    static = TransformStamped()
    static.header.frame_id = "base_link"
    static.child_frame_id = "laser"
    static.transform.translation.x = LASER_X
    static.transform.rotation.w = 1.0
    tf_pub = rospy.Publisher("/tf_static", TFMessage, queue_size=1, latch=True)
    tf_pub.publish(TFMessage([static]))
    scan_pub = rospy.Publisher("/scan", LaserScan, queue_size=1)
    scans = make_scans()

    rospy.wait_for_service("/ellipse_collision/check_collisions", timeout=30.0)
    check = rospy.ServiceProxy("/ellipse_collision/check_collisions", CheckCollisions)

    def scanned_obstacles_checked():
        # A probe ellipse over the whole room collides with every stored obstacle: the scanned
        # ones are named scan_<beam>.
        probe = Ellipse(name="probe", frame_id="laser", x=0.0, y=0.0, angle=0.0,
                        radius_x=20.0, radius_y=20.0)
        response = check(CheckCollisionsRequest(query=[probe]))
        return response.success and any(
            p.name_a.startswith("scan_") or p.name_b.startswith("scan_")
            for p in response.collisions)

    period = 1.0 / SCAN_HZ
    start = time.monotonic()
    sent = 0
    window = None
    ready = False
    while True:
        now = time.monotonic()
        if not ready and now - start > 30.0:
            raise RuntimeError("~check_collisions never named a scanned obstacle")
        scan = scans[sent % CYCLE]
        scan.header.stamp = rospy.Time.now()
        scan.header.seq = sent
        scan_pub.publish(scan)
        sent += 1
        if not ready and sent % 20 == 0 and scanned_obstacles_checked():
            ready, ready_at = True, now
        if ready and window is None and now - ready_at >= args.warmup:
            window = (now, sent, {name: cpu_seconds(pid) for name, pid in pids.items()})
        if window is not None and now - window[0] >= args.seconds:
            cpu_end = {name: cpu_seconds(pid) for name, pid in pids.items()}
            elapsed = now - window[0]
            scans_per_s = (sent - window[1]) / elapsed
            break
        next_at = start + sent * period
        time.sleep(max(0.0, next_at - time.monotonic()))
    if not scanned_obstacles_checked():
        raise RuntimeError("scanned obstacles gone from ~check_collisions after the window")
    cpu = {name: 100.0 * (cpu_end[name] - window[2][name]) / elapsed for name in pids}
    per_node = " ".join(f"{name}={value:.1f}" for name, value in cpu.items())
    print(f"mode={args.mode} scans_per_s={scans_per_s:.1f} total={sum(cpu.values()):.1f} "
          f"{per_node}", flush=True)


def median(path):
    runs = {}
    for line in open(path):
        fields = dict(field.split("=", 1) for field in line.split())
        if "mode" in fields:
            runs.setdefault(fields.pop("mode"), []).append(fields)
    for mode, lines in runs.items():
        keys = list(lines[0])
        medians = " ".join(
            f"{key}={statistics.median(float(line[key]) for line in lines):.1f}" for key in keys)
        print(f"median mode={mode} runs={len(lines)} {medians}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--mode")
    parser.add_argument("--nodes", nargs="+")
    parser.add_argument("--seconds", type=float, default=30.0)
    parser.add_argument("--warmup", type=float, default=5.0)
    parser.add_argument("--median")
    args = parser.parse_args()
    if args.median:
        median(args.median)
    elif not args.mode or not args.nodes:
        parser.error("--mode and --nodes, or --median")
    else:
        measure(args)


if __name__ == "__main__":
    sys.exit(main())
