#!/usr/bin/env python3
"""The scan pipeline under a 720-beam LaserScan at 40 Hz (issue 33), started by
scripts/nodelet_cpu.sh as separate processes or as nodelets in one manager. Publishes
base_link -> laser on /tf_static and the scans on /scan (a room with posts, a wall and a box that
moves past the arm, a new position every scan, range noise), waits until the collision node's
~check_collisions names scanned obstacles, measures the CPU (% of one core, utime + stime from
/proc/<pid>/stat) of each given node over the window, checks the obstacles are still fresh after
it, and prints one line:

  mode=M scans_per_s=S total=C /node_a=A /node_b=B ...

The obstacle sources inside the collision node (issue 42, scripts/nodelet_cpu.sh --sources): the
same scans on each topic of --scans (one per scanner), with --cloud TOPIC also a depth camera's
PointCloud2 of the same room (--cloud-points points at --cloud-hz), and with --gate-hz commands on
the node's ~cmd_vel_in.

No subscriber of its own on the obstacle ellipses: in one manager they would have to be
serialised for it, which is the very cost measured. --median FILE prints the medians per mode of
the lines in FILE, side by side.

Usage (roscore and the pipeline running, the collision node at /ellipse_collision):
  scan_pipeline_load.py --mode M --nodes /ellipse_collision /scan_obstacles [--seconds 30]
                        [--warmup 5] [--scans TOPIC ...] [--cloud TOPIC] [--cloud-hz 15]
                        [--cloud-points 20000] [--gate-hz 20]
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


def publish_scans(publishers, scans):
    """A function publishing scan number `step` on every scanner's topic, stamped now."""
    import rospy

    def publish(step):
        scan = scans[step % CYCLE]
        scan.header.stamp = rospy.Time.now()
        scan.header.seq = step
        for publisher in publishers:
            publisher.publish(scan)
    return publish


def make_cloud(step, points, rng):
    """A depth camera's PointCloud2 (float x, y, z) of the room at `step`: `points` points on its
    surfaces within 60 degrees either side of straight ahead, heights 0.05-1.5 m, 5 mm noise."""
    import struct
    from sensor_msgs.msg import PointCloud2, PointField
    rows = 50
    columns = points // rows
    circles = circles_at(step)
    data = bytearray()
    for c in range(columns):
        angle = -math.pi / 3.0 + (2.0 * math.pi / 3.0) * c / columns
        r = min(ray(angle, circles), RANGE_MAX) + rng.gauss(0.0, NOISE_M)
        x, y = r * math.cos(angle), r * math.sin(angle)
        for row in range(rows):
            data += struct.pack("<fff", x, y, 0.05 + 1.45 * row / (rows - 1))
    cloud = PointCloud2()
    cloud.header.frame_id = "laser"
    cloud.height = 1
    cloud.width = columns * rows
    cloud.fields = [PointField(name=n, offset=4 * i, datatype=PointField.FLOAT32, count=1)
                    for i, n in enumerate("xyz")]
    cloud.point_step = 12
    cloud.row_step = 12 * cloud.width
    cloud.is_dense = True
    cloud.data = bytes(data)
    return cloud


def publish_clouds(publisher, points):
    """A function publishing cloud number `step` (a cycle of 15 clouds), stamped now."""
    import rospy
    rng = random.Random(42)
    clouds = [make_cloud(step * CYCLE // 15, points, rng) for step in range(15)]

    def publish(step):
        cloud = clouds[step % len(clouds)]
        cloud.header.stamp = rospy.Time.now()
        cloud.header.seq = step
        publisher.publish(cloud)
    return publish


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
    from geometry_msgs.msg import Twist
    from sensor_msgs.msg import LaserScan, PointCloud2
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
    scan_pubs = [rospy.Publisher(topic, LaserScan, queue_size=1) for topic in args.scans]
    scans = make_scans()
    streams = [(1.0 / SCAN_HZ, publish_scans(scan_pubs, scans))]
    if args.cloud:
        cloud_pub = rospy.Publisher(args.cloud, PointCloud2, queue_size=1)
        streams.append((1.0 / args.cloud_hz, publish_clouds(cloud_pub, args.cloud_points)))
    if args.gate_hz > 0.0:
        cmd_pub = rospy.Publisher("/ellipse_collision/cmd_vel_in", Twist, queue_size=1)
        command = Twist()
        command.linear.x = 0.3
        streams.append((1.0 / args.gate_hz, lambda _: cmd_pub.publish(command)))

    rospy.wait_for_service("/ellipse_collision/check_collisions", timeout=30.0)
    check = rospy.ServiceProxy("/ellipse_collision/check_collisions", CheckCollisions)

    def scanned_obstacles_checked():
        # A probe ellipse over the whole room collides with every stored obstacle: the scanned
        # ones are named scan_<beam> (<source>/scan_<beam> from the node's own sources).
        probe = Ellipse(name="probe", frame_id="laser", x=0.0, y=0.0, angle=0.0,
                        radius_x=20.0, radius_y=20.0)
        response = check(CheckCollisionsRequest(query=[probe]))
        scanned = [name.rsplit("/", 1)[-1].startswith("scan_")
                   for p in response.collisions for name in (p.name_a, p.name_b)]
        return response.success and any(scanned)

    start = time.monotonic()
    due = [start] * len(streams)  # when each stream publishes next
    counts = [0] * len(streams)
    window = None
    ready = False
    while True:
        now = time.monotonic()
        if not ready and now - start > 30.0:
            raise RuntimeError("~check_collisions never named a scanned obstacle")
        for i, (period, publish) in enumerate(streams):
            if now >= due[i]:
                publish(counts[i])
                counts[i] += 1
                due[i] = start + counts[i] * period
        sent = counts[0]  # scans
        if not ready and sent % 20 == 0 and sent > 0 and scanned_obstacles_checked():
            ready, ready_at = True, now
        if ready and window is None and now - ready_at >= args.warmup:
            window = (now, sent, {name: cpu_seconds(pid) for name, pid in pids.items()})
        if window is not None and now - window[0] >= args.seconds:
            cpu_end = {name: cpu_seconds(pid) for name, pid in pids.items()}
            elapsed = now - window[0]
            scans_per_s = (sent - window[1]) / elapsed
            break
        time.sleep(max(0.0, min(due) - time.monotonic()))
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
    parser.add_argument("--scans", nargs="+", default=["/scan"],
                        help="topics the scans go to, one per scanner")
    parser.add_argument("--cloud", help="topic of a depth camera's PointCloud2 (none: no cloud)")
    parser.add_argument("--cloud-hz", type=float, default=15.0)
    parser.add_argument("--cloud-points", type=int, default=20000)
    parser.add_argument("--gate-hz", type=float, default=0.0,
                        help="commands on /ellipse_collision/cmd_vel_in (0: none)")
    args = parser.parse_args()
    if args.median:
        median(args.median)
    elif not args.mode or not args.nodes:
        parser.error("--mode and --nodes, or --median")
    else:
        measure(args)


if __name__ == "__main__":
    sys.exit(main())
