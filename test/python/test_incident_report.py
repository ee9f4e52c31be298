#!/usr/bin/env python3
"""incident_report (scripts/incident_report) on incident bags written here with the node's
format (doc/incidents.md): the page names the action and the limiting pair and lists every
decision; the scene figure has the limiting link, the limiting obstacle and another obstacle drawn
in their colours where the bag puts them, and nothing where it has nothing; a bag of plain
~gate_state messages gives a page without a scene. --replay reproduces the bags the node wrote
(test/incidents/), names a changed decision's field and refuses bags of an older format.

usage: test_incident_report.py [--gtest_output=xml:FILE]
(run by `catkin_make run_tests` after `source devel/setup.bash`, see cmake/test.cmake)
"""
import importlib.machinery
import importlib.util
import os
import re
import shutil
import subprocess
import sys
import tempfile
import unittest

import matplotlib.image
import rosbag
import rospy
from std_msgs.msg import String

from ellipse_collision.msg import Ellipse, GateState, RecordedDecision

SCRIPT = os.path.join(os.path.dirname(os.path.realpath(__file__)), "..", "..", "scripts",
                      "incident_report")


def load_report():
    loader = importlib.machinery.SourceFileLoader("incident_report", SCRIPT)
    spec = importlib.util.spec_from_loader("incident_report", loader)
    module = importlib.util.module_from_spec(spec)
    loader.exec_module(module)
    return module


def ellipse(name, x, y, rx, ry):
    return Ellipse(name=name, frame_id="map", x=x, y=y, angle=0.0, radius_x=rx, radius_y=ry)


def decision(t, action, with_obstacles, linear_x):
    msg = RecordedDecision()
    msg.header.stamp = rospy.Time.from_sec(t)
    msg.header.frame_id = "map"
    msg.decision.header = msg.header
    msg.decision.action = action
    msg.decision.input.linear.x = linear_x
    msg.decision.scale = 1.0 if action == "PASS" else 0.0
    msg.decision.output.linear.x = linear_x * msg.decision.scale
    if action == "STOP":
        msg.decision.link, msg.decision.obstacle = "body", "wall"
        msg.decision.contact_predicted = True
        msg.decision.time_to_contact = 0.2
        msg.decision.contact_point.x, msg.decision.contact_point.y = 1.5, 2.0
        msg.decision.reason = "contact of link 'body' with 'wall' in 0.2 s"
    msg.judged_scene = True
    msg.complete = True
    msg.robot.x, msg.robot.y = 1.0, 2.0
    msg.links.header = msg.header
    msg.links.ellipses = [ellipse("body", 1.0, 2.0, 0.3, 0.3)]
    msg.obstacle_set = 1
    msg.obstacles_changed = with_obstacles
    msg.obstacles.header = msg.header
    if with_obstacles:
        msg.obstacles.ellipses = [ellipse("wall", 1.7, 2.0, 0.2, 1.0),
                                  ellipse("crate", -0.5, 2.0, 0.4, 0.4)]
    msg.source_names, msg.source_ages = ["obstacles"], [0.1]
    return msg


