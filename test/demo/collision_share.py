#!/usr/bin/env python3
"""Share of the demo's collision states in which a robot link is in collision.

Records the collision node's ~collisions for --duration seconds (from the first message), drops
the first --skip seconds (start-up), and prints how many of the remaining states had a robot link
(a link of the URDF in ~robot_description) touching an obstacle, which links, and how many had
a self-collision (two links). Run it beside a running demo, with Debian's python3:

  /usr/bin/python3 test/demo/collision_share.py --duration 90 --skip 15
"""
import argparse
import collections
import sys
import xml.etree.ElementTree as ElementTree

import rospy
from ellipse_collision.msg import CollisionState


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--duration", type=float, default=90.0, help="[s] recorded in all")
    parser.add_argument("--skip", type=float, default=15.0, help="[s] dropped at the start")
    parser.add_argument("--topic", default="/ellipse_collision/collisions")
    args = parser.parse_args(rospy.myargv()[1:])
    if not 0.0 <= args.skip < args.duration:
        parser.error("expected 0 <= --skip < --duration, got %g and %g" % (args.skip, args.duration))

    rospy.init_node("collision_share", anonymous=True)
    # The demo's launch may still be setting its parameters.
    while not rospy.has_param("/robot_description") and not rospy.is_shutdown():
        rospy.sleep(0.5)
    urdf = rospy.get_param("/robot_description")
    links = {link.get("name") for link in ElementTree.fromstring(urdf).iter("link")}

    states = []
    rospy.Subscriber(args.topic, CollisionState, states.append, queue_size=1000)
    while not states and not rospy.is_shutdown():
        rospy.sleep(0.1)
    first = states[0].header.stamp
    rospy.sleep(args.duration - (rospy.Time.now() - first).to_sec())

    counted = [s for s in list(states) if (s.header.stamp - first).to_sec() >= args.skip]
    with_obstacle = 0
    self_collision = 0
    any_link = 0
    incomplete = 0
    per_link = collections.Counter()
    for state in counted:
        if not state.complete:
            incomplete += 1
        hit = set()
        selfs = False
        for pair in state.collisions:
            a_link, b_link = pair.name_a in links, pair.name_b in links
            if a_link and b_link:
                selfs = True
            elif a_link or b_link:
                hit.add(pair.name_a if a_link else pair.name_b)
        per_link.update(hit)
        with_obstacle += bool(hit)
        self_collision += selfs
        any_link += bool(hit) or selfs
    total = len(counted)
    if total == 0:
        print("no states after the first %g s" % args.skip)
        return 1

    def share(n):
        return "%d of %d (%.1f %%)" % (n, total, 100.0 * n / total)

    print("states from %g s to %g s: %d (%d incomplete)" % (args.skip, args.duration, total,
                                                            incomplete))
    print("a link touches an obstacle: " + share(with_obstacle))
    print("  by link: " + ", ".join("%s %d" % kv for kv in sorted(per_link.items())))
    print("self-collision: " + share(self_collision))
    print("any robot link in collision: " + share(any_link))
    return 0


if __name__ == "__main__":
    sys.exit(main())