class IncidentReport(unittest.TestCase):
    def setUp(self):
        self.directory = tempfile.mkdtemp(prefix="incident_report_test_")
        self.bag = os.path.join(self.directory, "incident_STOP.bag")
        with rosbag.Bag(self.bag, "w") as bag:
            bag.write("settings", String(data="trigger: 'STOP'\ntrigger_time: 10.0\n"
                                              "gate:\n  horizon: 3.0\n"),
                      rospy.Time.from_sec(9.8))
            for t, action, first in ((9.8, "PASS", True), (9.9, "PASS", False),
                                     (10.0, "STOP", False), (10.1, "STOP", False)):
                msg = decision(t, action, first, 0.0 if t < 9.85 else 1.0)
                bag.write("decisions", msg, msg.header.stamp)

    def tearDown(self):
        shutil.rmtree(self.directory, ignore_errors=True)

    def test_page_names_the_action_and_the_pair_and_lists_the_decisions(self):
        out = os.path.join(self.directory, "out")
        run = subprocess.run([sys.executable, SCRIPT, self.bag, "--output", out],
                             capture_output=True, text=True, timeout=120)
        self.assertEqual(run.returncode, 0, run.stderr)
        page = open(os.path.join(out, "incident_STOP.html")).read()
        self.assertIn("<h1>STOP at t = 10.000 s</h1>", page)
        self.assertIn("body / wall", page)
        self.assertEqual(page.count("<tr"), 5)  # the header and four decisions
        self.assertEqual(page.count('class="key"'), 1)
        for figure in ("incident_STOP_scene.png", "incident_STOP_timelines.png"):
            self.assertIn('src="%s"' % figure, page)
            self.assertTrue(os.path.getsize(os.path.join(out, figure)) > 1000)

    def test_scene_is_drawn_where_the_bag_puts_it(self):
        report = load_report()
        settings, decisions = report.read_bag(self.bag)
        key = report.deciding(settings, decisions)
        self.assertEqual(key.state.action, "STOP")
        self.assertEqual([o.name for o in key.obstacles], ["wall", "crate"])
        path = os.path.join(self.directory, "scene.png")
        pixel = report.draw_scene(key, 3.0, path)
        image = matplotlib.image.imread(path)

        def colour(x, y):
            column, row = pixel(x, y)
            return [round(float(c), 2) for c in image[int(row), int(column)][:3]]

        red, green, blue = colour(1.75, 2.5)  # the limiting obstacle, away from the contact cross
        self.assertGreater(red, 0.8)
        self.assertLess(green, 0.4)
        self.assertLess(blue, 0.4)
        red, green, blue = colour(0.8, 2.1)  # the limiting link (orange), clear of its moved outline
        self.assertGreater(red, 0.8)
        self.assertGreater(green, 0.5)
        self.assertLess(green, 0.85)
        self.assertLess(blue, 0.4)
        red, green, blue = colour(-0.5, 2.0)  # another obstacle: grey
        self.assertAlmostEqual(red, green, delta=0.05)
        self.assertAlmostEqual(green, blue, delta=0.05)
        self.assertLess(red, 0.85)
        for c in colour(1.3, 0.7):  # nothing there, off the grid lines
            self.assertGreater(c, 0.98)

    def test_gate_state_recording_gives_a_page_without_a_scene(self):
        bag_path = os.path.join(self.directory, "recorded.bag")
        with rosbag.Bag(bag_path, "w") as bag:
            for i, action in enumerate(("PASS", "SLOW", "STOP")):
                state = GateState(action=action)
                state.header.stamp = rospy.Time.from_sec(5.0 + 0.1 * i)
                bag.write("/ellipse_collision/gate_state", state, state.header.stamp)
        run = subprocess.run([sys.executable, SCRIPT, bag_path], capture_output=True, text=True,
                             timeout=120)
        self.assertEqual(run.returncode, 0, run.stderr)
        page = open(os.path.join(self.directory, "recorded.html")).read()
        self.assertIn("<h1>STOP at t = 5.200 s</h1>", page)
        self.assertIn("No scene in this bag", page)
        self.assertFalse(os.path.exists(os.path.join(self.directory, "recorded_scene.png")))

    def test_a_bag_without_decisions_is_refused(self):
        bag_path = os.path.join(self.directory, "empty.bag")
        rosbag.Bag(bag_path, "w").close()
        run = subprocess.run([sys.executable, SCRIPT, bag_path], capture_output=True, text=True,
                             timeout=120)
        self.assertEqual(run.returncode, 1)
        self.assertIn("holds no gate decisions", run.stderr)


COMMITTED = os.path.join(os.path.dirname(os.path.realpath(__file__)), "..", "incidents")
SUMMARY = re.compile(r"^replay: (\d+) of (\d+) decisions reproduced", re.MULTILINE)


def replay(bag):
    return subprocess.run([sys.executable, SCRIPT, "--replay", bag], capture_output=True,
                          text=True, timeout=120)


class Replay(unittest.TestCase):
    """--replay: the bags the node wrote (test/incidents/) reproduce every decision its rules
    judged; a tampered one is named; bags of an older or another format are refused."""

    def setUp(self):
        self.directory = tempfile.mkdtemp(prefix="incident_replay_test_")
        self.bags = sorted(os.path.join(COMMITTED, name) for name in os.listdir(COMMITTED)
                           if name.endswith(".bag"))

    def tearDown(self):
        shutil.rmtree(self.directory, ignore_errors=True)

    def test_the_committed_bags_are_reproduced(self):
        self.assertGreaterEqual(len(self.bags), 2)
        for bag in self.bags:
            run = replay(bag)
            self.assertEqual(run.returncode, 0, bag + "\n" + run.stdout + run.stderr)
            found = SUMMARY.search(run.stdout)
            self.assertIsNotNone(found, run.stdout)
            self.assertEqual(found.group(1), found.group(2))
            self.assertGreater(int(found.group(2)), 5, bag)

    def copy_with(self, source, change):
        """`source` rewritten to a bag of its own, each decision message passed through
        change(index, msg)."""
        path = os.path.join(self.directory, "changed.bag")
        with rosbag.Bag(source) as bag_in, rosbag.Bag(path, "w") as bag_out:
            index = 0
            for topic, msg, stamp in bag_in.read_messages():
                if topic == "decisions":
                    msg = change(index, msg)
                    index += 1
                bag_out.write(topic, msg, stamp)
        return path

    def test_a_changed_decision_is_named_with_both_values(self):
        def change(index, msg):
            if msg.judged_by_rules and msg.decision.action == "STOP" and not changed:
                changed.append((index, msg.decision.scale))
                msg.decision.scale = 0.25
            return msg

        changed = []
        run = replay(self.copy_with(self.bags[0], change))
        self.assertEqual(changed[0][1], 0.0)
        self.assertEqual(run.returncode, 1, run.stdout + run.stderr)
        lines = run.stdout.splitlines()
        self.assertEqual(len(lines), 2, run.stdout)
        self.assertRegex(lines[0], r"^decision %d at [0-9.]+ s: scale recorded 0.25, replayed 0$"
                         % changed[0][0])
        found = SUMMARY.search(run.stdout)
        self.assertEqual(int(found.group(1)), int(found.group(2)) - 1)

    def test_a_bag_of_the_older_format_is_refused(self):
        # Written as the node wrote bags before the replay's fields: no `format` in settings.
        old = os.path.join(self.directory, "old.bag")
        with rosbag.Bag(old, "w") as bag:
            bag.write("settings", String(data="trigger: 'STOP'\ntrigger_time: 10.0\n"),
                      rospy.Time.from_sec(9.8))
            msg = decision(9.8, "STOP", True, 1.0)
            bag.write("decisions", msg, msg.header.stamp)
        run = replay(old)
        self.assertEqual(run.returncode, 2)
        self.assertIn("no 'format': the bag was written before replay was possible", run.stderr)
        self.assertNotIn("reproduced", run.stdout)

    def test_decisions_of_another_type_are_refused(self):
        run = replay(self.copy_with(self.bags[0], lambda index, msg: String(data="decision")))
        self.assertEqual(run.returncode, 2)
        self.assertIn("decisions are std_msgs/String", run.stderr)
        self.assertIn("the bag is of another format", run.stderr)


if __name__ == "__main__":
    import rosunit
    rosunit.unitrun("ellipse_collision", "python_incident_report", "__main__",
                    sys.argv[:1] + [a for a in sys.argv[1:] if a.startswith("--gtest_output")])
